// The robot vehicles dialog: what it shows, robots following the Default row, what it hands back.

#include "ui/VehicleSettingsDialog.hpp"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QTest>

using namespace mcpp;
using namespace mcpp::io;

namespace {

Mission threeRobots() {
    Mission mission;
    mission.robots = {RobotSpec{"alpha", {1, 2}, ""}, RobotSpec{"beta", {3, 4}, ""},
                      RobotSpec{"", {5, 6}, ""}};
    mission.exports.vehicle.altitudeMetres = 30.0;
    mission.exports.vehicle.maxWaypoints = 700;
    mission.robots[1].vehicle.altitudeMetres = 60.0; // beta flies higher
    mission.robots[1].vehicle.type = VehicleType::Multirotor;
    return mission;
}

template <typename Widget> Widget* cell(QTableWidget* table, int row, int column) {
    return qobject_cast<Widget*>(table->cellWidget(row, column));
}

} // namespace

class VehicleSettingsDialogTest : public QObject {
    Q_OBJECT

  private slots:
    void showsEachRobotsVehicle() {
        ui::VehicleSettingsDialog dialog(threeRobots());
        auto* table = dialog.findChild<QTableWidget*>();
        QVERIFY(table != nullptr);
        QCOMPARE(table->rowCount(), 4);
        QCOMPARE(table->verticalHeaderItem(0)->text(), QStringLiteral("Default"));
        QCOMPARE(table->verticalHeaderItem(2)->text(), QStringLiteral("beta"));
        QCOMPARE(table->verticalHeaderItem(3)->text(), QStringLiteral("Robot 3"));
        QCOMPARE(cell<QDoubleSpinBox>(table, 1, 1)->value(), 30.0);
        QCOMPARE(cell<QDoubleSpinBox>(table, 2, 1)->value(), 60.0);
        QCOMPARE(cell<QComboBox>(table, 2, 0)->currentText(), QStringLiteral("Multirotor"));
        QCOMPARE(cell<QSpinBox>(table, 3, 3)->value(), 700);
        // A rover's altitude is greyed (its files are at 0 m); an aircraft's is not, and follows its type.
        QVERIFY(!cell<QDoubleSpinBox>(table, 1, 1)->isEnabled());
        QVERIFY(cell<QDoubleSpinBox>(table, 2, 1)->isEnabled());
        cell<QComboBox>(table, 1, 0)->setCurrentIndex(cell<QComboBox>(table, 1, 0)->findText("Fixed wing"));
        QVERIFY(cell<QDoubleSpinBox>(table, 1, 1)->isEnabled());
        QCOMPARE(cell<QDoubleSpinBox>(table, 1, 1)->value(), 30.0);
        cell<QComboBox>(table, 1, 0)->setCurrentIndex(cell<QComboBox>(table, 1, 0)->findText("Rover"));
        QVERIFY(!cell<QDoubleSpinBox>(table, 1, 1)->isEnabled());
        // Nothing changed: no robot gets values of its own besides beta's.
        const auto vehicles = dialog.vehicles();
        QCOMPARE(vehicles.size(), std::size_t{3});
        QVERIFY(vehicles[0].empty());
        QVERIFY(vehicles[1] == threeRobots().robots[1].vehicle);
        QVERIFY(dialog.exports() == threeRobots().exports);
    }

    void robotsFollowTheDefaultRowUnlessTheyHaveTheirOwn() {
        ui::VehicleSettingsDialog dialog(threeRobots());
        auto* table = dialog.findChild<QTableWidget*>();
        cell<QDoubleSpinBox>(table, 0, 1)->setValue(40.0);
        cell<QSpinBox>(table, 0, 3)->setValue(250);
        QCOMPARE(cell<QDoubleSpinBox>(table, 1, 1)->value(), 40.0);
        QCOMPARE(cell<QDoubleSpinBox>(table, 2, 1)->value(), 60.0); // its own
        QCOMPARE(cell<QSpinBox>(table, 2, 3)->value(), 250);
        // A limit below the smallest that works stays as typed, holds OK back and is named; it is not
        // turned into "no limit" without a word.
        QSpinBox* limit = cell<QSpinBox>(table, 3, 3);
        auto* buttons = dialog.findChild<QDialogButtonBox*>();
        QVERIFY(buttons->button(QDialogButtonBox::Ok)->isEnabled());
        limit->setValue(5);
        QCOMPARE(limit->value(), 5);
        QVERIFY(!buttons->button(QDialogButtonBox::Ok)->isEnabled());
        QLabel* problem = nullptr;
        for (QLabel* label : dialog.findChildren<QLabel*>())
            if (label->text().contains(QStringLiteral("Too small")))
                problem = label;
        QVERIFY(problem != nullptr);
        QVERIFY(!problem->isHidden());
        QVERIFY2(problem->text().contains(QStringLiteral("5 (Robot 3)")), qPrintable(problem->text()));
        QVERIFY(problem->text().contains(QString::number(minimumMaxWaypoints)));
        // Robot 3 gets its own item limit: none.
        limit->setValue(0);
        QCOMPARE(limit->text(), QStringLiteral("no limit"));
        QVERIFY(buttons->button(QDialogButtonBox::Ok)->isEnabled());
        QVERIFY(problem->isHidden());
        const ExportSettings exports = dialog.exports();
        QCOMPARE(exports.vehicle.altitudeMetres, 40.0);
        QCOMPARE(exports.vehicle.maxWaypoints, 250);
        const auto vehicles = dialog.vehicles();
        QVERIFY(vehicles[0].empty());
        QCOMPARE(vehicles[1].altitudeMetres.value_or(-1.0), 60.0);
        QVERIFY(!vehicles[1].maxWaypoints);
        QCOMPARE(vehicles[2].maxWaypoints.value_or(-1), 0);
        QVERIFY(!vehicles[2].altitudeMetres);
    }

    // A limit every robot takes from the Default row is named once, beside a robot's own.
    void aProblemTheRobotsShareIsNamedOnce() {
        ui::VehicleSettingsDialog dialog(threeRobots());
        auto* table = dialog.findChild<QTableWidget*>();
        cell<QSpinBox>(table, 0, 3)->setValue(5);
        cell<QSpinBox>(table, 3, 3)->setValue(6);
        QString text;
        for (QLabel* label : dialog.findChildren<QLabel*>())
            if (label->text().contains(QStringLiteral("Too small")))
                text = label->text();
        QVERIFY2(text.contains(QStringLiteral("Too small: 5 (Default), 6 (Robot 3).")), qPrintable(text));
        QVERIFY2(!text.contains(QStringLiteral("alpha")), qPrintable(text));
    }

    // An aircraft's altitude above 120 m or below 5 m is allowed, with a caution naming the robot; a rover's
    // is not cautioned, as its files are on the ground.
    void unlikelyAltitudesAreCautioned() {
        ui::VehicleSettingsDialog dialog(threeRobots());
        auto* table = dialog.findChild<QTableWidget*>();
        auto* ok = dialog.findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok);
        const auto cautionShown = [&]() -> QLabel* {
            for (QLabel* label : dialog.findChildren<QLabel*>())
                if (label->text().contains(QStringLiteral("above home")) && !label->isHidden())
                    return label;
            return nullptr;
        };
        QVERIFY(cautionShown() == nullptr);
        cell<QDoubleSpinBox>(table, 2, 1)->setValue(500.0); // beta, a multirotor
        QLabel* caution = cautionShown();
        QVERIFY(caution != nullptr);
        QVERIFY2(caution->text().contains(QStringLiteral("Above 120 m (400 ft) above home")),
                 qPrintable(caution->text()));
        QVERIFY2(caution->text().contains(QStringLiteral("500 m (beta)")), qPrintable(caution->text()));
        QVERIFY(ok->isEnabled());
        cell<QDoubleSpinBox>(table, 2, 1)->setValue(2.0);
        QVERIFY2(caution->text().contains(QStringLiteral("trees and roofs: 2 m (beta)")),
                 qPrintable(caution->text()));
        cell<QDoubleSpinBox>(table, 2, 1)->setValue(60.0);
        QVERIFY(caution->isHidden());
        // alpha is a rover: however high its box says, nothing is cautioned.
        cell<QDoubleSpinBox>(table, 1, 1)->setValue(500.0);
        QVERIFY(caution->isHidden());
        cell<QComboBox>(table, 1, 0)->setCurrentIndex(cell<QComboBox>(table, 1, 0)->findText("Multirotor"));
        QVERIFY(!caution->isHidden());
        QVERIFY2(caution->text().contains(QStringLiteral("500 m (alpha)")), qPrintable(caution->text()));
    }

    // A flight time in minutes: all robots follow it, and one under a minute holds OK back.
    void flightTimeInMinutes() {
        ui::VehicleSettingsDialog dialog(threeRobots());
        auto* table = dialog.findChild<QTableWidget*>();
        QDoubleSpinBox* fleet = cell<QDoubleSpinBox>(table, 0, 4);
        QCOMPARE(fleet->text(), QStringLiteral("no limit"));
        fleet->setValue(25.0);
        QCOMPARE(cell<QDoubleSpinBox>(table, 2, 4)->value(), 25.0);
        cell<QDoubleSpinBox>(table, 1, 4)->setValue(0.5);
        auto* buttons = dialog.findChild<QDialogButtonBox*>();
        QVERIFY(!buttons->button(QDialogButtonBox::Ok)->isEnabled());
        bool named = false;
        for (QLabel* label : dialog.findChildren<QLabel*>())
            named =
                named || (!label->isHidden() && label->text().contains(QStringLiteral("0.5 min (alpha)")));
        QVERIFY(named);
        cell<QDoubleSpinBox>(table, 1, 4)->setValue(18.0);
        QVERIFY(buttons->button(QDialogButtonBox::Ok)->isEnabled());
        QCOMPARE(dialog.exports().vehicle.flightTimeSeconds, 1500.0);
        const auto vehicles = dialog.vehicles();
        QCOMPARE(vehicles[0].flightTimeSeconds.value_or(-1.0), 1080.0);
        QVERIFY(!vehicles[1].flightTimeSeconds);
    }

    // A turnaround in minutes beside the flight time: robots follow the fleet's, one keeps its own.
    void turnaroundInMinutes() {
        ui::VehicleSettingsDialog dialog(threeRobots());
        auto* table = dialog.findChild<QTableWidget*>();
        QCOMPARE(table->horizontalHeaderItem(5)->text(), QStringLiteral("Turnaround (min)"));
        cell<QDoubleSpinBox>(table, 2, 5)->setValue(2.0); // beta's own
        cell<QDoubleSpinBox>(table, 0, 5)->setValue(5.0);
        QCOMPARE(cell<QDoubleSpinBox>(table, 1, 5)->value(), 5.0);
        QCOMPARE(cell<QDoubleSpinBox>(table, 2, 5)->value(), 2.0);
        QCOMPARE(dialog.exports().vehicle.turnaroundSeconds, 300.0);
        const auto vehicles = dialog.vehicles();
        QVERIFY(!vehicles[0].turnaroundSeconds);
        QCOMPARE(vehicles[1].turnaroundSeconds.value_or(-1.0), 120.0);
    }

    // A distance between photos: none shown as "no camera"; robots follow the fleet's, one keeps its own.
    void cameraTriggerInMetres() {
        ui::VehicleSettingsDialog dialog(threeRobots());
        auto* table = dialog.findChild<QTableWidget*>();
        QCOMPARE(table->horizontalHeaderItem(6)->text(), QStringLiteral("Photo every (m)"));
        QCOMPARE(cell<QDoubleSpinBox>(table, 0, 6)->text(), QStringLiteral("no camera"));
        cell<QDoubleSpinBox>(table, 2, 6)->setValue(30.0); // beta's own
        cell<QDoubleSpinBox>(table, 0, 6)->setValue(48.0);
        QCOMPARE(cell<QDoubleSpinBox>(table, 1, 6)->value(), 48.0);
        QCOMPARE(cell<QDoubleSpinBox>(table, 2, 6)->value(), 30.0);
        QCOMPARE(dialog.exports().vehicle.cameraTriggerMetres, 48.0);
        const auto vehicles = dialog.vehicles();
        QVERIFY(!vehicles[0].cameraTriggerMetres);
        QCOMPARE(vehicles[1].cameraTriggerMetres.value_or(-1.0), 30.0);
    }

    // Values the boxes cannot show exactly come back unchanged: OK without an edit changes nothing.
    void untouchedValuesComeBackUnchanged() {
        Mission mission = threeRobots();
        mission.exports.speedTolerance = 0.1234;
        mission.exports.vehicle.altitudeMetres = 30.125;
        mission.exports.vehicle.maxWaypoints = 0;
        mission.exports.vehicle.flightTimeSeconds = 1000.0;  // 16.667 min in the box
        mission.exports.vehicle.turnaroundSeconds = 100.0;   // 1.667 min
        mission.exports.vehicle.cameraTriggerMetres = 12.25; // 12.3 m
        ui::VehicleSettingsDialog dialog(mission);
        QVERIFY(dialog.exports() == mission.exports);
        const auto vehicles = dialog.vehicles();
        QVERIFY(vehicles[0].empty());
        QVERIFY(vehicles[1] == mission.robots[1].vehicle);
    }

    void speedToleranceInPercent() {
        Mission mission = threeRobots();
        mission.exports.speedTolerance = 0.2;
        ui::VehicleSettingsDialog dialog(mission);
        auto spins = dialog.findChildren<QDoubleSpinBox*>();
        QDoubleSpinBox* tolerance = nullptr;
        for (QDoubleSpinBox* spin : spins)
            if (spin->suffix() == QStringLiteral(" %"))
                tolerance = spin;
        QVERIFY(tolerance != nullptr);
        QCOMPARE(tolerance->value(), 20.0);
        QCOMPARE(dialog.exports().speedTolerance, 0.2);
        tolerance->setValue(5.0);
        QCOMPARE(dialog.exports().speedTolerance, 0.05);
        auto* atTurns = dialog.findChild<QCheckBox*>();
        QVERIFY(atTurns != nullptr && !atTurns->isChecked());
        atTurns->setChecked(true);
        QVERIFY(dialog.exports().speedChangesAtTurnsOnly);
    }
};

QTEST_MAIN(VehicleSettingsDialogTest)
#include "test_vehicle_settings_dialog.moc"
