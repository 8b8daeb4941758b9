#pragma once

#include "io/Mission.hpp"

#include <QDialog>
#include <vector>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace mcpp::ui {

// The robots' autopilots: vehicle type, altitude, cruise speed and item limit as defaults and for each
// one, and the speed tolerance of waypoint files. A robot whose value equals the Default row follows
// that row when it changes.
class VehicleSettingsDialog : public QDialog {
    Q_OBJECT

  public:
    VehicleSettingsDialog(const io::Mission& mission, QWidget* parent = nullptr);

    [[nodiscard]] io::ExportSettings exports() const;
    // Each robot's own values: only those that differ from the Default row.
    [[nodiscard]] std::vector<io::VehicleOverrides> vehicles() const;

  private:
    struct Row {
        QComboBox* type = nullptr;
        QDoubleSpinBox* altitude = nullptr;
        QDoubleSpinBox* cruiseSpeed = nullptr;
        QSpinBox* maxWaypoints = nullptr;
        QDoubleSpinBox* flightTime = nullptr; // minutes
        // The flight time as given and as the box shows it: minutes to three decimals lose a seconds value
        // such as 1000 s, so a box left as shown gives back the value as given.
        double flightSeconds = 0.0;
        double flightMinutesShown = 0.0;
        QDoubleSpinBox* turnaround = nullptr; // minutes, given and shown as the flight time
        double turnaroundSeconds = 0.0;
        double turnaroundMinutesShown = 0.0;
        QDoubleSpinBox* cameraTrigger = nullptr; // metres between photos; 0: no camera commands
        // The distance as given and as the box shows it, to a tenth of a metre: 12.25 m left as shown
        // stays 12.25 m.
        double cameraTriggerMetres = 0.0;
        double cameraTriggerShown = 0.0;
    };

    Row addRow(int row, const QString& name, const io::VehicleSettings& settings);
    [[nodiscard]] static io::VehicleSettings settingsOf(const Row& row);
    static void show(Row& row, const io::VehicleSettings& settings);
    void followDefaults();
    // An item limit or flight time between 0 (none) and the smallest that works holds OK back and says why.
    void checkLimits();

    io::ExportSettings exports_;
    QTableWidget* table_ = nullptr;
    QDoubleSpinBox* speedTolerance_ = nullptr;
    QCheckBox* atTurnsOnly_ = nullptr;
    QLabel* problem_ = nullptr;
    QLabel* caution_ = nullptr; // altitudes allowed but most likely not meant
    QPushButton* okButton_ = nullptr;
    double shownTolerance_ = 0.0;
    std::vector<Row> rows_; // the Default row first
    io::VehicleSettings shownDefaults_;
};

} // namespace mcpp::ui
