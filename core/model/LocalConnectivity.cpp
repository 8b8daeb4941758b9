#include "core/model/LocalConnectivity.hpp"

#include <algorithm>

namespace mcpp {

bool LocalConnectivity::canRemove(int cell, const std::vector<int>& owner, std::size_t searchLimit) {
    const int region = owner[static_cast<std::size_t>(cell)];
    targets_.clear();
    for (int neighbour : neighbours_.of(cell))
        if (owner[static_cast<std::size_t>(neighbour)] == region)
            targets_.push_back(neighbour);
    if (targets_.size() <= 1)
        return !targets_.empty();
    const int mark = ++stampValue_;
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

} // namespace mcpp
