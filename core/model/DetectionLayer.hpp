#pragma once

#include "core/model/DetectionGrid.hpp"
#include "core/model/DetectionSummary.hpp"
#include "core/model/Plan.hpp"
#include "core/model/PlanLayer.hpp"

#include <memory>

namespace mcpp {

// What a detection planner's passes see (CPPIED): the grid and its figures.
class DetectionLayer final : public PlanLayer {
  public:
    static constexpr const char* kindName = "detection";

    DetectionLayer(DetectionGrid grid, DetectionSummary summary)
        : grid_(std::move(grid)), summary_(summary) {}
    [[nodiscard]] std::string kind() const override { return kindName; }
    [[nodiscard]] const DetectionGrid& grid() const { return grid_; }
    [[nodiscard]] const DetectionSummary& summary() const { return summary_; }

  private:
    DetectionGrid grid_;
    DetectionSummary summary_;
};

// The plan's detection layer, or null when its planner does not model detection.
[[nodiscard]] inline const DetectionLayer* detectionLayerOf(const Plan& plan) {
    for (const std::shared_ptr<const PlanLayer>& layer : plan.layers)
        if (const auto* detection = dynamic_cast<const DetectionLayer*>(layer.get()))
            return detection;
    return nullptr;
}

} // namespace mcpp
