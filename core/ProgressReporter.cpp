#include "core/ProgressReporter.hpp"

#include "core/PlanningError.hpp"

namespace mcpp {

void ProgressReporter::throwIfCancelled() const {
    if (cancelRequested()) throw PlanningError(PlanningError::Kind::Cancelled, "planning was cancelled");
}

} // namespace mcpp
