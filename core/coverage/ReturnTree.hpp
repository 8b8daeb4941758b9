#pragma once

#include "core/coverage/SubCellNodes.hpp"

#include <vector>

namespace mcpp {

// The ways home of a robot on a battery: from every node it may use, a way to its charger through those
// nodes, each node's way continuing its parent's, grown cheapest first from the charger. The time of each
// way is exact as a path's measurement counts it: travel, and every turn after the first node.
class ReturnTree {
  public:
    // usable: by node, whether the robot may pass it. root: the node nearest the charger, whose way home
    // ends at the charger point (a step when it is not the root's centre).
    ReturnTree(const SubCellNodes& nodes, const CellGraph& graph, const std::vector<char>& usable, int root,
               MapPoint charger);

    [[nodiscard]] bool reaches(int node) const {
        return parent_[static_cast<std::size_t>(node)] != unreached;
    }
    [[nodiscard]] const Waypoint& charger() const { return charger_; }
    [[nodiscard]] int root() const { return root_; }
    // Seconds from the node home, turns after it included.
    [[nodiscard]] double secondsHome(int node) const { return secondsHome_[static_cast<std::size_t>(node)]; }
    // Seconds home for a robot that reached the node moving along the unit vector (inX, inY): the turn
    // there, then the way.
    [[nodiscard]] double secondsHomeArriving(int node, double inX, double inY) const;
    // The most a robot can spend turning at the node: a U-turn at its cell's price.
    [[nodiscard]] double worstTurnSeconds(int node) const;
    [[nodiscard]] double worstTurnAtCharger() const;
    // The nodes after `node` on its way home, ending at the root; the charger point follows when apart.
    [[nodiscard]] std::vector<int> wayHome(int node) const;
    [[nodiscard]] bool chargerApart() const { return chargerApart_; }

  private:
    static constexpr int unreached = -2;
    static constexpr int atRoot = -1;

    // The next point of the way home after `node`, or false at its end.
    [[nodiscard]] bool nextPoint(int node, double& x, double& y) const;

    const SubCellNodes& nodes_;
    const CellGraph& graph_;
    int root_;
    Waypoint charger_;
    bool chargerApart_ = false; // the charger point is not the root's centre
    std::vector<int> parent_;   // by node: the next node home, atRoot, or unreached
    std::vector<double> secondsHome_;
};

} // namespace mcpp
