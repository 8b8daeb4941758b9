#pragma once

namespace mcpp {

// What a robot's flights allow it: an aircraft's mission split into flights of at most flightSeconds each,
// every one with its climb and descent, and turnaroundSeconds on the ground between two. A robot without a
// flight time (a rover) works its whole path in one go.
struct FlightLimits {
    double flightSeconds = 0.0; // 0: no limit
    double climbAndDescentSeconds = 0.0;
    double turnaroundSeconds = 0.0;
    // The fewest seconds its flights can take for a second of its planned path: below 1 where the waypoint
    // files command speeds rounded up or held within a tolerance, so that a cell may be flown faster.
    double fastestPace = 1.0;
    // The fastest it flies to its work and back (an aircraft's cruise speed): each flight takes off from the
    // robot's start and lands there. 0 where unknown: its trips are not counted.
    double tripMetresPerSecond = 0.0;

    [[nodiscard]] bool splitsPaths() const { return flightSeconds > climbAndDescentSeconds; }
    // The most seconds of planned path the robot can fly within `fieldSeconds` in the field: full flights one
    // after the other, the last one cut short, at the fastest pace. Trips out to the work and back would only
    // lower it.
    [[nodiscard]] double mostPathSecondsWithin(double fieldSeconds) const;
    // The fewest seconds in the field that fly `pathSeconds` of planned path at the fastest pace: its flights
    // (each but the last full) with their climbs and descents, and the turnarounds between them.
    [[nodiscard]] double leastFieldSecondsFor(double pathSeconds) const;
    // Whether its flights count the way out to their work and back.
    [[nodiscard]] bool makesTrips() const { return splitsPaths() && tripMetresPerSecond > 0.0; }
    // How far from its start one flight can work: infinite where its trips are not counted.
    [[nodiscard]] double reachMetres() const;
    // How far from its start one flight can go and still work a twentieth of its time: the least a waypoint
    // file's flight holds, a piece of a leg (a fortieth of a flight) and the turns at its ends (a flight
    // reaching farther would hold that piece and overrun).
    [[nodiscard]] double workingReachMetres() const;
    // The most seconds of planned path it can fly within `fieldSeconds` farther than `metres` from its start:
    // every flight working there spends the way out to that distance and back on it. 0 where no flight
    // reaches so far; as mostPathSecondsWithin for a robot whose trips are not counted.
    [[nodiscard]] double mostPathSecondsBeyond(double fieldSeconds, double metres) const;

  private:
    // The same in seconds flown.
    [[nodiscard]] double mostFlownSecondsWithin(double fieldSeconds) const;
};

} // namespace mcpp
