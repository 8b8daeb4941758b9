#include "core/coverage/RepeatedVisitCounter.hpp"

#include "core/coverage/PathMeasurement.hpp"

namespace mcpp {

void RepeatedVisitCounter::add(const Waypoint& waypoint) {
    const std::size_t index = added_++;
    const auto visited = subCellVisited(waypoint, graph_);
    if (visited.first < 0)
        return;
    if (firstVisit_.first < 0) {
        firstVisit_ = visited;
        firstVisitIndex_ = index;
    }
    lastVisit_ = visited;
    lastVisitIndex_ = index;
    std::uint8_t& marks = seen_[static_cast<std::size_t>(visited.first)];
    const auto bit = static_cast<std::uint8_t>(1U << static_cast<unsigned>(visited.second));
    if ((marks & bit) != 0)
        ++repeats_;
    marks = static_cast<std::uint8_t>(marks | bit);
}

int RepeatedVisitCounter::repeats(bool closed) const {
    const bool returnsToFirstVisit =
        closed && firstVisit_.first >= 0 && firstVisitIndex_ != lastVisitIndex_ && firstVisit_ == lastVisit_;
    return returnsToFirstVisit ? repeats_ - 1 : repeats_;
}

} // namespace mcpp
