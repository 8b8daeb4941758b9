#pragma once

#include "core/model/CellGraph.hpp"
#include "core/model/CoveragePath.hpp"
#include "core/planners/StartSquare.hpp"

#include <functional>
#include <vector>

namespace mcpp {

// Work on a map by how far it lies from the nearest of some starts, in even steps of distance: what robots
// flying out from those starts can reach only on trips at least that long.
class WorkByDistance {
  public:
    // A path whose turns are work, and the weight they are counted at.
    struct TurningPath {
        const CoveragePath* path = nullptr;
        double weight = 0.0;
    };

    // workOfCell: the travel a cell holds (0 for cells outside the work); turning: the paths whose turns
    // count too, each where it is made.
    WorkByDistance(const CellGraph& cells, std::vector<StartSquare> starts,
                   const std::function<double(int)>& workOfCell, const std::vector<TurningPath>& turning);

    [[nodiscard]] double stepMetres() const { return stepMetres_; }
    // [k]: the work on cells lying wholly beyond k * stepMetres() of every start. A path spends at least a
    // sub-cell's travel time within the circle inscribed in it (its steps to the sub-cells around, or a
    // flight's trip there, are at least half a sub-cell long each way; only where it ends at a start is
    // it half that), so at least a cell's work lies as far as the cell.
    [[nodiscard]] const std::vector<double>& secondsBeyond() const { return secondsBeyond_; }

  private:
    [[nodiscard]] std::size_t stepOf(double metres) const;
    // Adds the turns a path makes, each at its corner (as PathMeasurement times them), at most the path's
    // measured turn time in all.
    void addTurns(const CellGraph& cells, const std::vector<StartSquare>& starts, const TurningPath& turning);

    double stepMetres_ = 0.0;
    std::vector<double> secondsBeyond_;
};

} // namespace mcpp
