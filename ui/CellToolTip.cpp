#include "ui/CellToolTip.hpp"

#include "core/model/HumanUnits.hpp"
#include "ui/MissionDocument.hpp"

#include <QCoreApplication>
#include <algorithm>
#include <cmath>
#include <map>

namespace mcpp::ui {

namespace {

QString tr(const char* text) {
    return QCoreApplication::translate("CellToolTip", text);
}

QString percent(double fraction) {
    return QString::fromStdString(formatPercent(fraction));
}

QString className(const ClassTable& classes, std::int32_t value) {
    const LandCoverClass* found = classes.find(value);
    return found != nullptr ? QString::fromStdString(found->name) : tr("class %1").arg(value);
}

// Pixels of impassable classes whose centres lie in the cell, by class.
std::map<std::int32_t, std::int64_t> impassablePixels(const ClassGrid& grid, const ClassTable& classes,
                                                      const Cell& cell) {
    std::map<std::int32_t, std::int64_t> counts;
    const int firstColumn =
        std::max(0, static_cast<int>(std::floor((cell.minX - grid.originX) / grid.pixelWidth)));
    const int lastColumn = std::min(
        grid.columns - 1, static_cast<int>(std::floor((cell.maxX() - grid.originX) / grid.pixelWidth)));
    const int firstRow =
        std::max(0, static_cast<int>(std::floor((grid.originY - cell.maxY()) / grid.pixelHeight)));
    const int lastRow =
        std::min(grid.rows - 1, static_cast<int>(std::floor((grid.originY - cell.minY) / grid.pixelHeight)));
    for (int row = firstRow; row <= lastRow; ++row) {
        const double y = grid.originY - (row + 0.5) * grid.pixelHeight;
        if (y < cell.minY || y >= cell.maxY())
            continue;
        for (int column = firstColumn; column <= lastColumn; ++column) {
            const double x = grid.originX + (column + 0.5) * grid.pixelWidth;
            if (x < cell.minX || x >= cell.maxX() || grid.isOutside(column, row))
                continue;
            const std::int32_t value = grid.valueAt(column, row);
            const LandCoverClass* found = classes.find(value);
            if (found == nullptr || !found->isTraversable())
                ++counts[value];
        }
    }
    return counts;
}

QString crossingSentence(const MissionDocument& document, const Plan& plan, const Cell& cell) {
    QStringList parts;
    if (const ClassGrid* grid = document.grid()) {
        const auto counts = impassablePixels(*grid, document.classes(), cell);
        // Most of it first.
        std::vector<std::pair<std::int64_t, std::int32_t>> byCount;
        for (const auto& [value, count] : counts)
            byCount.emplace_back(count, value);
        std::sort(byCount.rbegin(), byCount.rend());
        for (const auto& entry : byCount)
            parts << className(document.classes(), entry.second);
    }
    const ParameterValue* threshold = plan.parameters.find("blocked_threshold");
    QString why = tr("cells are covered while obstacles take up to the blocked threshold");
    if (threshold != nullptr && std::holds_alternative<double>(*threshold))
        why = tr("cells are covered while obstacles take up to %1 of them (Blocked threshold)")
                  .arg(percent(std::get<double>(*threshold)));
    const QString classes =
        parts.isEmpty() ? QString() : QStringLiteral(" (%1)").arg(parts.join(QStringLiteral(", ")));
    return tr("%1 of this cell is impassable%2: the path crosses it because %3.")
        .arg(percent(cell.impassableFraction()), classes, why);
}

} // namespace

QString cellToolTip(const MissionDocument& document, MapPoint point) {
    const Plan* plan = document.plan();
    if (plan == nullptr)
        return {};
    const int id = plan->cells.cellAt(point);
    if (id < 0)
        return {};
    const Cell& cell = plan->cells.cell(id);
    const auto index = static_cast<std::size_t>(id);
    const int robot = index < plan->regions.robotOfCell.size() ? plan->regions.robotOfCell[index] : -1;
    QString who = tr("No robot reaches this cell.");
    if (robot >= 0) {
        const auto& robots = document.robots();
        const QString name = static_cast<std::size_t>(robot) < robots.size() && !robots[robot].name.empty()
                                 ? QString::fromStdString(robots[static_cast<std::size_t>(robot)].name)
                                 : tr("Robot %1").arg(robot + 1);
        who = tr("Covered by %1 (robot %2).").arg(name, QString::number(robot + 1));
    }
    QString text =
        who + QStringLiteral("\n") +
        tr("Cell of %1 (level %2): %3, %4.")
            .arg(QString::fromStdString(formatDistance(cell.size)))
            .arg(cell.level)
            .arg(className(document.classes(), cell.classValue),
                 tr("%1 m/s").arg(QString::fromStdString(formatQuantity(cell.speedMetresPerSecond, 3))));
    if (robot >= 0 && cell.crossesImpassableLand())
        text += QStringLiteral("\n") + crossingSentence(document, *plan, cell);
    if (document.planStale())
        text += QStringLiteral("\n") + tr("The plan is out of date.");
    return text;
}

} // namespace mcpp::ui
