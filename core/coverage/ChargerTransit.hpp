#pragma once

#include "core/model/CellGraph.hpp"
#include "core/model/CoveragePath.hpp"

#include <memory>
#include <vector>

namespace mcpp {

class SubCellNodes;

// The flight of a robot whose charger is not at its start: the quickest way over any passable sub-cells
// (other robots' regions too) from the start to the charger, turns counted as a path's measurement counts
// them, searched near the two (the whole map when no way joins them there). It begins the robot's first
// sortie.
class ChargerTransit {
  public:
    explicit ChargerTransit(const CellGraph& graph);
    ~ChargerTransit();

    // The points from the start to the charger, both included, at the robot's own speed (0: the cells').
    // Throws PlanningError when no way joins them or when one charge of `enduranceSeconds` cannot fly it.
    [[nodiscard]] std::vector<Waypoint> way(int robot, MapPoint start, int startCell, MapPoint charger,
                                            int chargerCell, double enduranceSeconds,
                                            double ownSpeed = 0.0) const;

  private:
    // The way over these nodes, or nothing when they join no way.
    [[nodiscard]] std::vector<Waypoint> wayThrough(const SubCellNodes& nodes, int robot, MapPoint start,
                                                   int startCell, MapPoint charger, int chargerCell) const;

    const CellGraph& graph_;
    mutable std::unique_ptr<SubCellNodes> everySubCell_; // made at the first robot that needs the whole map
};

} // namespace mcpp
