#include "io/PlanExport.hpp"

namespace mcpp::io {

const RegionOutlines& ExportContext::outlines() const {
    std::call_once(outlineCache->traced, [this] { outlineCache->outlines = regionOutlines(plan); });
    return outlineCache->outlines;
}

std::string ExportContext::robotName(int robot) const {
    const auto index = static_cast<std::size_t>(robot);
    if (robot >= 0 && index < robotNames.size() && !robotNames[index].empty())
        return robotNames[index];
    return "Robot " + std::to_string(robotNumber(robot));
}

const VehicleSettings& ExportContext::vehicle(int robot) const {
    const auto index = static_cast<std::size_t>(robot);
    return robot >= 0 && index < vehicles.size() ? vehicles[index] : settings.vehicle;
}

} // namespace mcpp::io
