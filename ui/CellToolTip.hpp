#pragma once

#include "core/model/MapPoint.hpp"

#include <QString>

namespace mcpp::ui {

class MissionDocument;

// What the map's tooltip says about the plan's cell under a point: which robot covers it, its size and land
// cover, and, where its path crosses impassable land (allowed by the blocked threshold), how much of which
// classes and why. Empty where the plan has no cell.
[[nodiscard]] QString cellToolTip(const MissionDocument& document, MapPoint point);

} // namespace mcpp::ui
