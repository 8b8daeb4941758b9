#include "ui/ClassTableEditCommand.hpp"

#include "ui/MissionDocument.hpp"

namespace mcpp::ui {

ClassTableEditCommand::ClassTableEditCommand(MissionDocument* document, ClassTable before,
                                             QString presetBefore, ClassTable after, QString presetAfter,
                                             const QString& text)
    : QUndoCommand(text), document_(document), before_(std::move(before)),
      presetBefore_(std::move(presetBefore)), after_(std::move(after)), presetAfter_(std::move(presetAfter)) {
}

void ClassTableEditCommand::undo() {
    document_->setClasses(before_, presetBefore_);
}

void ClassTableEditCommand::redo() {
    document_->setClasses(after_, presetAfter_);
}

} // namespace mcpp::ui
