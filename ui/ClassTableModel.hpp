#pragma once

#include "core/decomposition/FieldOfViewRounding.hpp"

#include <QAbstractTableModel>
#include <map>

class QUndoStack;

namespace mcpp::ui {

class MissionDocument;

// The land-cover classes of the open mission as an editable table. Every accepted edit goes through the
// undo stack; a refused edit leaves the table as it was and says why through editRefused.
class ClassTableModel : public QAbstractTableModel {
    Q_OBJECT

  public:
    enum Column {
        Value,
        Colour,
        Name,
        Speed,
        FieldOfView,
        Passable,
        RoundedFieldOfView,
        Level,
        Share,
        ColumnCount
    };

    ClassTableModel(MissionDocument* document, QUndoStack* undoStack, QObject* parent = nullptr);

    [[nodiscard]] int rowCount(const QModelIndex& parent = {}) const override;
    [[nodiscard]] int columnCount(const QModelIndex& parent = {}) const override;
    [[nodiscard]] QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    [[nodiscard]] QVariant headerData(int section, Qt::Orientation orientation,
                                      int role = Qt::DisplayRole) const override;
    [[nodiscard]] Qt::ItemFlags flags(const QModelIndex& index) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;

    // The row showing a raster value, or -1.
    [[nodiscard]] int rowOfValue(std::int32_t value) const;
    [[nodiscard]] const QString& lastRefusal() const { return lastRefusal_; }

  signals:
    void editRefused(const QString& reason);

  private:
    void reload();
    bool refuse(const QString& reason);

    MissionDocument* document_;
    QUndoStack* undoStack_;
    std::map<std::int32_t, mcpp::RoundedFieldOfView> rounded_;
    std::int64_t insidePixels_ = 0;
    QString lastRefusal_;
};

} // namespace mcpp::ui
