#include "render/PlanSheet.hpp"

#include "core/model/HumanUnits.hpp"
#include "render/MapDecorations.hpp"
#include "render/PlanFrame.hpp"
#include "render/PlanRenderer.hpp"

#include <QFontMetricsF>
#include <algorithm>
#include <cmath>

namespace mcpp::render {

namespace {

// When the last robot is home, where some robot is done in the field later than its path (flights, trips
// from its start, turnarounds); 0 where none is.
double lastHomeSeconds(const Plan& plan, const std::vector<FieldTime>& fieldTimes) {
    double last = 0.0;
    bool later = false;
    for (std::size_t robot = 0; robot < plan.paths.size(); ++robot) {
        const bool inTheField = robot < fieldTimes.size() && fieldTimes[robot].seconds > 0.0;
        later = later || inTheField;
        last = std::max(last, inTheField ? fieldTimes[robot].seconds : plan.paths[robot].timeSeconds);
    }
    // A second's difference is no news: the title then gives the makespan alone.
    return later && last > plan.metrics.makespanSeconds + 1.0 ? last : 0.0;
}

// As batch mode's summary words it: where flights make the robots later than their paths, the last one
// home comes first and the paths' makespan second.
QString titleOf(const Plan& plan, const std::vector<FieldTime>& fieldTimes) {
    const std::size_t robots = plan.paths.size();
    const QString makespan = QStringLiteral("makespan %1 (%2 × the lower bound)")
                                 .arg(QString::fromStdString(formatDuration(plan.metrics.makespanSeconds)))
                                 .arg(plan.metrics.ratio, 0, 'f', 3);
    const double lastHome = lastHomeSeconds(plan, fieldTimes);
    return QStringLiteral("Coverage plan: %1, %2 %3, %4")
        .arg(QString::fromStdString(plan.planner))
        .arg(robots)
        .arg(robots == 1 ? QStringLiteral("robot") : QStringLiteral("robots"))
        .arg(lastHome > 0.0 ? QStringLiteral("the last home after %1; the paths' %2")
                                  .arg(QString::fromStdString(formatDuration(lastHome)), makespan)
                            : makespan);
}

} // namespace

QSize PlanSheet::fittedMapSize(const ClassGrid& grid, QSize maxSize) {
    const double width = std::max(grid.width(), 1e-9);
    const double height = std::max(grid.height(), 1e-9);
    const double scale = std::min(maxSize.width() / width, maxSize.height() / height);
    return {std::max(1, static_cast<int>(std::lround(width * scale))),
            std::max(1, static_cast<int>(std::lround(height * scale)))};
}

void PlanSheet::prepareFonts() {
    QFont bold;
    bold.setBold(true);
    // Measuring a text resolves its font: the font database (fontconfig's files and caches) is loaded once
    // for the process; the font engine made here is this thread's and goes with it.
    static_cast<void>(QFontMetricsF(bold).horizontalAdvance(QStringLiteral("Coverage plan")));
}

PlanSheet::PlanSheet(const ClassGrid& grid, const ClassTable& classes, const Plan& plan, SheetExtras extras,
                     QSize maxMapSize)
    : grid_(grid), classes_(classes), plan_(plan), extras_(std::move(extras)),
      crossings_(impassableCrossings(plan.cells, plan.regions, grid, classes)),
      sections_(planLegend(classes, &plan, extras_.robotNames, &grid, &crossings_)),
      title_(titleOf(plan, extras_.fieldTimes)), rings_(flightReachRings(plan, extras_.flightReach)),
      frame_(planFrame(grid, {&plan}, rings_)) {
    // Only rings that show in the frame are explained (one round a far take-off may lie wholly outside).
    if (someRingShows(frame_, rings_))
        addFlightReach(sections_, extras_.flightReach);
    if (extras_.area != nullptr)
        addAreaOutline(sections_, *extras_.area);
    addFieldTimes(sections_, extras_.fieldTimes);
    const QSize mapSize = fittedMapSize(frame_, maxMapSize);
    // Text keeps its size against the map: readable on a 1600-pixel sheet, not huge on a small one.
    const int textPixels = std::clamp(std::max(maxMapSize.width(), maxMapSize.height()) / 110, 10, 18);
    font_.setPixelSize(textPixels);
    titleFont_.setPixelSize(textPixels + 4);
    titleFont_.setBold(true);
    const int margin = textPixels + 4;
    const int titleHeight = static_cast<int>(std::ceil(QFontMetricsF(titleFont_).height())) + margin / 2;
    const QSizeF legend = legendSize(sections_, font_);
    map_ = QRect(QPoint(margin, margin + titleHeight), mapSize);
    legend_ = QRectF(QPointF(map_.right() + 1 + margin, map_.top()), legend);
    const int width = std::max(
        static_cast<int>(std::ceil(legend_.right())) + margin,
        static_cast<int>(std::ceil(QFontMetricsF(titleFont_).horizontalAdvance(title_))) + 2 * margin);
    const int height =
        static_cast<int>(std::ceil(std::max<double>(map_.bottom() + 1, legend_.bottom()))) + margin;
    size_ = QSize(width, height);
}

void PlanSheet::paint(QPainter& painter) const {
    painter.fillRect(QRect(QPoint(0, 0), size_), Qt::white);
    painter.setFont(titleFont_);
    painter.setPen(QColor(20, 20, 20));
    painter.drawText(QRectF(map_.left(), 0, size_.width() - map_.left(), map_.top()),
                     Qt::AlignLeft | Qt::AlignVCenter, title_);

    PlanRenderer renderer;
    renderer.setMap(&grid_, &classes_);
    renderer.setPlan(&plan_, extras_.outlines, &crossings_);
    renderer.setFlightReach(extras_.flightReach);
    if (extras_.area != nullptr)
        renderer.setArea(*extras_.area);
    painter.save();
    painter.setClipRect(map_);
    // The renderer draws in device coordinates: the map's placement goes into its transform.
    const QTransform worldToSheet = PlanRenderer::fitTransform(frame_, QSizeF(map_.size())) *
                                    QTransform::fromTranslate(map_.left(), map_.top());
    renderer.paint(painter, worldToSheet, QRectF(map_));
    painter.restore();
    painter.setPen(QPen(QColor(90, 90, 90), 1.0));
    painter.setBrush(Qt::NoBrush);
    painter.drawRect(QRectF(map_).adjusted(-0.5, -0.5, 0.5, 0.5));

    painter.setFont(font_);
    const double pixelsPerMetre = map_.width() / std::max(frame_.width(), 1e-9);
    paintScaleBar(painter, QPointF(map_.left() + 8, map_.bottom() - 8), pixelsPerMetre, map_.width() / 5.0);
    paintNorthArrow(painter, QPointF(map_.right() - 20, map_.top() + 10), grid_.trueNorthRadians);
    paintLegend(painter, legend_.topLeft(), sections_);
}

} // namespace mcpp::render
