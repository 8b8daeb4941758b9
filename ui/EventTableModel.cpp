#include "ui/EventTableModel.hpp"

#include "core/model/HumanUnits.hpp"
#include "core/model/SpeedEventCheck.hpp"
#include "ui/EventsEditCommand.hpp"
#include "ui/MissionDocument.hpp"

#include <QUndoStack>
#include <algorithm>
#include <cmath>

namespace mcpp::ui {

EventTableModel::EventTableModel(MissionDocument* document, QUndoStack* undoStack, QObject* parent)
    : QAbstractTableModel(parent), document_(document), undoStack_(undoStack) {
    const auto reset = [this] {
        beginResetModel();
        endResetModel();
    };
    connect(document_, &MissionDocument::eventsChanged, this, reset);
    connect(document_, &MissionDocument::robotsChanged, this, reset);
}

int EventTableModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : static_cast<int>(document_->events().size());
}

int EventTableModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant EventTableModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= rowCount())
        return {};
    const SpeedEvent& event = document_->events()[static_cast<std::size_t>(index.row())];
    if (role == Qt::EditRole) {
        // As text: a spin box would round a factor such as 0.125 to two decimals.
        switch (index.column()) {
        case Time:
            return QString::fromStdString(formatQuantity(event.timeSeconds));
        case Robot:
            return QString::number(event.robot);
        default:
            return QString::fromStdString(formatQuantity(event.speedFactor));
        }
    }
    if (role == Qt::ToolTipRole && index.column() == Time)
        return QString::fromStdString(formatDuration(event.timeSeconds));
    if (role != Qt::DisplayRole)
        return {};
    switch (index.column()) {
    case Time:
        return QString::fromStdString(formatQuantity(event.timeSeconds));
    case Robot: {
        const auto& robots = document_->robots();
        const bool named = event.robot >= 0 && static_cast<std::size_t>(event.robot) < robots.size() &&
                           !robots[static_cast<std::size_t>(event.robot)].name.empty();
        return named ? QStringLiteral("%1 · %2")
                           .arg(event.robot)
                           .arg(QString::fromStdString(robots[static_cast<std::size_t>(event.robot)].name))
                     : QString::number(event.robot);
    }
    default:
        return event.speedFactor == 0.0 ? tr("0 (stops)")
                                        : QString::fromStdString(formatQuantity(event.speedFactor));
    }
}

QVariant EventTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
    case Time:
        return tr("Time (s)");
    case Robot:
        return tr("Robot");
    default:
        return tr("Speed factor");
    }
}

Qt::ItemFlags EventTableModel::flags(const QModelIndex& index) const {
    return index.isValid() ? QAbstractTableModel::flags(index) | Qt::ItemIsEditable : Qt::NoItemFlags;
}

bool EventTableModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    if (!index.isValid() || role != Qt::EditRole || index.row() >= rowCount())
        return false;
    bool number = false;
    const double typed = value.toString().toDouble(&number);
    if (!number)
        return refuse(tr("\"%1\" is not a number").arg(value.toString()));
    std::vector<SpeedEvent> after = document_->events();
    SpeedEvent& event = after[static_cast<std::size_t>(index.row())];
    switch (index.column()) {
    case Time:
        event.timeSeconds = typed;
        break;
    case Robot:
        if (!(typed >= -1.0 && typed <= 1e6) || typed != std::floor(typed))
            return refuse(tr("Robot: %1 is not a robot number (0, 1, 2, ...)").arg(value.toString()));
        event.robot = static_cast<int>(typed);
        break;
    default:
        event.speedFactor = typed;
        break;
    }
    if (const auto wrong = speedEventProblem(event, document_->robots().size()))
        return refuse(tr("Event %1 %2: %3")
                          .arg(index.row() + 1)
                          .arg(QString::fromStdString(wrong->field), QString::fromStdString(wrong->detail)));
    if (after == document_->events())
        return true; // the same value: nothing to undo
    undoStack_->push(new EventsEditCommand(document_, document_->events(), after,
                                           tr("Edit event %1").arg(index.row() + 1)));
    return true;
}

bool EventTableModel::addEvent() {
    if (document_->robots().empty())
        return refuse(tr("Place a robot first: an event slows a robot down or stops it"));
    std::vector<SpeedEvent> after = document_->events();
    double latest = 0.0;
    for (const SpeedEvent& event : after)
        latest = std::max(latest, event.timeSeconds);
    after.push_back({after.empty() ? 600.0 : latest + 600.0, 0, 0.5});
    undoStack_->push(new EventsEditCommand(document_, document_->events(), after, tr("Add event")));
    return true;
}

bool EventTableModel::removeEvent(int row) {
    if (row < 0 || row >= rowCount())
        return false;
    std::vector<SpeedEvent> after = document_->events();
    after.erase(after.begin() + row);
    undoStack_->push(
        new EventsEditCommand(document_, document_->events(), after, tr("Remove event %1").arg(row + 1)));
    return true;
}

bool EventTableModel::refuse(const QString& reason) {
    emit editRefused(reason);
    return false;
}

} // namespace mcpp::ui
