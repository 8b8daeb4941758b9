#include "core/coverage/DetectionAccumulator.hpp"

#include <cstdlib>
#include <optional>

namespace mcpp {
namespace {

// The lattice centres the path passes, in order, without the off-centre start point or a point repeated.
std::vector<LatticePosition> centresPassed(const CoveragePath& path, const DetectionLattice& lattice) {
    std::vector<LatticePosition> centres;
    for (const Waypoint& waypoint : path.waypoints) {
        const std::optional<LatticePosition> position = lattice.centreAt({waypoint.x, waypoint.y});
        if (!position)
            continue;
        if (!centres.empty() && centres.back().column == position->column &&
            centres.back().row == position->row)
            continue;
        centres.push_back(*position);
    }
    return centres;
}

bool isHorizontalStep(LatticePosition from, LatticePosition to) {
    return from.row == to.row;
}

} // namespace

DetectionAccumulator::DetectionAccumulator(const DetectionLattice& lattice, const CellGraph& graph,
                                           const DetectionModel& model, LatticeWindow window)
    : lattice_(lattice), model_(model), window_(window), probability_(window.size(), 0.0),
      profile_(window.size(), DetectionModel::noProfile) {
    // Neighbouring cells mostly share a land cover: look a class up only when it changes.
    std::int32_t lastClass = 0;
    int lastProfile = model.profileOf(lastClass);
    for (int row = window.row; row < window.row + window.rows; ++row)
        for (int column = window.column; column < window.column + window.columns; ++column) {
            const LatticePosition position{column, row};
            const int cell = lattice.cellAt(position);
            if (cell < 0)
                continue;
            if (const std::int32_t landCover = graph.cell(cell).classValue; landCover != lastClass) {
                lastClass = landCover;
                lastProfile = model.profileOf(landCover);
            }
            profile_[window.index(position)] = lastProfile;
        }
}

void DetectionAccumulator::addPass(LatticePosition position, bool horizontal) {
    const int reach = model_.reach();
    for (int offset = -reach; offset <= reach; ++offset) {
        const LatticePosition seen = horizontal ? LatticePosition{position.column, position.row + offset}
                                                : LatticePosition{position.column + offset, position.row};
        if (!window_.contains(seen))
            continue;
        const std::size_t index = window_.index(seen);
        const double chance = model_.probability(profile_[index], offset);
        double& seenSoFar = probability_[index];
        seenSoFar += (1.0 - seenSoFar) * chance;
    }
}

void DetectionAccumulator::addPath(const CoveragePath& path) {
    const std::vector<LatticePosition> centres = centresPassed(path, lattice_);
    for (std::size_t i = 0; i < centres.size(); ++i) {
        std::optional<bool> arriving;
        std::optional<bool> leaving;
        if (i > 0)
            arriving = isHorizontalStep(centres[i - 1], centres[i]);
        if (i + 1 < centres.size())
            leaving = isHorizontalStep(centres[i], centres[i + 1]);
        if (!arriving && !leaving) {
            // A robot that never leaves its one centre looks both ways there.
            addPass(centres[i], true);
            addPass(centres[i], false);
            continue;
        }
        const bool first = arriving.value_or(*leaving);
        addPass(centres[i], first);
        if (leaving && *leaving != first)
            addPass(centres[i], *leaving);
    }
}

} // namespace mcpp
