#pragma once

#include "core/model/MapPoint.hpp"

#include <QAbstractTableModel>

class QUndoStack;

namespace mcpp::ui {

class MissionDocument;

// The robots of the open mission: name, colour, start in the map CRS and in WGS84, and for planners that
// fly on batteries the robot's own battery and its charger (empty: at its start). Edits go through the undo
// stack; a value the mission would refuse is reported through editRefused.
class RobotTableModel : public QAbstractTableModel {
    Q_OBJECT

  public:
    enum Column {
        Name,
        Colour,
        Easting,
        Northing,
        Longitude,
        Latitude,
        Battery,
        ChargerEasting,
        ChargerNorthing,
        ColumnCount
    };

    RobotTableModel(MissionDocument* document, QUndoStack* undoStack, QObject* parent = nullptr);

    [[nodiscard]] int rowCount(const QModelIndex& parent = {}) const override;
    [[nodiscard]] int columnCount(const QModelIndex& parent = {}) const override;
    [[nodiscard]] QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    [[nodiscard]] QVariant headerData(int section, Qt::Orientation orientation,
                                      int role = Qt::DisplayRole) const override;
    [[nodiscard]] Qt::ItemFlags flags(const QModelIndex& index) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;

    // The undoable robot edits the canvas and the buttons use. Each returns false, and says why through
    // editRefused, when the start is not allowed.
    bool addRobot(MapPoint start);
    bool moveRobot(int robot, MapPoint start);
    bool removeRobot(int robot);

  signals:
    void editRefused(const QString& reason);

  private:
    bool refuse(const QString& reason);
    bool setBattery(int robot, const QString& text);
    // Whose battery the robot plans on: its own, its vehicle's flight time or the planner's.
    [[nodiscard]] QString batteryToolTip(int robot) const;
    bool setCharger(int robot, int column, const QString& text);

    MissionDocument* document_;
    QUndoStack* undoStack_;
    int shownRows_ = 0; // the rows the views were last told of
};

} // namespace mcpp::ui
