#include "core/coverage/GridTurnRule.hpp"

namespace mcpp {

namespace {

bool hasEdge(unsigned sides, int side) {
    return ((sides >> side) & 1U) != 0;
}

} // namespace

int GridTurnRule::turnsInCell(unsigned sides) {
    int turns = 0;
    for (int side = 0; side < 4; ++side) // the sub-cell between side and the next side round
        turns += hasEdge(sides, side) == hasEdge(sides, (side + 1) % 4) ? 1 : 0;
    return turns;
}

int GridTurnRule::toggle(unsigned& sides, int side) {
    const int before = turnsInCell(sides);
    sides ^= 1U << side;
    return turnsInCell(sides) - before;
}

} // namespace mcpp
