#pragma once

#include <array>
#include <cstddef>
#include <span>

namespace mcpp {

// A cell's neighbours: a view of lists a graph stores, or up to four ids worked out for a cell of a grid
// (which keeps no lists). Read it while it lives; its ids may be its own.
class NeighbourList {
  public:
    static constexpr std::size_t mostWorkedOut = 4;

    NeighbourList() = default;
    explicit NeighbourList(std::span<const int> stored) : stored_(stored.data()), size_(stored.size()) {}

    // For lists worked out: at most mostWorkedOut ids.
    void add(int id) { own_[size_++] = id; }

    [[nodiscard]] const int* begin() const { return stored_ != nullptr ? stored_ : own_.data(); }
    [[nodiscard]] const int* end() const { return begin() + size_; }
    [[nodiscard]] std::size_t size() const { return size_; }
    [[nodiscard]] bool empty() const { return size_ == 0; }
    [[nodiscard]] int operator[](std::size_t i) const { return begin()[i]; }

  private:
    const int* stored_ = nullptr;
    std::size_t size_ = 0;
    std::array<int, mostWorkedOut> own_{};
};

} // namespace mcpp
