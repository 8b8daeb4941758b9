#pragma once

#include "core/model/Cell.hpp"
#include "core/model/TurnTimeModel.hpp"

#include <cstddef>
#include <vector>

namespace mcpp {

// What a turn costs in each cell of a cell graph, and the turns each cell's cost expects per sub-cell.
// Kept beside the cell records instead of in them, 8 bytes a cell less (550 MB on a map of 69 million
// cells): on a planned map the turn time follows from the cell's speed and one model, and the expected
// turns are the default until a planner measures them. Only figures given cell by cell (by hand, from a
// plan file, measured per region) are kept, one for each cell.
class CellTurnFigures {
  public:
    [[nodiscard]] float turnSeconds(std::size_t id, float speedMetresPerSecond) const {
        if (!turnSecondsOfCell_.empty())
            return turnSecondsOfCell_[id];
        return static_cast<float>(model_.secondsPer90Degrees(speedMetresPerSecond));
    }
    [[nodiscard]] float expectedTurns(std::size_t id) const {
        return expectedTurnsOfCell_.empty() ? defaultExpectedTurnsPerSubCell : expectedTurnsOfCell_[id];
    }
    // Whether the turn times are worked out from the cells' speeds (so change with them).
    [[nodiscard]] bool followSpeeds() const {
        return !(model_.fixedSecondsPer90Degrees >= 0.0) && turnSecondsOfCell_.empty();
    }

    // Every cell's turn time from its speed, by this model.
    void applyModel(const TurnTimeModel& model);
    // Turn times and expected turns given cell by cell; kept only where some cell differs from what the
    // graph gives without them (0 seconds; defaultExpectedTurnsPerSubCell).
    void setTurnSeconds(std::vector<float> secondsOfCell);
    void setExpectedTurns(std::vector<float> turnsOfCell);

  private:
    TurnTimeModel model_{0.0};               // before a model is applied, turns cost nothing
    std::vector<float> turnSecondsOfCell_;   // empty: from the model, or 0 without one
    std::vector<float> expectedTurnsOfCell_; // empty: the default for every cell
};

} // namespace mcpp
