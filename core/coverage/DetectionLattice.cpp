#include "core/coverage/DetectionLattice.hpp"

#include <cmath>

namespace mcpp {

DetectionLattice::DetectionLattice(const CellGraph& graph)
    : originX_(graph.frame().originX), originY_(graph.frame().originY),
      cellSize_(graph.frame().bottomCellSize / 2.0), columns_(2 * graph.frame().columns),
      rows_(2 * graph.frame().rows) {
    cellOfPosition_.assign(whole().size(), -1);
    for (std::size_t id = 0; id < graph.size(); ++id) {
        const Cell& cell = graph.cell(static_cast<int>(id));
        for (int south = 0; south < 2; ++south)
            for (int east = 0; east < 2; ++east) {
                const LatticePosition position{2 * cell.column + east, 2 * cell.row + south};
                if (cell.isFree(subCellAt(position)))
                    cellOfPosition_[whole().index(position)] = static_cast<int>(id);
            }
    }
}

int DetectionLattice::cellAt(LatticePosition position) const {
    return whole().contains(position) ? cellOfPosition_[whole().index(position)] : -1;
}

MapPoint DetectionLattice::centre(LatticePosition position) const {
    return {originX_ + (position.column + 0.5) * cellSize_, originY_ - (position.row + 0.5) * cellSize_};
}

std::optional<LatticePosition> DetectionLattice::centreAt(MapPoint point) const {
    const LatticePosition position{static_cast<int>(std::floor((point.x - originX_) / cellSize_)),
                                   static_cast<int>(std::floor((originY_ - point.y) / cellSize_))};
    if (!whole().contains(position))
        return std::nullopt;
    const MapPoint centred = centre(position);
    const double tolerance = 1e-6 * cellSize_;
    if (std::abs(centred.x - point.x) > tolerance || std::abs(centred.y - point.y) > tolerance)
        return std::nullopt;
    return position;
}

SubCell DetectionLattice::subCellAt(LatticePosition position) {
    return subCellOf(position.column % 2 == 1, position.row % 2 == 1);
}

} // namespace mcpp
