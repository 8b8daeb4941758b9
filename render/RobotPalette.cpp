#include "render/RobotPalette.hpp"

#include "core/model/RobotColours.hpp"

namespace mcpp::render {

QColor RobotPalette::colour(int robot) {
    return QColor::fromRgb(robotColourRgb(robot));
}

int RobotPalette::size() {
    return static_cast<int>(robotColourTable.size());
}

QColor RobotPalette::levelColour(int level, int levels) {
    // Coarse cells dark blue, fine cells light violet: the eye reads the nesting without a legend.
    const double t = levels <= 1 ? 0.0 : static_cast<double>(level - 1) / static_cast<double>(levels - 1);
    const int hue = static_cast<int>(220.0 + 80.0 * t);
    const int value = static_cast<int>(90.0 + 130.0 * t);
    return QColor::fromHsv(hue % 360, 200, value);
}

} // namespace mcpp::render
