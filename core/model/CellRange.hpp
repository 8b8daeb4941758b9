#pragma once

#include "core/model/Cell.hpp"
#include "core/model/CellRecord.hpp"
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
        Iterator(const CellRecord* record, const GridFrame* frame) : record_(record), frame_(frame) {}
        [[nodiscard]] Cell operator*() const { return cellOf(*record_, *frame_); }
        Iterator& operator++() {
            ++record_;
            return *this;
        }
        Iterator operator++(int) {
            Iterator before = *this;
            ++record_;
            return before;
        }
        [[nodiscard]] bool operator==(const Iterator& other) const { return record_ == other.record_; }

      private:
        const CellRecord* record_ = nullptr;
        const GridFrame* frame_ = nullptr;
    };

    CellRange(const std::vector<CellRecord>& records, const GridFrame& frame)
        : records_(records), frame_(frame) {}

    [[nodiscard]] Iterator begin() const { return {records_.data(), &frame_}; }
    [[nodiscard]] Iterator end() const { return {records_.data() + records_.size(), &frame_}; }
    [[nodiscard]] std::size_t size() const { return records_.size(); }
    [[nodiscard]] bool empty() const { return records_.empty(); }
    [[nodiscard]] Cell operator[](std::size_t id) const { return cellOf(records_[id], frame_); }
    // Every cell, whole: for a planner that changes a copy of them.
    [[nodiscard]] std::vector<Cell> toVector() const { return {begin(), end()}; }

  private:
    const std::vector<CellRecord>& records_;
    const GridFrame& frame_;
};

} // namespace mcpp
