#pragma once

#include <vector>

namespace mcpp {

// One robot's mission as simulated under the events: when it reaches each point of its driven path, when it
// was done and what it took over from others.
struct RobotTimeline {
    int robot = 0;
    std::vector<double> secondsAtWaypoint; // by waypoint of the plan's path: time since the start
    double completionSeconds = 0.0;        // when it passed its last point
    bool stopped = false;                  // an event stopped it for good; others covered what it left
    // Cells of another robot's first region (as grown from the starts) it covered: the evening out before
    // anyone moves counts too, so a mission without events has some.
    std::vector<int> cellsTakenOver;
    double takenOverAreaSquareMetres = 0.0;
    // The static plan's robot under the same events: when it would be done (infinity when stopped first);
    // 0 when the plan was not compared with a static one.
    double staticCompletionSeconds = 0.0;
};

} // namespace mcpp
