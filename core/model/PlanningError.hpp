#pragma once

#include <stdexcept>
#include <string>

namespace mcpp {

// Bad input found by the core. The message names what is wrong: robot index and coordinates,
// class value or parameter.
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

    PlanningError(Kind kind, const std::string& message) : std::runtime_error(message), kind_(kind) {}
    [[nodiscard]] Kind kind() const { return kind_; }

private:
    Kind kind_;
};

} // namespace mcpp
