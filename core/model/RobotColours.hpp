#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

namespace mcpp {

struct RgbColour {
    std::uint8_t red = 0;
    std::uint8_t green = 0;
    std::uint8_t blue = 0;
};

// Robot i's colour everywhere: the map, the tables, the chart and regions.tif's colour table. A qualitative
// palette of saturated colours chosen by hand to differ in hue and lightness; light pastels are left out
// because paths are drawn over land cover that is itself pale.
inline constexpr std::array<std::uint32_t, 16> robotColourTable = {
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

[[nodiscard]] constexpr std::uint32_t robotColourRgb(int robot) {
    const auto count = static_cast<int>(robotColourTable.size());
    return robotColourTable[static_cast<std::size_t>(((robot % count) + count) % count)];
}

[[nodiscard]] constexpr RgbColour robotColour(int robot) {
    const std::uint32_t rgb = robotColourRgb(robot);
    return {static_cast<std::uint8_t>(rgb >> 16U & 0xffU), static_cast<std::uint8_t>(rgb >> 8U & 0xffU),
            static_cast<std::uint8_t>(rgb & 0xffU)};
}

} // namespace mcpp
