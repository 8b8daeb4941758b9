#pragma once

namespace mcpp {

// Something that happens to a robot during the mission: from `timeSeconds` on, it drives at `speedFactor`
// times its land-cover speeds (0.5 at half speed, 0 stopped) until its next event.
struct SpeedEvent {
    double timeSeconds = 0.0;
    int robot = 0; // index among the mission's robots, from 0
    double speedFactor = 1.0;

    friend bool operator==(const SpeedEvent&, const SpeedEvent&) = default;
};

} // namespace mcpp
