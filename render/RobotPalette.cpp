#include "render/RobotPalette.hpp"

#include <array>
#include <cstddef>

namespace mcpp::render {

namespace {

// Chosen by hand to differ in hue and lightness; light pastels are left out because paths are drawn over
// land cover that is itself pale.
constexpr std::array<unsigned, 16> kRobotColours = {
    0xe6194b, // red
    0x4363d8, // blue
    0xf58231, // orange
    0x911eb4, // purple
    0x2ca02c, // green
    0xf032e6, // magenta
    0x00a3c4, // cyan
    0x9a6324, // brown
    0x1a1a80, // navy
    0x808000, // olive
    0x800000, // maroon
    0x469990, // teal
    0xffc20a, // amber
    0x5d5d5d, // grey
    0xb2528a, // plum
    0x6a9a1f, // moss
};

} // namespace

QColor RobotPalette::colour(int robot) {
    const auto count = static_cast<int>(kRobotColours.size());
    const int index = ((robot % count) + count) % count;
    return QColor::fromRgb(kRobotColours[static_cast<std::size_t>(index)]);
}

int RobotPalette::size() {
    return static_cast<int>(kRobotColours.size());
}

QColor RobotPalette::levelColour(int level, int levels) {
    // Coarse cells dark blue, fine cells light violet: the eye reads the nesting without a legend.
    const double t = levels <= 1 ? 0.0 : static_cast<double>(level - 1) / static_cast<double>(levels - 1);
    const int hue = static_cast<int>(220.0 + 80.0 * t);
    const int value = static_cast<int>(90.0 + 130.0 * t);
    return QColor::fromHsv(hue % 360, 200, value);
}

} // namespace mcpp::render
