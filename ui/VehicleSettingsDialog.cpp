#include "ui/VehicleSettingsDialog.hpp"

#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>

namespace mcpp::ui {
namespace {

// The seconds a box of minutes holds: those given while it still shows them, so that minutes to three
// decimals lose nothing of a value such as 1000 s.
double secondsIn(const QDoubleSpinBox* minutes, double givenSeconds, double shownMinutes) {
    return minutes->value() == shownMinutes ? givenSeconds : minutes->value() * 60.0;
}

// A rover's waypoints are on the ground whatever altitude it is given: the box stays, greyed, so that the
// altitude comes back if the robot is made an aircraft again.
void followVehicleType(const QComboBox* type, QDoubleSpinBox* altitude) {
    const bool aircraft = io::isAircraft(static_cast<io::VehicleType>(type->currentData().toInt()));
    altitude->setEnabled(aircraft);
    altitude->setToolTip(aircraft ? QString()
                                  : QCoreApplication::translate(
                                        "mcpp::ui::VehicleSettingsDialog",
                                        "A rover drives on the ground: its waypoint files are at 0 m."));
}

} // namespace

VehicleSettingsDialog::VehicleSettingsDialog(const io::Mission& mission, QWidget* parent)
    : QDialog(parent), exports_(mission.exports), shownDefaults_(mission.exports.vehicle) {
    setWindowTitle(tr("Robot vehicles"));
    auto* layout = new QVBoxLayout(this);
    auto* intro = new QLabel(
        tr("What each robot's waypoint files (.plan, .waypoints) tell its autopilot. A mission with "
           "more items than the limit, or longer than the flight time, is written in parts, each "
           "beginning where the one before it ended; aircraft take off from their start and return "
           "to it in every part. The turnaround, the time on the ground between two parts, adds to "
           "when each robot is done in the field. With a distance between photos, each part starts "
           "the camera at its first waypoint and stops it at its last. A robot's cruise speed is "
           "also the speed the plan gives it over every passable class: a faster robot gets more "
           "ground (MCPP-MLCT)."),
        this);
    intro->setWordWrap(true);
    layout->addWidget(intro);

    table_ = new QTableWidget(static_cast<int>(mission.robots.size()) + 1, 7, this);
    table_->setHorizontalHeaderLabels({tr("Vehicle"), tr("Altitude above home (m)"), tr("Cruise speed (m/s)"),
                                       tr("Item limit"), tr("Flight time (min)"), tr("Turnaround (min)"),
                                       tr("Photo every (m)")});
    table_->horizontalHeaderItem(2)->setToolTip(
        tr("0: each land-cover class's speed. Otherwise the robot drives at it over every passable class, "
           "in the plan too."));
    table_->horizontalHeaderItem(3)->setToolTip(
        tr("Mission items the autopilot holds, home included: %1 or more, or 0 for no limit")
            .arg(io::minimumMaxWaypoints));
    table_->horizontalHeaderItem(4)->setToolTip(
        tr("The longest flight one battery allows. A longer mission is written in parts that each fit it, an "
           "aircraft's flights from its start and back included. 0: no limit."));
    table_->horizontalHeaderItem(5)->setToolTip(
        tr("Time on the ground between two parts: a battery swap, the next part uploaded. The report adds it "
           "to the flights to say when each robot is done. 0: not counted."));
    table_->horizontalHeaderItem(6)->setToolTip(
        tr("A photo survey: the waypoint files tell the camera to take a photo every so many metres along "
           "each part's waypoints (MAV_CMD_DO_SET_CAM_TRIGG_DIST), two more items a part. For 20 % overlap, "
           "0.8 times the photo's footprint. 0: no camera commands."));
    // The mission's defaults, which robots without values of their own follow. Named "Default", not "All
    // robots": that read as the robots' values where each has its own (two drones beside a rover default).
    QStringList names{tr("Default")};
    for (std::size_t robot = 0; robot < mission.robots.size(); ++robot) {
        const std::string& name = mission.robots[robot].name;
        names << (name.empty() ? tr("Robot %1").arg(robot + 1) : QString::fromStdString(name));
    }
    table_->setVerticalHeaderLabels(names);
    table_->verticalHeaderItem(0)->setToolTip(
        tr("What a robot without a value of its own takes; a robot showing the same value follows it when it "
           "changes"));
    const std::vector<io::VehicleSettings> vehicles = io::robotVehicles(mission);
    rows_.push_back(addRow(0, names[0], mission.exports.vehicle));
    for (std::size_t robot = 0; robot < vehicles.size(); ++robot)
        rows_.push_back(
            addRow(static_cast<int>(robot) + 1, names[static_cast<qsizetype>(robot) + 1], vehicles[robot]));
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table_->setSelectionMode(QAbstractItemView::NoSelection);
    // Up to six rows stay in view when a problem's text below takes room.
    constexpr int rowsKeptInView = 6;
    table_->setMinimumHeight(table_->horizontalHeader()->sizeHint().height() + 2 * table_->frameWidth() +
                             std::min(static_cast<int>(rows_.size()), rowsKeptInView) *
                                 table_->verticalHeader()->defaultSectionSize());
    layout->addWidget(table_);

    auto* form = new QFormLayout;
    speedTolerance_ = new QDoubleSpinBox(this);
    speedTolerance_->setRange(0.0, 99.0);
    speedTolerance_->setDecimals(1);
    speedTolerance_->setSuffix(QStringLiteral(" %"));
    speedTolerance_->setValue(exports_.speedTolerance * 100.0);
    shownTolerance_ = speedTolerance_->value();
    speedTolerance_->setToolTip(
        tr("A new speed is commanded only where the land-cover speed differs from the "
           "speed in force by more than this share of it. Speeds are rounded to two "
           "significant digits."));
    form->addRow(tr("Speed change tolerance:"), speedTolerance_);
    atTurnsOnly_ =
        new QCheckBox(tr("Change speed only at turns (each straight leg at its slowest speed)"), this);
    atTurnsOnly_->setChecked(exports_.speedChangesAtTurnsOnly);
    atTurnsOnly_->setToolTip(
        tr("Fewer mission items: no waypoint in the middle of a straight leg. The vehicle "
           "never goes faster than a land cover allows, so the flight takes longer."));
    form->addRow(QString(), atTurnsOnly_);
    layout->addLayout(form);

    problem_ = new QLabel(this);
    problem_->setWordWrap(true);
    problem_->setStyleSheet(QStringLiteral("color: #b00020;"));
    problem_->hide();
    layout->addWidget(problem_);
    caution_ = new QLabel(this);
    caution_->setWordWrap(true);
    caution_->setStyleSheet(QStringLiteral("color: #8a5300;"));
    caution_->hide();
    layout->addWidget(caution_);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    okButton_ = buttons->button(QDialogButtonBox::Ok);
    for (const Row& row : rows_) {
        connect(row.maxWaypoints, &QSpinBox::valueChanged, this, &VehicleSettingsDialog::checkLimits);
        connect(row.flightTime, &QDoubleSpinBox::valueChanged, this, &VehicleSettingsDialog::checkLimits);
        connect(row.altitude, &QDoubleSpinBox::valueChanged, this, &VehicleSettingsDialog::checkLimits);
        connect(row.type, &QComboBox::currentIndexChanged, this, &VehicleSettingsDialog::checkLimits);
    }
    checkLimits();
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
    resize(1000, 250 + 32 * static_cast<int>(rows_.size())); // room for the intro and a limit's problem
    shownDefaults_ = settingsOf(rows_.front());              // as the boxes show them, for followDefaults
}

VehicleSettingsDialog::Row VehicleSettingsDialog::addRow(int row, const QString& name,
                                                         const io::VehicleSettings& settings) {
    Row widgets;
    widgets.type = new QComboBox(table_);
    for (const io::VehicleType type :
         {io::VehicleType::Rover, io::VehicleType::Multirotor, io::VehicleType::FixedWing}) {
        widgets.type->addItem(QString::fromStdString(io::vehicleTypeLabel(type)), static_cast<int>(type));
    }
    widgets.altitude = new QDoubleSpinBox(table_);
    widgets.altitude->setRange(0.0, 10000.0);
    widgets.altitude->setDecimals(3); // as many as a mission file is likely to hold, so OK changes nothing
    widgets.cruiseSpeed = new QDoubleSpinBox(table_);
    widgets.cruiseSpeed->setRange(0.0, 1000.0);
    widgets.cruiseSpeed->setDecimals(3);
    widgets.cruiseSpeed->setSpecialValueText(tr("land cover"));
    widgets.maxWaypoints = new QSpinBox(table_);
    // A limit typed below the smallest that works stays as typed, and checkLimits says so: clamped, it
    // would have read "no limit" without a word.
    widgets.maxWaypoints->setRange(0, 1000000);
    widgets.maxWaypoints->setSpecialValueText(tr("no limit"));
    widgets.flightTime = new QDoubleSpinBox(table_);
    widgets.flightTime->setRange(0.0, io::maximumFlightTimeSeconds / 60.0);
    widgets.flightTime->setDecimals(3);
    widgets.flightTime->setSpecialValueText(tr("no limit"));
    widgets.turnaround = new QDoubleSpinBox(table_);
    widgets.turnaround->setRange(0.0, io::maximumTurnaroundSeconds / 60.0);
    widgets.turnaround->setDecimals(3);
    widgets.cameraTrigger = new QDoubleSpinBox(table_);
    widgets.cameraTrigger->setRange(0.0, io::maximumCameraTriggerMetres);
    widgets.cameraTrigger->setDecimals(1); // the least distance but none: 0.1 m
    widgets.cameraTrigger->setSpecialValueText(tr("no camera"));
    show(widgets, settings);
    // The Default row's altitude stays open: robots that are aircraft of their own inherit it.
    if (row > 0) {
        followVehicleType(widgets.type, widgets.altitude);
        connect(widgets.type, &QComboBox::currentIndexChanged, widgets.altitude,
                [type = widgets.type, altitude = widgets.altitude] { followVehicleType(type, altitude); });
    }
    table_->setCellWidget(row, 0, widgets.type);
    table_->setCellWidget(row, 1, widgets.altitude);
    table_->setCellWidget(row, 2, widgets.cruiseSpeed);
    table_->setCellWidget(row, 3, widgets.maxWaypoints);
    table_->setCellWidget(row, 4, widgets.flightTime);
    table_->setCellWidget(row, 5, widgets.turnaround);
    table_->setCellWidget(row, 6, widgets.cameraTrigger);
    for (QWidget* widget : std::initializer_list<QWidget*>{
             widgets.type, widgets.altitude, widgets.cruiseSpeed, widgets.maxWaypoints, widgets.flightTime,
             widgets.turnaround, widgets.cameraTrigger})
        widget->setAccessibleName(name);
    if (row == 0) {
        connect(widgets.type, &QComboBox::currentIndexChanged, this, &VehicleSettingsDialog::followDefaults);
        connect(widgets.altitude, &QDoubleSpinBox::valueChanged, this,
                &VehicleSettingsDialog::followDefaults);
        connect(widgets.cruiseSpeed, &QDoubleSpinBox::valueChanged, this,
                &VehicleSettingsDialog::followDefaults);
        connect(widgets.maxWaypoints, &QSpinBox::valueChanged, this, &VehicleSettingsDialog::followDefaults);
        connect(widgets.flightTime, &QDoubleSpinBox::valueChanged, this,
                &VehicleSettingsDialog::followDefaults);
        connect(widgets.turnaround, &QDoubleSpinBox::valueChanged, this,
                &VehicleSettingsDialog::followDefaults);
        connect(widgets.cameraTrigger, &QDoubleSpinBox::valueChanged, this,
                &VehicleSettingsDialog::followDefaults);
    }
    return widgets;
}

io::VehicleSettings VehicleSettingsDialog::settingsOf(const Row& row) {
    io::VehicleSettings settings;
    settings.type = static_cast<io::VehicleType>(row.type->currentData().toInt());
    settings.altitudeMetres = row.altitude->value();
    settings.cruiseSpeedMetresPerSecond = row.cruiseSpeed->value();
    settings.maxWaypoints = row.maxWaypoints->value();
    settings.flightTimeSeconds = secondsIn(row.flightTime, row.flightSeconds, row.flightMinutesShown);
    settings.turnaroundSeconds = secondsIn(row.turnaround, row.turnaroundSeconds, row.turnaroundMinutesShown);
    settings.cameraTriggerMetres = row.cameraTrigger->value() == row.cameraTriggerShown
                                       ? row.cameraTriggerMetres
                                       : row.cameraTrigger->value();
    return settings;
}

void VehicleSettingsDialog::show(Row& row, const io::VehicleSettings& settings) {
    row.type->setCurrentIndex(row.type->findData(static_cast<int>(settings.type)));
    row.altitude->setValue(settings.altitudeMetres);
    row.cruiseSpeed->setValue(settings.cruiseSpeedMetresPerSecond);
    row.maxWaypoints->setValue(settings.maxWaypoints);
    row.flightTime->setValue(settings.flightTimeSeconds / 60.0);
    row.flightSeconds = settings.flightTimeSeconds;
    row.flightMinutesShown = row.flightTime->value();
    row.turnaround->setValue(settings.turnaroundSeconds / 60.0);
    row.turnaroundSeconds = settings.turnaroundSeconds;
    row.turnaroundMinutesShown = row.turnaround->value();
    row.cameraTrigger->setValue(settings.cameraTriggerMetres);
    row.cameraTriggerMetres = settings.cameraTriggerMetres;
    row.cameraTriggerShown = row.cameraTrigger->value();
}

void VehicleSettingsDialog::followDefaults() {
    // Robots that had the old default take the new one; those with their own keep it.
    const io::VehicleSettings defaults = settingsOf(rows_.front());
    for (std::size_t i = 1; i < rows_.size(); ++i) {
        io::VehicleSettings robot = settingsOf(rows_[i]);
        if (robot.type == shownDefaults_.type)
            robot.type = defaults.type;
        if (robot.altitudeMetres == shownDefaults_.altitudeMetres)
            robot.altitudeMetres = defaults.altitudeMetres;
        if (robot.cruiseSpeedMetresPerSecond == shownDefaults_.cruiseSpeedMetresPerSecond)
            robot.cruiseSpeedMetresPerSecond = defaults.cruiseSpeedMetresPerSecond;
        if (robot.maxWaypoints == shownDefaults_.maxWaypoints)
            robot.maxWaypoints = defaults.maxWaypoints;
        if (robot.flightTimeSeconds == shownDefaults_.flightTimeSeconds)
            robot.flightTimeSeconds = defaults.flightTimeSeconds;
        if (robot.turnaroundSeconds == shownDefaults_.turnaroundSeconds)
            robot.turnaroundSeconds = defaults.turnaroundSeconds;
        if (robot.cameraTriggerMetres == shownDefaults_.cameraTriggerMetres)
            robot.cameraTriggerMetres = defaults.cameraTriggerMetres;
        show(rows_[i], robot);
    }
    shownDefaults_ = defaults;
}

namespace {

// A row of the table with what is wrong in it ("5", "0.5 min", a sentence).
struct RowProblem {
    std::size_t row; // 0: Default
    QString name;
    QString detail;
};

// The problems with their rows, a robot's left out where it is what the Default row has:
// "5 (Default), 6 (Robot 3)", not the same value once a row; sentences after their row ("Robot 3: a flight
// of ...").
enum class Detail { Value, Sentence };
QStringList namedOnce(const std::vector<RowProblem>& rows, Detail detail = Detail::Value) {
    const auto fleet =
        std::find_if(rows.begin(), rows.end(), [](const RowProblem& row) { return row.row == 0; });
    QStringList named;
    for (const RowProblem& row : rows)
        if (row.row == 0 || fleet == rows.end() || row.detail != fleet->detail)
            named << (detail == Detail::Value ? QStringLiteral("%1 (%2)").arg(row.detail, row.name)
                                              : QStringLiteral("%1: %2").arg(row.name, row.detail));
    return named;
}

} // namespace

void VehicleSettingsDialog::checkLimits() {
    std::vector<RowProblem> items;
    std::vector<RowProblem> flights;
    std::vector<RowProblem> climbs; // flights too short for the climb and descent
    std::vector<RowProblem> low;    // aircraft altitudes allowed but most likely not meant
    std::vector<RowProblem> high;
    for (std::size_t i = 0; i < rows_.size(); ++i) {
        const QString name = table_->verticalHeaderItem(static_cast<int>(i))->text();
        const io::VehicleSettings settings = settingsOf(rows_[i]);
        const QString altitude = tr("%1 m").arg(settings.altitudeMetres);
        if (io::fliesTooLow(settings))
            low.push_back({i, name, altitude});
        else if (io::fliesAbovePermitFreeHeight(settings))
            high.push_back({i, name, altitude});
        const int limit = rows_[i].maxWaypoints->value();
        if (!io::isWorkableItemLimit(limit))
            items.push_back({i, name, QString::number(limit)});
        const double minutes = rows_[i].flightTime->value();
        if (minutes > 0.0 && minutes * 60.0 < io::minimumFlightTimeSeconds)
            flights.push_back({i, name, tr("%1 min").arg(minutes)});
        else if (const auto tooShort = io::flightTooShortProblem(settingsOf(rows_[i])))
            climbs.push_back({i, name, QString::fromStdString(*tooShort)});
    }
    QStringList problems;
    if (!items.empty())
        problems << tr("An item limit must be %1 or more mission items, or 0 for no limit. Too small: %2.")
                        .arg(io::minimumMaxWaypoints)
                        .arg(namedOnce(items).join(QStringLiteral(", ")));
    if (!flights.empty())
        problems << tr("A flight time must be at least 1 min, or 0 for no limit. Too short: %1.")
                        .arg(namedOnce(flights).join(QStringLiteral(", ")));
    for (const QString& climb : namedOnce(climbs, Detail::Sentence))
        problems << climb + QLatin1Char('.');
    QStringList cautions;
    if (!low.empty())
        cautions << tr("Below %1 m above home an aircraft flies into trees and roofs: %2.")
                        .arg(io::lowestSurveyAltitudeMetres)
                        .arg(namedOnce(low).join(QStringLiteral(", ")));
    if (!high.empty())
        cautions << tr("Above %1 m (%2 ft) above home, higher than most countries let drones fly without a "
                       "permit: %3.")
                        .arg(io::highestAltitudeWithoutPermitMetres)
                        .arg(io::highestAltitudeWithoutPermitFeet)
                        .arg(namedOnce(high).join(QStringLiteral(", ")));
    caution_->setText(cautions.join(QLatin1Char(' ')));
    caution_->setVisible(!cautions.isEmpty());
    problem_->setText(problems.join(QLatin1Char(' ')));
    problem_->setVisible(!problems.isEmpty());
    if (okButton_ != nullptr)
        okButton_->setEnabled(problems.isEmpty());
}

io::ExportSettings VehicleSettingsDialog::exports() const {
    io::ExportSettings exports = exports_;
    exports.vehicle = settingsOf(rows_.front());
    // Unchanged in the box, the mission's own value stays, unrounded.
    if (speedTolerance_->value() != shownTolerance_)
        exports.speedTolerance = speedTolerance_->value() / 100.0;
    exports.speedChangesAtTurnsOnly = atTurnsOnly_->isChecked();
    return exports;
}

std::vector<io::VehicleOverrides> VehicleSettingsDialog::vehicles() const {
    const io::VehicleSettings defaults = settingsOf(rows_.front());
    std::vector<io::VehicleOverrides> overrides;
    for (std::size_t i = 1; i < rows_.size(); ++i)
        overrides.push_back(io::VehicleOverrides::between(defaults, settingsOf(rows_[i])));
    return overrides;
}

} // namespace mcpp::ui
