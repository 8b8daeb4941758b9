#include "core/coverage/ReallocationSimulation.hpp"

#include "core/allocation/PieceSettlement.hpp"
#include "core/allocation/RegionExpansion.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>
#include <queue>
#include <utility>

namespace mcpp {
namespace {

std::vector<int> everyCell(const CellGraph& graph) {
    std::vector<int> cells(graph.size());
    std::iota(cells.begin(), cells.end(), 0);
    return cells;
}

std::vector<double> eventTimes(const std::vector<SpeedEvent>& events) {
    std::vector<double> times;
    for (const SpeedEvent& event : events)
        times.push_back(event.timeSeconds);
    std::sort(times.begin(), times.end());
    return times;
}

} // namespace

ReallocationSimulation::ReallocationSimulation(const CellGraph& graph, std::vector<SpeedEvent> events)
    : graph_(graph), events_(std::move(events)), nodes_(graph, everyCell(graph)), exchange_(graph) {}

ReallocationSimulation::Result ReallocationSimulation::run(const std::vector<int>& startCells,
                                                           const std::vector<MapPoint>& starts,
                                                           const ProgressReporter& progress) {
    owner_ = firstDivision(startCells);
    firstRegions_ = owner_;
    entered_.assign(graph_.size(), 0);
    robots_.clear();
    robots_.resize(startCells.size());
    for (std::size_t r = 0; r < robots_.size(); ++r) {
        robots_[r].schedule = SpeedSchedule(events_, static_cast<int>(r));
        robots_[r].walk = std::make_unique<DynamicTreeWalk>(graph_, nodes_, static_cast<int>(r), starts[r],
                                                            startCells[r], entered_);
        timeNewWaypoints(static_cast<int>(r));
    }
    const int everyMove = static_cast<int>(graph_.size());
    exchange(0.0, everyMove);

    using Turn = std::pair<double, int>; // (clock, robot): the robot that is furthest behind acts next
    std::priority_queue<Turn, std::vector<Turn>, std::greater<>> turns;
    for (std::size_t r = 0; r < robots_.size(); ++r)
        if (robots_[r].state == State::Driving)
            turns.emplace(robots_[r].clock, static_cast<int>(r));
    const std::vector<double> changes = eventTimes(events_);
    std::size_t nextChange = 0;
    // Between events, a rebalance every so many cell moves keeps slow drifts in check at a bounded cost.
    const int rhythm = std::max(8 * static_cast<int>(robots_.size()), everyMove / 64);
    int movesSinceExchange = 0;
    std::size_t movesInAll = 0;
    const std::size_t moveLimit = 64 * graph_.size() + 1024; // never spin, whatever the exchange does

    const auto rebalance = [&](double now) {
        const bool moved = exchange(now, everyMove) > 0;
        movesSinceExchange = 0;
        if (!moved)
            return;
        std::vector<char> holdsFreeCell(robots_.size(), 0);
        for (std::size_t cell = 0; cell < owner_.size(); ++cell)
            if (owner_[cell] >= 0 && entered_[cell] == 0)
                holdsFreeCell[static_cast<std::size_t>(owner_[cell])] = 1;
        for (std::size_t r = 0; r < robots_.size(); ++r)
            if (robots_[r].state == State::Idle && holdsFreeCell[r] != 0) {
                robots_[r].state = State::Driving;
                robots_[r].clock = std::max(robots_[r].clock, now);
                turns.emplace(robots_[r].clock, static_cast<int>(r));
            }
    };

    while (!turns.empty() && movesInAll < moveLimit) {
        const auto [now, r] = turns.top();
        turns.pop();
        Robot& robot = robots_[static_cast<std::size_t>(r)];
        if (robot.state != State::Driving)
            continue;
        bool due = movesSinceExchange >= rhythm;
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
        ++movesSinceExchange;
        if (++movesInAll % 4096 == 0) {
            progress.throwIfCancelled();
            const auto entered = std::count(entered_.begin(), entered_.end(), char{1});
            progress.report("simulation", static_cast<double>(entered) / static_cast<double>(owner_.size()));
        }
        if (robot.state == State::Driving)
            turns.emplace(robot.clock, r);
    }
    return finish();
}

// The regions grown from the starts in turns, then evened out before anyone moves (seed 003, figure 6 b).
std::vector<int> ReallocationSimulation::firstDivision(const std::vector<int>& startCells) const {
    RegionAllocation regions;
    regions.robotOfCell = expandRegions(graph_, startCells);
    regions.startCell = startCells;
    regions.costSeconds.assign(startCells.size(), 0.0);
    for (std::size_t cell = 0; cell < regions.robotOfCell.size(); ++cell)
        if (regions.robotOfCell[cell] >= 0)
            regions.costSeconds[static_cast<std::size_t>(regions.robotOfCell[cell])] +=
                graph_.cell(static_cast<int>(cell)).coverSeconds();
    settleRegionsWithPieces(graph_, regions);
    return regions.robotOfCell;
}

int ReallocationSimulation::exchange(double now, int maxMoves) {
    std::vector<RemainingWorkExchange::Robot> robots(robots_.size());
    for (std::size_t r = 0; r < robots_.size(); ++r) {
        robots[r].speedFactor = robots_[r].state == State::Stopped ? 0.0 : robots_[r].schedule.factorAt(now);
        robots[r].committedSeconds = robots_[r].walk->committedSeconds();
        robots[r].cell = robots_[r].walk->waypoints().back().cell;
    }
    const int moved = exchange_.exchange(owner_, entered_, robots, maxMoves);
    return moved;
}

bool ReallocationSimulation::act(int robot) {
    if (!robots_[static_cast<std::size_t>(robot)].walk->advance(owner_, entered_))
        return false;
    timeNewWaypoints(robot);
    return true;
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

// The robot stops for good after its first `reachedWaypoints` points: the cells it has not finished, and
// those of the points it never reached, are nobody's work done and go back to the pool.
void ReallocationSimulation::stop(int robot, std::size_t reachedWaypoints) {
    Robot& state = robots_[static_cast<std::size_t>(robot)];
    state.state = State::Stopped;
    for (const int cell : state.walk->abandonOpenCells())
        entered_[static_cast<std::size_t>(cell)] = 0;
    const std::vector<Waypoint>& waypoints = state.walk->waypoints();
    for (std::size_t i = reachedWaypoints; i < waypoints.size(); ++i) {
        const auto cell = static_cast<std::size_t>(waypoints[i].cell);
        if (owner_[cell] == robot)
            entered_[cell] = 0;
    }
}

ReallocationSimulation::Result ReallocationSimulation::finish() {
    Result result;
    result.firstRegions = firstRegions_;
    result.finalRegions = owner_;
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
        for (std::size_t cell = 0; cell < owner_.size(); ++cell)
            if (result.finalRegions[cell] == static_cast<int>(r) &&
                firstRegions_[cell] != static_cast<int>(r)) {
                timeline.cellsTakenOver.push_back(static_cast<int>(cell));
                timeline.takenOverAreaSquareMetres +=
                    graph_.cell(static_cast<int>(cell)).passableAreaSquareMetres;
            }
        result.paths.push_back(std::move(path));
        result.robots.push_back(std::move(timeline));
    }
    return result;
}

} // namespace mcpp
