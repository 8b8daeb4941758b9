#pragma once

#include <QColor>

namespace mcpp::render {

// Robot colours as Qt colours (core/model/RobotColours.hpp holds them, so regions.tif agrees).
class RobotPalette {
  public:
    [[nodiscard]] static QColor colour(int robot);
    [[nodiscard]] static int size();
    // Every second sortie of a robot on a battery: its colour, darker, so flights between charges show.
    [[nodiscard]] static QColor alternateSortieColour(int robot) { return colour(robot).darker(170); }
    // Outline colour for quadtree cells of a level (1 = top), from a dark-to-light ramp.
    [[nodiscard]] static QColor levelColour(int level, int levels);
    // Dashes around cells whose path crosses impassable land: dark red, like the unreachable hatching.
    [[nodiscard]] static QColor crossingColour() { return {150, 0, 20}; }
    // The area of interest's edge, near black, and the no-go zones', a brighter red than the crossings'.
    [[nodiscard]] static QColor areaEdgeColour() { return {25, 25, 25}; }
    [[nodiscard]] static QColor noGoColour() { return {215, 25, 25}; }
};

} // namespace mcpp::render
