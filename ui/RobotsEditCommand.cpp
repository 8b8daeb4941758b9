#include "ui/RobotsEditCommand.hpp"

#include "ui/MissionDocument.hpp"

namespace mcpp::ui {

RobotsEditCommand::RobotsEditCommand(MissionDocument* document, std::vector<io::RobotSpec> before,
                                     std::vector<io::RobotSpec> after, const QString& text)
    : QUndoCommand(text), document_(document), before_(std::move(before)), after_(std::move(after)) {}

void RobotsEditCommand::undo() {
    document_->setRobots(before_);
}

void RobotsEditCommand::redo() {
    document_->setRobots(after_);
}

} // namespace mcpp::ui
