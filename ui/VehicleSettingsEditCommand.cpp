#include "ui/VehicleSettingsEditCommand.hpp"

#include "ui/MissionDocument.hpp"

namespace mcpp::ui {

VehicleSettingsEditCommand::VehicleSettingsEditCommand(MissionDocument* document, io::ExportSettings exports,
                                                       std::vector<io::VehicleOverrides> vehicles)
    : QUndoCommand(QObject::tr("Change robot vehicles")), document_(document),
      exportsBefore_(document->mission().exports), exportsAfter_(std::move(exports)),
      vehiclesAfter_(std::move(vehicles)) {
    for (const io::RobotSpec& robot : document->robots())
        vehiclesBefore_.push_back(robot.vehicle);
}

void VehicleSettingsEditCommand::undo() {
    document_->setVehicles(exportsBefore_, vehiclesBefore_);
}

void VehicleSettingsEditCommand::redo() {
    document_->setVehicles(exportsAfter_, vehiclesAfter_);
}

} // namespace mcpp::ui
