#include "render/PlanLegend.hpp"

#include "core/coverage/ImpassableCrossings.hpp"
#include "core/model/DetectionLayer.hpp"
#include "core/model/HumanUnits.hpp"
#include "core/model/SortieLayer.hpp"
#include "core/model/TimelineLayer.hpp"
#include "core/planners/UncoveredLand.hpp"
#include "render/DetectionPalette.hpp"
#include "render/RobotPalette.hpp"

#include <QFontMetricsF>
#include <algorithm>

namespace mcpp::render {

namespace {

constexpr double kSymbolWidth = 22.0;
constexpr double kGap = 6.0;

// Land no robot covers; on batteries, how much of it lies beyond their reach rather than cut off.
QString unreachableText(const Plan& plan) {
    const double area = plan.metrics.unreachableAreaSquareMetres;
    const double beyond = sortieLayerOf(plan) != nullptr ? uncoveredLand(plan).leftOutSquareMetres : 0.0;
    if (beyond > 0.0)
        return QStringLiteral("Not covered: %1, %2 of it beyond the batteries' reach")
            .arg(QString::fromStdString(formatArea(area)), QString::fromStdString(formatArea(beyond)));
    return QStringLiteral("Unreachable: %1").arg(QString::fromStdString(formatArea(area)));
}
constexpr double kSectionGap = 8.0;

QColor colourOf(std::uint32_t rgb) {
    return QColor::fromRgb(static_cast<int>(rgb >> 16U & 0xffU), static_cast<int>(rgb >> 8U & 0xffU),
                           static_cast<int>(rgb & 0xffU));
}

QString robotLabel(const Plan& plan, std::size_t robot, const std::vector<std::string>& names) {
    QString label = robot < names.size() && !names[robot].empty() ? QString::fromStdString(names[robot])
                                                                  : QStringLiteral("Robot %1").arg(robot + 1);
    if (robot < plan.metrics.robots.size())
        label += QStringLiteral(" — %1").arg(
            QString::fromStdString(formatDuration(plan.metrics.robots[robot].timeSeconds)));
    return label;
}

double lineHeight(const QFontMetricsF& metrics) {
    return std::max(metrics.height(), 14.0) + 3.0;
}

void paintSymbol(QPainter& painter, const LegendItem& item, const QRectF& box) {
    const QRectF swatch = box.adjusted(2.0, 2.0, -2.0, -2.0);
    switch (item.symbol) {
    case LegendSymbol::Swatch:
    case LegendSymbol::Obstacle:
        painter.setPen(QPen(QColor(60, 60, 60), 0.8));
        painter.setBrush(item.colour);
        painter.drawRect(swatch);
        if (item.symbol == LegendSymbol::Obstacle) {
            painter.setPen(QPen(QColor(30, 30, 30), 1.2));
            painter.drawLine(swatch.topLeft(), swatch.bottomRight());
        }
        break;
    case LegendSymbol::RegionTint: {
        QColor tint = item.colour;
        tint.setAlpha(90);
        painter.setPen(QPen(item.colour, 1.5));
        painter.setBrush(tint);
        painter.drawRect(swatch);
        break;
    }
    case LegendSymbol::PathLine:
        painter.setPen(QPen(QColor(255, 255, 255, 190), 4.0, Qt::SolidLine, Qt::RoundCap));
        painter.drawLine(QPointF(swatch.left(), swatch.center().y()),
                         QPointF(swatch.right(), swatch.center().y()));
        painter.setPen(QPen(item.colour, 2.0, Qt::SolidLine, Qt::RoundCap));
        painter.drawLine(QPointF(swatch.left(), swatch.center().y()),
                         QPointF(swatch.right(), swatch.center().y()));
        break;
    case LegendSymbol::StartMarker: {
        const double radius = std::min(swatch.width(), swatch.height()) / 2.0;
        painter.setPen(QPen(QColor(20, 20, 20), 1.2));
        painter.setBrush(item.colour);
        painter.drawEllipse(swatch.center(), radius, radius);
        if (!item.marker.isEmpty()) {
            QFont font = painter.font();
            font.setBold(true);
            font.setPixelSize(std::max(7, static_cast<int>(radius * 1.3)));
            painter.save();
            painter.setFont(font);
            painter.setPen(Qt::white);
            painter.drawText(
                QRectF(swatch.center().x() - radius, swatch.center().y() - radius, 2 * radius, 2 * radius),
                Qt::AlignCenter, item.marker);
            painter.restore();
        }
        break;
    }
    case LegendSymbol::Unreachable:
        painter.setPen(QPen(QColor(140, 0, 0), 0.8));
        painter.setBrush(QBrush(QColor(140, 0, 0, 220), Qt::BDiagPattern));
        painter.drawRect(swatch);
        break;
    case LegendSymbol::TakenOver:
        painter.setPen(QPen(item.colour.darker(140), 0.8));
        painter.setBrush(QBrush(item.colour.darker(140), Qt::FDiagPattern));
        painter.drawRect(swatch);
        break;
    case LegendSymbol::Crossing:
        painter.setPen(QPen(RobotPalette::crossingColour(), 1.0, Qt::DashLine));
        painter.setBrush(Qt::NoBrush);
        painter.drawRect(swatch.adjusted(1.0, 1.0, -1.0, -1.0));
        break;
    case LegendSymbol::FlightReach:
        painter.setPen(QPen(item.colour, 1.5, Qt::DashLine));
        painter.setBrush(Qt::NoBrush);
        painter.drawEllipse(swatch);
        break;
    case LegendSymbol::AreaEdge:
    case LegendSymbol::NoGoZone: {
        const bool noGo = item.symbol == LegendSymbol::NoGoZone;
        const QRectF zone = swatch.adjusted(1.5, 1.5, -1.5, -1.5);
        painter.setPen(QPen(QColor(255, 255, 255, 220), 3.0));
        painter.setBrush(noGo ? QBrush(item.colour, Qt::DiagCrossPattern) : QBrush(Qt::NoBrush));
        painter.drawRect(zone);
        QPen dashes(item.colour, 1.5, Qt::CustomDashLine, Qt::FlatCap, Qt::MiterJoin);
        dashes.setDashPattern({4.0, 2.5});
        painter.setPen(dashes);
        painter.setBrush(Qt::NoBrush);
        painter.drawRect(zone);
        break;
    }
    case LegendSymbol::CellOutline:
        painter.setPen(QPen(item.colour, 1.0));
        painter.setBrush(Qt::NoBrush);
        painter.drawRect(swatch);
        painter.drawLine(QPointF(swatch.center().x(), swatch.top()),
                         QPointF(swatch.center().x(), swatch.bottom()));
        painter.drawLine(QPointF(swatch.left(), swatch.center().y()),
                         QPointF(swatch.right(), swatch.center().y()));
        break;
    }
}

} // namespace

std::vector<LegendSection> planLegend(const ClassTable& classes, const Plan* plan,
                                      const std::vector<std::string>& robotNames, const ClassGrid* grid,
                                      const std::vector<ImpassableCrossing>* crossings) {
    std::vector<LegendSection> sections;
    LegendSection landCover{LegendSectionKind::LandCover, QStringLiteral("Land cover"), {}};
    for (const LandCoverClass& entry : classes.classes()) {
        const bool wall = !entry.isTraversable();
        landCover.items.push_back(
            {wall ? LegendSymbol::Obstacle : LegendSymbol::Swatch,
             colourOf(entry.colorRgb),
             QString::fromStdString(entry.name) + (wall ? QStringLiteral(" (obstacle)") : QString()),
             {}});
    }
    sections.push_back(std::move(landCover));
    if (plan != nullptr && !plan->paths.empty()) {
        const bool onBatteries = sortieLayerOf(*plan) != nullptr;
        LegendSection robots{LegendSectionKind::Robots,
                             onBatteries ? QStringLiteral("Robots (start and charger, region, path)")
                                         : QStringLiteral("Robots (start, region, path)"),
                             {}};
        for (std::size_t robot = 0; robot < plan->paths.size(); ++robot)
            robots.items.push_back({LegendSymbol::StartMarker, RobotPalette::colour(static_cast<int>(robot)),
                                    robotLabel(*plan, robot, robotNames), QString::number(robot + 1)});
        sections.push_back(std::move(robots));
        LegendSection overlays{LegendSectionKind::OnTheMap, QStringLiteral("On the map"), {}};
        const QColor first = RobotPalette::colour(0);
        if (const DetectionLayer* detection = detectionLayerOf(*plan)) {
            const QString required = QString::number(detection->summary().requiredProbability, 'g', 3);
            overlays.items.push_back({LegendSymbol::Swatch,
                                      DetectionPalette::certain(),
                                      QStringLiteral("Targets seen for certain"),
                                      {}});
            overlays.items.push_back({LegendSymbol::Swatch,
                                      DetectionPalette::met(),
                                      QStringLiteral("Targets seen with %1 or more").arg(required),
                                      {}});
            overlays.items.push_back({LegendSymbol::Swatch,
                                      DetectionPalette::halfway(),
                                      QStringLiteral("Seen half as likely as required"),
                                      {}});
            overlays.items.push_back(
                {LegendSymbol::Swatch, DetectionPalette::unseen(), QStringLiteral("Not seen"), {}});
            if (detection->summary().undetectableAreaSquareMetres > 0.0)
                overlays.items.push_back({LegendSymbol::Swatch,
                                          DetectionPalette::hidden(),
                                          QStringLiteral("Land cover that hides targets"),
                                          {}});
        } else {
            overlays.items.push_back(
                {LegendSymbol::RegionTint, first, QStringLiteral("Region a robot covers"), {}});
        }
        overlays.items.push_back({LegendSymbol::PathLine, first, QStringLiteral("Its path"), {}});
        if (onBatteries)
            overlays.items.push_back({LegendSymbol::PathLine,
                                      RobotPalette::alternateSortieColour(0),
                                      QStringLiteral("Every second sortie, darker"),
                                      {}});
        overlays.items.push_back({LegendSymbol::CellOutline,
                                  RobotPalette::levelColour(1, 2),
                                  QStringLiteral("Cells (smaller where the view is shorter)"),
                                  {}});
        if (plan->metrics.unreachableAreaSquareMetres > 0.0)
            overlays.items.push_back({LegendSymbol::Unreachable, {}, unreachableText(*plan), {}});
        if (const TimelineLayer* timeline = timelineLayerOf(*plan);
            timeline != nullptr &&
            std::any_of(timeline->robots().begin(), timeline->robots().end(),
                        [](const RobotTimeline& robot) { return !robot.cellsTakenOver.empty(); }))
            overlays.items.push_back({LegendSymbol::TakenOver,
                                      first,
                                      QStringLiteral("Cells it took over from another robot"),
                                      {}});
        const bool crossed =
            crossings != nullptr
                ? !crossings->empty()
                : grid != nullptr &&
                      !impassableCrossings(plan->cells, plan->regions, *grid, classes, 1).empty();
        if (crossed)
            overlays.items.push_back(
                {LegendSymbol::Crossing,
                 {},
                 QStringLiteral("Path crosses some impassable land (within the blocked threshold)"),
                 {}});
        sections.push_back(std::move(overlays));
    }
    return sections;
}

namespace {

// The legend's last section, "On the map", made when there is none yet (no plan).
LegendSection& onTheMap(std::vector<LegendSection>& sections) {
    if (sections.empty() || sections.back().kind != LegendSectionKind::OnTheMap)
        sections.push_back({LegendSectionKind::OnTheMap, QStringLiteral("On the map"), {}});
    return sections.back();
}

} // namespace

FieldTime fieldTimeBeyondPath(double pathSeconds, double fieldSeconds, std::size_t parts, bool flights) {
    if (!(fieldSeconds > pathSeconds + 1.0))
        return {};
    return {fieldSeconds, parts, flights};
}

void addFieldTimes(std::vector<LegendSection>& sections, const std::vector<FieldTime>& times) {
    const auto robots = std::find_if(sections.begin(), sections.end(), [](const LegendSection& section) {
        return section.kind == LegendSectionKind::Robots;
    });
    if (robots == sections.end())
        return;
    for (std::size_t robot = 0; robot < robots->items.size() && robot < times.size(); ++robot) {
        const FieldTime& time = times[robot];
        if (!(time.seconds > 0.0))
            continue;
        QString parts;
        if (time.parts > 1)
            parts = (time.flights ? QStringLiteral(", %1 flights") : QStringLiteral(", %1 parts"))
                        .arg(time.parts);
        robots->items[robot].label += QStringLiteral("; in the field %1%2")
                                          .arg(QString::fromStdString(formatDuration(time.seconds)), parts);
    }
}

void addFlightReach(std::vector<LegendSection>& sections, const std::vector<double>& reaches) {
    if (std::none_of(reaches.begin(), reaches.end(), [](double metres) { return metres > 0.0; }))
        return;
    onTheMap(sections).items.push_back({LegendSymbol::FlightReach,
                                        RobotPalette::colour(0).darker(130),
                                        QStringLiteral("How far one flight reaches and comes back"),
                                        {}});
}

void addAreaOutline(std::vector<LegendSection>& sections, const AreaOutline& area) {
    if (area.empty())
        return;
    LegendSection& overlays = onTheMap(sections);
    if (!area.include.empty())
        overlays.items.push_back({LegendSymbol::AreaEdge,
                                  RobotPalette::areaEdgeColour(),
                                  QStringLiteral("Edge of the area of interest"),
                                  {}});
    if (!area.exclude.empty())
        overlays.items.push_back(
            {LegendSymbol::NoGoZone, RobotPalette::noGoColour(), QStringLiteral("No-go zone"), {}});
}

QSizeF legendSize(const std::vector<LegendSection>& sections, const QFont& font) {
    QFont bold = font;
    bold.setBold(true);
    const QFontMetricsF metrics(font);
    const QFontMetricsF boldMetrics(bold);
    double width = 0.0;
    double height = 0.0;
    for (const LegendSection& section : sections) {
        width = std::max(width, boldMetrics.horizontalAdvance(section.title));
        height += lineHeight(boldMetrics);
        for (const LegendItem& item : section.items) {
            width = std::max(width, kSymbolWidth + kGap + metrics.horizontalAdvance(item.label));
            height += lineHeight(metrics);
        }
        height += kSectionGap;
    }
    return {std::ceil(width), std::ceil(std::max(0.0, height - kSectionGap))};
}

void paintLegend(QPainter& painter, QPointF topLeft, const std::vector<LegendSection>& sections) {
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, true);
    const QFont font = painter.font();
    QFont bold = font;
    bold.setBold(true);
    const QFontMetricsF metrics(font);
    const QFontMetricsF boldMetrics(bold);
    double y = topLeft.y();
    for (const LegendSection& section : sections) {
        painter.setFont(bold);
        painter.setPen(QColor(30, 30, 30));
        painter.drawText(QRectF(topLeft.x(), y, 2000.0, lineHeight(boldMetrics)),
                         Qt::AlignLeft | Qt::AlignVCenter, section.title);
        y += lineHeight(boldMetrics);
        painter.setFont(font);
        for (const LegendItem& item : section.items) {
            const double height = lineHeight(metrics);
            paintSymbol(painter, item, QRectF(topLeft.x(), y + (height - 14.0) / 2.0, kSymbolWidth, 14.0));
            painter.setPen(QColor(30, 30, 30));
            painter.drawText(QRectF(topLeft.x() + kSymbolWidth + kGap, y, 2000.0, height),
                             Qt::AlignLeft | Qt::AlignVCenter, item.label);
            y += height;
        }
        y += kSectionGap;
    }
    painter.restore();
}

} // namespace mcpp::render
