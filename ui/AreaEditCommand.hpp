#pragma once

#include "io/Mission.hpp"

#include <QByteArray>
#include <QString>
#include <QUndoCommand>
#include <functional>
#include <optional>
#include <vector>

namespace mcpp::ui {

// A change of the area of interest or the no-go zones (drawn, chosen from a file, or cleared), kept as the
// area's files before and after. A zone drawn onto the window's own drawn file rewrites that file, so the
// file's bytes before and after are kept too and written back: undo gives back the polygons the file held.
// The command is pushed once the change has been made, so its first redo does nothing.
class AreaEditCommand : public QUndoCommand {
  public:
    // A file the change rewrote: its bytes before (none where it did not exist) and after.
    struct RewrittenFile {
        QString path;
        std::optional<QByteArray> before;
        QByteArray after;
    };
    // Uses an area's files (reads them again and replans on them); false where they cannot be used.
    using UseArea = std::function<bool(const io::AreaOfInterest&)>;

    AreaEditCommand(io::AreaOfInterest before, io::AreaOfInterest after, std::vector<RewrittenFile> files,
                    UseArea useArea, const QString& text);
    void undo() override;
    void redo() override;

  private:
    io::AreaOfInterest before_;
    io::AreaOfInterest after_;
    std::vector<RewrittenFile> files_;
    UseArea useArea_;
    bool made_ = true; // the change was made before the command was pushed
};

} // namespace mcpp::ui
