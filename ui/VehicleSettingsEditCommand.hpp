#pragma once

#include "io/Mission.hpp"

#include <QUndoCommand>
#include <vector>

namespace mcpp::ui {

class MissionDocument;

// A change to the robots' autopilot settings (the mission's export settings and each robot's vehicle).
class VehicleSettingsEditCommand : public QUndoCommand {
  public:
    VehicleSettingsEditCommand(MissionDocument* document, io::ExportSettings exports,
                               std::vector<io::VehicleOverrides> vehicles);
    void undo() override;
    void redo() override;

  private:
    MissionDocument* document_;
    io::ExportSettings exportsBefore_;
    std::vector<io::VehicleOverrides> vehiclesBefore_;
    io::ExportSettings exportsAfter_;
    std::vector<io::VehicleOverrides> vehiclesAfter_;
};

} // namespace mcpp::ui
