#include "core/coverage/OwnSpeeds.hpp"

#include "core/coverage/PathMeasurement.hpp"

#include <algorithm>
#include <map>

namespace mcpp {

bool someOwnSpeed(const std::vector<double>& speeds) {
    return std::any_of(speeds.begin(), speeds.end(), [](double speed) { return speed > 0.0; });
}

bool someFieldPace(const std::vector<double>& fieldPaces) {
    return std::any_of(fieldPaces.begin(), fieldPaces.end(),
                       [](double pace) { return pace > 0.0 && pace != 1.0; });
}

double fieldPaceOf(const std::vector<double>& fieldPaces, std::size_t robot) {
    return robot < fieldPaces.size() && fieldPaces[robot] > 0.0 ? fieldPaces[robot] : 1.0;
}

std::vector<double> withFieldPaces(const std::vector<double>& paces, const std::vector<double>& fieldPaces,
                                   std::size_t robots) {
    std::vector<double> paced(robots, 1.0);
    for (std::size_t robot = 0; robot < robots; ++robot)
        paced[robot] = paceOf(paces, robot) * fieldPaceOf(fieldPaces, robot);
    return paced;
}

double fieldSeconds(const CoveragePath& path, const std::vector<double>& fieldPaces) {
    return path.timeSeconds * fieldPaceOf(fieldPaces, static_cast<std::size_t>(path.robot));
}

double ownSpeedOf(const std::vector<double>& speeds, std::size_t robot) {
    return robot < speeds.size() && speeds[robot] > 0.0 ? speeds[robot] : 0.0;
}

void setOwnSpeed(CoveragePath& path, double speed) {
    if (!(speed > 0.0))
        return;
    for (Waypoint& waypoint : path.waypoints)
        waypoint.speedMetresPerSecond = static_cast<float>(speed);
}

void driveAtOwnSpeed(CoveragePath& path, const CellGraph& graph, double speed) {
    if (!(speed > 0.0))
        return;
    const double travelBefore = path.timeSeconds - path.turnSeconds;
    setOwnSpeed(path, speed);
    timePath(path, graph);
    if (path.runsMerged() && travelBefore > 0.0)
        path.connectorSeconds *= (path.timeSeconds - path.turnSeconds) / travelBefore;
}

void driveAtOwnSpeeds(std::vector<CoveragePath>& paths, const CellGraph& graph,
                      const std::vector<double>& speeds) {
    for (CoveragePath& path : paths)
        driveAtOwnSpeed(path, graph, ownSpeedOf(speeds, static_cast<std::size_t>(path.robot)));
}

namespace {

// The cells' travel time at `speed` over their cover time at the class speeds (turns are left to the
// driven paths: at an aircraft's speed they weigh far more, and cells expect more of them than coverage
// walks make).
double paceAt(const CellGraph& graph, float speed) {
    double cost = 0.0; // at the class speeds
    double own = 0.0;
    for (std::size_t id = 0; id < graph.size(); ++id) {
        const Cell cell = graph.cell(static_cast<int>(id));
        cost += cell.coverSeconds();
        own += cell.travelSeconds() * cell.speedMetresPerSecond / speed;
    }
    return cost > 0.0 ? own / cost : 1.0;
}

} // namespace

std::vector<double> drivenPaces(const CellGraph& graph, const RegionAllocation& regions,
                                const std::vector<CoveragePath>& paths, const std::vector<double>& guessed) {
    std::vector<double> costs(paths.size(), 0.0);
    for (std::size_t id = 0; id < graph.size() && id < regions.robotOfCell.size(); ++id) {
        const int robot = regions.robotOfCell[id];
        if (robot >= 0 && static_cast<std::size_t>(robot) < costs.size())
            costs[static_cast<std::size_t>(robot)] += graph.cell(static_cast<int>(id)).coverSeconds();
    }
    std::vector<double> paces(paths.size(), 1.0);
    for (std::size_t robot = 0; robot < paths.size(); ++robot)
        paces[robot] = costs[robot] > 0.0 && paths[robot].timeSeconds > 0.0
                           ? paths[robot].timeSeconds / costs[robot]
                           : paceOf(guessed, robot);
    return paces;
}

std::vector<double> robotPaces(const CellGraph& graph, const std::vector<double>& speeds,
                               std::size_t robots) {
    std::vector<double> paces(robots, 1.0);
    std::map<float, double> paceOfSpeed; // robots of one speed share a pass over the cells
    for (std::size_t robot = 0; robot < robots; ++robot) {
        const auto speed = static_cast<float>(ownSpeedOf(speeds, robot));
        if (!(speed > 0.0F))
            continue;
        auto known = paceOfSpeed.find(speed);
        if (known == paceOfSpeed.end())
            known = paceOfSpeed.emplace(speed, paceAt(graph, speed)).first;
        paces[robot] = known->second;
    }
    return paces;
}

} // namespace mcpp
