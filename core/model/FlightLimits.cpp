#include "core/model/FlightLimits.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mcpp {

double FlightLimits::mostPathSecondsWithin(double fieldSeconds) const {
    return mostFlownSecondsWithin(fieldSeconds) / fastestPace;
}

double FlightLimits::mostFlownSecondsWithin(double fieldSeconds) const {
    if (!splitsPaths())
        return std::max(0.0, fieldSeconds);
    const double workPerFlight = flightSeconds - climbAndDescentSeconds;
    // Full flights, each followed by a turnaround but the last.
    const double fullFlights =
        std::floor((fieldSeconds + turnaroundSeconds) / (flightSeconds + turnaroundSeconds));
    const double left = fieldSeconds - fullFlights * (flightSeconds + turnaroundSeconds);
    const double lastFlight = std::clamp(left - climbAndDescentSeconds, 0.0, workPerFlight);
    return std::max(0.0, fullFlights) * workPerFlight + lastFlight;
}

double FlightLimits::mostPathSecondsBeyond(double fieldSeconds, double metres) const {
    if (!makesTrips() || !(metres > 0.0))
        return mostPathSecondsWithin(fieldSeconds);
    FlightLimits farther = *this;
    // The way out and back is flown in every flight, as the climb and descent are.
    farther.climbAndDescentSeconds += 2.0 * metres / tripMetresPerSecond;
    return farther.splitsPaths() ? farther.mostPathSecondsWithin(fieldSeconds) : 0.0;
}

double FlightLimits::reachMetres() const {
    if (!makesTrips())
        return std::numeric_limits<double>::infinity();
    return (flightSeconds - climbAndDescentSeconds) * tripMetresPerSecond / 2.0;
}

double FlightLimits::workingReachMetres() const {
    constexpr double leastWorkPerFlight = 1.0 / 20.0;
    return reachMetres() - leastWorkPerFlight * flightSeconds * tripMetresPerSecond / 2.0;
}

double FlightLimits::leastFieldSecondsFor(double pathSeconds) const {
    const double flown = pathSeconds * fastestPace;
    if (!splitsPaths() || !(flown > 0.0))
        return std::max(0.0, flown);
    const double flights = std::ceil(flown / (flightSeconds - climbAndDescentSeconds));
    return flown + flights * climbAndDescentSeconds + (flights - 1.0) * turnaroundSeconds;
}

} // namespace mcpp
