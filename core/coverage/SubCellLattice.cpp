#include "core/coverage/SubCellLattice.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace mcpp {
namespace {

SubCell subCellOf(int dx, int dy) {
    if (dy == 0)
        return dx == 0 ? SubCell::NorthWest : SubCell::NorthEast;
    return dx == 0 ? SubCell::SouthWest : SubCell::SouthEast;
}

constexpr std::array<std::array<int, 2>, 4> steps{{{1, 0}, {0, 1}, {-1, 0}, {0, -1}}};

} // namespace

SubCellLattice::SubCellLattice(const CellGraph& graph, const std::vector<int>& cells)
    : graph_(graph), width_(2 * graph.frame().columns), height_(2 * graph.frame().rows) {
    cellOfPlacement_.assign(
        static_cast<std::size_t>(graph.frame().columns) * static_cast<std::size_t>(graph.frame().rows), -1);
    for (int id : cells) {
        const Cell& cell = graph.cell(id);
        cellOfPlacement_[static_cast<std::size_t>(cell.row) *
                             static_cast<std::size_t>(graph.frame().columns) +
                         static_cast<std::size_t>(cell.column)] = id;
    }
    cameFrom_.assign(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_), -1);
}

std::size_t SubCellLattice::index(Position position) const {
    return static_cast<std::size_t>(position.y) * static_cast<std::size_t>(width_) +
           static_cast<std::size_t>(position.x);
}

int SubCellLattice::cellAt(Position position) const {
    if (position.x < 0 || position.y < 0 || position.x >= width_ || position.y >= height_)
        return -1;
    return cellOfPlacement_[static_cast<std::size_t>(position.y / 2) * static_cast<std::size_t>(width_ / 2) +
                            static_cast<std::size_t>(position.x / 2)];
}

bool SubCellLattice::isFree(Position position) const {
    const int cell = cellAt(position);
    return cell >= 0 && graph_.cell(cell).isFree(subCellOf(position.x % 2, position.y % 2));
}

std::optional<SubCellLattice::Position> SubCellLattice::at(MapPoint point) const {
    const GridFrame& frame = graph_.frame();
    const double half = frame.bottomCellSize / 2.0;
    const Position position{static_cast<int>(std::floor((point.x - frame.originX) / half)),
                            static_cast<int>(std::floor((frame.originY - point.y) / half))};
    if (cellAt(position) < 0)
        return std::nullopt;
    return position;
}

Waypoint SubCellLattice::waypointAt(Position position) const {
    const int id = cellAt(position);
    const Cell& cell = graph_.cell(id);
    const MapPoint centre = cell.subCellCentre(subCellOf(position.x % 2, position.y % 2));
    return {centre.x, centre.y, id, cell.speedMetresPerSecond};
}

std::vector<SubCellLattice::Position> SubCellLattice::reachableFrom(Position start) const {
    std::vector<Position> reached;
    if (!isFree(start))
        return reached;
    std::vector<char> seen(cameFrom_.size(), 0);
    reached.push_back(start);
    seen[index(start)] = 1;
    for (std::size_t head = 0; head < reached.size(); ++head)
        for (const auto& [dx, dy] : steps) {
            const Position next{reached[head].x + dx, reached[head].y + dy};
            if (!isFree(next) || seen[index(next)] != 0)
                continue;
            seen[index(next)] = 1;
            reached.push_back(next);
        }
    return reached;
}

std::vector<SubCellLattice::Position> SubCellLattice::shortestWay(Position from, Position to) const {
    std::vector<Position> way;
    if (!isFree(from) || !isFree(to))
        return way;
    std::vector<Position> queue{from};
    cameFrom_[index(from)] = static_cast<int>(index(from));
    touched_.assign(1, index(from));
    bool found = from == to;
    for (std::size_t head = 0; head < queue.size() && !found; ++head)
        for (const auto& [dx, dy] : steps) {
            const Position next{queue[head].x + dx, queue[head].y + dy};
            if (!isFree(next) || cameFrom_[index(next)] >= 0)
                continue;
            cameFrom_[index(next)] = static_cast<int>(index(queue[head]));
            touched_.push_back(index(next));
            queue.push_back(next);
            if (next == to) {
                found = true;
                break;
            }
        }
    if (found)
        for (Position at = to; !(at == from);) {
            way.push_back(at);
            const auto previous = static_cast<std::size_t>(cameFrom_[index(at)]);
            at = {static_cast<int>(previous % static_cast<std::size_t>(width_)),
                  static_cast<int>(previous / static_cast<std::size_t>(width_))};
        }
    std::reverse(way.begin(), way.end());
    for (std::size_t touched : touched_)
        cameFrom_[touched] = -1;
    return way;
}

} // namespace mcpp
