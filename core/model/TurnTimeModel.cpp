#include "core/model/TurnTimeModel.hpp"

namespace mcpp {

ParameterSpec TurnTimeModel::turnSecondsParameter() {
    ParameterSpec spec = realParameter(
        "turn_s", "Time per 90° turn", automaticParameterValue, 0.0, 600.0,
        "Seconds a robot loses slowing down for a 90-degree turn and speeding up again; auto works it out "
        "from the speed and the acceleration at turns, 0 makes turns free",
        "s");
    spec.automatic = "auto";
    return spec;
}

ParameterSpec TurnTimeModel::accelerationParameter() {
    return realParameter("turn_acceleration", "Acceleration at turns", 1.0, 0.05, 50.0,
                         "How fast a robot brakes before a turn and speeds up after it, for an automatic "
                         "turn time: a 90-degree turn at speed v costs v / acceleration seconds",
                         "m/s²");
}

TurnTimeModel TurnTimeModel::from(const ParameterValues& values) {
    TurnTimeModel model;
    if (values.has("turn_s"))
        model.fixedSecondsPer90Degrees = values.real("turn_s");
    if (values.has("turn_acceleration"))
        model.accelerationMetresPerSecondSquared = values.real("turn_acceleration");
    return model;
}

} // namespace mcpp
