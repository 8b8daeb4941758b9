#include "ui/EventsEditCommand.hpp"

#include "ui/MissionDocument.hpp"

namespace mcpp::ui {

EventsEditCommand::EventsEditCommand(MissionDocument* document, std::vector<SpeedEvent> before,
                                     std::vector<SpeedEvent> after, const QString& text)
    : QUndoCommand(text), document_(document), before_(std::move(before)), after_(std::move(after)) {}

void EventsEditCommand::undo() {
    document_->setEvents(before_);
}

void EventsEditCommand::redo() {
    document_->setEvents(after_);
}

} // namespace mcpp::ui
