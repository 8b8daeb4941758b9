#pragma once

#include <cstddef>
#include <utility>
#include <vector>

namespace mcpp {

// The cells a growing region may take next, smallest key first (ties: the smaller cell index), as a
// four-ary heap: half the levels of a binary heap, and the four children of a node share a cache line or
// two. On a large map a region's frontier holds tens of thousands of entries and the growth spends most of
// its time taking the smallest out; the order taken is the same as any heap's, as no two entries compare
// equal unless they are the same.
class GrowthFrontier {
  public:
    using Entry = std::pair<double, int>; // key, cell

    [[nodiscard]] bool empty() const { return entries_.empty(); }
    [[nodiscard]] std::size_t size() const { return entries_.size(); }
    [[nodiscard]] const Entry& top() const { return entries_.front(); }

    void push(double key, int cell) {
        entries_.emplace_back(key, cell);
        siftUp(entries_.size() - 1);
    }

    void pop() {
        entries_.front() = entries_.back();
        entries_.pop_back();
        if (!entries_.empty())
            siftDown(0);
    }

  private:
    static constexpr std::size_t arity = 4;

    void siftUp(std::size_t index) {
        const Entry moving = entries_[index];
        while (index > 0) {
            const std::size_t parent = (index - 1) / arity;
            if (!(moving < entries_[parent]))
                break;
            entries_[index] = entries_[parent];
            index = parent;
        }
        entries_[index] = moving;
    }

    void siftDown(std::size_t index) {
        const Entry moving = entries_[index];
        const std::size_t count = entries_.size();
        while (true) {
            const std::size_t first = index * arity + 1;
            if (first >= count)
                break;
            const std::size_t last = first + arity < count ? first + arity : count;
            std::size_t smallest = first;
            for (std::size_t child = first + 1; child < last; ++child)
                if (entries_[child] < entries_[smallest])
                    smallest = child;
            if (!(entries_[smallest] < moving))
                break;
            entries_[index] = entries_[smallest];
            index = smallest;
        }
        entries_[index] = moving;
    }

    std::vector<Entry> entries_;
};

} // namespace mcpp
