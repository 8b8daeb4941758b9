#pragma once

#include "core/model/ClassGrid.hpp"
#include "core/model/ClassTable.hpp"
#include "core/model/Plan.hpp"
#include "render/MapLayers.hpp"

#include <QImage>
#include <QSize>
#include <QString>

namespace mcpp::render {

// The map (raster in class colours) and the plan over it, north up, fitted into maxSize keeping aspect.
// Pixels outside the raster's task area are white. plan may be null to draw the map alone.
[[nodiscard]] QImage renderPlanImage(const ClassGrid& grid, const ClassTable& classes, const Plan* plan,
                                     QSize maxSize, const MapLayers& layers = {});

// Writes the image as PNG. On failure returns false and says why in *error (when error is not null).
bool writePlanPng(const ClassGrid& grid, const ClassTable& classes, const Plan& plan, const QString& path,
                  QSize maxSize, QString* error);
// Writes the same picture as SVG (vector paths and cells; the land cover embedded as an image).
bool writePlanSvg(const ClassGrid& grid, const ClassTable& classes, const Plan& plan, const QString& path,
                  QSize maxSize, QString* error);

} // namespace mcpp::render
