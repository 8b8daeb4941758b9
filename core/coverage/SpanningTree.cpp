#include "core/coverage/SpanningTree.hpp"

namespace mcpp {

SpanningTree::SpanningTree(std::vector<int> cells, int root, const std::vector<std::pair<int, int>>& edges)
    : cells_(std::move(cells)), root_(root) {
    const std::size_t count = cells_.size();
    // Compressed adjacency lists: one allocation for the whole tree.
    offsets_.assign(count + 1, 0);
    for (const auto& [a, b] : edges) {
        ++offsets_[static_cast<std::size_t>(a) + 1];
        ++offsets_[static_cast<std::size_t>(b) + 1];
    }
    for (std::size_t i = 0; i < count; ++i)
        offsets_[i + 1] += offsets_[i];
    targets_.resize(2 * edges.size());
    std::vector<int> fill(offsets_.begin(), offsets_.end() - 1);
    for (const auto& [a, b] : edges) {
        targets_[static_cast<std::size_t>(fill[static_cast<std::size_t>(a)]++)] = b;
        targets_[static_cast<std::size_t>(fill[static_cast<std::size_t>(b)]++)] = a;
    }
    parent_.assign(count, -1);
    depth_.assign(count, 0);
    if (count == 0)
        return;
    std::vector<int> queue;
    queue.reserve(count);
    queue.push_back(root_);
    std::vector<char> seen(count, 0);
    seen[static_cast<std::size_t>(root_)] = 1;
    for (std::size_t head = 0; head < queue.size(); ++head) {
        const int node = queue[head];
        for (int next : neighbours(node)) {
            if (seen[static_cast<std::size_t>(next)] != 0)
                continue;
            seen[static_cast<std::size_t>(next)] = 1;
            parent_[static_cast<std::size_t>(next)] = node;
            depth_[static_cast<std::size_t>(next)] = depth_[static_cast<std::size_t>(node)] + 1;
            queue.push_back(next);
        }
    }
}

void SpanningTree::pack() {
    std::vector<int>().swap(offsets_);
    std::vector<int>().swap(targets_);
    std::vector<int>().swap(depth_);
    packed_ = true;
}

// The same lists and depths again: the edges are those to each node's parent, and the tree's parents and
// depths from its root are unique. The walk orders a node's neighbours by place, not by list order.
void SpanningTree::unpack() {
    if (!packed_)
        return;
    const std::vector<std::pair<int, int>> treeEdges = edges();
    std::vector<int>().swap(parent_);
    *this = SpanningTree(std::move(cells_), root_, treeEdges);
}

std::vector<std::pair<int, int>> SpanningTree::edges() const {
    std::vector<std::pair<int, int>> result;
    for (std::size_t node = 0; node < cells_.size(); ++node)
        if (parent_[node] >= 0)
            result.emplace_back(parent_[node], static_cast<int>(node));
    return result;
}

} // namespace mcpp
