#pragma once

#include "io/Mission.hpp"

#include <QUndoCommand>
#include <vector>

namespace mcpp::ui {

class MissionDocument;

// Any change to the robot list (add, move, rename, remove), kept as before/after snapshots: robot lists
// are short, and snapshots make undo exact whatever the edit was.
class RobotsEditCommand : public QUndoCommand {
  public:
    RobotsEditCommand(MissionDocument* document, std::vector<io::RobotSpec> before,
                      std::vector<io::RobotSpec> after, const QString& text);
    void undo() override;
    void redo() override;

  private:
    MissionDocument* document_;
    std::vector<io::RobotSpec> before_;
    std::vector<io::RobotSpec> after_;
};

} // namespace mcpp::ui
