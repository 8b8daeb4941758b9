#include "ui/RobotTableModel.hpp"

#include "core/model/BatteryEndurance.hpp"
#include "core/model/HumanUnits.hpp"
#include "render/RobotPalette.hpp"
#include "ui/MissionDocument.hpp"
#include "ui/RobotsEditCommand.hpp"

#include <QRegularExpression>
#include <QUndoStack>
#include <cmath>

namespace mcpp::ui {

RobotTableModel::RobotTableModel(MissionDocument* document, QUndoStack* undoStack, QObject* parent)
    : QAbstractTableModel(parent), document_(document), undoStack_(undoStack),
      shownRows_(static_cast<int>(document_->robots().size())) {
    auto reset = [this] {
        beginResetModel();
        shownRows_ = rowCount();
        endResetModel();
    };
    // An edit in the table changes the robots from within the view's commit: resetting then would pull the
    // editor from under it, so rows that stay are only redrawn.
    connect(document_, &MissionDocument::robotsChanged, this, [this, reset] {
        if (rowCount() != shownRows_)
            reset();
        else if (shownRows_ > 0)
            emit dataChanged(index(0, 0), index(shownRows_ - 1, ColumnCount - 1));
    });
    connect(document_, &MissionDocument::mapChanged, this, reset);
}

int RobotTableModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : static_cast<int>(document_->robots().size());
}

int RobotTableModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QString RobotTableModel::batteryToolTip(int robot) const {
    const io::RobotSpec& spec = document_->robots()[static_cast<std::size_t>(robot)];
    if (spec.batterySeconds)
        return tr("%1 of travel on one charge")
            .arg(QString::fromStdString(formatDuration(*spec.batterySeconds)));
    const double fromVehicle =
        io::vehicleBatterySeconds(spec.vehicle.over(document_->mission().exports.vehicle));
    if (fromVehicle > 0.0)
        return tr("Its vehicle's flight time less the climb and descent: %1 of travel on one charge (type "
                  "minutes here to give this robot its own)")
            .arg(QString::fromStdString(formatDuration(fromVehicle)));
    return tr("The planner's battery endurance (type minutes here to give this robot its own)");
}

QVariant RobotTableModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= rowCount())
        return {};
    const io::RobotSpec& robot = document_->robots()[static_cast<std::size_t>(index.row())];
    const bool text = role == Qt::DisplayRole || role == Qt::EditRole;
    switch (index.column()) {
    case Name:
        if (text)
            return QString::fromStdString(robot.name);
        if (role == Qt::DecorationRole) // the colour beside the name, as in the results and the legend
            return render::RobotPalette::colour(index.row());
        break;
    case Colour:
        if (role == Qt::DecorationRole)
            return render::RobotPalette::colour(index.row());
        if (role == Qt::ToolTipRole)
            return render::RobotPalette::colour(index.row()).name();
        break;
    case Easting:
        if (text)
            return QString::number(robot.start.x, 'f', role == Qt::EditRole ? 3 : 0);
        break;
    case Northing:
        if (text)
            return QString::number(robot.start.y, 'f', role == Qt::EditRole ? 3 : 0);
        break;
    case Longitude:
    case Latitude: {
        if (!text || document_->raster() == nullptr)
            break;
        const auto lonLat = document_->raster()->georeference.toWgs84(robot.start);
        if (!lonLat.ok())
            return QStringLiteral("–");
        const double degrees =
            index.column() == Longitude ? lonLat.value().longitude : lonLat.value().latitude;
        return QString::number(degrees, 'f', role == Qt::EditRole ? 7 : 5); // 5 decimals: about a metre
    }
    case Battery:
        if (text && robot.batterySeconds) // all the digits to edit: a cell tabbed through changes nothing
            return QString::fromStdString(
                formatQuantity(*robot.batterySeconds / 60.0, role == Qt::EditRole ? 15 : 4));
        if (role == Qt::ToolTipRole)
            return batteryToolTip(index.row());
        break;
    case ChargerEasting:
    case ChargerNorthing:
        if (text && robot.charger)
            return QString::number(index.column() == ChargerEasting ? robot.charger->x : robot.charger->y,
                                   'f', role == Qt::EditRole ? 3 : 0);
        if (role == Qt::ToolTipRole)
            return robot.charger
                       ? tr("Where this robot charges; every sortie ends here (empty: at its start)")
                       : tr("At its start (type a coordinate, or \"x, y\", to place the charger elsewhere)");
        break;
    default:
        break;
    }
    if (role == Qt::TextAlignmentRole && index.column() >= Easting)
        return QVariant::fromValue(Qt::Alignment(Qt::AlignRight | Qt::AlignVCenter));
    return {};
}

QVariant RobotTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    if (orientation == Qt::Vertical)
        return section + 1;
    switch (section) {
    case Name:
        return tr("Name");
    case Colour:
        return tr("Colour");
    case Easting:
        return tr("X (m)");
    case Northing:
        return tr("Y (m)");
    case Longitude:
        return tr("Longitude");
    case Latitude:
        return tr("Latitude");
    case Battery:
        return tr("Battery (min)");
    case ChargerEasting:
        return tr("Charger X (m)");
    case ChargerNorthing:
        return tr("Charger Y (m)");
    default:
        return {};
    }
}

Qt::ItemFlags RobotTableModel::flags(const QModelIndex& index) const {
    if (!index.isValid())
        return Qt::NoItemFlags;
    Qt::ItemFlags result = Qt::ItemIsEnabled | Qt::ItemIsSelectable;
    if (index.column() != Colour)
        result |= Qt::ItemIsEditable;
    return result;
}

bool RobotTableModel::refuse(const QString& reason) {
    emit editRefused(reason);
    return false;
}

bool RobotTableModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    if (!index.isValid() || role != Qt::EditRole || index.row() >= rowCount())
        return false;
    const int row = index.row();
    const io::RobotSpec& robot = document_->robots()[static_cast<std::size_t>(row)];
    if (index.column() == Name) {
        const QString name = value.toString().trimmed();
        if (name.isEmpty())
            return refuse(tr("A robot name cannot be empty."));
        if (name.toStdString() == robot.name)
            return true;
        auto after = document_->robots();
        after[static_cast<std::size_t>(row)].name = name.toStdString();
        undoStack_->push(
            new RobotsEditCommand(document_, document_->robots(), after, tr("Rename %1").arg(name)));
        return true;
    }
    if (index.column() == Battery)
        return setBattery(row, value.toString());
    if (index.column() == ChargerEasting || index.column() == ChargerNorthing)
        return setCharger(row, index.column(), value.toString());
    bool isNumber = false;
    const double number = value.toString().trimmed().toDouble(&isNumber);
    if (!isNumber)
        return refuse(tr("\"%1\" is not a number.").arg(value.toString()));
    MapPoint start = robot.start;
    if (index.column() == Easting)
        start.x = number;
    else if (index.column() == Northing)
        start.y = number;
    else if (index.column() == Longitude || index.column() == Latitude) {
        const io::LoadedRaster* raster = document_->raster();
        if (raster == nullptr)
            return false;
        auto lonLat = raster->georeference.toWgs84(robot.start);
        if (!lonLat.ok())
            return refuse(tr("The map has no CRS, so longitude and latitude cannot be used."));
        io::LonLat edited = lonLat.value();
        (index.column() == Longitude ? edited.longitude : edited.latitude) = number;
        const auto point = raster->georeference.fromWgs84(edited);
        if (!point.ok())
            return refuse(QString::fromStdString(point.error()));
        start = point.value();
    } else {
        return false;
    }
    return moveRobot(row, start);
}

// Minutes, or a number with its unit ("90 s", "1.5 h"); empty gives the robot the planner's battery again.
bool RobotTableModel::setBattery(int robot, const QString& text) {
    static const QRegularExpression pattern(
        QStringLiteral(R"(^\s*([-+]?[0-9]*\.?[0-9]+(?:[eE][-+]?[0-9]+)?)\s*(s|min|h)?\s*$)"));
    std::optional<double> seconds;
    if (!text.trimmed().isEmpty()) {
        const QRegularExpressionMatch match = pattern.match(text);
        if (!match.hasMatch())
            return refuse(tr("Battery: \"%1\" is not a duration; type minutes, or a number with s, min or h.")
                              .arg(text));
        const QString unit = match.captured(2);
        const double perUnit = unit == QLatin1String("s") ? 1.0 : unit == QLatin1String("h") ? 3600.0 : 60.0;
        seconds = match.captured(1).toDouble() * perUnit;
        if (const auto problem = BatteryEndurance::problem(*seconds))
            return refuse(tr("Battery: %1.").arg(QString::fromStdString(*problem)));
    }
    auto after = document_->robots();
    auto& edited = after[static_cast<std::size_t>(robot)];
    const bool same = edited.batterySeconds.has_value() == seconds.has_value() &&
                      (!seconds || std::abs(*seconds - *edited.batterySeconds) <= 1e-9 * *seconds);
    if (same)
        return true;
    edited.batterySeconds = seconds;
    undoStack_->push(new RobotsEditCommand(document_, document_->robots(), after,
                                           tr("Battery of %1").arg(QString::fromStdString(edited.name))));
    return true;
}

// One coordinate of the charger (the other is the start's until given), or both as "x, y" in either
// column. Empty puts it back at the start.
bool RobotTableModel::setCharger(int robot, int column, const QString& text) {
    auto after = document_->robots();
    auto& edited = after[static_cast<std::size_t>(robot)];
    std::optional<MapPoint> charger;
    if (!text.trimmed().isEmpty()) {
        const QStringList parts = text.trimmed().split(QRegularExpression(QStringLiteral("[,;\\s]+")));
        std::vector<double> numbers;
        for (const QString& part : parts) {
            bool isNumber = false;
            numbers.push_back(part.toDouble(&isNumber));
            if (!isNumber || numbers.size() > 2)
                return refuse(tr("Charger: \"%1\" is not a coordinate, nor \"x, y\".").arg(text));
        }
        charger = edited.charger.value_or(edited.start);
        if (numbers.size() == 2)
            charger = MapPoint{numbers[0], numbers[1]};
        else
            (column == ChargerEasting ? charger->x : charger->y) = numbers.front();
        if (const auto problem = document_->startProblem(*charger, robot, tr("Charger")))
            return refuse(*problem);
    }
    if (edited.charger == charger)
        return true;
    edited.charger = charger;
    undoStack_->push(new RobotsEditCommand(document_, document_->robots(), after,
                                           tr("Charger of %1").arg(QString::fromStdString(edited.name))));
    return true;
}

bool RobotTableModel::addRobot(MapPoint start) {
    if (const auto problem = document_->startProblem(start, -1, {}, document_->robotFlies(-1)))
        return refuse(*problem);
    auto after = document_->robots();
    io::RobotSpec robot;
    robot.name = document_->nextRobotName().toStdString();
    robot.start = start;
    after.push_back(robot);
    undoStack_->push(new RobotsEditCommand(document_, document_->robots(), after,
                                           tr("Add %1").arg(QString::fromStdString(robot.name))));
    return true;
}

bool RobotTableModel::moveRobot(int robot, MapPoint start) {
    if (robot < 0 || robot >= rowCount())
        return false;
    if (const auto problem = document_->startProblem(start, robot, {}, document_->robotFlies(robot)))
        return refuse(*problem);
    auto after = document_->robots();
    auto& moved = after[static_cast<std::size_t>(robot)];
    if (moved.start == start)
        return true;
    moved.start = start; // saved in its start_crs still, where it has one
    undoStack_->push(new RobotsEditCommand(document_, document_->robots(), after,
                                           tr("Move %1").arg(QString::fromStdString(moved.name))));
    return true;
}

bool RobotTableModel::removeRobot(int robot) {
    if (robot < 0 || robot >= rowCount())
        return false;
    auto after = document_->robots();
    const QString name = QString::fromStdString(after[static_cast<std::size_t>(robot)].name);
    after.erase(after.begin() + robot);
    undoStack_->push(new RobotsEditCommand(document_, document_->robots(), after, tr("Remove %1").arg(name)));
    return true;
}

} // namespace mcpp::ui
