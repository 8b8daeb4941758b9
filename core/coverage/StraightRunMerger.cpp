#include "core/coverage/StraightRunMerger.hpp"

#include "core/coverage/PathMeasurement.hpp"
#include "core/model/CellRecord.hpp"

#include <cmath>

namespace mcpp {
namespace {

// Whether a step from `from` to `to` is one sub-cell of `to`'s cell long (a robot's step between
// neighbouring sub-cell centres of cells of one size).
bool isSubCellStep(const Waypoint& from, const Waypoint& to, double cellSize) {
    const double length = stepOf(to.x - from.x, to.y - from.y).length; // no square root along an axis
    return std::abs(length - cellSize / 2.0) <= 1e-9 * cellSize;
}

// Whether the walk goes straight on through waypoint b, in steps of one sub-cell, with one speed, one
// cell size and one land cover from a through b to c: b can be left out and put back from a and c.
bool insideStraightRun(const Waypoint& a, const Waypoint& b, const Waypoint& c, const CellGraph& graph) {
    // Straight on first: a turn, the one test most waypoints that are kept fail, needs no cell.
    const double inX = b.x - a.x, inY = b.y - a.y, outX = c.x - b.x, outY = c.y - b.y;
    if (!(inX * outY - inY * outX == 0.0 && inX * outX + inY * outY > 0.0))
        return false;
    if (!graph.contains(a.cell) || !graph.contains(b.cell) || !graph.contains(c.cell))
        return false;
    if (a.speedMetresPerSecond != b.speedMetresPerSecond || b.speedMetresPerSecond != c.speedMetresPerSecond)
        return false;
    // Records, not whole cells: a waypoint needs only their sizes and land covers.
    const auto sizeOf = [&](const CellRecord& cell) {
        return squareOf(graph.frame(), cell.column, cell.row, cell.span).size;
    };
    const CellRecord& middle = graph.record(b.cell);
    const double size = sizeOf(middle);
    for (const Waypoint* side : {&a, &c}) {
        const CellRecord& cell = graph.record(side->cell);
        if (sizeOf(cell) != size || cell.classValue != middle.classValue)
            return false; // a change of size or of land cover, which exports show
    }
    return isSubCellStep(a, b, size) && isSubCellStep(b, c, size);
}

} // namespace

void StraightRunMerger::add(const Waypoint& waypoint) {
    // The waypoint before this one is judged now that the one after it is known; the first is kept.
    if (walked_ == 0)
        kept_.push_back(waypoint);
    else if (walked_ >= 2 && !insideStraightRun(beforePrevious_, previous_, waypoint, graph_))
        keep(previous_, walked_ - 1);
    beforePrevious_ = previous_;
    previous_ = waypoint;
    ++walked_;
}

void StraightRunMerger::keep(const Waypoint& waypoint, std::size_t index) {
    runFollows_.push_back(index - lastKept_ > 1); // of the waypoint kept before this one
    kept_.push_back(waypoint);
    lastKept_ = index;
}

void StraightRunMerger::finishInto(CoveragePath& path) {
    if (walked_ >= 2)
        keep(previous_, walked_ - 1);
    runFollows_.push_back(false); // the last waypoint: nothing follows
    const bool merged = walked_ >= 3 && kept_.size() < walked_;
    kept_.shrink_to_fit(); // the point: the walk's memory is handed back
    path.waypoints = std::move(kept_);
    path.walkedWaypoints = merged ? walked_ : 0;
    path.runFollows = merged ? std::move(runFollows_) : std::vector<bool>{};
    kept_.clear();
    runFollows_.clear();
    walked_ = 0;
    lastKept_ = 0;
}

} // namespace mcpp
