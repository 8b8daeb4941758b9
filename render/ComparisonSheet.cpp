#include "render/ComparisonSheet.hpp"

#include "core/model/HumanUnits.hpp"
#include "io/AtomicFile.hpp"
#include "io/ComparisonRanking.hpp"
#include "render/PlanFrame.hpp"
#include "render/PlanImage.hpp"
#include "render/PngEncoder.hpp"
#include "render/RobotPalette.hpp"

#include <QPainter>
#include <algorithm>
#include <cmath>

namespace mcpp::render {

namespace {

constexpr int tileSide = 520;
constexpr int margin = 24;
constexpr int titleHeight = 28;
constexpr int leastCaptionHeight = 86; // a title and three lines of figures
constexpr int chartHeight = 300;
constexpr int captionPixels = 13;
constexpr int unplannedLineHeight = 20;

QFont fontOf(const QFont& base, int pixels, bool bold) {
    QFont font = base;
    font.setPixelSize(pixels);
    font.setBold(bold);
    return font;
}

// The height under each map: its title and the longest caption as wrapped to the map's width.
int captionHeightOf(const QFont& base, const std::vector<const ComparisonPanel*>& panels) {
    const QFontMetrics metrics(fontOf(base, captionPixels, false));
    int height = leastCaptionHeight;
    for (const ComparisonPanel* panel : panels)
        height = std::max(height, titleHeight + 4 +
                                      metrics
                                          .boundingRect(QRect(0, 0, tileSide, 100000),
                                                        Qt::AlignLeft | Qt::AlignTop | Qt::TextWordWrap,
                                                        panel->caption.join('\n'))
                                          .height());
    return height;
}

int columnsFor(std::size_t panels) {
    return static_cast<int>(std::clamp<std::size_t>(panels, 1, 3));
}

void drawPanel(QPainter& painter, const ClassGrid& grid, const ClassGrid& frame, const ClassTable& classes,
               const ComparisonPanel& panel, QRect area, const AreaOutline* taskArea, int captionHeight) {
    const QRect mapArea(area.left(), area.top(), area.width(), tileSide);
    const QImage map =
        renderPlanImage(grid, classes, panel.plan, mapArea.size(), {}, nullptr, &frame, taskArea);
    painter.drawImage(mapArea.left() + (mapArea.width() - map.width()) / 2,
                      mapArea.top() + (mapArea.height() - map.height()) / 2, map);
    painter.setPen(QColor(120, 120, 120));
    painter.drawRect(mapArea.adjusted(0, 0, -1, -1));
    painter.setFont(fontOf(painter.font(), 16, true));
    painter.setPen(Qt::black);
    const QRect titleBox(area.left(), mapArea.bottom() + 6, area.width(), 22);
    painter.drawText(titleBox, Qt::AlignLeft | Qt::AlignVCenter, panel.title);
    painter.setFont(fontOf(painter.font(), captionPixels, false));
    const QRect captionBox(area.left(), titleBox.bottom() + 2, area.width(), captionHeight - titleHeight);
    painter.drawText(captionBox, Qt::AlignLeft | Qt::AlignTop | Qt::TextWordWrap, panel.caption.join('\n'));
}

// A line for each planner without a plan (skipped, failed): its name and why, cut to the sheet's width.
void drawUnplanned(QPainter& painter, const std::vector<const ComparisonPanel*>& panels, QRect area) {
    painter.setPen(Qt::black);
    for (std::size_t i = 0; i < panels.size(); ++i) {
        const QRect line(area.left(), area.top() + static_cast<int>(i) * unplannedLineHeight, area.width(),
                         unplannedLineHeight);
        painter.setFont(fontOf(painter.font(), captionPixels, true));
        const QString name = panels[i]->title + QStringLiteral(": ");
        painter.drawText(line, Qt::AlignLeft | Qt::AlignVCenter, name);
        const int nameWidth = QFontMetrics(painter.font()).horizontalAdvance(name);
        painter.setFont(fontOf(painter.font(), captionPixels, false));
        const QRect why = line.adjusted(nameWidth, 0, 0, 0);
        painter.drawText(
            why, Qt::AlignLeft | Qt::AlignVCenter,
            QFontMetrics(painter.font())
                .elidedText(panels[i]->caption.join(QStringLiteral("; ")), Qt::ElideRight, why.width()));
    }
}

// The least of 1, 2, 2.5 and 5 times a power of ten that is at least the given step: ticks a reader adds up.
double roundTickStep(double step) {
    const double power = std::pow(10.0, std::floor(std::log10(step)));
    for (const double multiple : {1.0, 2.0, 2.5, 5.0})
        if (multiple * power >= step * (1.0 - 1e-9))
            return multiple * power;
    return 10.0 * power;
}

// A tick's label: whole numbers as they are (not 4e+04), fractions to three significant digits.
QString tickLabel(double value) {
    return value >= 10.0 || value == std::floor(value) ? QString::number(value, 'f', 0)
                                                       : QString::number(value, 'g', 3);
}

// A robot's bar: when it is done in the field where its plan says so, else its path's time.
double barSeconds(const PlanMetrics& metrics, const RobotMetrics& robot) {
    return metrics.timedInTheField() && robot.fieldSeconds > 0.0 ? robot.fieldSeconds : robot.timeSeconds;
}

// Groups of bars, one group per planner and one bar per robot in its colour, heights in hours (in days where
// the longest robot takes over ten days); times in the field where a plan has them, as the table ranks by.
void drawChart(QPainter& painter, const std::vector<const ComparisonPanel*>& panels, QRect area) {
    double longest = 0.0;
    bool inTheField = false;
    for (const ComparisonPanel* panel : panels) {
        inTheField = inTheField || panel->plan->metrics.timedInTheField();
        for (const RobotMetrics& robot : panel->plan->metrics.robots)
            longest = std::max(longest, barSeconds(panel->plan->metrics, robot));
    }
    const bool inDays = longest > 10.0 * 86400.0;
    const double unitSeconds = inDays ? 86400.0 : 3600.0;
    const QString what =
        inTheField ? QStringLiteral("Time in the field per robot") : QStringLiteral("Time per robot");
    QFont font = painter.font();
    font.setPixelSize(13);
    font.setBold(true);
    painter.setFont(font);
    painter.setPen(Qt::black);
    painter.drawText(QRect(area.left(), area.top(), area.width(), 20), Qt::AlignHCenter,
                     what + (inDays ? QStringLiteral(" (days)") : QStringLiteral(" (hours)")));
    font.setBold(false);
    painter.setFont(font);
    if (longest <= 0.0)
        return;
    const QRect plot = area.adjusted(60, 30, -10, -30);
    // Four to five ticks whose top is the longest bar rounded up to the next tick.
    const double longestInUnits = longest / unitSeconds;
    const double tickStep = roundTickStep(longestInUnits / 5.0);
    const int ticks = std::max(1, static_cast<int>(std::ceil(longestInUnits / tickStep - 1e-9)));
    const double top = tickStep * ticks;
    painter.setPen(QColor(200, 200, 200));
    for (int tick = 0; tick <= ticks; ++tick) {
        const int y = plot.bottom() - static_cast<int>(plot.height() * tick / static_cast<double>(ticks));
        painter.drawLine(plot.left(), y, plot.right(), y);
        painter.setPen(Qt::black);
        painter.drawText(QRect(area.left(), y - 9, 55, 18), Qt::AlignRight | Qt::AlignVCenter,
                         tickLabel(tickStep * tick));
        painter.setPen(QColor(200, 200, 200));
    }
    const double groupWidth = static_cast<double>(plot.width()) / static_cast<double>(panels.size());
    for (std::size_t i = 0; i < panels.size(); ++i) {
        const double left = plot.left() + groupWidth * static_cast<double>(i);
        painter.setPen(Qt::black);
        const QString label = panels[i]->label.isEmpty() ? panels[i]->title : panels[i]->label;
        painter.drawText(
            QRectF(left, plot.bottom() + 4, groupWidth, 20), Qt::AlignHCenter,
            QFontMetrics(painter.font()).elidedText(label, Qt::ElideRight, static_cast<int>(groupWidth) - 4));
        const auto& robots = panels[i]->plan->metrics.robots;
        const double barWidth = groupWidth * 0.8 / std::max<std::size_t>(robots.size(), 1);
        for (std::size_t r = 0; r < robots.size(); ++r) {
            const double seconds = barSeconds(panels[i]->plan->metrics, robots[r]);
            const double height = plot.height() * (seconds / unitSeconds) / top;
            painter.fillRect(QRectF(left + groupWidth * 0.1 + barWidth * static_cast<double>(r),
                                    plot.bottom() - height, barWidth * 0.9, height),
                             RobotPalette::colour(robots[r].robot));
        }
    }
}

} // namespace

ComparisonPanel comparisonPanelOf(const io::ComparisonRow& row, const Plan* plan, const QString& timed) {
    ComparisonPanel panel;
    panel.title = QString::fromStdString(row.planner);
    panel.plan = plan;
    if (row.outcome != io::ComparisonRow::Outcome::Planned) {
        panel.caption << QString::fromStdString(io::outcomeName(row.outcome) + ": " + row.message);
        return panel;
    }
    // Where flights split the missions, plans are ranked and timed against the first by when the last robot
    // is home: the time beside the comparison is that one.
    if (row.metrics.timedInTheField())
        panel.caption << QStringLiteral("last robot home after %1%2, the last %3 x the first")
                             .arg(QString::fromStdString(formatDuration(row.metrics.fieldMakespanSeconds)),
                                  timed)
                             .arg(row.metrics.fieldSpread(), 0, 'f', 3);
    panel.caption << (row.metrics.timedInTheField()
                          ? QStringLiteral("paths' makespan %1%2, %3 x its own lower bound")
                          : QStringLiteral("makespan %1%2, %3 x its own lower bound"))
                         .arg(QString::fromStdString(formatDuration(row.metrics.makespanSeconds)),
                              row.metrics.timedInTheField() ? QString() : timed)
                         .arg(row.metrics.ratio, 0, 'f', 3)
                  << QStringLiteral("%1 turns, covered %2 %, planned in %3 s")
                         .arg(row.metrics.totalTurns())
                         .arg(row.metrics.coveredFraction * 100.0, 0, 'f', 1)
                         .arg(row.planningMilliseconds / 1000.0, 0, 'f', 2);
    return panel;
}

std::vector<ComparisonPanel> rankedComparisonPanels(const std::vector<io::ComparisonRow>& rows,
                                                    const std::vector<const Plan*>& plans) {
    const std::vector<int> ranks = io::ranksOf(rows);
    const std::vector<double> againstFirst = io::timesTheFirst(rows);
    const std::vector<std::size_t> order = io::rankedRows(rows);
    std::vector<ComparisonPanel> panels;
    for (const std::size_t index : order) {
        // The figure that compares plans, beside the makespan; each ratio is to the plan's own bound.
        const QString timed = ranks[index] > 1 && againstFirst[index] > 0.0
                                  ? QStringLiteral(" (%1 x %2's)")
                                        .arg(againstFirst[index], 0, 'f', 2)
                                        .arg(QString::fromStdString(rows[order.front()].planner))
                                  : QString();
        ComparisonPanel panel = comparisonPanelOf(rows[index], plans[index], timed);
        if (ranks[index] > 0) {
            panel.label = QStringLiteral("%1. %2").arg(ranks[index]).arg(panel.title);
            const std::string apart = io::rankedApartReason(io::readingGroup(rows[index], rows));
            // Why a plan reading sooner done is ranked after the first, on its title where the captions
            // have no line to spare.
            panel.title = panel.label +
                          (apart.empty() ? QString() : QStringLiteral(": ") + QString::fromStdString(apart));
        }

        panels.push_back(std::move(panel));
    }
    return panels;
}

QImage renderComparisonSheet(const ClassGrid& grid, const ClassTable& classes,
                             const std::vector<ComparisonPanel>& panels, const AreaOutline* area,
                             int mostColumns) {
    std::vector<const ComparisonPanel*> mapped;
    std::vector<const ComparisonPanel*> unplanned;
    for (const ComparisonPanel& panel : panels)
        (panel.plan != nullptr ? mapped : unplanned).push_back(&panel);
    const int columns = std::min(columnsFor(mapped.size()), std::max(mostColumns, 1));
    const int rows = static_cast<int>((mapped.size() + static_cast<std::size_t>(columns) - 1) /
                                      static_cast<std::size_t>(columns));
    const int captionHeight = captionHeightOf(QFont(), mapped);
    const int width = margin + columns * (tileSide + margin);
    const int unplannedHeight =
        unplanned.empty() ? 0 : static_cast<int>(unplanned.size()) * unplannedLineHeight + margin;
    const int chart = mapped.empty() ? 0 : chartHeight + margin;
    const int height = margin + rows * (tileSide + captionHeight + margin) + unplannedHeight + chart;
    QImage sheet(width, std::max(height, 2 * margin), QImage::Format_RGB32);
    sheet.fill(Qt::white);
    QPainter painter(&sheet);
    painter.setRenderHint(QPainter::Antialiasing, true);
    // Every panel shows the same part of the raster, at the same scale.
    std::vector<const Plan*> plans;
    for (const ComparisonPanel* panel : mapped)
        plans.push_back(panel->plan);
    const ClassGrid frame = planFrame(grid, plans);
    for (std::size_t i = 0; i < mapped.size(); ++i) {
        const int column = static_cast<int>(i) % columns;
        const int row = static_cast<int>(i) / columns;
        const QRect tile(margin + column * (tileSide + margin),
                         margin + row * (tileSide + captionHeight + margin), tileSide,
                         tileSide + captionHeight);
        drawPanel(painter, grid, frame, classes, *mapped[i], tile, area, captionHeight);
    }
    const int belowTiles = margin + rows * (tileSide + captionHeight + margin);
    drawUnplanned(painter, unplanned, QRect(margin, belowTiles, width - 2 * margin, unplannedHeight));
    if (!mapped.empty())
        drawChart(painter, mapped,
                  QRect(margin, belowTiles + unplannedHeight, width - 2 * margin, chartHeight));
    painter.end();
    return sheet;
}

bool writeComparisonSheet(const ClassGrid& grid, const ClassTable& classes,
                          const std::vector<ComparisonPanel>& panels, const QString& path, QString* error,
                          const AreaOutline* area) {
    const QByteArray encoded = encodePng(renderComparisonSheet(grid, classes, panels, area));
    const io::Status written =
        !encoded.isEmpty()
            ? io::writeFileAtomically(
                  path.toStdString(),
                  std::string_view(encoded.constData(), static_cast<std::size_t>(encoded.size())),
                  io::Sync::BySystem)
            : io::Status::failure(path.toStdString() + ": PNG encoding failed");
    if (!written && error != nullptr)
        *error = QString::fromStdString(written.error());
    return written.ok();
}

} // namespace mcpp::render
