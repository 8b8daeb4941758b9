#include "ui/CellToolTip.hpp"

#include "core/coverage/ImpassableCrossings.hpp"
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

// Empty where the cell's free sub-cells hold no impassable pixel.
QString crossingSentence(const MissionDocument& document, const Plan& plan, const Cell& cell) {
    const ClassGrid* grid = document.grid();
    if (grid == nullptr)
        return {};
    std::int64_t pixels = 0;
    const auto counts = impassableClassesIn(cell, *grid, document.classes(), pixels);
    std::int64_t impassable = 0;
    std::vector<std::pair<std::int64_t, std::int32_t>> byCount; // most of it first
    for (const auto& [value, count] : counts) {
        byCount.emplace_back(count, value);
        impassable += count;
    }
    if (impassable == 0 || pixels == 0)
        return {};
    std::sort(byCount.rbegin(), byCount.rend());
    QStringList parts;
    for (const auto& entry : byCount)
        parts << (entry.second == outsideTaskArea ? tr("outside the task area")
                                                  : className(document.classes(), entry.second));
    const ParameterValue* threshold = plan.parameters.find("blocked_threshold");
    QString why = tr("cells are covered while obstacles take up to the blocked threshold");
    if (threshold != nullptr && std::holds_alternative<double>(*threshold))
        why = tr("cells are covered while obstacles take up to %1 of them (Blocked threshold)")
                  .arg(percent(std::get<double>(*threshold)));
    return tr("%1 of this cell is impassable (%2): the path crosses it because %3.")
        .arg(percent(static_cast<double>(impassable) / static_cast<double>(pixels)),
             parts.join(QStringLiteral(", ")), why);
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
        // A robot named by its number needs it only once (default names are stored untranslated).
        who = name.compare(QStringLiteral("Robot %1").arg(robot + 1), Qt::CaseInsensitive) == 0
                  ? tr("Covered by %1.").arg(name)
                  : tr("Covered by %1 (robot %2).").arg(name, QString::number(robot + 1));
    }
    QString text =
        who + QStringLiteral("\n") +
        tr("Cell of %1 (level %2): %3, %4.")
            .arg(QString::fromStdString(formatDistance(cell.size)))
            .arg(int{cell.level})
            .arg(className(document.classes(), cell.classValue),
                 tr("%1 m/s").arg(QString::fromStdString(formatQuantity(cell.speedMetresPerSecond, 3))));
    if (robot >= 0) {
        if (const QString crossing = crossingSentence(document, *plan, cell); !crossing.isEmpty())
            text += QStringLiteral("\n") + crossing;
    }
    if (document.planStale())
        text += QStringLiteral("\n") + tr("The plan is out of date.");
    return text;
}

} // namespace mcpp::ui
