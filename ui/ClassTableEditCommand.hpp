#pragma once

#include "core/model/ClassTable.hpp"

#include <QString>
#include <QUndoCommand>

namespace mcpp::ui {

class MissionDocument;

// A change to the land-cover class table (one cell edited or a preset applied), as before/after snapshots.
class ClassTableEditCommand : public QUndoCommand {
  public:
    ClassTableEditCommand(MissionDocument* document, ClassTable before, QString presetBefore,
                          ClassTable after, QString presetAfter, const QString& text);
    void undo() override;
    void redo() override;

  private:
    MissionDocument* document_;
    ClassTable before_;
    QString presetBefore_;
    ClassTable after_;
    QString presetAfter_;
};

} // namespace mcpp::ui
