#pragma once

#include <QColor>

namespace mcpp::render {

// A qualitative palette of saturated colours that stay apart from each other and from land-cover tints.
// Robot i always gets the same colour so the map, the tables and the chart agree.
class RobotPalette {
  public:
    [[nodiscard]] static QColor colour(int robot);
    [[nodiscard]] static int size();
    // Outline colour for quadtree cells of a level (1 = top), from a dark-to-light ramp.
    [[nodiscard]] static QColor levelColour(int level, int levels);
};

} // namespace mcpp::render
