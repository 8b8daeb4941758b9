#pragma once

#include "core/model/ClassTable.hpp"
#include "io/internal/JsonValue.hpp"

#include <cstdint>
#include <set>

namespace mcpp::io::internal {

// The class table as mission files and report.json hold it: an object a class (value, name, color,
// speed_mps, fov_m, passable and any detection_probability), pushed onto `table`, an array. The rows of
// values in `withoutColour` are written without one, as they were read.
void addClassRows(JsonValue& table, const ClassTable& classes,
                  const std::set<std::int32_t>& withoutColour = {});

} // namespace mcpp::io::internal
