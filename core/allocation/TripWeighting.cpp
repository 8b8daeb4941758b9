#include "core/allocation/TripWeighting.hpp"

#include "core/allocation/RegionCosts.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mcpp {
namespace {

// The weight of work `metres` from a robot's launch point.
float weightAt(const FlightLimits& flight, double metres) {
    if (!flight.makesTrips())
        return 1.0F;
    const double work = flight.flightSeconds - flight.climbAndDescentSeconds;
    const double left =
        std::max(work / TripWeighting::farthestShare, work - 2.0 * metres / flight.tripMetresPerSecond);
    return static_cast<float>((flight.flightSeconds + flight.turnaroundSeconds) / left);
}

// The cells covered `weights` times slower, turns included: far out they take field time on trips as
// travel does.
CellGraph weightedCells(const CellGraph& cells, const std::vector<float>& weights) {
    std::vector<CellRecord> records = cells.records();
    std::vector<float> turnSeconds(records.size());
    for (std::size_t id = 0; id < records.size(); ++id) {
        turnSeconds[id] = cells.turnSeconds(static_cast<int>(id)) * weights[id];
        records[id].speedMetresPerSecond /= weights[id];
    }
    CellGraph weighted(cells, std::move(records));
    CellTurnFigures figures = weighted.turnFigures();
    figures.setTurnSeconds(std::move(turnSeconds));
    weighted.setTurnFigures(std::move(figures));
    return weighted;
}

} // namespace

TripWeighting::TripWeighting(const CellGraph& cells, const std::vector<MapPoint>& launchPoints,
                             const std::vector<FlightLimits>& flights) {
    const std::vector<float> weights = weightsOf(cells, launchPoints, flights);
    if (!weights.empty())
        weighted_ = weightedCells(cells, weights);
}

std::vector<float> TripWeighting::weightsOf(const CellGraph& cells, const std::vector<MapPoint>& launchPoints,
                                            const std::vector<FlightLimits>& flights) {
    // A robot past the end of `flights` works in one go (PlanningProblem::robotFlights).
    const std::size_t robots = launchPoints.size();
    const auto flightOf = [&](std::size_t robot) {
        return robot < flights.size() ? flights[robot] : FlightLimits{};
    };
    if (std::none_of(flights.begin(),
                     flights.begin() + static_cast<std::ptrdiff_t>(std::min(robots, flights.size())),
                     [](const FlightLimits& flight) { return flight.makesTrips(); }))
        return {};
    std::vector<float> weights(cells.size(), 1.0F);
    for (std::size_t id = 0; id < cells.size(); ++id) {
        const Cell cell = cells.cell(static_cast<int>(id));
        double nearest = std::numeric_limits<double>::infinity();
        for (std::size_t robot = 0; robot < robots; ++robot) {
            const double metres =
                std::hypot(cell.centreX() - launchPoints[robot].x, cell.centreY() - launchPoints[robot].y);
            if (metres < nearest) {
                nearest = metres;
                weights[id] = weightAt(flightOf(robot), metres);
            }
        }
    }
    return weights;
}

std::vector<double> TripWeighting::paces(const CellGraph& cells, const RegionAllocation& regions) const {
    if (!weighted_)
        return {};
    const std::size_t robots = regions.startCell.size();
    const std::vector<double> plain = regionCosts(cells, regions.robotOfCell, robots);
    const std::vector<double> far = regionCosts(*weighted_, regions.robotOfCell, robots);
    std::vector<double> paces(robots, 1.0);
    for (std::size_t robot = 0; robot < robots; ++robot)
        if (plain[robot] > 0.0)
            paces[robot] = far[robot] / plain[robot];
    return paces;
}

} // namespace mcpp
