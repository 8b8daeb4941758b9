#include "ui/AreaEditCommand.hpp"

#include <QSaveFile>

namespace mcpp::ui {
namespace {

// Written whole or not at all, as every write of the application is.
void writeBytes(const QString& path, const QByteArray& bytes) {
    QSaveFile file(path);
    if (file.open(QIODevice::WriteOnly) && file.write(bytes) == bytes.size())
        file.commit();
}

} // namespace

AreaEditCommand::AreaEditCommand(io::AreaOfInterest before, io::AreaOfInterest after,
                                 std::vector<RewrittenFile> files, UseArea useArea, const QString& text)
    : QUndoCommand(text), before_(std::move(before)), after_(std::move(after)), files_(std::move(files)),
      useArea_(std::move(useArea)) {}

void AreaEditCommand::undo() {
    // A file that did not exist before is left as it is: the area before does not name it.
    for (const RewrittenFile& file : files_)
        if (file.before)
            writeBytes(file.path, *file.before);
    useArea_(before_);
}

void AreaEditCommand::redo() {
    if (made_) {
        made_ = false;
        return;
    }
    for (const RewrittenFile& file : files_)
        writeBytes(file.path, file.after);
    useArea_(after_);
}

} // namespace mcpp::ui
