#pragma once

#include "core/model/Plan.hpp"
#include "core/model/PlanLayer.hpp"
#include "core/model/RobotSorties.hpp"

#include <memory>
#include <vector>

namespace mcpp {

// The sorties of a plan whose robots fly on batteries: one entry per robot, in robot order.
class SortieLayer final : public PlanLayer {
  public:
    static constexpr const char* kindName = "sorties";

    explicit SortieLayer(std::vector<RobotSorties> robots) : robots_(std::move(robots)) {}
    [[nodiscard]] std::string kind() const override { return kindName; }
    [[nodiscard]] const std::vector<RobotSorties>& robots() const { return robots_; }

  private:
    std::vector<RobotSorties> robots_;
};

// The plan's sortie layer, or null when its robots need no charging.
[[nodiscard]] inline const SortieLayer* sortieLayerOf(const Plan& plan) {
    for (const std::shared_ptr<const PlanLayer>& layer : plan.layers)
        if (const auto* sorties = dynamic_cast<const SortieLayer*>(layer.get()))
            return sorties;
    return nullptr;
}

// One robot's sorties in the plan's sortie layer, or null when it has none.
[[nodiscard]] inline const RobotSorties* sortiesOfRobot(const Plan& plan, int robot) {
    if (const SortieLayer* layer = sortieLayerOf(plan))
        for (const RobotSorties& sorties : layer->robots())
            if (sorties.robot == robot)
                return &sorties;
    return nullptr;
}

} // namespace mcpp
