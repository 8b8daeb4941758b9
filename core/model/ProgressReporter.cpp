#include "core/model/ProgressReporter.hpp"

#include "core/model/PlanningError.hpp"

namespace mcpp {

void ProgressReporter::throwIfCancelled() const {
    if (cancelRequested())
        throw PlanningError(PlanningError::Kind::Cancelled, "planning was cancelled");
}

} // namespace mcpp
