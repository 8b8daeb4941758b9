#include "io/internal/ClassTableJson.hpp"

#include "io/internal/LegendReader.hpp"

namespace mcpp::io::internal {

void addClassRows(JsonValue& table, const ClassTable& classes, const std::set<std::int32_t>& withoutColour) {
    for (const LandCoverClass& entry : classes.classes()) {
        JsonValue& row = table.push(JsonValue::object());
        row.add("value", static_cast<int>(entry.value));
        row.add("name", entry.name);
        if (withoutColour.count(entry.value) == 0)
            row.add("color", formatColor(entry.colorRgb));
        row.add("speed_mps", entry.speedMetresPerSecond);
        row.add("fov_m", entry.fieldOfViewMetres);
        row.add("passable", entry.passable);
        if (entry.detectionProbability)
            row.add("detection_probability", *entry.detectionProbability);
    }
}

} // namespace mcpp::io::internal
