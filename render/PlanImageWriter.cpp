#include "render/PlanImageWriter.hpp"

#include "io/AutopilotMission.hpp"
#include "io/PlanExport.hpp"
#include "render/PlanImage.hpp"

namespace mcpp::render {
namespace {

// When the robot is done in the field, as its waypoint files fly it, where that comes later than its path:
// an aircraft's trips to and from its start, the turnarounds between parts. A rover without turnarounds
// is done when its path is, and its mission is not worked out here.
FieldTime fieldTimeOf(const io::ExportContext& context, int robot) {
    const io::VehicleSettings& vehicle = context.vehicle(robot);
    if (!io::splitMissionEndsLater(vehicle))
        return {};
    const io::AutopilotMission& mission = io::autopilotMissionOf(context, robot);
    const auto index = static_cast<std::size_t>(robot);
    if (mission.parts.empty() || index >= context.plan.metrics.robots.size())
        return {};
    return fieldTimeBeyondPath(context.plan.metrics.robots[index].timeSeconds,
                               io::missionFlights(mission, vehicle).fieldSeconds, mission.parts.size(),
                               io::isAircraft(vehicle.type));
}

} // namespace

io::ImageWriter planImageWriter(int pngSide) {
    return [pngSide](const io::ExportContext& context, io::ImageFormat format, const std::string& path) {
        if (context.grid == nullptr)
            return io::Status::failure(path + ": there is no map to draw");
        QString error;
        const QString file = QString::fromStdString(path);
        SheetExtras extras{&context.outlines(), context.robotNames, {}, context.area, {}};
        const std::size_t robots = context.plan.paths.size();
        for (std::size_t robot = 0; robot < robots; ++robot)
            extras.flightReach.push_back(io::flightReachMetres(context.vehicle(static_cast<int>(robot))));
        // Last robot first: the robots' waypoint files, written beside the picture, work out their missions
        // from the first on, so the two threads share the work instead of one waiting on the other.
        extras.fieldTimes.resize(robots);
        for (std::size_t robot = robots; robot-- > 0;)
            extras.fieldTimes[robot] = fieldTimeOf(context, static_cast<int>(robot));
        const bool written = format == io::ImageFormat::Png
                                 ? writePlanPng(*context.grid, context.classes, context.plan, file,
                                                QSize(pngSide, pngSide), &error, extras)
                                 : writePlanSvg(*context.grid, context.classes, context.plan, file,
                                                QSize(1600, 1600), &error, extras);
        if (written)
            return io::Status();
        // The drawing's errors name the file already, most of them.
        return io::Status::failure(error.contains(file) ? error.toStdString()
                                                        : path + ": " + error.toStdString());
    };
}

} // namespace mcpp::render
