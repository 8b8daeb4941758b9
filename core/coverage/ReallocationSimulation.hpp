#pragma once

#include "core/allocation/RemainingWorkExchange.hpp"
#include "core/coverage/DynamicTreeWalk.hpp"
#include "core/model/CellGraph.hpp"
#include "core/model/CoveragePath.hpp"
#include "core/model/ProgressReporter.hpp"
#include "core/model/RegionAllocation.hpp"
#include "core/model/RobotTimeline.hpp"
#include "core/model/SpeedEvent.hpp"
#include "core/model/SpeedSchedule.hpp"

#include <functional>
#include <memory>
#include <queue>
#include <utility>
#include <vector>

namespace mcpp {

// MDSTC as the mission unfolds (seed 003): regions grown from the starts, each robot on its DSTC walk along
// its region's planned tree, and the exchange moving free border cells toward whoever will finish first
// whenever an event changes a robot's speed, a robot stops or one runs out of work, and at a steady rhythm
// once an event has come. Robots act in the order of their clocks, one cell move at a time; a stopped
// robot's unfinished cells go back to the pool for the others.
class ReallocationSimulation {
  public:
    struct Result {
        std::vector<CoveragePath> paths;   // the driven paths, by robot (waypoints only; measured later)
        std::vector<RobotTimeline> robots; // when each point is reached, under the events
        std::vector<int> firstRegions;     // by cell: the region expansion's robot
        std::vector<int> finalRegions;     // by cell: the robot that covered it, -1 for none
        std::vector<int> uncoveredCells;   // reachable cells nobody covered (every robot near them stopped)
        bool gaveUp = false;               // stopped at the move limit: the exchange kept moving cells
    };

    ReallocationSimulation(const CellGraph& graph, std::vector<SpeedEvent> events);

    // `division`: the regions the robots set out with (firstDivision, balanced), each holding its start cell.
    [[nodiscard]] Result run(const RegionAllocation& division, const std::vector<MapPoint>& starts,
                             const ProgressReporter& progress);

    // The regions grown from the starts in turns, then evened out before anyone moves (seed 003, figure 6 b).
    // Cancelled through `progress` while they are evened out.
    [[nodiscard]] static RegionAllocation firstDivision(const CellGraph& graph,
                                                        const std::vector<int>& startCells,
                                                        const ProgressReporter& progress);

  private:
    enum class State { Driving, Idle, Stopped };
    struct Robot {
        std::unique_ptr<DynamicTreeWalk> walk;
        SpeedSchedule schedule;
        std::vector<double> secondsAt; // real time at each waypoint so far
        double clock = 0.0;            // real time at its last waypoint, or when it last woke
        State state = State::Driving;
        int freeCells = 0; // cells of its region nobody has entered, as of the last count
    };

    void playEvents(const ProgressReporter& progress);
    void rebalance(double now);
    void reportProgress(const ProgressReporter& progress) const;
    [[nodiscard]] double currentFactor(int robot, double now) const;
    int exchange(double now, int maxMoves);
    [[nodiscard]] bool act(int robot);
    void stop(int robot, std::size_t reachedWaypoints);
    void countFreeCells();
    void planTrees(const std::vector<int>& startCells, const std::vector<MapPoint>& starts);
    void timeNewWaypoints(int robot);
    [[nodiscard]] Result finish();

    const CellGraph& graph_;
    std::vector<SpeedEvent> events_;
    RemainingWorkExchange exchange_;
    std::vector<int> owner_;
    std::vector<char> entered_; // by cell: 0 nobody has entered it, 1 a walk has it open (or a stopped robot
                                // kept it, covered whole), 2 done
    std::vector<int> firstRegions_;
    std::vector<int> plannedParent_; // by cell: where the walks' planned trees enter it from, -1 for none
    std::vector<Robot> robots_;
    using Turn = std::pair<double, int>; // (clock, robot): the robot that is furthest behind acts next
    std::priority_queue<Turn, std::vector<Turn>, std::greater<>> turns_;
    int movesSinceExchange_ = 0;
    bool gaveUp_ = false; // the move limit ended the simulation
};

} // namespace mcpp
