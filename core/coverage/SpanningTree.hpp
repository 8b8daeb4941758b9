#pragma once

#include <span>
#include <utility>
#include <vector>

namespace mcpp {

// A spanning tree over some cells of a cell graph. Nodes are positions in `cells()` (graph ids); the tree
// is rooted at the start cell, so every node knows its parent and depth.
class SpanningTree {
  public:
    SpanningTree() = default;
    SpanningTree(std::vector<int> cells, int root, const std::vector<std::pair<int, int>>& edges);

    [[nodiscard]] std::size_t size() const { return cells_.size(); }
    [[nodiscard]] const std::vector<int>& cells() const { return cells_; }
    [[nodiscard]] int cellOf(int node) const { return cells_[static_cast<std::size_t>(node)]; }
    [[nodiscard]] int root() const { return root_; }
    [[nodiscard]] std::span<const int> neighbours(int node) const {
        const auto begin = static_cast<std::size_t>(offsets_[static_cast<std::size_t>(node)]);
        const auto end = static_cast<std::size_t>(offsets_[static_cast<std::size_t>(node) + 1]);
        return {targets_.data() + begin, end - begin};
    }
    [[nodiscard]] int parent(int node) const { return parent_[static_cast<std::size_t>(node)]; }
    [[nodiscard]] int depth(int node) const { return depth_[static_cast<std::size_t>(node)]; }
    // The edges as (node, node) pairs, each once.
    [[nodiscard]] std::vector<std::pair<int, int>> edges() const;
    // While a tree waits to be walked it keeps only its cells and each node's parent: 8 bytes a node
    // instead of 24 (up to 1.1 GB on the 20 m tile's 69 M cells, between its trees' planning and their
    // walks). neighbours() and depth() need it unpacked first.
    void pack();
    void unpack();
    [[nodiscard]] bool packed() const { return packed_; }

  private:
    std::vector<int> cells_;
    int root_ = 0;
    std::vector<int> offsets_;
    std::vector<int> targets_;
    std::vector<int> parent_;
    std::vector<int> depth_;
    bool packed_ = false;
};

} // namespace mcpp
