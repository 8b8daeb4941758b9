#pragma once

namespace mcpp {

// Where the walk round a spanning tree turns, on a grid of like cells whose sub-cells are all free. A cell's
// sides are numbered 0 east, 1 north, 2 west, 3 south; `sides` has bit s set where the cell has a tree edge
// on side s. The walk passes each of the cell's four sub-cells once, and turns in a sub-cell exactly where
// the cell's two sides beside that sub-cell both have a tree edge or both lack one. Closed walks turn as
// the rule adds up over every cell; an open walk may differ in its start sub-cell, where it begins and ends.
class GridTurnRule {
  public:
    // The turns the walk makes in the cell's four sub-cells.
    [[nodiscard]] static int turnsInCell(unsigned sides);
    // Makes or cuts the edge on `side` and returns how the cell's turns change: only the two sub-cells
    // beside that side can change, by one each.
    static int toggle(unsigned& sides, int side);
};

} // namespace mcpp
