#pragma once

#include "core/model/RankedIdSet.hpp"

#include <algorithm>
#include <functional>
#include <vector>

namespace mcpp {

// Numbers a list of graph cells 0..n-1 for as long as the scope lives, so per-region work needs no map.
// With a shared array indexed by cell id (-1 elsewhere), the numbers are written into it and cleared again.
// With an empty array and cells in strictly ascending order (as cellsByRobot lists them), a cell's number
// is its rank in a bit set over the region's id range (0.19 bytes an id of that range), where the array
// takes four bytes a cell of the whole map for each thread (550 MB on a map of 69 million cells). An empty
// array and cells in another order: the scope numbers them in an array of its own.
class CellIndexScope {
  public:
    CellIndexScope(std::vector<int>& index, const std::vector<int>& cells)
        : index_(index.empty() ? own_ : index), cells_(cells) {
        if (index.empty() && !cells_.empty() &&
            std::adjacent_find(cells_.begin(), cells_.end(), std::greater_equal<>{}) == cells_.end()) {
            byRank_ = true;
            const auto first = static_cast<std::uint64_t>(cells_.front());
            ranks_ = RankedIdSet(first, static_cast<std::uint64_t>(cells_.back()) - first + 1);
            for (const int cell : cells_)
                ranks_.insert(static_cast<std::uint64_t>(cell));
            ranks_.countRanks();
            return;
        }
        if (index_.empty() && !cells_.empty())
            index_.assign(static_cast<std::size_t>(*std::max_element(cells_.begin(), cells_.end())) + 1, -1);
        for (std::size_t local = 0; local < cells_.size(); ++local)
            index_[static_cast<std::size_t>(cells_[local])] = static_cast<int>(local);
    }
    ~CellIndexScope() {
        if (!byRank_)
            for (int cell : cells_)
                index_[static_cast<std::size_t>(cell)] = -1;
    }
    CellIndexScope(const CellIndexScope&) = delete;
    CellIndexScope& operator=(const CellIndexScope&) = delete;

    [[nodiscard]] int operator[](int cell) const {
        if (byRank_)
            return ranks_.rankOf(static_cast<std::uint64_t>(cell));
        return static_cast<std::size_t>(cell) < index_.size() ? index_[static_cast<std::size_t>(cell)] : -1;
    }

  private:
    std::vector<int> own_; // declared before index_, which may refer to it
    std::vector<int>& index_;
    const std::vector<int>& cells_;
    bool byRank_ = false;
    RankedIdSet ranks_;
};

} // namespace mcpp
