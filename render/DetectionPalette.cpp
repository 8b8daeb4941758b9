#include "render/DetectionPalette.hpp"

#include <algorithm>
#include <cmath>

namespace mcpp::render {
namespace {

// Cells seen as required show lightly; the less a cell is seen, the more it stands out.
constexpr int metAlpha = 90;
constexpr int unseenAlpha = 210;

int blend(int from, int to, double share) {
    return static_cast<int>(std::lround(from + (to - from) * share));
}

} // namespace

QRgb DetectionPalette::colour(float probability, float required) {
    if (!(required > 0.0F))
        return qRgba(90, 90, 90, metAlpha);
    const double share = std::clamp(static_cast<double>(probability) / required, 0.0, 1.0);
    const int alpha = blend(unseenAlpha, metAlpha, share);
    // Red (215, 48, 39) to yellow (254, 224, 139) to green (26, 152, 80), as diverging map scales read.
    if (share < 0.5)
        return qRgba(blend(215, 254, share * 2.0), blend(48, 224, share * 2.0), blend(39, 139, share * 2.0),
                     alpha);
    const double upper = (share - 0.5) * 2.0;
    return qRgba(blend(254, 26, upper), blend(224, 152, upper), blend(139, 80, upper), alpha);
}

} // namespace mcpp::render
