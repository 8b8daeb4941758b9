#include "core/planners/MstcPlanner.hpp"

#include "core/allocation/StartComponents.hpp"
#include "core/coverage/PathMeasurement.hpp"
#include "core/coverage/SpanningTreeBuilder.hpp"
#include "core/coverage/TourSplitter.hpp"
#include "core/coverage/TreeCircumnavigation.hpp"
#include "core/coverage/TurnSearch.hpp"
#include "core/planners/GridStage.hpp"
#include "core/planners/PlanningRun.hpp"

#include <cmath>
#include <limits>

namespace mcpp {
namespace {

// The tour of one part as a cycle (the closing return dropped), of the candidate tree that turns least. On
// MSTC's uniform grid there is one candidate; time and turns would choose alike between more.
// plateauRounds: the turn-minimising tree's search across plateaus of equal turns.
std::vector<Waypoint> partTour(const CellGraph& graph, const StartComponent& part, int rootCell,
                               MapPoint start, int plateauRounds) {
    std::vector<int> scratchIndex(graph.size(), -1);
    const SpanningTreeBuilder trees(graph, scratchIndex, plateauRounds);
    TreeCircumnavigation walker(graph);
    std::vector<Waypoint> best;
    int fewestTurns = std::numeric_limits<int>::max();
    const int candidates = trees.candidatesFor(part.cells);
    for (int candidate = 0; candidate < candidates; ++candidate) {
        std::vector<Waypoint> walk =
            walker.walk(trees.candidate(candidate, part.cells, rootCell), start, true);
        if (walk.size() > 1)
            walk.pop_back();
        const int turns = countTurns(walk);
        if (turns < fewestTurns) {
            fewestTurns = turns;
            best = std::move(walk);
        }
    }
    return best;
}

// Each step of the closed tour: its travel and the turn at its end, as measurePath times them, so that
// pieces of equal time are what the paths take.
std::vector<double> stepSeconds(const std::vector<Waypoint>& tour, const CellGraph& graph) {
    std::vector<double> seconds(tour.size(), 0.0);
    for (std::size_t i = 0; i < tour.size(); ++i) {
        const Waypoint& a = tour[i];
        const Waypoint& b = tour[(i + 1) % tour.size()];
        const Waypoint& c = tour[(i + 2) % tour.size()];
        const double length = std::hypot(b.x - a.x, b.y - a.y);
        seconds[i] = travelSeconds(length, a.speedMetresPerSecond, b.speedMetresPerSecond);
        if (length > 0.0 && (c.x != b.x || c.y != b.y))
            seconds[i] += turnSecondsAt(b, b.x - a.x, b.y - a.y, c.x - b.x, c.y - b.y, graph);
    }
    return seconds;
}

// The tour point in the robot's start cell nearest its start point.
int tourPosition(const std::vector<Waypoint>& tour, int startCell, MapPoint start) {
    int best = 0;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < tour.size(); ++i) {
        const double distance = std::hypot(tour[i].x - start.x, tour[i].y - start.y);
        if (tour[i].cell == startCell && distance < bestDistance) {
            bestDistance = distance;
            best = static_cast<int>(i);
        }
    }
    return best;
}

} // namespace

PlannerDescription MstcPlanner::describe() const {
    PlannerDescription description;
    description.name = "mstc";
    description.label = "MSTC";
    description.summary = "one spanning-tree tour of the grid cut into a piece per robot at the starts";
    description.promises.regionsConnected = false;
    description.promises.pathsCoverOwnRegion = false;
    description.parameters = {
        DecompositionOptions::blockedThresholdParameter(),
        booleanParameter("balanced", "Balanced pieces", false,
                         "Cut the tour into pieces of equal time, each robot walking along the tour (through "
                         "other pieces, forwards or backwards) to its own; otherwise each robot covers the "
                         "tour from its start to the next robot's"),
        TurnSearch::roundsParameter(),
    };
    description.balanceSwitch = "balanced";
    description.unbalancedBecause =
        "each robot covers the tour from its start to the next robot's, so a robot "
        "whose start another's closely follows along the tour gets little";
    return description;
}

void MstcPlanner::run(PlanningRun& run) const {
    const ParameterValues& parameters = run.parameters();
    Plan& plan = run.plan();
    plan.cells = gridStage(run, GridCellRule::WholeCell);
    const std::vector<int> startCells = run.locateStarts();
    const std::vector<MapPoint>& starts = run.starts();
    plan.regions.robotOfCell.assign(plan.cells.size(), -1);
    plan.regions.startCell = startCells;
    plan.paths.resize(starts.size());
    const std::vector<StartComponent> parts =
        run.stage("allocation", [&] { return componentsWithStarts(plan.cells, startCells); });
    // One tree, built once: its search runs within it, not as a stage of its own.
    const int plateauRounds = TurnSearch::roundsFor(plan.cells, parameters);
    run.stage("paths", [&] {
        for (const StartComponent& part : parts) {
            run.progress().throwIfCancelled();
            const auto first = static_cast<std::size_t>(part.robots.front());
            const std::vector<Waypoint> tour =
                partTour(plan.cells, part, startCells[first], starts[first], plateauRounds);
            std::vector<int> positions;
            for (int robot : part.robots)
                positions.push_back(tourPosition(tour, startCells[static_cast<std::size_t>(robot)],
                                                 starts[static_cast<std::size_t>(robot)]));
            const TourSplitter splitter(stepSeconds(tour, plan.cells));
            const std::vector<TourSplitter::Share> shares = parameters.boolean("balanced")
                                                                ? splitter.balancedPieces(positions)
                                                                : splitter.forwardPieces(positions);
            for (std::size_t k = 0; k < part.robots.size(); ++k) {
                const int robot = part.robots[k];
                std::vector<Waypoint> walk;
                for (std::size_t step = 0; step < shares[k].order.size(); ++step) {
                    const Waypoint& point = tour[static_cast<std::size_t>(shares[k].order[step])];
                    walk.push_back(point);
                    // A cell goes to a robot whose piece passes it (two may share its sub-cells).
                    int& owner = plan.regions.robotOfCell[static_cast<std::size_t>(point.cell)];
                    if (step >= shares[k].approach && owner < 0)
                        owner = robot;
                }
                plan.paths[static_cast<std::size_t>(robot)] =
                    pathFromWalk(robot, starts[static_cast<std::size_t>(robot)], std::move(walk), false);
            }
        }
        return 0;
    });
}

} // namespace mcpp
