#pragma once

#include <QPainter>
#include <QPointF>

namespace mcpp::render {

// A round length (1, 2 or 5 times a power of ten metres) whose bar is at most targetPixels long.
[[nodiscard]] double scaleBarMetres(double pixelsPerMetre, double targetPixels);
// A scale bar on a pale box whose bottom-left corner is at bottomLeft; the same on the canvas and sheets.
void paintScaleBar(QPainter& painter, QPointF bottomLeft, double pixelsPerMetre, double targetPixels);
// A north arrow whose tip is at tip, pointing to true north: the maps are drawn grid north up, and a grid
// turned from true north (ClassGrid::trueNorthRadians, counter-clockwise) turns the arrow with it.
void paintNorthArrow(QPainter& painter, QPointF tip, double trueNorthRadians = 0.0);

} // namespace mcpp::render
