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
    return search(cell, targets_.front(), owner, searchLimit, targets_.size() - 1) == SearchEnd::FoundAll;
}

LocalConnectivity::SearchEnd LocalConnectivity::search(int cell, int from, const std::vector<int>& owner,
                                                       std::size_t limit, std::size_t wanted) {
    const int region = owner[static_cast<std::size_t>(cell)];
    const int mark = nextMark();
    stamp_[static_cast<std::size_t>(cell)] = mark;
    stamp_[static_cast<std::size_t>(from)] = mark;
    queue_.assign(1, from);
    std::size_t found = 0;
    std::size_t head = 0;
    for (; head < queue_.size() && queue_.size() < limit; ++head)
        for (int next : neighbours_.of(queue_[head])) {
            if (owner[static_cast<std::size_t>(next)] != region ||
                stamp_[static_cast<std::size_t>(next)] == mark)
                continue;
            stamp_[static_cast<std::size_t>(next)] = mark;
            queue_.push_back(next);
            if (std::find(targets_.begin(), targets_.end(), next) != targets_.end() && ++found == wanted)
                return SearchEnd::FoundAll;
        }
    return head == queue_.size() ? SearchEnd::RanOut : SearchEnd::HitLimit;
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
    for (std::size_t target = 1; target < targets_.size(); ++target)
        if (search(cell, targets_[target], owner, smallSideLimit, 1) == SearchEnd::RanOut)
            return true;
    return false;
}

} // namespace mcpp
