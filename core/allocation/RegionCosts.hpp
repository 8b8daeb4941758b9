#pragma once

#include "core/model/CellGraph.hpp"

#include <cstddef>
#include <vector>

namespace mcpp {

// Each robot's cover time: the costs of the cells `robotOfCell` gives it (cells of -1 belong to none).
[[nodiscard]] std::vector<double> regionCosts(const CellGraph& graph, const std::vector<int>& robotOfCell,
                                              std::size_t robots);

// Whether every cost is within `slack` of their mean.
[[nodiscard]] bool withinOfTheMean(const std::vector<double>& costs, double slack);

} // namespace mcpp
