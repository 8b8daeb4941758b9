#pragma once

#include "core/model/Cell.hpp"
#include "core/model/CellRecord.hpp"
#include "core/model/CellTurnFigures.hpp"
#include "core/model/GridFrame.hpp"

#include <cstddef>
#include <iterator>
#include <vector>

namespace mcpp {

// A cell graph's cells, each made whole (its square worked out from the frame) as it is read.
class CellRange {
  public:
    class Iterator {
      public:
        using iterator_category = std::forward_iterator_tag;
        using value_type = Cell;
        using difference_type = std::ptrdiff_t;
        using pointer = void;
        using reference = Cell;

        Iterator() = default;
        // Points into the graph, not the range: an iterator outlives the range a call returned.
        Iterator(const CellRecord* records, const GridFrame* frame, const CellTurnFigures* turns,
                 std::size_t id)
            : records_(records), frame_(frame), turns_(turns), id_(id) {}
        [[nodiscard]] Cell operator*() const { return cellAt(records_[id_], *frame_, *turns_, id_); }
        Iterator& operator++() {
            ++id_;
            return *this;
        }
        Iterator operator++(int) {
            Iterator before = *this;
            ++id_;
            return before;
        }
        [[nodiscard]] bool operator==(const Iterator& other) const { return id_ == other.id_; }

      private:
        const CellRecord* records_ = nullptr;
        const GridFrame* frame_ = nullptr;
        const CellTurnFigures* turns_ = nullptr;
        std::size_t id_ = 0;
    };

    CellRange(const std::vector<CellRecord>& records, const GridFrame& frame, const CellTurnFigures& turns)
        : records_(records), frame_(frame), turns_(turns) {}

    [[nodiscard]] Iterator begin() const { return {records_.data(), &frame_, &turns_, 0}; }
    [[nodiscard]] Iterator end() const { return {records_.data(), &frame_, &turns_, records_.size()}; }
    [[nodiscard]] std::size_t size() const { return records_.size(); }
    [[nodiscard]] bool empty() const { return records_.empty(); }
    [[nodiscard]] Cell operator[](std::size_t id) const { return cellAt(records_[id], frame_, turns_, id); }
    // Every cell, whole: for a planner that changes a copy of them.
    [[nodiscard]] std::vector<Cell> toVector() const { return {begin(), end()}; }

  private:
    // Cell `id` whole, its turn figures read beside its record.
    [[nodiscard]] static Cell cellAt(const CellRecord& record, const GridFrame& frame,
                                     const CellTurnFigures& turns, std::size_t id) {
        return cellOf(record, frame, turns.turnSeconds(id, record.speedMetresPerSecond),
                      turns.expectedTurns(id));
    }

    const std::vector<CellRecord>& records_;
    const GridFrame& frame_;
    const CellTurnFigures& turns_;
};

} // namespace mcpp
