#pragma once

#include "core/model/FlightLimits.hpp"
#include "core/model/Plan.hpp"
#include "core/planners/StartSquare.hpp"

#include <functional>
#include <optional>
#include <vector>

namespace mcpp {

// Fills plan.metrics and the regions' costs from the cell graph, the regions and the measured paths
// (spec section 6). Stage timings are left as they are.
class PlanMetricsCalculator {
  public:
    PlanMetricsCalculator() = default;
    // robotFlights: by robot, what its flights allow (PlanningProblem::robotFlights); where some robot's
    // path is split into flights, the bound in the field is worked out too.
    explicit PlanMetricsCalculator(std::vector<FlightLimits> robotFlights)
        : robotFlights_(std::move(robotFlights)) {}

    void compute(Plan& plan) const;

    // Work some robots must share: the sum over robots of weights[r] times robot r's path time is at least
    // `seconds` (weights by robot, 0 for a robot outside it), for any division making the plan's turns.
    struct SharedWork {
        std::vector<double> weights;
        double seconds = 0.0;
        // Of those seconds, what each cell holds (weighted as `seconds` is; 0 outside the share), where it is
        // known: the bound in the field counts the trips out to it.
        std::function<double(int)> workOfCell;
    };

  private:
    std::vector<FlightLimits> robotFlights_;

    // Raises the lower bound to what the robots of each connected part need (robots of one speed only),
    // adds each part's work to `shares`, and lists confined robots;
    // `regionsLinked`: the regions link every robot (regionsLinkEveryRobot), so the map is one part.
    static void boundByConnectedParts(Plan& plan, bool regionsLinked, std::vector<SharedWork>& shares);
    // The bound where some robots drive at their own speeds (Plan::robotSpeeds): no plan beats the weighted
    // mean, by each robot's share of what the fleet does in a second, of what each robot must do. Returns
    // that work, or none where no robot works.
    static std::optional<SharedWork> boundWithOwnSpeeds(Plan& plan);
    // The least time in the field in which the robots, each within its flights, can do every share;
    // dearestTurnSeconds: the highest price of a quarter turn on the map.
    [[nodiscard]] double fieldBound(const Plan& plan, const std::vector<SharedWork>& shares,
                                    double dearestTurnSeconds) const;
    // The least time in the field in which robots within `flights` can do every share, from `homes`.
    [[nodiscard]] static double boundOfFlights(const Plan& plan, const std::vector<SharedWork>& shares,
                                               const std::vector<FlightLimits>& flights,
                                               const std::vector<std::vector<StartSquare>>& homes);
    // The least time a plan flown in sorties from chargers takes, its trips out to the work included; 0 for
    // a plan without sorties. fastestCell: the highest speed over any cell.
    [[nodiscard]] static double sortieBound(const Plan& plan, const std::vector<SharedWork>& shares,
                                            double dearestTurnSeconds, double fastestCell);
    [[nodiscard]] std::vector<FlightLimits> boundedFlights(std::size_t robots,
                                                           double dearestTurnSeconds) const;
    [[nodiscard]] bool flightsReachTheirWork(const Plan& plan) const;
    [[nodiscard]] FlightLimits limitsOf(std::size_t robot) const {
        return robot < robotFlights_.size() ? robotFlights_[robot] : FlightLimits{};
    }
    // Raises the lower bound by the charges a robot on a battery must make to fly it.
    static void boundByCharges(Plan& plan);
};

} // namespace mcpp
