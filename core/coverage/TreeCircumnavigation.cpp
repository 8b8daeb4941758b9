#include "core/coverage/TreeCircumnavigation.hpp"

#include "core/coverage/PathMeasurement.hpp"
#include "core/coverage/PathMeasurer.hpp"
#include "core/coverage/RepeatedVisitCounter.hpp"
#include "core/coverage/RoundOrder.hpp"
#include "core/coverage/StraightRunMerger.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mcpp {
namespace {

// In a slot sequence, items >= 0 are tree neighbours and items < 0 sub-cells: -1 - SubCell.
MapPoint subCellCentre(const Cell& cell, int item) {
    return cell.subCellCentre(static_cast<SubCell>(-1 - item));
}

MapPoint nearestSubCell(const Cell& cell, MapPoint point) {
    MapPoint best{};
    double bestDistance = std::numeric_limits<double>::infinity();
    for (SubCell subCell : subCellsCounterClockwise) {
        const MapPoint centre = cell.subCellCentre(subCell);
        const double d = std::hypot(centre.x - point.x, centre.y - point.y);
        if (d < bestDistance) {
            bestDistance = d;
            best = centre;
        }
    }
    return best;
}

// Collects the walk's waypoints.
class WaypointSink {
  public:
    explicit WaypointSink(std::vector<Waypoint>& path) : path_(path) {}
    void push(const Waypoint& waypoint) { path_.push_back(waypoint); }
    [[nodiscard]] const Waypoint& back() const { return path_.back(); }
    [[nodiscard]] const Waypoint& front() const { return path_.front(); }

  private:
    std::vector<Waypoint>& path_;
};

// Collects the path pathFromWalk would make of the walk: the start point first when the walk does not
// begin there (in the first point's cell), and back to it at the end of a closed tour.
class StartedWaypointSink {
  public:
    StartedWaypointSink(std::vector<Waypoint>& path, MapPoint start, bool closed)
        : path_(path), start_(start), closed_(closed) {}
    void push(const Waypoint& waypoint) {
        if (path_.empty() && !startIsOnWalk(waypoint, start_)) {
            Waypoint origin = waypoint;
            origin.x = start_.x;
            origin.y = start_.y;
            path_.push_back(origin);
            firstOfWalk_ = 1;
        }
        path_.push_back(waypoint);
    }
    [[nodiscard]] const Waypoint& back() const { return path_.back(); }
    // The walk's first waypoint, as traverse wants, not the start point before it.
    [[nodiscard]] const Waypoint& front() const { return path_[firstOfWalk_]; }
    void finish() {
        if (closed_ && firstOfWalk_ == 1)
            path_.push_back(path_.front());
    }

  private:
    std::vector<Waypoint>& path_;
    MapPoint start_;
    bool closed_;
    std::size_t firstOfWalk_ = 0;
};

// Measures the path pathFromWalk would make of the walk: the start point first when the walk does not
// begin there (in the first point's cell), and back to it at the end of a closed tour.
class ShapeSink {
  public:
    ShapeSink(const CellGraph& graph, MapPoint start, bool closed, bool timed)
        : graph_(graph), start_(start), closed_(closed), timed_(timed) {}
    void push(const Waypoint& waypoint) {
        if (!haveFirst_) {
            haveFirst_ = true;
            first_ = waypoint;
            startIsOnWalk_ = startIsOnWalk(waypoint, start_);
            if (!startIsOnWalk_)
                add(start_, waypoint);
        }
        last_ = waypoint;
        add({waypoint.x, waypoint.y}, waypoint);
    }
    [[nodiscard]] const Waypoint& back() const { return last_; }
    [[nodiscard]] const Waypoint& front() const { return first_; }
    [[nodiscard]] PathShape finish() {
        if (haveFirst_ && closed_ && !startIsOnWalk_)
            add(start_, first_);
        return shape_;
    }
    // The shape so far (all of it once finished).
    [[nodiscard]] const PathShape& shape() const { return shape_; }

  private:
    // A point, with the speed and turn price of the waypoint whose cell it lies in.
    void add(MapPoint point, const Waypoint& inCell) {
        if (timed_)
            shape_.add(point.x, point.y, inCell.speedMetresPerSecond, graph_.turnSeconds(inCell.cell));
        else
            shape_.add(point.x, point.y);
    }

    const CellGraph& graph_;
    MapPoint start_;
    bool closed_;
    bool timed_;
    bool haveFirst_ = false;
    bool startIsOnWalk_ = true;
    Waypoint first_;
    Waypoint last_;
    PathShape shape_;
};

// Makes the path StartedWaypointSink collects, measured and with its straight runs merged as it goes:
// the whole walk, four waypoints a cell, is never held.
class MeasuringSink {
  public:
    // sharedShape: a shape fed the same points, for the length and turns (PathMeasurer).
    MeasuringSink(const CellGraph& graph, MapPoint start, bool closed, const PathShape* sharedShape = nullptr)
        : measurer_(graph, sharedShape), merger_(graph), visits_(graph), start_(start), closed_(closed) {}
    void push(const Waypoint& waypoint) {
        if (!haveFirst_) {
            haveFirst_ = true;
            first_ = waypoint;
            if (!startIsOnWalk(waypoint, start_)) {
                origin_ = waypoint;
                origin_.x = start_.x;
                origin_.y = start_.y;
                haveOrigin_ = true;
                feed(origin_);
            }
        }
        last_ = waypoint;
        feed(waypoint);
    }
    [[nodiscard]] const Waypoint& back() const { return last_; }
    // The walk's first waypoint, as traverse wants, not the start point before it.
    [[nodiscard]] const Waypoint& front() const { return first_; }
    [[nodiscard]] std::size_t keptWaypoints() const { return merger_.keptCount(); }
    [[nodiscard]] CoveragePath finish(int robot) {
        if (closed_ && haveOrigin_)
            feed(origin_);
        CoveragePath path;
        path.robot = robot;
        path.closed = closed_;
        measurer_.fill(path);
        path.repeatedSubCellVisits = visits_.repeats(closed_);
        merger_.finishInto(path);
        return path;
    }

  private:
    void feed(const Waypoint& waypoint) {
        measurer_.add(waypoint);
        merger_.add(waypoint);
        visits_.add(waypoint);
    }

    PathMeasurer measurer_;
    StraightRunMerger merger_;
    RepeatedVisitCounter visits_;
    MapPoint start_;
    bool closed_;
    bool haveFirst_ = false;
    bool haveOrigin_ = false;
    Waypoint first_;
    Waypoint last_;
    Waypoint origin_;
};

// ShapeSink and MeasuringSink fed the same walk; the measuring is given up (and its memory handed back)
// once the path keeps more waypoints than the limit. Both add the same points (the start point before and
// after the walk alike), so the path's length and turns are read from the shape's. Neither moved nor copied:
// the measuring reads the shape where it is.
class ShapeAndMeasuringSink {
  public:
    ShapeAndMeasuringSink(const CellGraph& graph, MapPoint start, bool closed, bool timed,
                          std::size_t waypointLimit)
        : shape_(graph, start, closed, timed),
          measuring_(std::in_place, graph, start, closed, &shape_.shape()), waypointLimit_(waypointLimit) {}
    ShapeAndMeasuringSink(const ShapeAndMeasuringSink&) = delete;
    ShapeAndMeasuringSink& operator=(const ShapeAndMeasuringSink&) = delete;
    void push(const Waypoint& waypoint) {
        shape_.push(waypoint);
        if (!measuring_)
            return;
        measuring_->push(waypoint);
        if (measuring_->keptWaypoints() > waypointLimit_)
            measuring_.reset();
    }
    [[nodiscard]] const Waypoint& back() const { return shape_.back(); }
    [[nodiscard]] const Waypoint& front() const { return shape_.front(); }
    [[nodiscard]] TreeCircumnavigation::ShapeAndPath finish(int robot) {
        TreeCircumnavigation::ShapeAndPath result{shape_.finish(), std::nullopt};
        if (measuring_) {
            result.path = measuring_->finish(robot); // after the shape's finish: its closing point too
            if (result.path->waypoints.size() > waypointLimit_)
                result.path.reset();
        }
        return result;
    }

  private:
    ShapeSink shape_;
    std::optional<MeasuringSink> measuring_;
    std::size_t waypointLimit_;
};

} // namespace

// Appends the cell's sub-cells and tree neighbours, counter-clockwise round it from the north-west.
void TreeCircumnavigation::appendSlots(const SpanningTree& tree, int node, std::vector<int>& out) {
    const Cell& self = graph_.cell(tree.cellOf(node));
    for (auto& side : sides_)
        side.clear(); // west, south, east, north: (position along the walk, neighbour)
    for (int neighbour : tree.neighbours(node)) {
        const RoundPlace place = roundPlaceOf(self, graph_.cell(tree.cellOf(neighbour)));
        sides_[static_cast<std::size_t>(place.side)].emplace_back(place.position, neighbour);
    }
    for (int side = 0; side < 4; ++side) {
        out.push_back(-1 - side); // the corner sub-cell before this side: NW, SW, SE, NE
        auto& list = sides_[static_cast<std::size_t>(side)];
        if (list.size() > 1)
            std::sort(list.begin(), list.end());
        for (const auto& entry : list)
            out.push_back(entry.second);
    }
}

bool TreeCircumnavigation::adjacent(const SpanningTree& tree, int a, int b) const {
    return a == b || graph_.areNeighbours(tree.cellOf(a), tree.cellOf(b));
}

Waypoint TreeCircumnavigation::waypointAt(const SpanningTree& tree, int node, MapPoint point) const {
    const int id = tree.cellOf(node);
    return {point.x, point.y, id, graph_.record(id).speedMetresPerSecond}; // no whole cell: once a waypoint
}

template <typename Sink>
void TreeCircumnavigation::emit(const SpanningTree& tree, Sink& path, int& previousNode, int node,
                                MapPoint point) {
    if (previousNode >= 0 && !adjacent(tree, previousNode, node)) {
        // The tree path between the two cells, without its ends.
        std::vector<int> up;
        std::vector<int> down;
        int a = previousNode;
        int b = node;
        while (tree.depth(a) > tree.depth(b))
            up.push_back(a = tree.parent(a));
        while (tree.depth(b) > tree.depth(a))
            down.push_back(b = tree.parent(b));
        while (a != b) {
            up.push_back(a = tree.parent(a));
            down.push_back(b = tree.parent(b));
        }
        if (!up.empty() && !down.empty() && up.back() == down.back())
            down.pop_back();
        std::vector<int> between(up.begin(), up.end());
        between.insert(between.end(), down.rbegin(), down.rend());
        std::erase(between, node);
        std::erase(between, previousNode);
        int last = previousNode;
        for (std::size_t i = 0; i < between.size(); ++i) {
            const int next = i + 1 < between.size() ? between[i + 1] : node;
            if (adjacent(tree, last, next))
                continue; // a bridge the walk does not need
            const Waypoint& from = path.back();
            path.push(waypointAt(tree, between[i],
                                 nearestSubCell(graph_.cell(tree.cellOf(between[i])), {from.x, from.y})));
            ++bridgeVisits_;
            last = between[i];
        }
    }
    path.push(waypointAt(tree, node, point));
    previousNode = node;
}

std::vector<Waypoint> TreeCircumnavigation::walk(const SpanningTree& tree, MapPoint start, bool closed,
                                                 std::size_t capacity) {
    std::vector<Waypoint> path;
    path.reserve(std::max(capacity, tree.size() * 4 + 2));
    WaypointSink sink(path);
    traverse(tree, start, closed, sink);
    return path;
}

std::vector<Waypoint> TreeCircumnavigation::walkFromStart(const SpanningTree& tree, MapPoint start,
                                                          bool closed, std::size_t capacity) {
    std::vector<Waypoint> path;
    path.reserve(std::max(capacity, tree.size() * 4 + 2));
    StartedWaypointSink sink(path, start, closed);
    traverse(tree, start, closed, sink);
    sink.finish();
    return path;
}

CoveragePath TreeCircumnavigation::measuredWalk(const SpanningTree& tree, int robot, MapPoint start,
                                                bool closed) {
    MeasuringSink sink(graph_, start, closed);
    traverse(tree, start, closed, sink);
    return sink.finish(robot);
}

TreeCircumnavigation::ShapeAndPath TreeCircumnavigation::walkShapeAndPath(const SpanningTree& tree, int robot,
                                                                          MapPoint start, bool closed,
                                                                          bool timed,
                                                                          std::size_t waypointLimit) {
    ShapeAndMeasuringSink sink(graph_, start, closed, timed, waypointLimit);
    traverse(tree, start, closed, sink);
    return sink.finish(robot);
}

PathShape TreeCircumnavigation::walkShape(const SpanningTree& tree, MapPoint start, bool closed, bool timed) {
    ShapeSink sink(graph_, start, closed, timed);
    traverse(tree, start, closed, sink);
    return sink.finish();
}

template <typename Sink>
void TreeCircumnavigation::traverse(const SpanningTree& tree, MapPoint start, bool closed, Sink& path) {
    // Frames keep their items in one arena, used as a stack: no allocation per cell.
    struct Frame {
        int node;
        std::size_t begin; // first item in the arena
        std::size_t end;
        std::size_t next;
    };
    bridgeVisits_ = 0;
    if (tree.size() == 0)
        return;
    int previousNode = -1;
    std::vector<int>& arena = arena_;
    arena.clear();
    const int root = tree.root();
    const Cell& rootCell = graph_.cell(tree.cellOf(root));
    appendSlots(tree, root, arena);
    std::size_t firstItem = 0;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < arena.size(); ++i) {
        if (arena[i] >= 0)
            continue;
        const MapPoint centre = subCellCentre(rootCell, arena[i]);
        const double d = std::hypot(centre.x - start.x, centre.y - start.y);
        if (d < bestDistance - 1e-12) {
            bestDistance = d;
            firstItem = i;
        }
    }
    std::rotate(arena.begin(), arena.begin() + static_cast<std::ptrdiff_t>(firstItem), arena.end());
    std::vector<Frame> stack;
    stack.push_back({root, 0, arena.size(), 0});
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
            emit(tree, path, previousNode, node, subCellCentre(graph_.cell(tree.cellOf(node)), item));
            continue;
        }
        // Enter the child just after this cell's place in its sequence and go round it.
        const std::size_t begin = arena.size();
        appendSlots(tree, item, arena);
        const auto self = std::find(arena.begin() + static_cast<std::ptrdiff_t>(begin), arena.end(), node);
        std::rotate(arena.begin() + static_cast<std::ptrdiff_t>(begin), self, arena.end());
        stack.push_back({item, begin + 1, arena.size(), 0}); // skip the parent's own slot
    }
    // The walk may end deep in a subtree; returning goes through emit so it is bridged like any step.
    if (closed)
        emit(tree, path, previousNode, root, {path.front().x, path.front().y});
}

} // namespace mcpp
