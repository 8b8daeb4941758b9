#pragma once

#include "core/model/ClassTable.hpp"
#include "io/internal/JsonValue.hpp"

namespace mcpp::io::internal {

// The class table as mission files and report.json hold it: an object a class (value, name, color,
// speed_mps, fov_m, passable and any detection_probability), pushed onto `table`, an array.
void addClassRows(JsonValue& table, const ClassTable& classes);

} // namespace mcpp::io::internal
