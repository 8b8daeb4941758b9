#include "core/coverage/SpanningTreeCoverage.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <span>

namespace mcpp {
namespace {

enum class EdgePreference { EastWest, NorthSouth };

// Sub-cells in counter-clockwise order starting north-west; items >= 0 in a slot sequence are tree
// neighbours, items < 0 are sub-cells: -1 north-west, -2 south-west, -3 south-east, -4 north-east.
MapPoint subCellCentre(const QuadCell& cell, int item) {
    const double quarter = cell.size / 4.0;
    switch (item) {
    case -1: return {cell.minX + quarter, cell.maxY() - quarter};
    case -2: return {cell.minX + quarter, cell.minY + quarter};
    case -3: return {cell.maxX() - quarter, cell.minY + quarter};
    default: return {cell.maxX() - quarter, cell.maxY() - quarter};
    }
}

class RegionTour {
public:
    RegionTour(const QuadTree& tree, const NeighbourTopology& topology, std::vector<int> cells, int startCell,
               std::vector<int>& localIndex)
        : tree_(tree), topology_(topology), cells_(std::move(cells)), localIndex_(localIndex) {
        for (std::size_t local = 0; local < cells_.size(); ++local) localIndex_[static_cast<std::size_t>(cells_[local])] = static_cast<int>(local);
        root_ = localIndex_[static_cast<std::size_t>(startCell)];
    }
    ~RegionTour() {
        for (int cell : cells_) localIndex_[static_cast<std::size_t>(cell)] = -1;
    }
    RegionTour(const RegionTour&) = delete;
    RegionTour& operator=(const RegionTour&) = delete;

    // The tour through every sub-cell; a closed one ends back at its first sub-cell.
    std::vector<Waypoint> walk(EdgePreference preference, MapPoint start, bool closed) {
        buildTree(preference);
        return circumnavigate(start, closed);
    }

    // Waypoints of the last walk that bridge cells that do not touch: visits of a sub-cell already seen.
    [[nodiscard]] int repeatedVisits() const { return repeatedVisits_; }

private:
    const QuadCell& cell(int local) const { return tree_.active(cells_[static_cast<std::size_t>(local)]); }

    std::span<const int> treeNeighbours(int node) const {
        const auto begin = static_cast<std::size_t>(treeOffsets_[static_cast<std::size_t>(node)]);
        const auto end = static_cast<std::size_t>(treeOffsets_[static_cast<std::size_t>(node) + 1]);
        return {treeTargets_.data() + begin, end - begin};
    }

    // Kruskal over the region's adjacencies, the preferred direction's edges first: long straight spines
    // give boustrophedon-like paths with few turns.
    void buildTree(EdgePreference preference) {
        const auto count = cells_.size();
        // Preferred-direction edges first, the rest after; within each, a fixed order.
        std::array<std::vector<std::pair<int, int>>, 2>& edges = edgeBuckets_;
        edges[0].clear();
        edges[1].clear();
        for (std::size_t a = 0; a < count; ++a) {
            const QuadCell& from = cell(static_cast<int>(a));
            for (int neighbour : topology_.of(cells_[a])) {
                const int b = localIndex_[static_cast<std::size_t>(neighbour)];
                if (b <= static_cast<int>(a)) continue;
                const QuadCell& to = cell(b);
                const bool eastWest = to.minX >= from.maxX() - 1e-9 * from.size || to.maxX() <= from.minX + 1e-9 * from.size;
                const std::size_t rank = (eastWest == (preference == EdgePreference::EastWest)) ? 0 : 1;
                edges[rank].emplace_back(static_cast<int>(a), b);
            }
        }
        std::vector<int> root(count);
        std::iota(root.begin(), root.end(), 0);
        auto find = [&](int x) {
            while (root[static_cast<std::size_t>(x)] != x) {
                root[static_cast<std::size_t>(x)] = root[static_cast<std::size_t>(root[static_cast<std::size_t>(x)])];
                x = root[static_cast<std::size_t>(x)];
            }
            return x;
        };
        // Tree edges, then compressed adjacency lists: one allocation for the whole tree.
        std::vector<std::pair<int, int>>& treeEdges = treeEdges_;
        treeEdges.clear();
        for (const auto& bucket : edges) {
            for (const auto& [first, second] : bucket) {
                const int a = find(first);
                const int b = find(second);
                if (a == b) continue;
                root[static_cast<std::size_t>(a)] = b;
                treeEdges.emplace_back(first, second);
            }
        }
        treeOffsets_.assign(count + 1, 0);
        for (const auto& [a, b] : treeEdges) {
            ++treeOffsets_[static_cast<std::size_t>(a) + 1];
            ++treeOffsets_[static_cast<std::size_t>(b) + 1];
        }
        for (std::size_t i = 0; i < count; ++i) treeOffsets_[i + 1] += treeOffsets_[i];
        treeTargets_.resize(2 * treeEdges.size());
        std::vector<int>& fill = scratchFill_;
        fill.assign(treeOffsets_.begin(), treeOffsets_.end() - 1);
        for (const auto& [a, b] : treeEdges) {
            treeTargets_[static_cast<std::size_t>(fill[static_cast<std::size_t>(a)]++)] = b;
            treeTargets_[static_cast<std::size_t>(fill[static_cast<std::size_t>(b)]++)] = a;
        }
        // Parents and depths from the start cell, for bridging between non-adjacent cells.
        parent_.assign(count, -1);
        depth_.assign(count, 0);
        std::vector<int> queue{root_};
        std::vector<char> seen(count, 0);
        seen[static_cast<std::size_t>(root_)] = 1;
        for (std::size_t head = 0; head < queue.size(); ++head) {
            const int node = queue[head];
            for (int next : treeNeighbours(node)) {
                if (seen[static_cast<std::size_t>(next)] != 0) continue;
                seen[static_cast<std::size_t>(next)] = 1;
                parent_[static_cast<std::size_t>(next)] = node;
                depth_[static_cast<std::size_t>(next)] = depth_[static_cast<std::size_t>(node)] + 1;
                queue.push_back(next);
            }
        }
    }

    // Appends the cell's sub-cells and tree neighbours, in counter-clockwise order around it from
    // north-west, to `out`.
    void appendSlots(int node, std::vector<int>& out) {
        const QuadCell& self = cell(node);
        const double tolerance = 1e-9 * self.size;
        auto& sides = sideScratch_; // west, south, east, north: (position along the walk, neighbour)
        for (auto& side : sides) side.clear();
        for (int neighbour : treeNeighbours(node)) {
            const QuadCell& other = cell(neighbour);
            if (other.maxX() <= self.minX + tolerance) sides[0].emplace_back(-other.centreY(), neighbour);
            else if (other.maxY() <= self.minY + tolerance) sides[1].emplace_back(other.centreX(), neighbour);
            else if (other.minX >= self.maxX() - tolerance) sides[2].emplace_back(other.centreY(), neighbour);
            else sides[3].emplace_back(-other.centreX(), neighbour);
        }
        for (int side = 0; side < 4; ++side) {
            out.push_back(-1 - side); // the corner sub-cell before this side
            auto& list = sides[static_cast<std::size_t>(side)];
            if (list.size() > 1) std::sort(list.begin(), list.end());
            for (const auto& entry : list) out.push_back(entry.second);
        }
    }

    bool adjacent(int a, int b) const {
        return a == b || topology_.areNeighbours(cells_[static_cast<std::size_t>(a)], cells_[static_cast<std::size_t>(b)]);
    }

    Waypoint waypointAt(int node, MapPoint point) const {
        const QuadCell& quadCell = cell(node);
        return {point.x, point.y, cells_[static_cast<std::size_t>(node)], quadCell.classValue, quadCell.speedMetresPerSecond,
                quadCell.fieldOfView(), 0.0};
    }

    // Nearest sub-cell centre of `node` to a point.
    MapPoint nearestSubCell(int node, MapPoint point) const {
        MapPoint best{};
        double bestDistance = std::numeric_limits<double>::infinity();
        for (int item = -1; item >= -4; --item) {
            const MapPoint centre = subCellCentre(cell(node), item);
            const double d = std::hypot(centre.x - point.x, centre.y - point.y);
            if (d < bestDistance) {
                bestDistance = d;
                best = centre;
            }
        }
        return best;
    }

    // When consecutive sub-cells lie in cells that do not touch (two excursions on one side of a large
    // cell with a gap between them), the path goes back through the cells on the tree path between them.
    void emit(std::vector<Waypoint>& path, int& previousNode, int node, MapPoint point) {
        if (previousNode >= 0 && !adjacent(previousNode, node)) {
            std::vector<int> up;
            std::vector<int> down;
            int a = previousNode;
            int b = node;
            while (depth_[static_cast<std::size_t>(a)] > depth_[static_cast<std::size_t>(b)]) up.push_back(a = parent_[static_cast<std::size_t>(a)]);
            while (depth_[static_cast<std::size_t>(b)] > depth_[static_cast<std::size_t>(a)]) down.push_back(b = parent_[static_cast<std::size_t>(b)]);
            while (a != b) {
                up.push_back(a = parent_[static_cast<std::size_t>(a)]);
                down.push_back(b = parent_[static_cast<std::size_t>(b)]);
            }
            if (!up.empty() && !down.empty() && up.back() == down.back()) down.pop_back();
            std::vector<int> between(up.begin(), up.end());
            between.insert(between.end(), down.rbegin(), down.rend());
            std::erase(between, node);
            std::erase(between, previousNode);
            int last = previousNode;
            for (std::size_t i = 0; i < between.size(); ++i) {
                const int next = i + 1 < between.size() ? between[i + 1] : node;
                if (adjacent(last, next)) continue; // skip a bridge the path does not need
                const Waypoint& from = path.back();
                path.push_back(waypointAt(between[i], nearestSubCell(between[i], {from.x, from.y})));
                ++repeatedVisits_;
                last = between[i];
            }
        }
        path.push_back(waypointAt(node, point));
        previousNode = node;
    }

    std::vector<Waypoint> circumnavigate(MapPoint start, bool closed) {
        // Frames keep their items in one arena, used as a stack: no allocation per cell.
        struct Frame {
            int node;
            std::size_t begin; // first item in the arena
            std::size_t end;
            std::size_t next;
        };
        std::vector<Waypoint> path;
        path.reserve(cells_.size() * 4 + 2);
        repeatedVisits_ = 0;
        int previousNode = -1;
        std::vector<int>& arena = arena_;
        arena.clear();
        // The tour starts at the start cell's sub-cell nearest the start point.
        appendSlots(root_, arena);
        std::size_t firstItem = 0;
        double bestDistance = std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < arena.size(); ++i) {
            if (arena[i] >= 0) continue;
            const MapPoint centre = subCellCentre(cell(root_), arena[i]);
            const double d = std::hypot(centre.x - start.x, centre.y - start.y);
            if (d < bestDistance - 1e-12) {
                bestDistance = d;
                firstItem = i;
            }
        }
        std::rotate(arena.begin(), arena.begin() + static_cast<std::ptrdiff_t>(firstItem), arena.end());
        std::vector<Frame> stack;
        stack.push_back({root_, 0, arena.size(), 0});
        while (!stack.empty()) {
            Frame& frame = stack.back();
            if (frame.next == frame.end - frame.begin) {
                arena.resize(frame.begin);
                stack.pop_back();
                continue;
            }
            const int item = arena[frame.begin + frame.next++];
            const int node = frame.node;
            if (item < 0) {
                emit(path, previousNode, node, subCellCentre(cell(node), item));
                continue;
            }
            // Enter the child just after this cell's place in its sequence and go round it.
            const std::size_t begin = arena.size();
            appendSlots(item, arena);
            const auto self = std::find(arena.begin() + static_cast<std::ptrdiff_t>(begin), arena.end(), node);
            std::rotate(arena.begin() + static_cast<std::ptrdiff_t>(begin), self, arena.end());
            stack.push_back({item, begin + 1, arena.size(), 0}); // skip the parent's own slot
        }
        // The walk may end deep in a subtree; returning goes through emit so it is bridged like any step.
        if (closed) emit(path, previousNode, root_, {path.front().x, path.front().y});
        return path;
    }

    const QuadTree& tree_;
    const NeighbourTopology& topology_;
    std::vector<int> cells_;
    std::vector<int>& localIndex_;
    int root_ = 0;
    std::vector<std::pair<int, int>> treeEdges_;
    std::vector<int> treeOffsets_;
    std::vector<int> treeTargets_;
    std::vector<int> scratchFill_;
    std::array<std::vector<std::pair<double, int>>, 4> sideScratch_;
    std::array<std::vector<std::pair<int, int>>, 2> edgeBuckets_;
    std::vector<int> arena_;
    int repeatedVisits_ = 0;
    std::vector<int> parent_;
    std::vector<int> depth_;
};

} // namespace

int countTurns(const std::vector<Waypoint>& waypoints) {
    int turns = 0;
    double previousX = 0.0;
    double previousY = 0.0;
    bool havePrevious = false;
    for (std::size_t i = 1; i < waypoints.size(); ++i) {
        const double dx = waypoints[i].x - waypoints[i - 1].x;
        const double dy = waypoints[i].y - waypoints[i - 1].y;
        const double length = std::sqrt(dx * dx + dy * dy);
        if (length < 1e-9) continue;
        const double ux = dx / length;
        const double uy = dy / length;
        if (havePrevious && std::abs(ux * previousY - uy * previousX) + std::max(0.0, -(ux * previousX + uy * previousY)) > 1e-6)
            ++turns;
        previousX = ux;
        previousY = uy;
        havePrevious = true;
    }
    return turns;
}

void measurePath(CoveragePath& path) {
    double length = 0.0;
    double time = 0.0;
    if (!path.waypoints.empty()) path.waypoints.front().cumulativeSeconds = 0.0;
    for (std::size_t i = 1; i < path.waypoints.size(); ++i) {
        const Waypoint& from = path.waypoints[i - 1];
        Waypoint& to = path.waypoints[i];
        const double dx = to.x - from.x;
        const double dy = to.y - from.y;
        const double segment = std::sqrt(dx * dx + dy * dy);
        length += segment;
        time += segment / 2.0 / from.speedMetresPerSecond + segment / 2.0 / to.speedMetresPerSecond;
        to.cumulativeSeconds = time;
    }
    path.lengthMetres = length;
    path.timeSeconds = time;
    path.turns = countTurns(path.waypoints);
}

std::vector<CoveragePath> SpanningTreeCoverage::plan(const QuadTree& tree, const NeighbourTopology& topology,
                                                     const RegionAllocation& allocation, const std::vector<MapPoint>& starts,
                                                     const PlannerSettings& settings, const ProgressReporter& progress) const {
    const std::size_t robots = allocation.startCell.size();
    std::vector<std::vector<int>> cellsOf(robots);
    for (std::size_t cell = 0; cell < allocation.robotOfCell.size(); ++cell) {
        const int robot = allocation.robotOfCell[cell];
        if (robot >= 0) cellsOf[static_cast<std::size_t>(robot)].push_back(static_cast<int>(cell));
    }
    std::vector<int> localIndex(tree.activeCount(), -1);
    std::vector<CoveragePath> paths;
    for (std::size_t robot = 0; robot < robots; ++robot) {
        progress.throwIfCancelled();
        progress.report("paths", static_cast<double>(robot) / static_cast<double>(robots));
        const MapPoint start = starts[robot];
        RegionTour tour(tree, topology, std::move(cellsOf[robot]), allocation.startCell[robot], localIndex);
        CoveragePath best;
        for (auto preference : {EdgePreference::EastWest, EdgePreference::NorthSouth}) {
            CoveragePath candidate;
            candidate.robot = static_cast<int>(robot);
            candidate.closed = settings.closedTour;
            std::vector<Waypoint> walked = tour.walk(preference, start, settings.closedTour);
            candidate.repeatedSubCellVisits = tour.repeatedVisits();
            const Waypoint first = walked.front();
            const bool startIsOnPath = std::hypot(first.x - start.x, first.y - start.y) < 1e-9;
            if (!startIsOnPath) {
                Waypoint origin = first;
                origin.x = start.x;
                origin.y = start.y;
                candidate.waypoints.push_back(origin);
            }
            candidate.waypoints.insert(candidate.waypoints.end(), walked.begin(), walked.end());
            if (settings.closedTour && !startIsOnPath) candidate.waypoints.push_back(candidate.waypoints.front());
            measurePath(candidate);
            if (best.waypoints.empty() || candidate.turns < best.turns ||
                (candidate.turns == best.turns && candidate.lengthMetres < best.lengthMetres - 1e-9))
                best = std::move(candidate);
        }
        paths.push_back(std::move(best));
    }
    progress.report("paths", 1.0);
    return paths;
}

} // namespace mcpp
