#include "ui/AreaEditCommand.hpp"

namespace mcpp::ui {

AreaEditCommand::AreaEditCommand(io::AreaOfInterest before, io::AreaOfInterest after, UseArea useArea,
                                 const QString& text)
    : QUndoCommand(text), before_(std::move(before)), after_(std::move(after)), useArea_(std::move(useArea)) {
}

// Where the files cannot be used any more (moved away), useArea says so, the map stays as it is and the
// step leaves the stack: the stack then holds no step it cannot take.
void AreaEditCommand::undo() {
    if (!useArea_(before_, true))
        setObsolete(true);
}

void AreaEditCommand::redo() {
    if (changeAlreadyMade_) {
        changeAlreadyMade_ = false;
        return;
    }
    if (!useArea_(after_, false))
        setObsolete(true);
}

} // namespace mcpp::ui
