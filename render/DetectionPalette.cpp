#include "render/DetectionPalette.hpp"

#include <algorithm>
#include <cmath>

namespace mcpp::render {
namespace {

// Cells seen as required show lightly; the less a cell is seen, the more it stands out.
constexpr int metAlpha = 110;
constexpr int unseenAlpha = 210;

struct Rgb {
    int red = 0;
    int green = 0;
    int blue = 0;
};

// A diverging scale as map readers know it: red (not seen), yellow (half way), light green (required),
// dark green (certain).
constexpr Rgb unseenShade{215, 48, 39};
constexpr Rgb halfwayShade{254, 224, 139};
constexpr Rgb requiredShade{166, 217, 106};
constexpr Rgb certainShade{0, 104, 55};

int blend(int from, int to, double share) {
    return static_cast<int>(std::lround(from + (to - from) * share));
}

QRgb mix(const Rgb& from, const Rgb& to, double share, int alpha) {
    return qRgba(blend(from.red, to.red, share), blend(from.green, to.green, share),
                 blend(from.blue, to.blue, share), alpha);
}

} // namespace

QRgb DetectionPalette::colour(float probability, float requiredProbability) {
    if (!(requiredProbability > 0.0F))
        return qRgba(90, 90, 90, metAlpha);
    const double seen = std::clamp(static_cast<double>(probability), 0.0, 1.0);
    const double share = seen / requiredProbability;
    if (share >= 1.0) {
        // Above the requirement the shade says how much more than needed the passes saw.
        const double spare =
            requiredProbability < 1.0F ? (seen - requiredProbability) / (1.0 - requiredProbability) : 1.0;
        return mix(requiredShade, certainShade, std::clamp(spare, 0.0, 1.0), metAlpha);
    }
    const int alpha = blend(unseenAlpha, metAlpha, share);
    if (share < 0.5)
        return mix(unseenShade, halfwayShade, share * 2.0, alpha);
    return mix(halfwayShade, requiredShade, (share - 0.5) * 2.0, alpha);
}

} // namespace mcpp::render
