#pragma once

#include <QColor>
#include <QRgb>

namespace mcpp::render {

// The colours of a detection layer: red where a target is hardly seen, through yellow, to light green at
// the required probability and dark green where it is certain; grey where the land cover hides targets.
// Translucent, over the land cover.
class DetectionPalette {
  public:
    // required: the cell's required probability, 0 where its land cover hides targets.
    [[nodiscard]] static QRgb colour(float probability, float requiredProbability);
    [[nodiscard]] static QColor met() { return QColor::fromRgba(colour(0.95F, 0.95F)); }
    [[nodiscard]] static QColor certain() { return QColor::fromRgba(colour(1.0F, 0.95F)); }
    [[nodiscard]] static QColor halfway() { return QColor::fromRgba(colour(0.5F, 1.0F)); }
    [[nodiscard]] static QColor unseen() { return QColor::fromRgba(colour(0.0F, 1.0F)); }
    [[nodiscard]] static QColor hidden() { return QColor::fromRgba(colour(0.0F, 0.0F)); }
};

} // namespace mcpp::render
