#include "ui/ClassTableModel.hpp"

#include "ui/ClassTableEditCommand.hpp"
#include "ui/MissionDocument.hpp"

#include <QBrush>
#include <QColor>
#include <QUndoStack>
#include <cmath>

namespace mcpp::ui {

namespace {

QColor colourOf(const LandCoverClass& landCoverClass) {
    return QColor::fromRgb(static_cast<QRgb>(landCoverClass.colorRgb & 0xffffffu));
}

QString number(double value) {
    return QString::number(value, 'g', 10);
}

} // namespace

ClassTableModel::ClassTableModel(MissionDocument* document, QUndoStack* undoStack, QObject* parent)
    : QAbstractTableModel(parent), document_(document), undoStack_(undoStack) {
    connect(document_, &MissionDocument::classesChanged, this, &ClassTableModel::reload);
    connect(document_, &MissionDocument::mapChanged, this, &ClassTableModel::reload);
    reload();
}

void ClassTableModel::reload() {
    beginResetModel();
    const io::LoadedRaster* raster = document_->raster();
    static const std::map<std::int32_t, std::int64_t> noCounts;
    const auto& counts = raster != nullptr ? raster->classPixelCounts : noCounts;
    // Classes absent from the raster take no part; without counts (no raster) every class does.
    std::vector<std::int32_t> present;
    for (const LandCoverClass& landCoverClass : document_->classes().classes()) {
        const auto found = counts.find(landCoverClass.value);
        if (counts.empty() || (found != counts.end() && found->second > 0))
            present.push_back(landCoverClass.value);
    }
    rounded_.clear();
    for (const mcpp::RoundedFieldOfView& entry : roundFieldsOfView(document_->classes(), present))
        rounded_[entry.classValue] = entry;
    insidePixels_ = 0;
    for (const auto& [value, count] : counts)
        insidePixels_ += count;
    endResetModel();
}

int ClassTableModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : static_cast<int>(document_->classes().size());
}

int ClassTableModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

int ClassTableModel::rowOfValue(std::int32_t value) const {
    const auto& classes = document_->classes().classes();
    for (std::size_t row = 0; row < classes.size(); ++row)
        if (classes[row].value == value)
            return static_cast<int>(row);
    return -1;
}

QVariant ClassTableModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= rowCount())
        return {};
    const LandCoverClass& landCoverClass =
        document_->classes().classes()[static_cast<std::size_t>(index.row())];
    const auto rounded = rounded_.find(landCoverClass.value);
    const bool hasRounded = rounded != rounded_.end();
    const bool display = role == Qt::DisplayRole;
    const bool edit = role == Qt::EditRole;

    switch (index.column()) {
    case Value:
        if (display || edit)
            return landCoverClass.value;
        break;
    case Colour:
        if (role == Qt::DecorationRole)
            return colourOf(landCoverClass);
        if (role == Qt::ToolTipRole)
            return colourOf(landCoverClass).name();
        break;
    case Name:
        if (display || edit)
            return QString::fromStdString(landCoverClass.name);
        break;
    case Speed:
        if (display || edit)
            return number(landCoverClass.speedMetresPerSecond);
        break;
    case FieldOfView:
        if (display || edit)
            return number(landCoverClass.fieldOfViewMetres);
        break;
    case Passable:
        if (role == Qt::CheckStateRole)
            return landCoverClass.passable ? Qt::Checked : Qt::Unchecked;
        break;
    case Detection:
        if (display)
            return landCoverClass.detectionProbability ? number(*landCoverClass.detectionProbability)
                                                       : tr("default");
        if (edit)
            return landCoverClass.detectionProbability ? number(*landCoverClass.detectionProbability)
                                                       : QString();
        break;
    case RoundedFieldOfView:
        if (display)
            return hasRounded ? number(rounded->second.roundedMetres) : QStringLiteral("–");
        break;
    case Level:
        if (display)
            return hasRounded ? QVariant(rounded->second.level) : QVariant(QStringLiteral("–"));
        break;
    case Share: {
        if (!display)
            break;
        const io::LoadedRaster* raster = document_->raster();
        if (raster == nullptr || insidePixels_ == 0)
            return QStringLiteral("–");
        const auto found = raster->classPixelCounts.find(landCoverClass.value);
        const double share =
            found == raster->classPixelCounts.end()
                ? 0.0
                : 100.0 * static_cast<double>(found->second) / static_cast<double>(insidePixels_);
        return QStringLiteral("%1 %").arg(share, 0, 'f', share < 1.0 ? 2 : 1);
    }
    default:
        break;
    }
    if (role == Qt::TextAlignmentRole && index.column() != Name)
        return QVariant::fromValue(Qt::Alignment(Qt::AlignRight | Qt::AlignVCenter));
    if (role == Qt::ForegroundRole && !landCoverClass.isTraversable())
        return QBrush(QColor(130, 130, 130));
    if (role == Qt::ToolTipRole) {
        if (index.column() == RoundedFieldOfView)
            return tr("The FOV rounded down to the smallest passable FOV times a power of two; the quadtree "
                      "uses this width.");
        if (index.column() == Level)
            return tr("Quadtree level whose sub-cells have this class's rounded FOV (1 = largest cells).");
        if (index.column() == Share)
            return tr("Share of the raster's task-area pixels in this class.");
        if (index.column() == Detection)
            return tr("For CPPIED: the chance one pass sees a target right beside it in this land cover (0 "
                      "to 1); empty: the planner's sensor detection.");
        if (!landCoverClass.isTraversable())
            return tr("Obstacle: robots do not enter this class.");
    }
    return {};
}

QVariant ClassTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
    case Value:
        return tr("Value");
    case Colour:
        return tr("Colour");
    case Name:
        return tr("Name");
    case Speed:
        return tr("Speed (m/s)");
    case FieldOfView:
        return tr("FOV (m)");
    case Passable:
        return tr("Passable");
    case Detection:
        return tr("Detection");
    case RoundedFieldOfView:
        return tr("Rounded FOV (m)");
    case Level:
        return tr("Level");
    case Share:
        return tr("Share");
    default:
        return {};
    }
}

Qt::ItemFlags ClassTableModel::flags(const QModelIndex& index) const {
    if (!index.isValid())
        return Qt::NoItemFlags;
    Qt::ItemFlags result = Qt::ItemIsEnabled | Qt::ItemIsSelectable;
    if (index.column() == Name || index.column() == Speed || index.column() == FieldOfView ||
        index.column() == Detection)
        result |= Qt::ItemIsEditable;
    if (index.column() == Passable)
        result |= Qt::ItemIsUserCheckable;
    return result;
}

bool ClassTableModel::refuse(const QString& reason) {
    lastRefusal_ = reason;
    emit editRefused(reason);
    return false;
}

QString ClassTableModel::speedProblem(double speed, const QString& className) {
    if (!std::isfinite(speed))
        return tr("Speed of %1 must be a finite number.").arg(className);
    if (speed < 0.0)
        return tr("Speed of %1 cannot be negative; use 0 or clear Passable to make it an obstacle.")
            .arg(className);
    if (speed > kMaximumSpeedMetresPerSecond)
        return tr("Speed of %1 cannot be above %2 m/s.").arg(className).arg(kMaximumSpeedMetresPerSecond);
    return {};
}

QString ClassTableModel::fieldOfViewProblem(double fieldOfView, const QString& className) {
    if (!std::isfinite(fieldOfView))
        return tr("FOV of %1 must be a finite number.").arg(className);
    if (fieldOfView <= 0.0)
        return tr("FOV of %1 must be greater than 0 m.").arg(className);
    if (fieldOfView > kMaximumFieldOfViewMetres)
        return tr("FOV of %1 cannot be above %2 m.").arg(className).arg(kMaximumFieldOfViewMetres);
    return {};
}

bool ClassTableModel::editRows(const QList<int>& rows, const ClassBulkEdit& edit) {
    if (rows.isEmpty())
        return refuse(tr("Select the classes to change first (click rows with Ctrl or Shift)."));
    if (!(edit.fieldOfViewFactor > 0.0) || !std::isfinite(edit.fieldOfViewFactor))
        return refuse(tr("The FOV factor must be a number greater than 0."));
    const ClassTable before = document_->classes();
    ClassTable after = before;
    for (const int row : rows) {
        if (row < 0 || row >= rowCount())
            continue;
        LandCoverClass edited = before.classes()[static_cast<std::size_t>(row)];
        const QString className = QString::fromStdString(edited.name);
        if (edit.speed) {
            if (const QString problem = speedProblem(*edit.speed, className); !problem.isEmpty())
                return refuse(problem);
            edited.speedMetresPerSecond = *edit.speed;
        }
        if (edit.fieldOfView)
            edited.fieldOfViewMetres = *edit.fieldOfView;
        edited.fieldOfViewMetres *= edit.fieldOfViewFactor;
        if (const QString problem = fieldOfViewProblem(edited.fieldOfViewMetres, className);
            !problem.isEmpty())
            return refuse(problem);
        if (edit.passable)
            edited.passable = *edit.passable;
        after.set(edited);
    }
    if (after == before)
        return true;
    const QString preset = QString::fromStdString(document_->mission().preset);
    undoStack_->push(
        new ClassTableEditCommand(document_, before, preset, after, preset,
                                  tr("Edit %n classes", nullptr, static_cast<int>(rows.size()))));
    lastRefusal_.clear();
    return true;
}

bool ClassTableModel::setDetection(LandCoverClass& edited, const QString& text, const QString& className,
                                   QString& description) {
    if (text.isEmpty()) {
        edited.detectionProbability.reset();
        description = tr("Use the planner's detection for %1").arg(className);
        return true;
    }
    bool isNumber = false;
    const double probability = text.toDouble(&isNumber);
    if (!isNumber || !(probability >= 0.0 && probability <= 1.0))
        return refuse(tr("Detection of %1 must be a probability from 0 to 1; \"%2\" is not. Leave it empty "
                         "for the planner's.")
                          .arg(className, text));
    edited.detectionProbability = probability;
    description = tr("Set detection of %1 to %2").arg(className).arg(probability);
    return true;
}

bool ClassTableModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    if (!index.isValid() || index.row() >= rowCount())
        return false;
    const ClassTable before = document_->classes();
    LandCoverClass edited = before.classes()[static_cast<std::size_t>(index.row())];
    const QString className = QString::fromStdString(edited.name);
    QString description;

    if (index.column() == Passable && role == Qt::CheckStateRole) {
        edited.passable = value.toInt() == Qt::Checked;
        description = edited.passable ? tr("Make %1 passable").arg(className)
                                      : tr("Make %1 an obstacle").arg(className);
    } else if (role != Qt::EditRole) {
        return false;
    } else if (index.column() == Name) {
        const QString name = value.toString().trimmed();
        if (name.isEmpty())
            return refuse(tr("A class name cannot be empty."));
        edited.name = name.toStdString();
        description = tr("Rename class %1").arg(edited.value);
    } else if (index.column() == Detection) {
        if (!setDetection(edited, value.toString().trimmed(), className, description))
            return false;
    } else if (index.column() == Speed || index.column() == FieldOfView) {
        bool isNumber = false;
        const double number = value.toString().trimmed().toDouble(&isNumber);
        const QString what = index.column() == Speed ? tr("Speed") : tr("FOV");
        if (!isNumber)
            return refuse(
                tr("%1 of %2 must be a number; \"%3\" is not.").arg(what, className, value.toString()));
        if (!std::isfinite(number))
            return refuse(tr("%1 of %2 must be a finite number.").arg(what, className));
        if (index.column() == Speed) {
            if (const QString problem = speedProblem(number, className); !problem.isEmpty())
                return refuse(problem);
            edited.speedMetresPerSecond = number;
            description = tr("Set speed of %1 to %2 m/s").arg(className).arg(number);
        } else {
            if (const QString problem = fieldOfViewProblem(number, className); !problem.isEmpty())
                return refuse(problem);
            edited.fieldOfViewMetres = number;
            description = tr("Set FOV of %1 to %2 m").arg(className).arg(number);
        }
    } else {
        return false;
    }

    if (edited == before.classes()[static_cast<std::size_t>(index.row())])
        return true;
    ClassTable after = before;
    after.set(edited);
    const QString preset = QString::fromStdString(document_->mission().preset);
    undoStack_->push(new ClassTableEditCommand(document_, before, preset, after, preset, description));
    lastRefusal_.clear();
    return true;
}

} // namespace mcpp::ui
