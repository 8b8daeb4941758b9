#include "ui/ResultsPanel.hpp"

#include "core/coverage/PathMeasurement.hpp"
#include "core/model/DetectionLayer.hpp"
#include "core/model/HumanUnits.hpp"
#include "core/model/SortieLayer.hpp"
#include "core/model/TimelineLayer.hpp"
#include "core/model/TimelineText.hpp"
#include "core/planners/UncoveredLand.hpp"
#include "io/MissionInputs.hpp"
#include "render/RobotPalette.hpp"

#include <QBarCategoryAxis>
#include <QBarSet>
#include <QCategoryAxis>
#include <QChart>
#include <QChartView>
#include <QEvent>
#include <QFormLayout>
#include <QHeaderView>
#include <QLabel>
#include <QScrollArea>
#include <QSplitter>
#include <QStackedBarSeries>
#include <QTableWidget>
#include <QVBoxLayout>
#include <QValueAxis>
#include <algorithm>
#include <cmath>
#include <numeric>

namespace mcpp::ui {

namespace {

constexpr int sortiesColumn = 6; // shown for robots on batteries only
constexpr int timeColumn = 4;    // "Done at" for plans played through events

// The robot's mission under the plan's events, when it was played through some.
const RobotTimeline* playedUnderEvents(const Plan& plan, int robot) {
    const TimelineLayer* timeline = timelineLayerOf(plan);
    if (timeline == nullptr || timeline->summary().events.empty() || robot < 0 ||
        static_cast<std::size_t>(robot) >= timeline->robots().size())
        return nullptr;
    return &timeline->robots()[static_cast<std::size_t>(robot)];
}

// What the chart shows per robot: its time, or when it is done under the events.
double chartSeconds(const Plan& plan, const RobotMetrics& robot) {
    const RobotTimeline* played = playedUnderEvents(plan, robot.robot);
    return played != nullptr ? played->completionSeconds : robot.timeSeconds;
}

QString hectares(double squareMetres) {
    return QObject::tr("%1 ha").arg(squareMetres / 10'000.0, 0, 'f', 1);
}

QTableWidgetItem* numberItem(const QString& text, double sortValue) {
    auto* item = new QTableWidgetItem(text);
    item->setData(Qt::UserRole, sortValue);
    item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
    item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable);
    return item;
}

// A battery robot's sorties, with the charges, the longest flight and what lay out of range in the tooltip.
QTableWidgetItem* sortiesItem(const Plan& plan, const RobotSorties& robot) {
    const double longest =
        longestSortieSeconds(plan.paths[static_cast<std::size_t>(robot.robot)], robot.sorties, plan.cells);
    auto* item = numberItem(QString::number(robot.sorties.size()), static_cast<double>(robot.sorties.size()));
    QString tip =
        QObject::tr("%1 charges of %2 each; longest sortie %3 of a %4 battery")
            .arg(robot.charges())
            .arg(ResultsPanel::formatDuration(robot.rechargeSeconds), ResultsPanel::formatDuration(longest),
                 ResultsPanel::formatDuration(robot.enduranceSeconds));
    if (robot.outOfRangeAreaSquareMetres > 0.0)
        tip += QObject::tr("; %1 of its region out of range, not covered")
                   .arg(QString::fromStdString(formatArea(robot.outOfRangeAreaSquareMetres)));
    item->setToolTip(tip);
    return item;
}

// Where a path steps between cells of different sizes, whose sub-cells never line up: what those steps take
// beyond the cells' own travel (a second or more either way; it can be less where the small cells are
// faster).
QString connectorNote(const RobotMetrics& robot) {
    if (std::abs(robot.connectorSeconds) < 1.0)
        return {};
    return robot.connectorSeconds > 0.0 ? QObject::tr("; %1 more on steps between cells of different sizes")
                                              .arg(ResultsPanel::formatDuration(robot.connectorSeconds))
                                        : QObject::tr("; %1 less on steps between cells of different sizes")
                                              .arg(ResultsPanel::formatDuration(-robot.connectorSeconds));
}

// For a robot on a battery: the part of its time spent at the charger.
QString chargingNote(const Plan& plan, int robot) {
    if (robot < 0 || static_cast<std::size_t>(robot) >= plan.paths.size())
        return {};
    const CoveragePath& path = plan.paths[static_cast<std::size_t>(robot)];
    if (path.pauses.empty())
        return {};
    return QObject::tr("; %1 of it charging (%2 charges)")
        .arg(ResultsPanel::formatDuration(pausedSecondsBetween(path.pauses, 0, path.waypoints.size())))
        .arg(path.pauses.size());
}

// For plans played through events: when the robot was really done, and whether it stopped.
QString completionNote(const Plan& plan, int robot) {
    const TimelineLayer* timeline = timelineLayerOf(plan);
    if (timeline == nullptr || robot < 0 || static_cast<std::size_t>(robot) >= timeline->robots().size())
        return {};
    const RobotTimeline& played = timeline->robots()[static_cast<std::size_t>(robot)];
    return played.stopped ? QObject::tr("; under the events it stopped at %1")
                                .arg(ResultsPanel::formatDuration(played.completionSeconds))
                          : QObject::tr("; under the events it is done at %1")
                                .arg(ResultsPanel::formatDuration(played.completionSeconds));
}

// When the robot is done under the events, or when it stopped for good.
QTableWidgetItem* doneItem(const RobotTimeline& played) {
    const QString time = ResultsPanel::formatDuration(played.completionSeconds);
    return numberItem(played.stopped ? QObject::tr("stopped at %1").arg(time) : time,
                      played.completionSeconds);
}

QLabel* valueLabel(const QString& objectName, QWidget* parent) {
    auto* label = new QLabel(QStringLiteral("–"), parent);
    label->setObjectName(objectName);
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    return label;
}

} // namespace

ResultsPanel::ResultsPanel(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("resultsPanel"));
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(6, 6, 6, 6);

    staleLabel_ = new QLabel(
        tr("These results are out of date: the inputs changed after planning. Press Plan (F5)."), this);
    staleLabel_->setObjectName(QStringLiteral("resultsStaleLabel"));
    staleLabel_->setWordWrap(true);
    staleLabel_->setStyleSheet(
        QStringLiteral("QLabel { background: #ffecb3; border: 1px solid #c9a227; padding: 4px; }"));
    staleLabel_->hide();
    layout->addWidget(staleLabel_);

    // The figures scroll on their own: a plan's warnings and notes may run to many lines, and a dock too
    // short for them cut them off.
    auto* summaryArea = new QScrollArea(this);
    summaryArea_ = summaryArea;
    summaryArea->setObjectName(QStringLiteral("resultsSummaryArea"));
    summaryArea->setWidgetResizable(true);
    summaryArea->setFrameShape(QFrame::NoFrame);
    summaryArea->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    auto* summaryWidget = new QWidget(summaryArea);
    auto* summary = new QFormLayout(summaryWidget);
    summary->setContentsMargins(0, 0, 0, 0);
    summary->setObjectName(QStringLiteral("resultsSummary"));
    makespan_ = valueLabel(QStringLiteral("makespanLabel"), this);
    lowerBound_ = valueLabel(QStringLiteral("lowerBoundLabel"), this);
    ratio_ = valueLabel(QStringLiteral("ratioLabel"), this);
    covered_ = valueLabel(QStringLiteral("coveredLabel"), this);
    unreachable_ = valueLabel(QStringLiteral("unreachableLabel"), this);
    planner_ = valueLabel(QStringLiteral("plannerLabel"), this);
    detection_ = valueLabel(QStringLiteral("detectionLabel"), this);
    detection_->setToolTip(tr("The chance a target in a covered cell is seen, over every cell the sensor "
                              "can see: the least, the mean and the share at the required probability"));
    timeline_ = valueLabel(QStringLiteral("timelineLabel"), this);
    timeline_->setWordWrap(true);
    timeline_->setToolTip(tr("The mission played through its events, beside a static plan run through the "
                             "same events without re-allocation"));
    warnings_ = valueLabel(QStringLiteral("warningsLabel"), this);
    warnings_->setWordWrap(true);
    notes_ = valueLabel(QStringLiteral("notesLabel"), this);
    notes_->setWordWrap(true);
    waypointFiles_ = valueLabel(QStringLiteral("waypointFilesLabel"), this);
    waypointFiles_->setWordWrap(true);
    summary->addRow(tr("Makespan"), makespan_);
    summary->addRow(tr("Lower bound"), lowerBound_);
    summary->addRow(tr("Makespan / bound"), ratio_);
    summary->addRow(tr("Covered"), covered_);
    summary->addRow(tr("Unreachable"), unreachable_);
    summary->addRow(tr("Planner"), planner_);
    summary->addRow(tr("Detection"), detection_);
    summary->addRow(tr("Events"), timeline_);
    summary->addRow(tr("Warnings"), warnings_);
    summary->addRow(tr("Notes"), notes_);
    summary->addRow(tr("Waypoint files"), waypointFiles_);
    summary_ = summary;
    summary->setRowVisible(detection_, false);
    summary->setRowVisible(timeline_, false);
    summary->setRowVisible(notes_, false);
    summary->setRowVisible(waypointFiles_, false);
    summaryArea->setWidget(summaryWidget);

    table_ = new QTableWidget(0, 7, this);
    table_->setObjectName(QStringLiteral("resultsTable"));
    table_->setHorizontalHeaderLabels(
        {tr("Robot"), tr("Cells"), tr("Area"), tr("Length"), tr("Time"), tr("Turns"), tr("Sorties")});
    table_->setColumnHidden(sortiesColumn, true);
    table_->verticalHeader()->hide();
    // Figures keep their width; the robot's name takes what is left (elided), so every column shows.
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table_->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    table_->setTextElideMode(Qt::ElideRight);
    table_->setWordWrap(false); // wrapped, a name with a space went onto two lines instead of eliding
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->setMinimumHeight(110);

    auto* chart = new QChart;
    chart->setTitle(tr("Time per robot"));
    chart->legend()->hide();
    chart->setMargins(QMargins(2, 2, 2, 2));
    chart->setBackgroundRoundness(0);
    chartView_ = new QChartView(chart, this);
    chartView_->setObjectName(QStringLiteral("timeChart"));
    chartView_->setRenderHint(QPainter::Antialiasing);
    chartView_->setMinimumHeight(180);
    chartView_->installEventFilter(this); // the bars' numbers follow the chart's width

    auto* splitter = new QSplitter(Qt::Vertical, this);
    splitter_ = splitter;
    splitter->setChildrenCollapsible(false);
    splitter->addWidget(summaryArea);
    splitter->addWidget(table_);
    splitter->addWidget(chartView_);
    layout->addWidget(splitter, 1);
    describeTimes(false);
}

QString ResultsPanel::formatDuration(double seconds) {
    if (!std::isfinite(seconds))
        return QStringLiteral("–");
    return QString::fromStdString(mcpp::formatDuration(seconds));
}

QString ResultsPanel::makespanText() const {
    return makespan_->text();
}

// Under events what a user waits for is when each robot is done (its full-speed time is in the tooltip),
// while the makespan is still the plan's at full speed; the Events row says when the mission is done.
void ResultsPanel::describeTimes(bool underEvents) {
    table_->horizontalHeaderItem(timeColumn)->setText(underEvents ? tr("Done at") : tr("Time"));
    table_->horizontalHeaderItem(timeColumn)
        ->setToolTip(underEvents ? tr("When it is done under the events (slowed down, waiting for cells) or "
                                      "stopped; each robot's tooltip gives its time at full speed")
                                 : tr("Driving at full speed, turns included"));
    if (auto* makespanName = qobject_cast<QLabel*>(summary_->labelForField(makespan_)))
        makespanName->setText(underEvents ? tr("Makespan at full speed") : tr("Makespan"));
    makespan_->setToolTip(underEvents
                              ? tr("The slowest robot's time driving at full speed, as planned before "
                                   "the events; when the mission is done under them is in the "
                                   "Events row")
                              : tr("The slowest robot's time, turns included"));
    lowerBound_->setToolTip(QString());
    ratio_->setToolTip(QString());
    if (auto* boundName = qobject_cast<QLabel*>(summary_->labelForField(lowerBound_)))
        boundName->setText(tr("Lower bound"));
    if (auto* ratioName = qobject_cast<QLabel*>(summary_->labelForField(ratio_)))
        ratioName->setText(tr("Makespan / bound"));
}

// The summary in the field: its rows' names and what the paths alone take, in the tooltips.
void ResultsPanel::describeFieldTimes(const PlanMetrics& metrics) {
    if (auto* makespanName = qobject_cast<QLabel*>(summary_->labelForField(makespan_)))
        makespanName->setText(tr("Last robot home"));
    makespan_->setToolTip(tr("When the last robot is done in the field: its flights, with their climbs, "
                             "descents and trips out to the work, and the turnarounds between them. The "
                             "slowest robot's path alone takes %1")
                              .arg(formatDuration(metrics.makespanSeconds)));
    if (auto* boundName = qobject_cast<QLabel*>(summary_->labelForField(lowerBound_)))
        boundName->setText(tr("Bound in the field"));
    lowerBound_->setToolTip(tr("No plan making these turns brings the last robot home sooner: the work no "
                               "plan avoids, shared out in full flights with the fewest turnarounds. An "
                               "aircraft at a cruise speed whose flights reach all its work spends 2 d of a "
                               "flight getting to work farther than d from its start and back; a flight may "
                               "work on its way out, so on land spread around the starts every plan takes "
                               "well over it. On the paths alone: %1")
                                .arg(formatDuration(metrics.lowerBoundSeconds)));
    ratio_->setToolTip(tr("The last robot's time in the field over the first's: how evenly they come home. "
                          "On the paths alone, makespan / bound is %1")
                           .arg(metrics.ratio, 0, 'f', 3));
    if (auto* ratioName = qobject_cast<QLabel*>(summary_->labelForField(ratio_)))
        ratioName->setText(tr("Last / first home"));
}

QString ResultsPanel::ratioText() const {
    return ratio_->text();
}

void ResultsPanel::setStale(bool stale) {
    staleLabel_->setVisible(stale);
}

void ResultsPanel::showPlan(const Plan* plan, const QStringList& names, const io::LoadedRaster* raster) {
    table_->setSortingEnabled(false);
    table_->setRowCount(0);
    planWarnings_.clear();
    if (plan == nullptr) {
        for (QLabel* label : {makespan_, lowerBound_, ratio_, covered_, unreachable_, planner_, detection_,
                              timeline_, warnings_, notes_, waypointFiles_})
            label->setText(QStringLiteral("–"));
        if (auto* label = qobject_cast<QLabel*>(summary_->labelForField(unreachable_)))
            label->setText(tr("Unreachable"));
        summary_->setRowVisible(detection_, false);
        summary_->setRowVisible(timeline_, false);
        summary_->setRowVisible(notes_, false);
        summary_->setRowVisible(waypointFiles_, false);
        describeTimes(false);
        clearChart();
        chartRobots_.clear(); // no later waypoint-file figures draw bars for a plan gone
        setStale(false);
        return;
    }
    const PlanMetrics& metrics = plan->metrics;
    table_->setRowCount(static_cast<int>(metrics.robots.size()));
    const SortieLayer* sorties = sortieLayerOf(*plan);
    for (std::size_t row = 0; row < metrics.robots.size(); ++row) {
        const RobotMetrics& robot = metrics.robots[row];
        const QString name =
            robot.robot < names.size() ? names[robot.robot] : tr("Robot %1").arg(robot.robot + 1);
        auto* nameItem = new QTableWidgetItem(name);
        nameItem->setData(Qt::DecorationRole, render::RobotPalette::colour(robot.robot));
        nameItem->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable);
        nameItem->setToolTip(name); // whole, for when the column elides it
        nameItem->setData(Qt::UserRole, robot.robot);
        const int r = static_cast<int>(row);
        table_->setItem(r, 0, nameItem);
        table_->setItem(r, 1, numberItem(QString::number(robot.cells), robot.cells));
        table_->setItem(r, 2, numberItem(hectares(robot.areaSquareMetres), robot.areaSquareMetres));
        table_->setItem(
            r, 3, numberItem(tr("%1 km").arg(robot.lengthMetres / 1000.0, 0, 'f', 2), robot.lengthMetres));
        const RobotTimeline* played = playedUnderEvents(*plan, robot.robot);
        auto* time = played != nullptr ? doneItem(*played)
                                       : numberItem(formatDuration(robot.timeSeconds), robot.timeSeconds);
        auto* turns = numberItem(QString::number(robot.turns), robot.turns);
        const QString turnNote = tr("%1 of it lost slowing down for turns and speeding up again (turn_s)")
                                     .arg(formatDuration(robot.turnSeconds));
        const QString fullSpeed =
            played != nullptr ? tr("%1 at full speed; ").arg(formatDuration(robot.timeSeconds)) : QString();
        time->setToolTip(fullSpeed + turnNote + connectorNote(robot) + chargingNote(*plan, robot.robot) +
                         (played != nullptr ? QString() : completionNote(*plan, robot.robot)));
        turns->setToolTip(turnNote);
        table_->setItem(r, timeColumn, time);
        table_->setItem(r, 5, turns);
        if (sorties != nullptr && row < sorties->robots().size())
            table_->setItem(r, sortiesColumn, sortiesItem(*plan, sorties->robots()[row]));
    }
    table_->setColumnHidden(sortiesColumn, sorties == nullptr);
    const bool underEvents =
        !metrics.robots.empty() && playedUnderEvents(*plan, metrics.robots.front().robot) != nullptr;
    // Where flights split the missions, the field team waits for the last robot home: the figures say when.
    const bool inTheField = !underEvents && metrics.timedInTheField();
    makespan_->setText(formatDuration(inTheField ? metrics.fieldMakespanSeconds : metrics.makespanSeconds));
    describeTimes(underEvents);
    lowerBound_->setText(
        formatDuration(inTheField ? metrics.fieldLowerBoundSeconds : metrics.lowerBoundSeconds));
    ratio_->setText(inTheField ? tr("%1 in the field").arg(metrics.fieldSpread(), 0, 'f', 3)
                               : QString::number(metrics.ratio, 'f', 3));
    // Robots alone in parts of their own give every plan their ratio: the others' balance beside it.
    if (!inTheField && metrics.boundSetByLoneRobots())
        ratio_->setText(tr("%1; the robots sharing parts: %2")
                            .arg(metrics.ratio, 0, 'f', 3)
                            .arg(metrics.sharedPartsRatio, 0, 'f', 3));
    // A detection plan's bound is of another kind: its ratio says against what.
    if (!inTheField && metrics.boundOfDetectionPasses)
        ratio_->setText(tr("%1 (to the passes its targets need, each at the fastest class's speed)")
                            .arg(metrics.ratio, 0, 'f', 3));
    if (inTheField)
        describeFieldTimes(metrics);
    covered_->setText(tr("%1 (%2 % of the passable area)")
                          .arg(hectares(metrics.coveredAreaSquareMetres))
                          .arg(metrics.coveredFraction * 100.0, 0, 'f', 1));
    // Robots on batteries leave land beyond their reach that a way joins to their starts: said apart, and
    // the row is then about land not covered, not only land no robot can reach.
    const double beyond = sorties != nullptr && metrics.unreachableAreaSquareMetres > 0.0
                              ? uncoveredLand(*plan).leftOutSquareMetres
                              : 0.0;
    unreachable_->setText(beyond > 0.0
                              ? tr("%1, of which %2 beyond the batteries' reach")
                                    .arg(hectares(metrics.unreachableAreaSquareMetres), hectares(beyond))
                              : hectares(metrics.unreachableAreaSquareMetres));
    if (auto* label = qobject_cast<QLabel*>(summary_->labelForField(unreachable_)))
        label->setText(beyond > 0.0 ? tr("Not covered") : tr("Unreachable"));
    planner_->setText(QString::fromStdString(plan->planner));
    const DetectionLayer* detection = detectionLayerOf(*plan);
    summary_->setRowVisible(detection_, detection != nullptr);
    if (detection != nullptr) {
        const DetectionSummary& seen = detection->summary();
        detection_->setText(tr("least %1, mean %2; %3 % of the cells at %4 or more")
                                .arg(seen.minimum, 0, 'f', 3)
                                .arg(seen.mean, 0, 'f', 3)
                                .arg(seen.shareMet * 100.0, 0, 'f', 1)
                                .arg(seen.requiredProbability));
    }
    const TimelineLayer* timeline = timelineLayerOf(*plan);
    summary_->setRowVisible(timeline_, timeline != nullptr);
    if (timeline != nullptr)
        timeline_->setText(QString::fromStdString(timelineSentence(timeline->summary())));
    // As the messages panel says them: map points with their degrees, robots numbered with their names
    // (the robot table lists names, not numbers).
    std::vector<std::string> robotNames;
    for (const QString& name : names)
        robotNames.push_back(name.toStdString());
    const auto placed = [raster, &robotNames](const std::string& message) {
        return QString::fromStdString(io::messageForPeople(message, raster, robotNames));
    };
    for (const auto& warning : plan->warnings())
        planWarnings_ << placed(warning);
    showWarnings(planWarnings_);
    QStringList notes;
    for (const PlanIssue& issue : plan->issues)
        if (issue.severity == IssueSeverity::Information)
            notes << placed(issue.message);
    if (notes.size() > 1)
        for (QString& note : notes)
            note.prepend(QStringLiteral("• "));
    notes_->setText(notes.join(QLatin1Char('\n')));
    summary_->setRowVisible(notes_, !notes.isEmpty());
    summary_->setRowVisible(waypointFiles_, false); // until showWaypointFiles has this plan's
    showChart(*plan, names);
    fitSummary();
}

void ResultsPanel::addNote(const QString& note) {
    if (note.isEmpty())
        return;
    const QString shown = notes_->text();
    notes_->setText(shown.isEmpty()
                        ? note
                        : (shown.startsWith(QStringLiteral("• ")) ? shown : QStringLiteral("• ") + shown) +
                              QStringLiteral("\n• ") + note);
    summary_->setRowVisible(notes_, true);
    fitSummary();
}

// A plan shown while the panel was hidden (a tab behind another) is fitted when the panel shows.
void ResultsPanel::showEvent(QShowEvent* event) {
    QWidget::showEvent(event);
    fitSummary();
}

// The figures shown whole where the panel has room, taken from the table's empty rows first, then from the
// chart down to its least height. The table keeps its first rows (up to rowsKept) before the figures: a
// plan's long warnings, shown whole under Messages, scroll here rather than hide the robot that finishes
// last. A user's drag holds until the next plan.
void ResultsPanel::fitSummary() {
    constexpr int rowsKept = 6;
    const QList<int> sizes = splitter_->sizes();
    const int total = std::accumulate(sizes.begin(), sizes.end(), 0);
    if (!isVisible() || total <= 0)
        return;
    QWidget* figures = summaryArea_->widget();
    const int width = summaryArea_->viewport()->width();
    const int figuresWanted =
        figures->hasHeightForWidth() ? figures->heightForWidth(width) : figures->sizeHint().height();
    const int rowsHeight = table_->rowCount() > 0 ? table_->rowCount() * table_->rowHeight(0) : 0;
    const int tableWanted = table_->horizontalHeader()->height() + rowsHeight + 2 * table_->frameWidth();
    const int tableLeast = std::min(tableWanted, table_->minimumHeight());
    const int tableKept =
        std::max(tableLeast, tableWanted - std::max(table_->rowCount() - rowsKept, 0) * table_->rowHeight(0));
    const int chartLeast = chartView_->minimumHeight();
    const int figuresHeight = std::max(std::min(figuresWanted, total - tableKept - chartLeast),
                                       summaryArea_->minimumSizeHint().height());
    const int tableHeight = std::max(std::min(tableWanted, total - figuresHeight - chartLeast), tableLeast);
    splitter_->setSizes({figuresHeight, tableHeight, std::max(total - figuresHeight - tableHeight, 0)});
}

namespace {

QString robotName(const QStringList& names, int robot) {
    return robot < names.size() && !names[robot].isEmpty() ? names[robot]
                                                           : ResultsPanel::tr("Robot %1").arg(robot + 1);
}

} // namespace

// Several warnings, each wrapped over lines, would read as one paragraph without a mark before each.
void ResultsPanel::showWarnings(QStringList warnings) {
    if (warnings.size() > 1)
        for (QString& warning : warnings)
            warning.prepend(QStringLiteral("• "));
    warnings_->setText(warnings.isEmpty() ? tr("none") : warnings.join(QLatin1Char('\n')));
}

void ResultsPanel::showWaypointFiles(const std::vector<io::MissionSize>& sizes,
                                     const std::vector<io::VehicleSettings>& vehicles,
                                     const QStringList& names) {
    waypointFiles_->setText(waypointFilesText(sizes, vehicles, names));
    showWarnings(planWarnings_ + flightsTooLongWarnings(sizes, vehicles, names));
    QStringList perRobot;
    for (std::size_t robot = 0; robot < sizes.size(); ++robot)
        perRobot << tr("%1: %2 items, %3%4")
                        .arg(robotName(names, static_cast<int>(robot)))
                        .arg(sizes[robot].items)
                        .arg(sizes[robot].parts == 1 ? tr("one file")
                                                     : tr("%1 parts").arg(sizes[robot].parts))
                        .arg(sizes[robot].longestPartSeconds > 0.0
                                 ? tr(", the longest flight %1, done after %2")
                                       .arg(formatDuration(sizes[robot].longestPartSeconds),
                                            formatDuration(sizes[robot].fieldSeconds))
                                 : QString());
    waypointFiles_->setToolTip(perRobot.join(QLatin1Char('\n')));
    summary_->setRowVisible(waypointFiles_, !sizes.empty());
    showTimeInTheField(sizes);
    fitSummary();
}

// Where flights and turnarounds keep some robot out longer than its path takes, the chart shows when each
// robot is home: the time a field team waits for, and what a plan balanced in the field evens out.
void ResultsPanel::showTimeInTheField(const std::vector<io::MissionSize>& sizes) {
    if (chartUnderEvents_)
        return;
    std::vector<double> field = chartPathSeconds_;
    bool later = false;
    for (std::size_t i = 0; i < chartRobots_.size(); ++i) {
        const auto robot = static_cast<std::size_t>(chartRobots_[i]);
        if (robot < sizes.size() && sizes[robot].fieldSeconds > field[i] + 1.0) {
            field[i] = sizes[robot].fieldSeconds;
            later = true;
        }
    }
    if (!later)
        return;
    drawBars(field, tr("Time in the field per robot"));
    // What the field team waits for, as in the summary and the chart; the path's time in the tooltip.
    table_->horizontalHeaderItem(timeColumn)->setText(tr("Home after"));
    table_->horizontalHeaderItem(timeColumn)
        ->setToolTip(tr("When the robot is done in the field: its flights, with their climbs, descents and "
                        "trips out to the work, and the turnarounds between them"));
    for (int row = 0; row < table_->rowCount(); ++row) {
        const auto robot = static_cast<std::size_t>(table_->item(row, 0)->data(Qt::UserRole).toInt());
        QTableWidgetItem* time = table_->item(row, timeColumn);
        if (robot >= sizes.size() || time == nullptr || !(sizes[robot].fieldSeconds > 0.0))
            continue;
        time->setToolTip(tr("Its path alone takes %1; ").arg(time->text()) + time->toolTip());
        time->setText(formatDuration(sizes[robot].fieldSeconds));
        time->setData(Qt::UserRole, sizes[robot].fieldSeconds);
    }
}

namespace {

// Whether a split mission's parts come from its flight time: where its items fit the limit, or where the
// parts are at least twice as many as the limit alone needs (items over the limit, rounded up).
bool splitForFlightTime(const io::MissionSize& size, const io::VehicleSettings& vehicle) {
    if (!(vehicle.flightTimeSeconds > 0.0))
        return false;
    if (vehicle.maxWaypoints == 0 || size.items <= vehicle.maxWaypoints)
        return true;
    const std::size_t byItemLimit =
        static_cast<std::size_t>((size.items + vehicle.maxWaypoints - 1) / vehicle.maxWaypoints);
    return size.parts >= 2 * byItemLimit;
}

} // namespace

QString ResultsPanel::waypointFilesText(const std::vector<io::MissionSize>& sizes,
                                        const std::vector<io::VehicleSettings>& vehicles,
                                        const QStringList& names) {
    QStringList split;
    QStringList reasons; // beside split: why each robot's mission is
    int aboveItemLimit = 0;
    int forFlightTime = 0;
    int inSorties = 0; // a battery plan's, each sortie a part
    int largest = 0;
    std::size_t overFlightTime = 0;
    double lastDone = 0.0;
    bool doneLater = false; // else the makespan already says when the robots are done
    for (std::size_t robot = 0; robot < sizes.size(); ++robot) {
        largest = std::max(largest, sizes[robot].items);
        overFlightTime += sizes[robot].partsOverFlightTime;
        lastDone = std::max(lastDone, sizes[robot].fieldSeconds);
        if (sizes[robot].parts > 1) {
            const bool sorties = sizes[robot].sorties > 0;
            const bool forFlight =
                !sorties && robot < vehicles.size() && splitForFlightTime(sizes[robot], vehicles[robot]);
            (sorties ? inSorties : forFlight ? forFlightTime : aboveItemLimit) += 1;
            split << tr("%1 in %2").arg(robotName(names, static_cast<int>(robot))).arg(sizes[robot].parts);
            reasons << (sorties ? tr("sorties") : forFlight ? tr("flight time") : tr("item limit"));
            doneLater = doneLater || (robot < vehicles.size() && io::splitMissionEndsLater(vehicles[robot]));
        }
    }
    const bool oneLimit =
        std::all_of(vehicles.begin(), vehicles.end(), [&](const io::VehicleSettings& vehicle) {
            return vehicle.maxWaypoints == vehicles.front().maxWaypoints;
        });
    const QString limit = !vehicles.empty() && oneLimit && vehicles.front().maxWaypoints > 0
                              ? tr(" of %1").arg(vehicles.front().maxWaypoints)
                              : QString();
    // Parts a flight cannot fly are what a user must not miss.
    const QString outOfReach =
        overFlightTime == 0
            ? QString()
            : tr("; %1 longer than a flight (out of its reach)")
                  .arg(overFlightTime == 1 ? tr("1 part") : tr("%1 parts").arg(overFlightTime));
    if (split.isEmpty())
        return tr("one file per robot, the largest %1%2 items").arg(largest).arg(limit) + outOfReach;
    // Where robots are split for either reason, each says its own.
    const bool mixed = (aboveItemLimit > 0) + (forFlightTime > 0) + (inSorties > 0) > 1;
    if (mixed)
        for (qsizetype i = 0; i < split.size(); ++i)
            split[i] += tr(" (%1)").arg(reasons[i]);
    constexpr int named = 6; // more would wrap over many lines
    const qsizetype count = split.size();
    if (count > named)
        split = split.mid(0, named) << tr("…");
    const QString robots = count == 1 ? tr("1 robot") : tr("%1 robots").arg(count);
    const QString shownLimit = limit.isEmpty() ? QString() : tr(" (%1)").arg(vehicles.front().maxWaypoints);
    const QString header = mixed       ? tr("%1 in parts").arg(robots)
                           : inSorties ? tr("%1 in sorties, a part or more each").arg(robots)
                           : forFlightTime
                               ? tr("%1 over the flight time, in parts").arg(robots)
                               : tr("%1 above the item limit%2, in parts").arg(robots, shownLimit);
    // An aircraft's split missions end later than the plan's makespan: the trips to each part and the
    // turnarounds.
    const QString done = doneLater && lastDone > 0.0
                             ? tr("; all done in the field after %1").arg(formatDuration(lastDone))
                             : QString();
    return header + tr(": ") + split.join(QStringLiteral(", ")) + outOfReach + done;
}

QStringList ResultsPanel::flightsTooLongWarnings(const std::vector<io::MissionSize>& sizes,
                                                 const std::vector<io::VehicleSettings>& vehicles,
                                                 const QStringList& names) {
    QStringList warnings;
    for (std::size_t robot = 0; robot < sizes.size() && robot < vehicles.size(); ++robot) {
        const io::MissionSize& size = sizes[robot];
        const io::VehicleSettings& vehicle = vehicles[robot];
        if (size.partsOverFlightTime == 0 || !(vehicle.flightTimeSeconds > 0.0))
            continue;
        // The exports' lead and advice ("1 h 8 min", not the table's "1:08:00"); the cause in general, as
        // the panel holds no mission to name the farthest waypoint or the files from.
        const std::string lead =
            io::flightsTooLongLead(robotName(names, static_cast<int>(robot)).toStdString(), vehicle,
                                   size.parts, size.partsOverFlightTime, size.longestPartSeconds);
        warnings << QString::fromStdString(lead + ": " + io::flightsTooLongCause(vehicle) + ". " +
                                           io::flightsTooLongAdvice(vehicle) + ".");
    }
    return warnings;
}

int ResultsPanel::robotLabelStep(int robots, int labelsThatFit) {
    const int fit = std::max(labelsThatFit, 1);
    for (int step = 1;; step *= 10)
        for (const int multiple : {1, 2, 5})
            if ((robots + step * multiple - 1) / (step * multiple) <= fit)
                return step * multiple;
}

bool ResultsPanel::eventFilter(QObject* watched, QEvent* event) {
    if (watched == chartView_ && event->type() == QEvent::Resize && !barNumbers_.isEmpty())
        numberBars();
    return QWidget::eventFilter(watched, event);
}

void ResultsPanel::clearChart() {
    barNumbers_.clear();
    QChart* chart = chartView_->chart();
    chart->setTitle(tr("Time per robot"));
    chart->removeAllSeries();
    for (auto* axis : chart->axes()) {
        chart->removeAxis(axis); // the chart gives up the axis: it is ours to delete
        delete axis;
    }
}

void ResultsPanel::showChart(const Plan& plan, const QStringList& names) {
    chartRobots_.clear();
    chartPathSeconds_.clear();
    chartNames_ = names;
    for (const auto& robot : plan.metrics.robots) {
        chartRobots_.push_back(robot.robot);
        chartPathSeconds_.push_back(chartSeconds(plan, robot));
    }
    chartUnderEvents_ = !chartRobots_.empty() && playedUnderEvents(plan, chartRobots_.front()) != nullptr;
    drawBars(chartPathSeconds_, chartUnderEvents_ ? tr("Done at, under the events") : tr("Time per robot"));
}

void ResultsPanel::drawBars(const std::vector<double>& seconds, const QString& title) {
    clearChart();
    QChart* chart = chartView_->chart();
    chart->setTitle(title);
    if (chartRobots_.empty())
        return;
    // One set per robot with a value only in its own category: each bar takes its robot's colour.
    auto* series = new QStackedBarSeries;
    QStringList categories;
    const double longestSeconds = *std::max_element(seconds.begin(), seconds.end());
    // Hours once the longest run passes two hours: "34" reads better than "2040".
    const bool inHours = longestSeconds > 7200.0;
    const double unitSeconds = inHours ? 3600.0 : 60.0;
    for (std::size_t i = 0; i < chartRobots_.size(); ++i) {
        const int robot = chartRobots_[i];
        // Names do not fit under narrow bars; the numbers are the ones on the map's start markers.
        categories << QString::number(robot + 1);
        auto* set =
            new QBarSet(robot < chartNames_.size() ? chartNames_[robot] : tr("Robot %1").arg(robot + 1));
        set->setColor(render::RobotPalette::colour(robot));
        set->setBorderColor(render::RobotPalette::colour(robot).darker(130));
        for (std::size_t j = 0; j < chartRobots_.size(); ++j)
            *set << (j == i ? seconds[i] / unitSeconds : 0.0);
        series->append(set);
    }
    series->setBarWidth(0.7);
    chart->addSeries(series);
    barNumbers_ = categories;
    numberBars();
    auto* valueAxis = new QValueAxis;
    valueAxis->setTitleText(inHours ? tr("hours") : tr("minutes"));
    valueAxis->setRange(0.0, std::max(longestSeconds / unitSeconds * 1.1, 1.0));
    valueAxis->setLabelFormat(QStringLiteral("%.0f"));
    valueAxis->applyNiceNumbers();
    chart->addAxis(valueAxis, Qt::AlignLeft);
    series->attachAxis(valueAxis);
}

// Each bar numbered while the numbers fit under their bars; past that (20 robots in a narrow dock showed
// "..." under every bar) only every second, fifth or tenth robot, and the first, at its bar.
void ResultsPanel::numberBars() {
    QChart* chart = chartView_->chart();
    if (chart->series().isEmpty())
        return;
    QAbstractSeries* series = chart->series().front();
    for (auto* axis : chart->axes(Qt::Horizontal)) {
        chart->removeAxis(axis);
        delete axis;
    }
    const QFontMetrics metrics(chart->font());
    const int labelWidth = metrics.horizontalAdvance(barNumbers_.back()) + metrics.averageCharWidth() * 2;
    const int plotWidth = std::max(chartView_->width() - 70, labelWidth); // less the value axis
    const int count = static_cast<int>(barNumbers_.size());
    const int step = robotLabelStep(count, plotWidth / labelWidth);
    QAbstractAxis* numbers = nullptr;
    if (step == 1) {
        auto* categories = new QBarCategoryAxis;
        categories->append(barNumbers_);
        numbers = categories;
    } else {
        auto* positions = new QCategoryAxis;
        positions->setLabelsPosition(QCategoryAxis::AxisLabelsPositionOnValue);
        positions->setRange(-0.5, count - 0.5);
        positions->setStartValue(-0.5);
        positions->setGridLineVisible(false);
        for (int bar = 0; bar < count; ++bar)
            if (bar == 0 || (bar + 1) % step == 0)
                positions->append(barNumbers_[bar], bar);
        numbers = positions;
    }
    numbers->setTitleText(tr("robot, numbered as on the map"));
    chart->addAxis(numbers, Qt::AlignBottom);
    series->attachAxis(numbers);
}

} // namespace mcpp::ui
