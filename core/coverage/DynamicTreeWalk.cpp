#include "core/coverage/DynamicTreeWalk.hpp"

#include "core/coverage/RoundOrder.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <utility>

namespace mcpp {
namespace {

int itemOf(SubCell subCell) {
    return -1 - static_cast<int>(subCell);
}
SubCell subCellOfItem(int item) {
    return static_cast<SubCell>(-1 - item);
}

// The sub-cell of a cell whose centre is nearest a point (inside the cell or not).
SubCell nearestSubCell(const Cell& cell, const Waypoint& point) {
    return cell.subCellAt(
        {std::clamp(point.x, cell.minX, cell.maxX()), std::clamp(point.y, cell.minY, cell.maxY())});
}

// Where a tree's walk begins: the sub-cell nearest the robot, the first in counter-clockwise order from the
// north-west on a tie (a start at the cell's centre), as TreeCircumnavigation begins.
SubCell startingSubCell(const Cell& cell, const Waypoint& point) {
    SubCell best = SubCell::NorthWest;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (const SubCell subCell : subCellsCounterClockwise) {
        const MapPoint centre = cell.subCellCentre(subCell);
        const double distance = std::hypot(centre.x - point.x, centre.y - point.y);
        if (distance < bestDistance - 1e-12) {
            bestDistance = distance;
            best = subCell;
        }
    }
    return best;
}

} // namespace

DynamicTreeWalk::DynamicTreeWalk(const CellGraph& graph, int robot, MapPoint start, int startCell,
                                 std::vector<char>& entered)
    : graph_(graph), robot_(robot), clock_(graph) {
    const Cell& cell = graph.cell(startCell);
    clock_.append({start.x, start.y, startCell, cell.speedMetresPerSecond});
    nominalSecondsAt_.push_back(0.0);
    enter(startCell, -1, entered);
}

// The cell's round, counter-clockwise from its north-west sub-cell: each corner sub-cell, then the
// neighbours along the side after it in the order the walk passes them.
void DynamicTreeWalk::appendRound(int cell) {
    const Cell& self = graph_.cell(cell);
    std::array<std::vector<std::pair<double, int>>, 4> sides; // west, south, east, north
    for (const int id : graph_.neighbours(cell)) {
        const RoundPlace place = roundPlaceOf(self, graph_.cell(id));
        sides[static_cast<std::size_t>(place.side)].emplace_back(place.position, id);
    }
    for (std::size_t side = 0; side < 4; ++side) {
        arena_.push_back(itemOf(subCellsCounterClockwise[side]));
        std::sort(sides[side].begin(), sides[side].end());
        for (const auto& entry : sides[side])
            arena_.push_back(entry.second);
    }
}

// Opens a cell: its round begins just after the cell it came from, or, for a tree's first cell, at the
// sub-cell nearest the robot.
void DynamicTreeWalk::enter(int cell, int parent, std::vector<char>& entered) {
    entered[static_cast<std::size_t>(cell)] = 1;
    ++cellsEntered_;
    committedSeconds_ += graph_.cell(cell).coverSeconds();
    const std::size_t start = arena_.size();
    appendRound(cell);
    const auto begin = arena_.begin() + static_cast<std::ptrdiff_t>(start);
    auto first = begin;
    if (parent >= 0) {
        first = std::find(begin, arena_.end(), parent);
    } else {
        first = std::find(begin, arena_.end(),
                          itemOf(startingSubCell(graph_.cell(cell), clock_.waypoints().back())));
    }
    std::rotate(begin, first, arena_.end());
    frameOfCell_[cell] = frames_.size();
    frames_.push_back({cell, start, arena_.size(), parent >= 0 ? start + 1 : start, 0, notYet});
    passedThrough_.push_back(cell);
}

void DynamicTreeWalk::stepTo(int cell, SubCell subCell) {
    const Cell& target = graph_.cell(cell);
    const MapPoint centre = target.subCellCentre(subCell);
    const Waypoint& last = clock_.waypoints().back();
    if (centre.x != last.x || centre.y != last.y) {
        clock_.append({centre.x, centre.y, cell, target.speedMetresPerSecond});
        nominalSecondsAt_.push_back(clock_.elapsed());
    }
    if (!frames_.empty() && frames_.back().cell == cell)
        markPassed(frames_.back(), subCell);
}

// Passes a sub-cell of the open cell. When the last point lies in a cell that does not touch it (the tree
// went down or up through a cell without passing a sub-cell of it), the way goes through the cells between,
// as TreeCircumnavigation bridges them.
void DynamicTreeWalk::pass(int cell, SubCell subCell) {
    int from = clock_.waypoints().back().cell;
    if (from != cell && !graph_.areNeighbours(from, cell)) {
        std::vector<int> between;
        for (const int through : passedThrough_)
            if (through != from && through != cell)
                between.push_back(through);
        for (std::size_t i = 0; i < between.size(); ++i) {
            const int next = i + 1 < between.size() ? between[i + 1] : cell;
            if (from == next || graph_.areNeighbours(from, next))
                continue;
            stepTo(between[i], nearestSubCell(graph_.cell(between[i]), clock_.waypoints().back()));
            from = between[i];
        }
    }
    passedThrough_.clear();
    stepTo(cell, subCell);
}

// Counts a sub-cell of an open cell as passed: the work committed to shrinks by its share of the cell.
void DynamicTreeWalk::markPassed(Frame& frame, SubCell subCell) {
    const auto bit = static_cast<std::uint8_t>(1U << static_cast<unsigned>(subCell));
    if ((frame.passed & bit) != 0)
        return;
    frame.passed |= bit;
    if (frame.passed == allSubCells)
        frame.wholeAt = clock_.lastIndex();
    committedSeconds_ = std::max(0.0, committedSeconds_ - graph_.cell(frame.cell).coverSeconds() / 4.0);
}

bool DynamicTreeWalk::mayEnter(int from, int cell, const std::vector<int>& owner,
                               const std::vector<char>& entered) const {
    if (plannedParent_ == nullptr)
        return true;
    const int planned = (*plannedParent_)[static_cast<std::size_t>(cell)];
    if (planned < 0 || planned == from || owner[static_cast<std::size_t>(planned)] != robot_)
        return true;
    const char mark = entered[static_cast<std::size_t>(planned)];
    if (mark != 1)
        return mark == 2; // not yet entered: it will come to the cell; done: it went by without it
    const auto open = frameOfCell_.find(planned);
    if (open == frameOfCell_.end())
        return true;
    // Open, so an ancestor of `from`: it comes to the cell later unless its round has passed it.
    const Frame& frame = frames_[open->second];
    const auto begin = arena_.begin() + static_cast<std::ptrdiff_t>(frame.start);
    const auto end = arena_.begin() + static_cast<std::ptrdiff_t>(frame.end);
    const auto at = std::find(begin, end, cell);
    return at == end || static_cast<std::size_t>(at - arena_.begin()) < frame.next;
}

bool DynamicTreeWalk::advance(const std::vector<int>& owner, std::vector<char>& entered) {
    if (frames_.empty())
        return startTree(owner, entered);
    while (frames_.back().next < frames_.back().end) {
        Frame& frame = frames_.back();
        const int item = arena_[frame.next++];
        if (item < 0) {
            pass(frame.cell, subCellOfItem(item));
            continue;
        }
        const auto next = static_cast<std::size_t>(item);
        if (owner[next] != robot_ || entered[next] != 0 || !mayEnter(frame.cell, item, owner, entered))
            continue;
        enter(item, frame.cell, entered);
        return true;
    }
    closeFrame(entered);
    return true;
}

// Finishes the open cell (its round passed all its sub-cells); the walk carries on round the cell it came
// from.
void DynamicTreeWalk::closeFrame(std::vector<char>& entered) {
    const Frame done = frames_.back();
    lastClosedCell_ = done.cell;
    lastClosedWholeAt_ = done.wholeAt;
    entered[static_cast<std::size_t>(done.cell)] = 2;
    frameOfCell_.erase(done.cell);
    arena_.resize(done.start);
    frames_.pop_back();
    if (!frames_.empty())
        passedThrough_.push_back(frames_.back().cell);
}

// The cells from the robot's to the nearest cell of its region nobody entered, by the distance between
// cell centres; empty when none is left. Most such drives are short: a map of the cells reached costs far
// less than an array the map's size.
std::vector<int> DynamicTreeWalk::wayToNearestFreeCell(const std::vector<int>& owner,
                                                       const std::vector<char>& entered) const {
    struct Reached {
        double distance = 0.0;
        int previous = -1;
    };
    const int origin = clock_.waypoints().back().cell;
    std::unordered_map<int, Reached> reached;
    reached.reserve(4096);
    using Entry = std::pair<double, int>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
    reached[origin] = {0.0, origin};
    queue.emplace(0.0, origin);
    while (!queue.empty()) {
        const auto [distance, at] = queue.top();
        queue.pop();
        if (distance > reached[at].distance)
            continue;
        const auto index = static_cast<std::size_t>(at);
        if (owner[index] == robot_ && entered[index] == 0) {
            std::vector<int> way;
            for (int cell = at; cell != origin; cell = reached[cell].previous)
                way.push_back(cell);
            std::reverse(way.begin(), way.end());
            return way;
        }
        const Cell& here = graph_.cell(at);
        for (const int next : graph_.neighbours(at)) {
            const Cell& there = graph_.cell(next);
            const double through =
                distance + std::hypot(there.centreX() - here.centreX(), there.centreY() - here.centreY());
            const auto [slot, isNew] = reached.try_emplace(next, Reached{through, at});
            if (!isNew && through >= slot->second.distance)
                continue;
            slot->second = {through, at};
            queue.emplace(through, next);
        }
    }
    return {};
}

// Drives to the nearest cell of its region nobody entered and begins a tree there; false when none is left.
bool DynamicTreeWalk::startTree(const std::vector<int>& owner, std::vector<char>& entered) {
    const std::vector<int> way = wayToNearestFreeCell(owner, entered);
    if (way.empty())
        return false;
    passedThrough_.clear();
    for (const int cell : way)
        stepTo(cell, nearestSubCell(graph_.cell(cell), clock_.waypoints().back()));
    enter(way.back(), -1, entered);
    return true;
}

std::vector<int> DynamicTreeWalk::abandonUnfinishedCells(std::size_t reachedWaypoints) {
    std::vector<int> cells;
    for (const Frame& frame : frames_)
        if (frame.wholeAt == notYet || frame.wholeAt >= reachedWaypoints)
            cells.push_back(frame.cell);
    if (lastClosedCell_ >= 0 && lastClosedWholeAt_ >= reachedWaypoints)
        cells.push_back(lastClosedCell_);
    lastClosedCell_ = -1;
    frames_.clear();
    arena_.clear();
    frameOfCell_.clear();
    passedThrough_.clear();
    committedSeconds_ = 0.0;
    return cells;
}

} // namespace mcpp
