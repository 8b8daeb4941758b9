#include "core/coverage/DetectionCoverage.hpp"

#include "core/coverage/DetectionAccumulator.hpp"
#include "core/coverage/DetectionSegmentSelection.hpp"
#include "core/coverage/SegmentTour.hpp"
#include "core/coverage/SubCellNodes.hpp"
#include "core/model/PlanningError.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <queue>

namespace mcpp {
namespace {

// Times passes are added for what the finished path still misses. A pass counted apart from the others
// may be one with them in flight (two passes of a line meeting end to end are flown as one), so the path
// can fall short of the plan where passes meet; each round of additions is smaller.
constexpr int maximumReplans = 8;

// The robot's sub-cells on the lattice: its window, which positions are its own and their nodes.
struct RegionLattice {
    LatticeWindow window;
    std::vector<char> own;   // by window index
    std::vector<int> nodeAt; // by window index: the node there, or SubCellNodes::none
};

RegionLattice regionLattice(const SubCellNodes& nodes, const DetectionLattice& lattice) {
    std::vector<LatticePosition> positions;
    int minColumn = std::numeric_limits<int>::max(), minRow = minColumn, maxColumn = -1, maxRow = -1;
    for (int node = 0; node < nodes.size(); ++node) {
        const std::optional<LatticePosition> centre =
            lattice.centreAt({nodes.waypoint(node).x, nodes.waypoint(node).y});
        if (!centre)
            throw PlanningError(PlanningError::Kind::InvalidGrid,
                                "a sub-cell centre lies off the detection lattice");
        const LatticePosition position = *centre;
        positions.push_back(position);
        minColumn = std::min(minColumn, position.column);
        minRow = std::min(minRow, position.row);
        maxColumn = std::max(maxColumn, position.column);
        maxRow = std::max(maxRow, position.row);
    }
    RegionLattice region;
    region.window = {minColumn, minRow, maxColumn - minColumn + 1, maxRow - minRow + 1};
    region.own.assign(region.window.size(), 0);
    region.nodeAt.assign(region.window.size(), SubCellNodes::none);
    for (int node = 0; node < nodes.size(); ++node) {
        const std::size_t index = region.window.index(positions[static_cast<std::size_t>(node)]);
        region.own[index] = 1;
        region.nodeAt[index] = node;
    }
    return region;
}

// Quickest ways between nodes of the region (A* on travel time), reusing its arrays between searches.
class NodeRoutes {
  public:
    explicit NodeRoutes(const SubCellNodes& nodes)
        : nodes_(nodes), seconds_(static_cast<std::size_t>(nodes.size()), infinity),
          cameFrom_(static_cast<std::size_t>(nodes.size()), SubCellNodes::none) {
        for (int node = 0; node < nodes.size(); ++node)
            fastest_ = std::max(fastest_, double{nodes.waypoint(node).speedMetresPerSecond});
    }

    // The nodes after `from` up to and including `to`.
    std::vector<int> route(int from, int to) {
        using Entry = std::pair<double, int>; // (estimate, node)
        std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
        touch(from, 0.0, SubCellNodes::none);
        open.emplace(estimate(from, to), from);
        while (!open.empty()) {
            const auto [guess, node] = open.top();
            open.pop();
            if (node == to)
                break;
            if (guess > seconds_[static_cast<std::size_t>(node)] + estimate(node, to) + 1e-12)
                continue;
            for (int direction = 0; direction < 4; ++direction) {
                const int next = nodes_.neighbour(node, direction);
                if (next == SubCellNodes::none)
                    continue;
                const double seconds =
                    seconds_[static_cast<std::size_t>(node)] + nodes_.stepSeconds(node, next);
                if (seconds < seconds_[static_cast<std::size_t>(next)]) {
                    touch(next, seconds, node);
                    open.emplace(seconds + estimate(next, to), next);
                }
            }
        }
        std::vector<int> way;
        for (int node = to; node != from && node != SubCellNodes::none;
             node = cameFrom_[static_cast<std::size_t>(node)])
            way.push_back(node);
        const bool found = cameFrom_[static_cast<std::size_t>(to)] != SubCellNodes::none || to == from;
        reset();
        if (!found)
            throw PlanningError(PlanningError::Kind::InvalidGrid, "a robot's region is not connected");
        std::reverse(way.begin(), way.end());
        return way;
    }

  private:
    static constexpr double infinity = std::numeric_limits<double>::infinity();

    [[nodiscard]] double estimate(int from, int to) const {
        const Waypoint& a = nodes_.waypoint(from);
        const Waypoint& b = nodes_.waypoint(to);
        return std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y)) / fastest_;
    }
    void touch(int node, double seconds, int cameFrom) {
        if (seconds_[static_cast<std::size_t>(node)] == infinity)
            touched_.push_back(node);
        seconds_[static_cast<std::size_t>(node)] = seconds;
        cameFrom_[static_cast<std::size_t>(node)] = cameFrom;
    }
    void reset() {
        for (const int node : touched_) {
            seconds_[static_cast<std::size_t>(node)] = infinity;
            cameFrom_[static_cast<std::size_t>(node)] = SubCellNodes::none;
        }
        touched_.clear();
    }

    const SubCellNodes& nodes_;
    std::vector<double> seconds_;
    std::vector<int> cameFrom_;
    std::vector<int> touched_;
    double fastest_ = 0.0;
};

// The nodes that fly the passes in tour order from the root, joined by quickest ways; the root first.
std::vector<int> flyPasses(const std::vector<DetectionSegment>& segments, const RegionLattice& region,
                           const DetectionLattice& lattice, const SubCellNodes& nodes, int root) {
    std::vector<SegmentTour::Pass> passes;
    for (const DetectionSegment& segment : segments)
        passes.push_back({lattice.centre(segment.from), lattice.centre(segment.to)});
    const Waypoint& rootPoint = nodes.waypoint(root);
    NodeRoutes routes(nodes);
    std::vector<int> flown{root};
    for (const SegmentTour::Visit& visit : SegmentTour::order(passes, {rootPoint.x, rootPoint.y})) {
        const DetectionSegment& segment = segments[static_cast<std::size_t>(visit.pass)];
        const LatticePosition entry = visit.reversed ? segment.to : segment.from;
        const LatticePosition exit = visit.reversed ? segment.from : segment.to;
        const std::vector<int> way = routes.route(flown.back(), region.nodeAt[region.window.index(entry)]);
        flown.insert(flown.end(), way.begin(), way.end());
        const int columnStep = exit.column > entry.column ? 1 : (exit.column < entry.column ? -1 : 0);
        const int rowStep = exit.row > entry.row ? 1 : (exit.row < entry.row ? -1 : 0);
        for (LatticePosition at = entry; at.column != exit.column || at.row != exit.row;) {
            at = {at.column + columnStep, at.row + rowStep};
            flown.push_back(region.nodeAt[region.window.index(at)]);
        }
    }
    return flown;
}

CoveragePath pathOf(int robot, const std::vector<int>& flown, const SubCellNodes& nodes,
                    const Cell& startCell, int startCellId, MapPoint start) {
    CoveragePath path;
    path.robot = robot;
    path.closed = false;
    path.waypoints.push_back({start.x, start.y, startCellId, startCell.speedMetresPerSecond});
    for (const int node : flown) {
        const Waypoint& waypoint = nodes.waypoint(node);
        const Waypoint& last = path.waypoints.back();
        if (waypoint.x != last.x || waypoint.y != last.y)
            path.waypoints.push_back(waypoint);
    }
    return path;
}

} // namespace

CoveragePath DetectionCoverage::cover(int robot, const std::vector<int>& cells, int startCell, MapPoint start,
                                      const ProgressReporter& progress) const {
    const SubCellNodes nodes(graph_, cells);
    const int root = nodes.startNode(robot, startCell, start);
    const RegionLattice region = regionLattice(nodes, lattice_);
    const DetectionSegmentSelection selection(model_, required_);
    DetectionAccumulator planned(lattice_, graph_, model_, region.window);
    std::vector<int> flown =
        flyPasses(selection.select(region.own, planned, progress), region, lattice_, nodes, root);
    for (int attempt = 0;; ++attempt) {
        CoveragePath path = pathOf(robot, flown, nodes, graph_.cell(startCell), startCell, start);
        DetectionAccumulator seen(lattice_, graph_, model_, region.window);
        seen.addPath(path);
        if (attempt == maximumReplans || selection.unmetTargets(region.own, seen) == 0)
            return path;
        // The passes for what is short are flown after the rest, so nothing already seen is lost.
        const std::vector<DetectionSegment> more = selection.select(region.own, seen, progress);
        if (more.empty())
            return path; // nothing gains any more; the plan's summary counts what stays short
        const std::vector<int> after = flyPasses(more, region, lattice_, nodes, flown.back());
        flown.insert(flown.end(), after.begin() + 1, after.end());
    }
}

} // namespace mcpp
