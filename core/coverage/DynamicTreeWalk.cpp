#include "core/coverage/DynamicTreeWalk.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <unordered_map>

namespace mcpp {
namespace {

// Sides counter-clockwise from east (SubCellNodes::Direction); sub-cells by their counter-clockwise index
// (SubCell). Circling counter-clockwise, a robot leaves a cell eastwards from its south-east sub-cell and
// enters the south-west one of the cell beyond, and so on round.
int opposite(int direction) {
    return (direction + 2) % 4;
}
// By these two numberings the sub-cell a robot leaves by is the index of the opposite side.
int exitSubCell(int direction) {
    return opposite(direction);
}

} // namespace

DynamicTreeWalk::DynamicTreeWalk(const CellGraph& graph, const SubCellNodes& nodes, int robot, MapPoint start,
                                 int startCell, std::vector<char>& entered)
    : graph_(graph), nodes_(nodes), robot_(robot), clock_(graph) {
    const Cell& cell = graph.cell(startCell);
    clock_.append({start.x, start.y, startCell, cell.classValue, cell.speedMetresPerSecond, 0.0});
    nominalSecondsAt_.push_back(0.0);
    const int first = nodes.startNode(robot, startCell, start);
    stepTo(first);
    const int subCell = subCellIndexOf(first);
    enter(startCell, first, (subCell + 1) % 4, true, entered);
}

int DynamicTreeWalk::subCellIndexOf(int node) const {
    const Waypoint& point = nodes_.waypoint(node);
    return static_cast<int>(graph_.cell(point.cell).subCellAt({point.x, point.y}));
}

void DynamicTreeWalk::stepTo(int node) {
    const Waypoint& point = nodes_.waypoint(node);
    const Waypoint& last = clock_.waypoints().back();
    if (point.x != last.x || point.y != last.y) {
        clock_.append(point);
        nominalSecondsAt_.push_back(clock_.elapsed());
    }
    node_ = node;
    if (!frames_.empty() && frames_.back().cell == point.cell)
        markPassed(frames_.back(), subCellIndexOf(node));
}

// Counts a sub-cell of an open cell as passed: the work committed to shrinks by its share of the cell.
void DynamicTreeWalk::markPassed(Frame& frame, int subCellIndex) {
    const auto bit = static_cast<std::uint8_t>(1U << static_cast<unsigned>(subCellIndex));
    if ((frame.passed & bit) != 0)
        return;
    frame.passed |= bit;
    committedSeconds_ -= graph_.cell(frame.cell).coverSeconds() / 4.0;
}

void DynamicTreeWalk::circleTo(int subCellIndex) {
    const int cell = nodes_.waypoint(node_).cell;
    for (int index = subCellIndexOf(node_); index != subCellIndex;) {
        index = (index + 1) % 4;
        stepTo(nodes_.at(cell, static_cast<SubCell>(index)));
    }
}

void DynamicTreeWalk::enter(int cell, int node, int parentDirection, bool root, std::vector<char>& entered) {
    entered[static_cast<std::size_t>(cell)] = 1;
    ++cellsEntered_;
    if (root)
        treeStartSubCell_ = subCellIndexOf(node);
    frames_.push_back({cell, parentDirection, 0, root, 0, 0});
    committedSeconds_ += graph_.cell(cell).coverSeconds();
    markPassed(frames_.back(), subCellIndexOf(node));
}

// The node a robot steps onto leaving `cell` by `direction` into a cell of its region nobody has entered,
// or none.
int DynamicTreeWalk::openSide(int cell, int direction, const std::vector<int>& owner,
                              const std::vector<char>& entered) const {
    const int exit = nodes_.at(cell, static_cast<SubCell>(exitSubCell(direction)));
    const int beyond = exit == SubCellNodes::none ? SubCellNodes::none : nodes_.neighbour(exit, direction);
    if (beyond == SubCellNodes::none)
        return SubCellNodes::none;
    const auto next = static_cast<std::size_t>(nodes_.waypoint(beyond).cell);
    return owner[next] == robot_ && entered[next] == 0 ? beyond : SubCellNodes::none;
}

bool DynamicTreeWalk::advance(const std::vector<int>& owner, std::vector<char>& entered) {
    if (frames_.empty())
        return startTree(owner, entered);
    Frame& frame = frames_.back();
    const int sides = frame.root ? 4 : 3;
    while (frame.scanned < sides) {
        const int direction = (frame.parentDirection + 1 + frame.scanned) % 4;
        ++frame.scanned;
        const int beyond = openSide(frame.cell, direction, owner, entered);
        if (beyond == SubCellNodes::none)
            continue;
        const int next = nodes_.waypoint(beyond).cell;
        ++frame.children;
        circleTo(exitSubCell(direction));
        stepTo(beyond);
        enter(next, beyond, opposite(direction), false, entered);
        return true;
    }
    const Frame done = frame;
    frames_.pop_back();
    // What is left of it is passed on the way out below; the cell leaves the open ones.
    const int unpassed = 4 - std::popcount(done.passed);
    committedSeconds_ =
        std::max(0.0, committedSeconds_ - unpassed * graph_.cell(done.cell).coverSeconds() / 4.0);
    lastClosedCell_ = done.cell;
    if (!done.root) {
        circleTo(exitSubCell(done.parentDirection));
        lastClosedWaypoint_ = clock_.lastIndex();
        stepTo(nodes_.neighbour(node_, done.parentDirection));
        return true;
    }
    // The tree's first cell: round to the sub-cell before the one it began in, unless the last return
    // already closed the circle.
    const int last = (treeStartSubCell_ + 3) % 4;
    if (!(done.children > 0 && subCellIndexOf(node_) == treeStartSubCell_))
        circleTo(last);
    lastClosedWaypoint_ = clock_.lastIndex();
    return true;
}

// The shortest way over sub-cells to the nearest cell of its region nobody entered; false when none is left.
bool DynamicTreeWalk::startTree(const std::vector<int>& owner, std::vector<char>& entered) {
    // Most such drives are short: a map of the nodes reached costs far less than an array the map's size.
    std::unordered_map<int, int> previous;
    previous.reserve(4096);
    previous.emplace(node_, node_);
    std::vector<int> queue{node_};
    int found = SubCellNodes::none;
    for (std::size_t head = 0; head < queue.size() && found == SubCellNodes::none; ++head) {
        const int at = queue[head];
        for (int direction = 0; direction < 4 && found == SubCellNodes::none; ++direction) {
            const int next = nodes_.neighbour(at, direction);
            if (next == SubCellNodes::none || !previous.emplace(next, at).second)
                continue;
            queue.push_back(next);
            const auto cell = static_cast<std::size_t>(nodes_.waypoint(next).cell);
            if (owner[cell] == robot_ && entered[cell] == 0)
                found = next;
        }
    }
    if (found == SubCellNodes::none)
        return false;
    std::vector<int> way;
    for (int at = found; at != node_; at = previous.at(at))
        way.push_back(at);
    for (auto it = way.rbegin(); it != way.rend(); ++it)
        stepTo(*it);
    const int subCell = subCellIndexOf(found);
    enter(nodes_.waypoint(found).cell, found, (subCell + 1) % 4, true, entered);
    return true;
}

std::vector<int> DynamicTreeWalk::abandonUnfinishedCells(std::size_t reachedWaypoints) {
    std::vector<int> cells;
    for (const Frame& frame : frames_)
        cells.push_back(frame.cell);
    if (lastClosedCell_ >= 0 && lastClosedWaypoint_ >= reachedWaypoints)
        cells.push_back(lastClosedCell_);
    frames_.clear();
    committedSeconds_ = 0.0;
    return cells;
}

} // namespace mcpp
