#pragma once

#include "core/coverage/PathShape.hpp"
#include "core/coverage/SpanningTree.hpp"
#include "core/model/CellGraph.hpp"
#include "core/model/CoveragePath.hpp"

#include <array>
#include <optional>
#include <utility>
#include <vector>

namespace mcpp {

// The walk round a spanning tree through the centres of every cell's four sub-cells, keeping the tree on
// the left (counter-clockwise), as in STC (spec 5). Between cells of different sizes the walk joins the
// nearest sub-cell centres across their shared border; where two consecutive sub-cells lie in cells that
// do not touch (two excursions on one side of a large cell), it goes back through the cells between them.
class TreeCircumnavigation {
  public:
    explicit TreeCircumnavigation(const CellGraph& graph) : graph_(graph) {}

    // Starts at the root cell's sub-cell nearest `start`; a closed walk ends back at that sub-cell.
    // `capacity`: room to reserve, when the caller knows the length (walkShape's points): a walk of millions
    // of waypoints that outgrows its vector costs a copy and twice the memory.
    [[nodiscard]] std::vector<Waypoint> walk(const SpanningTree& tree, MapPoint start, bool closed,
                                             std::size_t capacity = 0);
    // The waypoints pathFromWalk makes of walk(tree, start, closed), written in place: on a region of
    // millions of cells, putting the start point before the walk afterwards moves every waypoint.
    [[nodiscard]] std::vector<Waypoint> walkFromStart(const SpanningTree& tree, MapPoint start, bool closed,
                                                      std::size_t capacity = 0);
    // The path pathFromWalk makes of walk(tree, start, closed), measured as measurePath measures it and with
    // its straight runs merged as mergeStraightRuns merges them, both done as it is walked: on a region of
    // millions of cells only the waypoints kept are ever held.
    [[nodiscard]] CoveragePath measuredWalk(const SpanningTree& tree, int robot, MapPoint start, bool closed);
    // The length and turns of the path pathFromWalk would make of walk(tree, start, closed), and with
    // `timed` its time, without storing it: choosing between trees this way keeps one path in memory
    // instead of two.
    [[nodiscard]] PathShape walkShape(const SpanningTree& tree, MapPoint start, bool closed,
                                      bool timed = true);
    struct ShapeAndPath {
        PathShape shape;
        std::optional<CoveragePath> path; // none when it kept more waypoints than the limit
    };
    // walkShape and, in the same walk, measuredWalk's path while that keeps at most `waypointLimit`
    // waypoints: a large region whose path turns little is walked once instead of twice.
    [[nodiscard]] ShapeAndPath walkShapeAndPath(const SpanningTree& tree, int robot, MapPoint start,
                                                bool closed, bool timed, std::size_t waypointLimit);
    // Waypoints of the last walk that pass a cell again to bridge cells that do not touch.
    [[nodiscard]] int bridgeVisits() const { return bridgeVisits_; }

  private:
    void appendSlots(const SpanningTree& tree, int node, std::vector<int>& out);
    [[nodiscard]] bool adjacent(const SpanningTree& tree, int a, int b) const;
    [[nodiscard]] Waypoint waypointAt(const SpanningTree& tree, int node, MapPoint point) const;
    template <typename Sink> void traverse(const SpanningTree& tree, MapPoint start, bool closed, Sink& sink);
    template <typename Sink>
    void emit(const SpanningTree& tree, Sink& sink, int& previousNode, int node, MapPoint point);

    const CellGraph& graph_;
    std::array<std::vector<std::pair<double, int>>, 4> sides_;
    std::vector<int> arena_;
    int bridgeVisits_ = 0;
};

} // namespace mcpp
