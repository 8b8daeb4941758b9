#pragma once

#include <stdexcept>
#include <string>

namespace mcpp {

// Bad input found by the core. The message names what is wrong: robot index and coordinates, class value
// or parameter. Errors about one robot's start or one parameter also carry which, and the detail without
// that subject, so a caller can name it in its own terms (a batch flag, a field of a mission file).
class PlanningError : public std::runtime_error {
  public:
    enum class Kind {
        InvalidParameter,
        InvalidClassTable,
        InvalidGrid,
        StartOutsideArea,
        StartOnObstacle,
        StartsShareCell,
        NoPassableCell,
        TooManyRobots,
        Cancelled
    };

    PlanningError(Kind kind, const std::string& message)
        : std::runtime_error(message), kind_(kind), detail_(message) {}

    // "robot 2 start " + detail, e.g. detail "(10, 20) is outside the raster".
    static PlanningError aboutStart(Kind kind, int robot, const std::string& detail) {
        // Robots are numbered from 1 in messages, as on the map and in every other message.
        PlanningError error(kind, "robot " + std::to_string(robot + 1) + " start " + detail, detail);
        error.robot_ = robot;
        return error;
    }
    // "robot 2 charger " + detail: a charger the problem gives (PlanningProblem::chargers).
    static PlanningError aboutCharger(Kind kind, int robot, const std::string& detail) {
        PlanningError error(kind, "robot " + std::to_string(robot + 1) + " charger " + detail, detail);
        error.robot_ = robot;
        error.charger_ = true;
        return error;
    }
    // "parameter key: " + detail, e.g. detail "must be from 0 to 1, got 2".
    static PlanningError aboutParameter(const std::string& key, const std::string& detail) {
        PlanningError error(Kind::InvalidParameter, "parameter " + key + ": " + detail, detail);
        error.parameter_ = key;
        return error;
    }

    [[nodiscard]] Kind kind() const { return kind_; }
    [[nodiscard]] int robot() const { return robot_; }                        // -1 when about no one robot
    [[nodiscard]] bool aboutCharger() const { return charger_; }              // else the robot's start
    [[nodiscard]] const std::string& parameter() const { return parameter_; } // empty when about no parameter
    [[nodiscard]] const std::string& detail() const { return detail_; }

  private:
    PlanningError(Kind kind, const std::string& message, std::string detail)
        : std::runtime_error(message), kind_(kind), detail_(std::move(detail)) {}

    Kind kind_;
    int robot_ = -1;
    bool charger_ = false;
    std::string parameter_;
    std::string detail_;
};

} // namespace mcpp
