#pragma once

#include "core/model/AreaOutline.hpp"
#include "core/model/ClassGrid.hpp"
#include "core/model/ClassTable.hpp"
#include "core/model/Plan.hpp"
#include "core/outlines/RegionOutlines.hpp"
#include "render/MapLayers.hpp"
#include "render/PlanSheet.hpp"

#include <QImage>
#include <QSize>
#include <QString>
#include <string>
#include <vector>

namespace mcpp::render {

// The map (raster in class colours) and the plan over it, north up, fitted into maxSize keeping aspect.
// Pixels outside the raster's task area are white. plan may be null to draw the map alone; outlines are the
// plan's region outlines when the caller has them (traced here otherwise). frame: the part of the raster to
// show (planFrame), the whole raster when null.
[[nodiscard]] QImage renderPlanImage(const ClassGrid& grid, const ClassTable& classes, const Plan* plan,
                                     QSize maxSize, const MapLayers& layers = {},
                                     const RegionOutlines* outlines = nullptr,
                                     const ClassGrid* frame = nullptr, const AreaOutline* area = nullptr);

// Writes the plan's map sheet (PlanSheet: title, map fitted into maxSize with scale bar and north arrow,
// legend naming the robots) as PNG. On failure returns false and says why in *error (when not null).
bool writePlanPng(const ClassGrid& grid, const ClassTable& classes, const Plan& plan, const QString& path,
                  QSize maxSize, QString* error, const SheetExtras& extras = {});
// Writes the same sheet as SVG (vector paths and cells; the land cover embedded as an image).
bool writePlanSvg(const ClassGrid& grid, const ClassTable& classes, const Plan& plan, const QString& path,
                  QSize maxSize, QString* error, const SheetExtras& extras = {});

} // namespace mcpp::render
