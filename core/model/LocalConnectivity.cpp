#include "core/model/LocalConnectivity.hpp"

#include <algorithm>
#include <limits>

namespace mcpp {

bool LocalConnectivity::canRemove(int cell, const std::vector<int>& owner, std::size_t searchLimit) {
    const int region = owner[static_cast<std::size_t>(cell)];
    targets_.clear();
    for (int neighbour : neighbours_.of(cell))
        if (owner[static_cast<std::size_t>(neighbour)] == region)
            targets_.push_back(neighbour);
    if (targets_.size() <= 1)
        return !targets_.empty();
    // Most wide searches that fail run to their limit on one side of a cell that cuts a few cells off on
    // the other: finding those few first answers the same for a fraction of the search.
    if (searchLimit > smallSideLimit && someNeighbourIsCutOff(cell, owner))
        return false;
    const int mark = nextMark();
    stamp_[static_cast<std::size_t>(cell)] = mark;
    stamp_[static_cast<std::size_t>(targets_.front())] = mark;
    queue_.assign(1, targets_.front());
    std::size_t found = 1;
    for (std::size_t head = 0; head < queue_.size() && queue_.size() < searchLimit; ++head)
        for (int next : neighbours_.of(queue_[head])) {
            if (owner[static_cast<std::size_t>(next)] != region ||
                stamp_[static_cast<std::size_t>(next)] == mark)
                continue;
            stamp_[static_cast<std::size_t>(next)] = mark;
            queue_.push_back(next);
            if (std::find(targets_.begin(), targets_.end(), next) != targets_.end() &&
                ++found == targets_.size())
                return true;
        }
    return false;
}

int LocalConnectivity::nextMark() {
    if (stampValue_ ==
        std::numeric_limits<int>::max()) { // after two billion searches: start the stamps again
        std::fill(stamp_.begin(), stamp_.end(), 0);
        stampValue_ = 0;
    }
    return ++stampValue_;
}

bool LocalConnectivity::someNeighbourIsCutOff(int cell, const std::vector<int>& owner) {
    const int region = owner[static_cast<std::size_t>(cell)];
    for (std::size_t target = 1; target < targets_.size(); ++target) {
        const int mark = nextMark();
        stamp_[static_cast<std::size_t>(cell)] = mark;
        stamp_[static_cast<std::size_t>(targets_[target])] = mark;
        queue_.assign(1, targets_[target]);
        bool exhausted = true; // until the search meets another neighbour or grows past the small side
        for (std::size_t head = 0; head < queue_.size() && exhausted; ++head)
            for (int next : neighbours_.of(queue_[head])) {
                if (owner[static_cast<std::size_t>(next)] != region ||
                    stamp_[static_cast<std::size_t>(next)] == mark)
                    continue;
                stamp_[static_cast<std::size_t>(next)] = mark;
                queue_.push_back(next);
                if (queue_.size() >= smallSideLimit ||
                    std::find(targets_.begin(), targets_.end(), next) != targets_.end()) {
                    exhausted = false;
                    break;
                }
            }
        if (exhausted)
            return true;
    }
    return false;
}

} // namespace mcpp
