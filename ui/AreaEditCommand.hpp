#pragma once

#include "io/Mission.hpp"

#include <QString>
#include <QUndoCommand>
#include <functional>

namespace mcpp::ui {

// A change of the area of interest or the no-go zones (drawn, chosen from a file, or cleared), kept as the
// area's files before and after: every drawn zone goes to a file of its own, so undo only switches files.
// The command is pushed once the change has been made, so its first redo does nothing.
class AreaEditCommand : public QUndoCommand {
  public:
    // Uses an area's files (reads them again and replans on them), undoing or redoing; false where they
    // cannot be used.
    using UseArea = std::function<bool(const io::AreaOfInterest&, bool undoing)>;

    AreaEditCommand(io::AreaOfInterest before, io::AreaOfInterest after, UseArea useArea,
                    const QString& text);
    void undo() override;
    void redo() override;

  private:
    io::AreaOfInterest before_;
    io::AreaOfInterest after_;
    UseArea useArea_;
    bool changeAlreadyMade_ = true; // the change was made before the command was pushed
};

} // namespace mcpp::ui
