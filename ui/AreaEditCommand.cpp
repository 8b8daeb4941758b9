#include "ui/AreaEditCommand.hpp"

namespace mcpp::ui {

AreaEditCommand::AreaEditCommand(io::AreaOfInterest before, io::AreaOfInterest after, UseArea useArea,
                                 const QString& text)
    : QUndoCommand(text), before_(std::move(before)), after_(std::move(after)), useArea_(std::move(useArea)) {
}

// Where the files cannot be used any more (moved away), useArea says so and the map stays as it is.
void AreaEditCommand::undo() {
    useArea_(before_);
}

void AreaEditCommand::redo() {
    if (changeAlreadyMade_) {
        changeAlreadyMade_ = false;
        return;
    }
    useArea_(after_);
}

} // namespace mcpp::ui
