#pragma once

#include "core/model/Plan.hpp"
#include "core/model/PlanLayer.hpp"
#include "core/model/RobotTimeline.hpp"
#include "core/model/SpeedEvent.hpp"

#include <memory>
#include <string>
#include <vector>

namespace mcpp {

// A plan simulated over time with events (robots slowing down or stopping), beside a static plan run
// through the same events: what re-allocation saved.
class TimelineLayer final : public PlanLayer {
  public:
    static constexpr const char* kindName = "timeline";

    struct Summary {
        std::vector<SpeedEvent> events;
        double makespanSeconds = 0.0;       // under the events
        std::string staticPlanner;          // the plan run without re-allocation; empty when not compared
        double staticMakespanSeconds = 0.0; // its makespan under the events; infinity when one stopped first
        double staticPlanMakespanSeconds = 0.0; // its makespan without events
    };

    TimelineLayer(Summary summary, std::vector<RobotTimeline> robots, std::vector<int> firstRegions)
        : summary_(std::move(summary)), robots_(std::move(robots)), firstRegions_(std::move(firstRegions)) {}
    [[nodiscard]] std::string kind() const override { return kindName; }
    [[nodiscard]] const Summary& summary() const { return summary_; }
    [[nodiscard]] const std::vector<RobotTimeline>& robots() const { return robots_; }
    // Which robot each cell was first given to (-1: none), before any exchange.
    [[nodiscard]] const std::vector<int>& firstRegions() const { return firstRegions_; }

  private:
    Summary summary_;
    std::vector<RobotTimeline> robots_;
    std::vector<int> firstRegions_;
};

// The plan's timeline, or null when it was not simulated over time.
[[nodiscard]] inline const TimelineLayer* timelineLayerOf(const Plan& plan) {
    for (const std::shared_ptr<const PlanLayer>& layer : plan.layers)
        if (const auto* timeline = dynamic_cast<const TimelineLayer*>(layer.get()))
            return timeline;
    return nullptr;
}

} // namespace mcpp
