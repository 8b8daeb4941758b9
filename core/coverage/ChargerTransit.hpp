#pragma once

#include "core/model/CellGraph.hpp"
#include "core/model/CoveragePath.hpp"

#include <memory>
#include <vector>

namespace mcpp {

class SubCellNodes;

// The flight of a robot whose charger is not at its start: the quickest way over any passable sub-cells
// (other robots' regions too) from the start to the charger, turns counted as a path's measurement counts
// them. It is the beginning of the robot's first sortie.
class ChargerTransit {
  public:
    explicit ChargerTransit(const CellGraph& graph);
    ~ChargerTransit();

    // The points from the start to the charger, both included. Throws PlanningError when no way joins them
    // or when one charge of `enduranceSeconds` cannot fly it.
    [[nodiscard]] std::vector<Waypoint> way(int robot, MapPoint start, int startCell, MapPoint charger,
                                            int chargerCell, double enduranceSeconds) const;

  private:
    const CellGraph& graph_;
    std::unique_ptr<SubCellNodes> nodes_; // every free sub-cell of the map, made once for every robot
};

} // namespace mcpp
