#pragma once

#include "core/decomposition/FieldOfViewRounding.hpp"

#include <QAbstractTableModel>
#include <map>
#include <optional>

class QUndoStack;

namespace mcpp::ui {

class MissionDocument;

// One change to several classes at once; each part left empty keeps that column as it is. The FOV factor
// applies after a new FOV, so "scale every FOV by 2" is the factor alone.
struct ClassBulkEdit {
    std::optional<double> speed;
    std::optional<double> fieldOfView;
    std::optional<bool> passable;
    double fieldOfViewFactor = 1.0;
};

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
        Detection,
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

    // Applies the edit to these rows as one undoable step; refused whole (nothing changes) when any row
    // would get a value a single edit would refuse.
    bool editRows(const QList<int>& rows, const ClassBulkEdit& edit);
    // The row showing a raster value, or -1.
    [[nodiscard]] int rowOfValue(std::int32_t value) const;
    [[nodiscard]] const QString& lastRefusal() const { return lastRefusal_; }

  signals:
    void editRefused(const QString& reason);

  private:
    // Empty when the value is fine, else why not, naming the class.
    [[nodiscard]] static QString speedProblem(double speed, const QString& className);
    [[nodiscard]] static QString fieldOfViewProblem(double fieldOfView, const QString& className);
    // Sets or clears (empty text) a class's own detection probability; false when refused.
    bool setDetection(LandCoverClass& edited, const QString& text, const QString& className,
                      QString& description);
    void reload();
    bool refuse(const QString& reason);

    MissionDocument* document_;
    QUndoStack* undoStack_;
    std::map<std::int32_t, mcpp::RoundedFieldOfView> rounded_;
    std::int64_t insidePixels_ = 0;
    QString lastRefusal_;
};

} // namespace mcpp::ui
