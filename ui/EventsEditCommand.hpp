#pragma once

#include "core/model/SpeedEvent.hpp"

#include <QUndoCommand>
#include <vector>

namespace mcpp::ui {

class MissionDocument;

// Any change to the mission's events (add, edit, remove), kept as before/after snapshots like robot edits.
class EventsEditCommand : public QUndoCommand {
  public:
    EventsEditCommand(MissionDocument* document, std::vector<SpeedEvent> before,
                      std::vector<SpeedEvent> after, const QString& text);
    void undo() override;
    void redo() override;

  private:
    MissionDocument* document_;
    std::vector<SpeedEvent> before_;
    std::vector<SpeedEvent> after_;
};

} // namespace mcpp::ui
