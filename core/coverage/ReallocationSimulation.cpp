#include "core/coverage/ReallocationSimulation.hpp"

#include "core/allocation/PieceSettlement.hpp"
#include "core/allocation/RegionCosts.hpp"
#include "core/allocation/RegionExpansion.hpp"
#include "core/coverage/SpanningTreeCoverage.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <queue>
#include <utility>

namespace mcpp {
namespace {

std::vector<double> eventTimes(const std::vector<SpeedEvent>& events) {
    std::vector<double> times;
    for (const SpeedEvent& event : events)
        times.push_back(event.timeSeconds);
    std::sort(times.begin(), times.end());
    return times;
}

} // namespace

ReallocationSimulation::ReallocationSimulation(const CellGraph& graph, std::vector<SpeedEvent> events)
    : graph_(graph), events_(std::move(events)), exchange_(graph) {}

ReallocationSimulation::Result ReallocationSimulation::run(const RegionAllocation& division,
                                                           const std::vector<MapPoint>& starts,
                                                           const ProgressReporter& progress) {
    const std::vector<int>& startCells = division.startCell;
    owner_ = division.robotOfCell;
    firstRegions_ = owner_;
    entered_.assign(graph_.size(), 0);
    robots_.clear();
    robots_.resize(startCells.size());
    for (std::size_t r = 0; r < robots_.size(); ++r) {
        robots_[r].schedule = SpeedSchedule(events_, static_cast<int>(r));
        robots_[r].walk = std::make_unique<DynamicTreeWalk>(graph_, static_cast<int>(r), starts[r],
                                                            startCells[r], entered_);
        timeNewWaypoints(static_cast<int>(r));
    }
    planTrees(startCells, starts);
    for (Robot& robot : robots_)
        robot.walk->followPlannedTrees(&plannedParent_);
    countFreeCells();
    for (std::size_t r = 0; r < robots_.size(); ++r)
        if (robots_[r].state == State::Driving)
            turns_.emplace(robots_[r].clock, static_cast<int>(r));
    playEvents(progress);
    return finish();
}

// Robots act in the order of their clocks, one cell move at a time, until none has anything left to do.
void ReallocationSimulation::playEvents(const ProgressReporter& progress) {
    const std::vector<double> changes = eventTimes(events_);
    std::size_t nextChange = 0;
    // After the first event, a rebalance every so many cell moves keeps slow drifts in check at a bounded
    // cost. Before it the walks drive the planned trees, balanced on their paths: cells move then only to a
    // robot that has run out of work.
    const int rhythm = std::max(8 * static_cast<int>(robots_.size()), static_cast<int>(graph_.size()) / 64);
    std::size_t movesInAll = 0;
    const std::size_t moveLimit = 64 * graph_.size() + 1024; // never spin, whatever the exchange does
    while (!turns_.empty() && movesInAll < moveLimit) {
        const auto [now, r] = turns_.top();
        turns_.pop();
        Robot& robot = robots_[static_cast<std::size_t>(r)];
        if (robot.state != State::Driving)
            continue;
        bool due = nextChange > 0 && movesSinceExchange_ >= rhythm;
        for (; nextChange < changes.size() && changes[nextChange] <= now; ++nextChange)
            due = true;
        if (robot.schedule.stoppedFrom(robot.clock)) {
            stop(r, robot.secondsAt.size());
            due = true;
        }
        if (due)
            rebalance(now);
        if (robot.state != State::Driving)
            continue;
        if (!act(r)) {
            robot.state = State::Idle;
            rebalance(now);
            continue;
        }
        ++movesSinceExchange_;
        if (++movesInAll % 4096 == 0)
            reportProgress(progress);
        if (robot.state == State::Stopped) // it stopped on the way: the others take over now
            rebalance(robot.clock);
        else
            turns_.emplace(robot.clock, r);
    }
    if (movesInAll >= moveLimit)
        gaveUp_ = true;
}

void ReallocationSimulation::reportProgress(const ProgressReporter& progress) const {
    progress.throwIfCancelled();
    // Cells entered so far, from the walks' counts: counting the map here would cost a pass per report.
    std::size_t entered = 0;
    for (const Robot& robot : robots_)
        entered += robot.walk->cellsEntered();
    progress.report("simulation",
                    std::min(1.0, static_cast<double>(entered) / static_cast<double>(owner_.size())));
}

// Exchanges cells and wakes the idle robots that got some, at `now` (they waited until then).
void ReallocationSimulation::rebalance(double now) {
    movesSinceExchange_ = 0;
    if (exchange(now, static_cast<int>(graph_.size())) == 0)
        return;
    countFreeCells();
    for (std::size_t r = 0; r < robots_.size(); ++r)
        if (robots_[r].state == State::Idle && robots_[r].freeCells > 0) {
            robots_[r].state = State::Driving;
            robots_[r].clock = std::max(robots_[r].clock, now);
            turns_.emplace(robots_[r].clock, static_cast<int>(r));
        }
}

// The regions grown from the starts in turns, then evened out before anyone moves (seed 003, figure 6 b).
RegionAllocation ReallocationSimulation::firstDivision(const CellGraph& graph,
                                                       const std::vector<int>& startCells,
                                                       const ProgressReporter& progress) {
    RegionAllocation regions;
    regions.robotOfCell = expandRegions(graph, startCells);
    regions.startCell = startCells;
    regions.costSeconds = regionCosts(graph, regions.robotOfCell, startCells.size());
    settleRegionsWithPieces(graph, regions, progress);
    return regions;
}

// Each region's MCPP-MLCT tree (the candidate whose walk is quickest), as the walks' plan: without events
// they drive it as the static plan would.
void ReallocationSimulation::planTrees(const std::vector<int>& startCells,
                                       const std::vector<MapPoint>& starts) {
    plannedParent_.assign(graph_.size(), -1);
    std::vector<std::vector<int>> cells(startCells.size());
    for (std::size_t cell = 0; cell < owner_.size(); ++cell)
        if (owner_[cell] >= 0)
            cells[static_cast<std::size_t>(owner_[cell])].push_back(static_cast<int>(cell));
    std::vector<int> scratch(graph_.size(), -1);
    const SpanningTreeCoverage coverage(false);
    for (std::size_t r = 0; r < startCells.size(); ++r) {
        if (cells[r].empty() || owner_[static_cast<std::size_t>(startCells[r])] != static_cast<int>(r))
            continue;
        const SpanningTree tree =
            coverage.bestTree(graph_, cells[r], startCells[r], starts[r], scratch).first;
        for (int node = 0; node < static_cast<int>(tree.size()); ++node)
            if (const int parent = tree.parent(node); parent >= 0)
                plannedParent_[static_cast<std::size_t>(tree.cellOf(node))] = tree.cellOf(parent);
    }
}

int ReallocationSimulation::exchange(double now, int maxMoves) {
    std::vector<RemainingWorkExchange::Robot> robots(robots_.size());
    for (std::size_t r = 0; r < robots_.size(); ++r) {
        robots[r].speedFactor = currentFactor(static_cast<int>(r), now);
        robots[r].committedSeconds = robots_[r].walk->committedSeconds();
        robots[r].cell = robots_[r].walk->waypoints().back().cell;
    }
    return exchange_.exchange(owner_, entered_, robots, maxMoves);
}

// The robot's speed factor as known at `now`: the simulation plays the events as they come and foresees
// none. A robot at 0 gives its free cells away; should it start again, it is idle and gets cells back.
double ReallocationSimulation::currentFactor(int robot, double now) const {
    const Robot& state = robots_[static_cast<std::size_t>(robot)];
    return state.state == State::Stopped ? 0.0 : state.schedule.factorAt(now);
}

// One move of the robot's walk; false when it has nothing left to do. A robot whose tree is done and whose
// region holds no free cell is idle without searching the map for one.
bool ReallocationSimulation::act(int robot) {
    Robot& state = robots_[static_cast<std::size_t>(robot)];
    if (state.walk->treeDone() && state.freeCells == 0)
        return false;
    const std::size_t enteredBefore = state.walk->cellsEntered();
    if (!state.walk->advance(owner_, entered_))
        return false;
    state.freeCells -= static_cast<int>(state.walk->cellsEntered() - enteredBefore);
    timeNewWaypoints(robot);
    return true;
}

void ReallocationSimulation::countFreeCells() {
    for (Robot& robot : robots_)
        robot.freeCells = 0;
    for (std::size_t cell = 0; cell < owner_.size(); ++cell)
        if (owner_[cell] >= 0 && entered_[cell] == 0)
            ++robots_[static_cast<std::size_t>(owner_[cell])].freeCells;
}

// Real times for the waypoints the walk just added; a robot that stops for good on the way stops there.
void ReallocationSimulation::timeNewWaypoints(int robot) {
    Robot& state = robots_[static_cast<std::size_t>(robot)];
    const std::vector<double>& nominal = state.walk->nominalSecondsAt();
    for (std::size_t i = state.secondsAt.size(); i < nominal.size(); ++i) {
        const double step = i == 0 ? 0.0 : nominal[i] - nominal[i - 1];
        const double reached = state.schedule.finishTime(state.clock, step);
        if (std::isinf(reached)) {
            stop(robot, i);
            return;
        }
        state.secondsAt.push_back(reached);
        state.clock = reached;
    }
}

// The robot stops for good after its first `reachedWaypoints` points: the cells it has not finished are
// nobody's work done and go back to the pool.
void ReallocationSimulation::stop(int robot, std::size_t reachedWaypoints) {
    Robot& state = robots_[static_cast<std::size_t>(robot)];
    state.state = State::Stopped;
    for (const int cell : state.walk->abandonUnfinishedCells(reachedWaypoints))
        entered_[static_cast<std::size_t>(cell)] = 0;
    countFreeCells();
}

ReallocationSimulation::Result ReallocationSimulation::finish() {
    Result result;
    result.firstRegions = firstRegions_;
    result.finalRegions = owner_;
    result.gaveUp = gaveUp_;
    for (std::size_t cell = 0; cell < owner_.size(); ++cell)
        if (owner_[cell] >= 0 && entered_[cell] == 0) {
            result.finalRegions[cell] = -1;
            result.uncoveredCells.push_back(static_cast<int>(cell));
        }
    for (std::size_t r = 0; r < robots_.size(); ++r) {
        Robot& robot = robots_[r];
        CoveragePath path;
        path.robot = static_cast<int>(r);
        path.waypoints = robot.walk->takeWaypoints();
        path.waypoints.resize(robot.secondsAt.size());
        path.closed = false;
        RobotTimeline timeline;
        timeline.robot = static_cast<int>(r);
        timeline.completionSeconds = robot.secondsAt.empty() ? 0.0 : robot.secondsAt.back();
        timeline.secondsAtWaypoint = std::move(robot.secondsAt);
        timeline.stopped = robot.state == State::Stopped;
        result.paths.push_back(std::move(path));
        result.robots.push_back(std::move(timeline));
    }
    // One pass over the map for every robot's taken-over cells.
    for (std::size_t cell = 0; cell < owner_.size(); ++cell) {
        const int robot = result.finalRegions[cell];
        if (robot < 0 || firstRegions_[cell] == robot)
            continue;
        RobotTimeline& timeline = result.robots[static_cast<std::size_t>(robot)];
        timeline.cellsTakenOver.push_back(static_cast<int>(cell));
        timeline.takenOverAreaSquareMetres += graph_.cell(static_cast<int>(cell)).passableAreaSquareMetres;
    }
    return result;
}

} // namespace mcpp
