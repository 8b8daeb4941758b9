#pragma once

#include <string>

namespace mcpp {

// An optional part of a plan that only some planners make (a timeline, sorties, a detection grid).
// Readers that do not know a kind leave it alone.
class PlanLayer {
  public:
    virtual ~PlanLayer() = default;
    [[nodiscard]] virtual std::string kind() const = 0;
};

} // namespace mcpp
