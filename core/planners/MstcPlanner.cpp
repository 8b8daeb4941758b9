#include "core/planners/MstcPlanner.hpp"

#include "core/allocation/StartComponents.hpp"
#include "core/coverage/ApproachRoutes.hpp"
#include "core/coverage/PathMeasurement.hpp"
#include "core/coverage/PathShape.hpp"
#include "core/coverage/SpanningTreeBuilder.hpp"
#include "core/coverage/SubtreePieces.hpp"
#include "core/coverage/TourSplitter.hpp"
#include "core/coverage/TreeCircumnavigation.hpp"
#include "core/coverage/TurnSearch.hpp"
#include "core/model/ParallelFor.hpp"
#include "core/model/ProgressReporter.hpp"
#include "core/planners/GridStage.hpp"
#include "core/planners/PlanningRun.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

namespace mcpp {
namespace {

// The tour of one part as a cycle (the closing return dropped), of the candidate tree that turns least. On
// MSTC's uniform grid there is one candidate; time and turns would choose alike between more.
// plateauRounds: the turn-minimising tree's search across plateaus of equal turns.
std::vector<Waypoint> partTour(const CellGraph& graph, const StartComponent& part, int rootCell,
                               MapPoint start, int plateauRounds, const ProgressReporter& progress) {
    std::vector<int> scratchIndex(graph.size(), -1);
    const SpanningTreeBuilder trees(graph, scratchIndex, plateauRounds, &progress);
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

// The waypoints of a robot's way from its tour position to the tour point `entry` along `cells` (its start
// cell first): in each cell between, the centre of the sub-cell in the entry's quarter, so that straight
// runs of cells make straight legs; another free one where that is blocked.
std::vector<Waypoint> approachWaypoints(const CellGraph& graph, const std::vector<Waypoint>& tour,
                                        int position, const std::vector<int>& cells, const Waypoint& entry,
                                        const std::vector<int>& tourPointOfCell) {
    std::vector<Waypoint> way{tour[static_cast<std::size_t>(position)]};
    const SubCell quarter = graph.cell(entry.cell).subCellAt({entry.x, entry.y});
    for (std::size_t k = 1; k + 1 < cells.size(); ++k) {
        const Cell cell = graph.cell(cells[k]);
        SubCell chosen = quarter;
        for (SubCell other : subCellsCounterClockwise)
            if (!cell.isFree(chosen) && cell.isFree(other))
                chosen = other;
        Waypoint point = tour[static_cast<std::size_t>(tourPointOfCell[static_cast<std::size_t>(cells[k])])];
        const MapPoint centre = cell.subCellCentre(chosen);
        point.x = centre.x;
        point.y = centre.y;
        way.push_back(point);
    }
    if (way.back().x == entry.x && way.back().y == entry.y)
        way.pop_back(); // it starts where its piece does
    return way;
}

// A robot's walk: its way to its piece (the first `approach` points), then the piece.
struct PieceWalk {
    std::vector<Waypoint> walk;
    std::size_t approach = 0;
};

// The robots of one part: their start cells and points, in the part's order.
struct PartRobots {
    std::vector<int> robots;
    std::vector<int> startCells;
    std::vector<MapPoint> starts;
};

// Each robot's quickest ways from its start cell (ApproachRoutes), searched once for every cut of the part.
struct RobotWays {
    RobotWays(const CellGraph& graph, const PartRobots& part, const ProgressReporter& progress)
        : routes(graph), secondsToCell(part.startCells.size()) {
        parallelFor(part.startCells.size(),
                    [&](std::size_t k, int) { secondsToCell[k] = routes.secondsFrom(part.startCells[k]); });
        progress.throwIfCancelled(); // a search per robot over the whole part: a second or so on big maps
    }

    ApproachRoutes routes;
    std::vector<std::vector<float>> secondsToCell; // by robot, then cell
};

// Balanced pieces, each robot going to its own by its quickest way.
std::vector<PieceWalk> directPieces(const CellGraph& graph, const std::vector<Waypoint>& tour,
                                    const TourSplitter& splitter, const std::vector<int>& positions,
                                    const std::vector<int>& robotStartCells, const RobotWays& ways) {
    std::vector<int> tourPointOfCell(graph.size(), -1);
    for (std::size_t i = 0; i < tour.size(); ++i)
        if (tourPointOfCell[static_cast<std::size_t>(tour[i].cell)] < 0)
            tourPointOfCell[static_cast<std::size_t>(tour[i].cell)] = static_cast<int>(i);
    const ApproachRoutes& routes = ways.routes;
    const std::vector<std::vector<float>>& secondsToCell = ways.secondsToCell;
    std::vector<int> cellOfPoint(tour.size());
    for (std::size_t i = 0; i < tour.size(); ++i)
        cellOfPoint[i] = tour[i].cell;
    const std::vector<TourSplitter::Share> shares =
        splitter.piecesReachedDirectly(positions, secondsToCell, cellOfPoint);
    std::vector<PieceWalk> walks(shares.size());
    parallelFor(shares.size(), [&](std::size_t k, int) {
        const TourSplitter::Share& share = shares[k];
        PieceWalk& piece = walks[k];
        if (share.approach == 0) {
            const Waypoint& entry = tour[static_cast<std::size_t>(share.order.front())];
            piece.walk = approachWaypoints(graph, tour, positions[k],
                                           routes.cellsBetween(robotStartCells[k], entry.cell), entry,
                                           tourPointOfCell);
        }
        piece.approach = share.approach == 0 ? piece.walk.size() : share.approach;
        for (const int index : share.order)
            piece.walk.push_back(tour[static_cast<std::size_t>(index)]);
    });
    return walks;
}

// The walks of the pieces of `tour`: balanced where the robots' ways are given, otherwise from each robot's
// start to the next robot's.
std::vector<PieceWalk> piecesOf(const CellGraph& graph, const std::vector<Waypoint>& tour,
                                const PartRobots& part, const RobotWays* ways) {
    std::vector<int> positions;
    for (std::size_t k = 0; k < part.robots.size(); ++k)
        positions.push_back(tourPosition(tour, part.startCells[k], part.starts[k]));
    const TourSplitter splitter(stepSeconds(tour, graph));
    if (ways != nullptr)
        return directPieces(graph, tour, splitter, positions, part.startCells, *ways);
    std::vector<PieceWalk> walks;
    for (const TourSplitter::Share& share : splitter.forwardPieces(positions)) {
        PieceWalk& piece = walks.emplace_back();
        for (const int index : share.order)
            piece.walk.push_back(tour[static_cast<std::size_t>(index)]);
    }
    return walks;
}

// The longest time of the paths the walks make, as the plan's metrics time them.
double longestPieceSeconds(const CellGraph& graph, const std::vector<PieceWalk>& walks,
                           const PartRobots& part) {
    double longest = 0.0;
    for (std::size_t k = 0; k < walks.size(); ++k) {
        CoveragePath path = pathFromWalk(part.robots[k], part.starts[k], walks[k].walk, false);
        timePath(path, graph);
        longest = std::max(longest, path.timeSeconds);
    }
    return longest;
}

constexpr const char* subtreeTurnsSlackKey = "subtree_turns_slack";

// Evening out subtree pieces scans the part at every move: 85 000 cells with 8 robots take 3.3 s.
constexpr std::size_t mostSubtreeCells = 100'000;

// Whether every start has a cell of its own, as a subtree piece needs (starts sharing one are refused
// before planning; a caller of the core may still pass them).
bool startsApart(std::vector<int> startCells) {
    std::sort(startCells.begin(), startCells.end());
    return std::adjacent_find(startCells.begin(), startCells.end()) == startCells.end();
}

struct SubtreeWalks {
    std::vector<PieceWalk> walks;
    double longestSeconds = 0.0; // as longestPieceSeconds would time them
};

// Balanced pieces as subtrees of the part's tree that turns least, one start in each (SubtreePieces). Each
// piece is walked round the subtree it was cut as, or round a tree built again over its cells where that
// walk is quicker, or as quick with fewer turns (isQuicker): the branches handed between pieces leave turns
// a tree of the piece's own can save (100 x 100 cells with 14 robots and turn_s 0, where the two take the
// same time: 78 turns).
// slack: how much longer than the pieces' mean a piece may grow to save turns, a fraction; tourSeconds: the
// longest of the tour's pieces, which the subtree pieces must beat to be kept.
SubtreeWalks subtreeWalks(const CellGraph& graph, const StartComponent& part, const PartRobots& robots,
                          int plateauRounds, double slack, double tourSeconds,
                          const ProgressReporter& progress) {
    std::vector<int> scratchIndex(graph.size(), -1);
    const SpanningTreeBuilder trees(graph, scratchIndex, plateauRounds, &progress);
    const SpanningTree tree = trees.candidate(0, part.cells, robots.startCells.front());
    SubtreePieces pieces(graph, tree, robots.startCells, robots.starts, progress);
    // Pieces may grow up to the tour's longest piece, never to it: the subtree division must end sooner
    // to be kept. Where its longest piece as cut is already longer, none grows.
    const double belowTour = std::nextafter(tourSeconds, 0.0);
    if (pieces.longestSeconds() < belowTour)
        pieces.saveTurns(std::min((1.0 + slack) * pieces.meanSeconds(), belowTour), progress);
    SubtreeWalks result;
    result.walks.resize(robots.robots.size());
    TreeCircumnavigation walker(graph);
    for (std::size_t k = 0; k < result.walks.size(); ++k) {
        const SpanningTree cut = pieces.pieceTree(k);
        const SpanningTree own = trees.candidate(0, cut.cells(), robots.startCells[k]);
        const PathShape cutShape = walker.walkShape(cut, robots.starts[k], false);
        const PathShape ownShape = walker.walkShape(own, robots.starts[k], false);
        const bool ownWalked = isQuicker(ownShape, cutShape);
        result.walks[k].walk = walker.walk(ownWalked ? own : cut, robots.starts[k], false);
        result.longestSeconds = std::max(result.longestSeconds, (ownWalked ? ownShape : cutShape).seconds());
    }
    return result;
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
        booleanParameter(
            "balanced", "Balanced pieces", false,
            "Cut the tour into pieces that take equal time with the way to them, each robot "
            "going to its own by the quickest way; otherwise each robot covers the tour from its "
            "start to the next robot's"),
        onlyWith(booleanParameter("subtree_pieces", "Pieces as subtrees", false,
                                  "Also cut the tour's tree into a subtree per robot around its start, "
                                  "evened out by handing branches to neighbouring pieces, so that no robot "
                                  "has a way to its piece; the plan whose last robot finishes sooner is "
                                  "kept. A few more turns where pieces meet; planning takes longer, and "
                                  "parts above 100 000 cells keep the tour's pieces"),
                 "balanced"),
        onlyWith(realParameter(subtreeTurnsSlackKey, "Piece growth for turns", 0.8, 0.0, 10.0,
                               "Where handing a few cells to a neighbouring piece saves turns, a subtree "
                               "piece may grow to this much above the pieces' mean time, or to the longest "
                               "piece's time as cut if that is more, but never to the longest of the "
                               "tour's pieces. More means fewer turns and a less even split (100 x 100 "
                               "cells with 14 robots: 72 fewer turns at 0.8 % than at 0, ratio 1.0077 "
                               "instead of 1.0019); 0 lets no piece grow past the longest",
                               "%"),
                 "subtree_pieces"),
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
            PartRobots robots{part.robots, {}, {}};
            for (const int robot : part.robots) {
                robots.startCells.push_back(startCells[static_cast<std::size_t>(robot)]);
                robots.starts.push_back(starts[static_cast<std::size_t>(robot)]);
            }
            std::vector<Waypoint> tour =
                partTour(plan.cells, part, startCells[first], starts[first], plateauRounds, run.progress());
            std::optional<RobotWays> ways;
            if (parameters.boolean("balanced"))
                ways.emplace(plan.cells, robots, run.progress());
            std::vector<PieceWalk> walks = piecesOf(plan.cells, tour, robots, ways ? &*ways : nullptr);
            // The tour walked the other way round is cut elsewhere about the starts: the robots' ways to
            // their pieces differ, and the quicker plan is kept (100 x 100 with 14 robots: ratio 1.0188 ->
            // 1.0163; no benchmark grid slower).
            double tourSeconds = 0.0; // the longest of the kept tour pieces, timed once
            if (ways && part.robots.size() > 1) {
                tourSeconds = longestPieceSeconds(plan.cells, walks, robots);
                std::reverse(tour.begin(), tour.end());
                std::vector<PieceWalk> reversed = piecesOf(plan.cells, tour, robots, &*ways);
                if (const double reversedSeconds = longestPieceSeconds(plan.cells, reversed, robots);
                    reversedSeconds < tourSeconds) {
                    walks = std::move(reversed);
                    tourSeconds = reversedSeconds;
                }
            }
            if (ways && part.robots.size() > 1 && parameters.boolean("subtree_pieces")) {
                if (part.cells.size() > mostSubtreeCells) {
                    run.addIssue(IssueSeverity::Warning, "subtree-pieces-skipped",
                                 "pieces as subtrees: a connected part of " +
                                     std::to_string(part.cells.size()) + " cells is above the " +
                                     std::to_string(mostSubtreeCells) +
                                     " they are tried on; its pieces are the tour's");
                } else if (!startsApart(robots.startCells)) {
                    run.addIssue(IssueSeverity::Warning, "subtree-pieces-skipped",
                                 "pieces as subtrees: two robots start in one cell, and a subtree holds one "
                                 "start; the pieces are the tour's");
                } else {
                    SubtreeWalks subtrees = subtreeWalks(plan.cells, part, robots, plateauRounds,
                                                         parameters.real(subtreeTurnsSlackKey) / 100.0,
                                                         tourSeconds, run.progress());
                    if (subtrees.longestSeconds < tourSeconds)
                        walks = std::move(subtrees.walks);
                }
            }
            for (std::size_t k = 0; k < part.robots.size(); ++k) {
                const int robot = part.robots[k];
                // A cell goes to the first robot whose piece passes it (two may share its sub-cells).
                for (std::size_t step = walks[k].approach; step < walks[k].walk.size(); ++step) {
                    int& owner = plan.regions.robotOfCell[static_cast<std::size_t>(walks[k].walk[step].cell)];
                    if (owner < 0)
                        owner = robot;
                }
                plan.paths[static_cast<std::size_t>(robot)] = pathFromWalk(
                    robot, starts[static_cast<std::size_t>(robot)], std::move(walks[k].walk), false);
            }
        }
        return 0;
    });
}

} // namespace mcpp
