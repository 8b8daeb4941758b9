#pragma once

#include <vector>

namespace mcpp {

// Numbers a list of graph cells 0..n-1 in a shared array indexed by cell id (-1 elsewhere) for as long
// as the scope lives, so per-region work needs no map and no allocation the size of the graph.
class CellIndexScope {
  public:
    CellIndexScope(std::vector<int>& index, const std::vector<int>& cells) : index_(index), cells_(cells) {
        for (std::size_t local = 0; local < cells_.size(); ++local)
            index_[static_cast<std::size_t>(cells_[local])] = static_cast<int>(local);
    }
    ~CellIndexScope() {
        for (int cell : cells_)
            index_[static_cast<std::size_t>(cell)] = -1;
    }
    CellIndexScope(const CellIndexScope&) = delete;
    CellIndexScope& operator=(const CellIndexScope&) = delete;

    [[nodiscard]] int operator[](int cell) const { return index_[static_cast<std::size_t>(cell)]; }

  private:
    std::vector<int>& index_;
    const std::vector<int>& cells_;
};

} // namespace mcpp
