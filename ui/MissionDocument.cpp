#include "ui/MissionDocument.hpp"

#include <cmath>

namespace mcpp::ui {

namespace {

bool sameSettings(const PlannerSettings& a, const PlannerSettings& b) {
    return a.planner == b.planner && a.purityTolerance == b.purityTolerance &&
           a.blockedThreshold == b.blockedThreshold && a.closedTour == b.closedTour &&
           a.rebalanceIterations == b.rebalanceIterations &&
           a.snapStartsToFreeCells == b.snapStartsToFreeCells;
}

} // namespace

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

bool MissionDocument::planStale() const {
    if (!plan_)
        return false;
    const PlanInputs current = currentInputs();
    return !(current.classes == planInputs_.classes && current.starts == planInputs_.starts &&
             sameSettings(current.settings, planInputs_.settings));
}

PlanInputs MissionDocument::currentInputs() const {
    return {mission_.classes, starts(), mission_.settings};
}

void MissionDocument::setClasses(const ClassTable& classes, const QString& preset) {
    mission_.classes = classes;
    mission_.preset = preset.toStdString();
    emit classesChanged();
    emitStaleIfChanged();
}

void MissionDocument::setRobots(std::vector<io::RobotSpec> robots) {
    mission_.robots = std::move(robots);
    emit robotsChanged();
    emitStaleIfChanged();
}

void MissionDocument::setSettings(const PlannerSettings& settings) {
    mission_.settings = settings;
    emit settingsChanged();
    emitStaleIfChanged();
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
    const double column = std::floor((point.x - grid.originX) / grid.pixelWidth);
    const double row = std::floor((grid.originY - point.y) / grid.pixelHeight);
    if (column < 0.0 || row < 0.0 || column >= grid.columns || row >= grid.rows)
        return std::nullopt;
    const int c = static_cast<int>(column);
    const int r = static_cast<int>(row);
    if (grid.isOutside(c, r))
        return std::nullopt;
    return grid.valueAt(c, r);
}

std::optional<QString> MissionDocument::startProblem(MapPoint point, int ignoreRobot) const {
    if (!raster_)
        return tr("Open a land-cover raster before placing robots.");
    const QString where = QStringLiteral("(%1, %2)").arg(point.x, 0, 'f', 1).arg(point.y, 0, 'f', 1);
    const ClassGrid& grid = raster_->grid;
    if (point.x < grid.originX || point.x >= grid.maxX() || point.y <= grid.minY() || point.y > grid.originY)
        return tr("Start %1 is outside the map.").arg(where);
    const auto value = classValueAt(point);
    if (!value)
        return tr("Start %1 is on a pixel with no data or outside the task area.").arg(where);
    const LandCoverClass* landCoverClass = mission_.classes.find(*value);
    if (landCoverClass == nullptr)
        return tr("Start %1 is on class %2, which has no row in the class table.").arg(where).arg(*value);
    if (!landCoverClass->isTraversable())
        return tr("Start %1 is on an obstacle: %2 (%3) is not passable.")
            .arg(where, QString::fromStdString(landCoverClass->name))
            .arg(*value);
    const double column = std::floor((point.x - grid.originX) / grid.pixelWidth);
    const double row = std::floor((grid.originY - point.y) / grid.pixelHeight);
    for (std::size_t robot = 0; robot < mission_.robots.size(); ++robot) {
        if (static_cast<int>(robot) == ignoreRobot)
            continue;
        const MapPoint other = mission_.robots[robot].start;
        if (std::floor((other.x - grid.originX) / grid.pixelWidth) == column &&
            std::floor((grid.originY - other.y) / grid.pixelHeight) == row)
            return tr("Start %1 is on the same pixel as %2's start.")
                .arg(where, QString::fromStdString(mission_.robots[robot].name));
    }
    return std::nullopt;
}

QString MissionDocument::nextRobotName() const {
    for (int number = 1;; ++number) {
        const std::string candidate = "Robot " + std::to_string(number);
        bool used = false;
        for (const auto& robot : mission_.robots)
            used = used || robot.name == candidate;
        if (!used)
            return QString::fromStdString(candidate);
    }
}

} // namespace mcpp::ui
