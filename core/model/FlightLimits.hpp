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

    [[nodiscard]] bool splitsPaths() const { return flightSeconds > climbAndDescentSeconds; }
    // The most seconds of planned path the robot can fly within `fieldSeconds` in the field: full flights one
    // after the other, the last one cut short, at the fastest pace. Trips out to the work and back would only
    // lower it.
    [[nodiscard]] double mostPathSecondsWithin(double fieldSeconds) const;
    // The fewest seconds in the field that fly `pathSeconds` of planned path at the fastest pace: its flights
    // (each but the last full) with their climbs and descents, and the turnarounds between them.
    [[nodiscard]] double leastFieldSecondsFor(double pathSeconds) const;

  private:
    // The same in seconds flown.
    [[nodiscard]] double mostFlownSecondsWithin(double fieldSeconds) const;
};

} // namespace mcpp
