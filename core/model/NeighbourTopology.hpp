#pragma once

#include <span>
#include <vector>

namespace mcpp {

// Which active cells share a border of positive length, as compressed adjacency lists over active indices.
class NeighbourTopology {
  public:
    NeighbourTopology() = default;
    NeighbourTopology(std::vector<int> offsets, std::vector<int> neighbours)
        : offsets_(std::move(offsets)), neighbours_(std::move(neighbours)) {}

    [[nodiscard]] std::span<const int> of(int activeIndex) const {
        const auto begin = static_cast<std::size_t>(offsets_[static_cast<std::size_t>(activeIndex)]);
        const auto end = static_cast<std::size_t>(offsets_[static_cast<std::size_t>(activeIndex) + 1]);
        return {neighbours_.data() + begin, end - begin};
    }
    [[nodiscard]] std::size_t cellCount() const { return offsets_.empty() ? 0 : offsets_.size() - 1; }
    [[nodiscard]] std::size_t pairCount() const { return neighbours_.size() / 2; }
    // The lists as stored, for saving a plan: cell i's neighbours are neighbours()[offsets()[i] ...
    // offsets()[i + 1]).
    [[nodiscard]] const std::vector<int>& offsets() const { return offsets_; }
    [[nodiscard]] const std::vector<int>& neighbours() const { return neighbours_; }

  private:
    std::vector<int> offsets_;
    std::vector<int> neighbours_;
};

} // namespace mcpp
