#include "ui/MissionDocument.hpp"

#include "core/model/StartPointCheck.hpp"
#include "io/PointsInDegrees.hpp"

#include <cmath>

namespace mcpp::ui {

MissionDocument::MissionDocument(QObject* parent) : QObject(parent) {}

void MissionDocument::reset(std::shared_ptr<const io::LoadedRaster> raster, io::Mission mission,
                            QString missionPath) {
    raster_ = std::move(raster);
    mission_ = std::move(mission);
    missionPath_ = std::move(missionPath);
    plan_.reset();
    planInputs_ = {};
    emit mapChanged();
    emit classesChanged();
    emit robotsChanged();
    emit settingsChanged();
    emit planChanged();
    emit missionPathChanged(missionPath_);
    emitStaleIfChanged();
}

void MissionDocument::clear() {
    reset(nullptr, io::Mission{}, QString());
}

std::vector<MapPoint> MissionDocument::starts() const {
    std::vector<MapPoint> points;
    points.reserve(mission_.robots.size());
    for (const auto& robot : mission_.robots)
        points.push_back(robot.start);
    return points;
}

std::vector<std::optional<MapPoint>> MissionDocument::chargers() const {
    std::vector<std::optional<MapPoint>> points;
    points.reserve(mission_.robots.size());
    for (const auto& robot : mission_.robots)
        points.push_back(robot.charger);
    return points;
}

bool MissionDocument::planStale() const {
    if (!plan_)
        return false;
    return !(currentInputs() == planInputs_);
}

PlanInputs MissionDocument::currentInputs() const {
    return inputsOf(mission_);
}

PlanInputs MissionDocument::inputsFor(const PlannerChoice& planner) const {
    io::Mission mission = mission_;
    mission.planner = planner;
    return inputsOf(mission);
}

PlanInputs MissionDocument::inputsOf(const io::Mission& mission) const {
    return {mission.classes,
            starts(),
            mission.planner,
            mission.events,
            io::plannerBatteries(mission),
            io::plannerRecharges(mission),
            chargers(),
            io::robotCruiseSpeeds(mission),
            io::fieldTimeInputs(mission),
            io::flyingRobots(mission)};
}

void MissionDocument::setClasses(const ClassTable& classes, const QString& preset) {
    mission_.classes = classes;
    mission_.classesWithoutColour.clear(); // the window's table is coloured throughout
    mission_.preset = preset.toStdString();
    emit classesChanged();
    emitStaleIfChanged();
}

void MissionDocument::setRobots(std::vector<io::RobotSpec> robots) {
    mission_.robots = std::move(robots);
    emit robotsChanged();
    emitStaleIfChanged();
}

void MissionDocument::setEvents(std::vector<SpeedEvent> events) {
    mission_.events = std::move(events);
    emit eventsChanged();
    emitStaleIfChanged();
}

void MissionDocument::setPlannerChoice(const PlannerChoice& choice) {
    mission_.planner = choice;
    emit settingsChanged();
    emitStaleIfChanged();
}

void MissionDocument::setVehicles(const io::ExportSettings& exports,
                                  const std::vector<io::VehicleOverrides>& vehicles) {
    mission_.exports = exports;
    for (std::size_t robot = 0; robot < mission_.robots.size() && robot < vehicles.size(); ++robot)
        mission_.robots[robot].vehicle = vehicles[robot];
    emit robotsChanged();
    emitStaleIfChanged(); // cruise speeds are planned with
}

void MissionDocument::setMissionPath(const QString& path) {
    missionPath_ = path;
    emit missionPathChanged(path);
}

void MissionDocument::setPlan(std::shared_ptr<const Plan> plan, PlanInputs inputs) {
    plan_ = std::move(plan);
    planInputs_ = std::move(inputs);
    emit planChanged();
    emitStaleIfChanged();
}

void MissionDocument::emitStaleIfChanged() {
    const bool stale = planStale();
    if (stale == lastStale_)
        return;
    lastStale_ = stale;
    emit staleChanged(stale);
}

std::optional<std::int32_t> MissionDocument::classValueAt(MapPoint point) const {
    if (!raster_)
        return std::nullopt;
    const ClassGrid& grid = raster_->grid;
    const auto pixel = grid.pixelAt(point);
    if (!pixel || grid.isOutside(pixel->column, pixel->row))
        return std::nullopt;
    return grid.valueAt(pixel->column, pixel->row);
}

QString MissionDocument::aircraftHint() {
    return tr("An aircraft would take off there (Plan menu, Robot vehicles: %1 or %2).")
        .arg(QString::fromStdString(io::vehicleTypeLabel(io::VehicleType::Multirotor)),
             QString::fromStdString(io::vehicleTypeLabel(io::VehicleType::FixedWing)));
}

std::optional<QString> MissionDocument::startProblem(MapPoint point, int ignoreRobot, const QString& what,
                                                     bool takesOff) const {
    if (!raster_)
        return tr("Open a land-cover raster before placing robots.");
    const ClassGrid& grid = raster_->grid;
    const QString name = what.isEmpty() ? tr("Start") : what;
    if (const auto problem = startPointProblem(grid, mission_.classes, point)) {
        const bool aircraftMay = takesOffThere(grid, point, *problem);
        if (takesOff && aircraftMay)
            return std::nullopt;
        // The nearest land it names with its degrees, as the start is named.
        const QString refusal = tr("%1 %2.").arg(
            name, QString::fromStdString(io::withPointsInDegrees(
                      startRefusal(grid, mission_.classes, point, *problem), raster_->georeference, grid)));
        // A ground robot refused where a drone would take off: say so, and where the window sets the vehicle.
        return aircraftMay ? refusal + QStringLiteral(" ") + aircraftHint() : refusal;
    }
    if (takesOff) // several aircraft may take off from one spot
        return std::nullopt;
    const auto pixel = grid.pixelAt(point);
    for (std::size_t robot = 0; robot < mission_.robots.size(); ++robot) {
        if (static_cast<int>(robot) == ignoreRobot)
            continue;
        const auto other = grid.pixelAt(mission_.robots[robot].start);
        if (other && other->column == pixel->column && other->row == pixel->row)
            return tr("%1 %2 is on the same pixel as %3's start.")
                .arg(name, QString::fromStdString(describePoint(point)),
                     QString::fromStdString(mission_.robots[robot].name));
    }
    return std::nullopt;
}

bool MissionDocument::robotFlies(int robot) const {
    if (robot < 0 || static_cast<std::size_t>(robot) >= mission_.robots.size())
        return io::isAircraft(mission_.exports.vehicle.type);
    return io::flyingRobots(mission_)[static_cast<std::size_t>(robot)];
}

QString MissionDocument::nextRobotName() const {
    // Numbered by its place, so that "robot 3" in a message is the robot named Robot 3.
    for (auto number = mission_.robots.size() + 1;; ++number) {
        const std::string candidate = "Robot " + std::to_string(number);
        bool used = false;
        for (const auto& robot : mission_.robots)
            used = used || robot.name == candidate;
        if (!used)
            return QString::fromStdString(candidate);
    }
}

} // namespace mcpp::ui
