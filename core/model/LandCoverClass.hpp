#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace mcpp {

// Beyond these a value is a typo (a speed in km/h as m/s, a FOV in millimetres as metres), not a robot:
// faster than any ground robot or multirotor, wider than any sensor footprint.
inline constexpr double kMaximumSpeedMetresPerSecond = 1000.0;
inline constexpr double kMaximumFieldOfViewMetres = 100000.0;

// How one land-cover class affects a robot: how fast it moves there and how wide a swath it senses.
struct LandCoverClass {
    std::int32_t value = 0; // raster value of the class
    std::string name;
    std::uint32_t colorRgb = 0x808080; // 0xRRGGBB
    double speedMetresPerSecond = 1.0;
    double fieldOfViewMetres = 10.0;
    bool passable = true;
    // Chance the sensor sees a target in this land cover right beside the path (p0 of the detection model,
    // 0 to 1); unset: the planner's default.
    std::optional<double> detectionProbability = {};

    // Speed <= 0 or passable == false makes the class an obstacle (spec section 1).
    [[nodiscard]] bool isTraversable() const { return passable && speedMetresPerSecond > 0.0; }

    friend bool operator==(const LandCoverClass&, const LandCoverClass&) = default;
};

} // namespace mcpp
