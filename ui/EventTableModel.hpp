#pragma once

#include <QAbstractTableModel>

class QUndoStack;

namespace mcpp::ui {

class MissionDocument;

// The mission's events, one per row: when (seconds from the start), which robot (from 0, named) and its
// speed factor from then on. Edits go through the undo stack; a value the planner would refuse is refused
// here with the reason, through editRefused.
class EventTableModel : public QAbstractTableModel {
    Q_OBJECT

  public:
    enum Column { Time, Robot, SpeedFactor, ColumnCount };

    EventTableModel(MissionDocument* document, QUndoStack* undoStack, QObject* parent = nullptr);

    [[nodiscard]] int rowCount(const QModelIndex& parent = {}) const override;
    [[nodiscard]] int columnCount(const QModelIndex& parent = {}) const override;
    [[nodiscard]] QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    [[nodiscard]] QVariant headerData(int section, Qt::Orientation orientation,
                                      int role = Qt::DisplayRole) const override;
    [[nodiscard]] Qt::ItemFlags flags(const QModelIndex& index) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;

    // A new event 10 minutes after the latest one: the first robot at half speed. False, with the reason,
    // without robots.
    bool addEvent();
    bool removeEvent(int row);

  signals:
    void editRefused(const QString& reason);

  private:
    bool refuse(const QString& reason);

    MissionDocument* document_;
    QUndoStack* undoStack_;
};

} // namespace mcpp::ui
