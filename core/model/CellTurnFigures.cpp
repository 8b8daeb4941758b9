#include "core/model/CellTurnFigures.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace mcpp {

void CellTurnFigures::applyModel(const TurnTimeModel& model) {
    model_ = model;
    turnSecondsOfCell_ = {};
}

void CellTurnFigures::setTurnSeconds(std::vector<float> secondsOfCell) {
    model_ = TurnTimeModel{0.0};
    // -0 is kept as given: the graph without a list gives +0.
    const bool allZero = std::all_of(secondsOfCell.begin(), secondsOfCell.end(),
                                     [](float seconds) { return seconds == 0.0F && !std::signbit(seconds); });
    turnSecondsOfCell_ = allZero ? std::vector<float>{} : std::move(secondsOfCell);
}

void CellTurnFigures::setExpectedTurns(std::vector<float> turnsOfCell) {
    const bool allDefault = std::all_of(turnsOfCell.begin(), turnsOfCell.end(),
                                        [](float turns) { return turns == defaultExpectedTurnsPerSubCell; });
    expectedTurnsOfCell_ = allDefault ? std::vector<float>{} : std::move(turnsOfCell);
}

} // namespace mcpp
