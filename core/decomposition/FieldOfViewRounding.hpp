#pragma once

#include "core/model/ClassTable.hpp"
#include "core/model/RoundedFieldOfView.hpp"

#include <cstdint>
#include <optional>
#include <vector>

namespace mcpp {

// Spec section 2: Fd_min is the smallest FOV among the passable classes present; every such FOV is rounded
// down to Fd_min * 2^k and given the quadtree level whose sub-cells have that side (1 = top, the largest).
// Classes absent from `presentValues`, obstacles and classes without a usable FOV take no part; with no
// passable class at all the result is empty. The planners and the class table view share this one rule.
[[nodiscard]] std::vector<RoundedFieldOfView>
roundFieldsOfView(const ClassTable& classes, const std::vector<std::int32_t>& presentValues);

// Fd_min alone: the smallest usable FOV among the passable classes present, the spacing of the finest
// passes; none without such a class.
[[nodiscard]] std::optional<double> smallestFieldOfView(const ClassTable& classes,
                                                        const std::vector<std::int32_t>& presentValues);

} // namespace mcpp
