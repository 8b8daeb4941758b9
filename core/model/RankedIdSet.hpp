#pragma once

#include "core/model/BitCount.hpp"

#include <cstdint>
#include <vector>

namespace mcpp {

// A set of ids, each with its rank (how many held ids are smaller): a bit an id of its room and a count
// every 64 ids, about 0.19 bytes an id, where an array of ranks takes 4. Ids are inserted first, then
// countRanks() readies the ranks.
class RankedIdSet {
  public:
    RankedIdSet() = default;
    // Room for the ids first .. first + size - 1, none held yet.
    RankedIdSet(std::uint64_t first, std::uint64_t size);

    void insert(std::uint64_t id) {
        words_[(id - first_) / 64U] |= std::uint64_t{1} << ((id - first_) % 64U);
    }
    // After the last insert, before the first rankOf.
    void countRanks();

    // Whether it was made with room for any id.
    [[nodiscard]] bool hasRoom() const { return !words_.empty(); }
    // Whether the id is held (false outside the room).
    [[nodiscard]] bool holds(std::uint64_t id) const {
        if (id < first_ || id - first_ >= size_)
            return false;
        const std::uint64_t place = id - first_;
        return (words_[place / 64U] >> (place % 64U) & 1U) != 0;
    }
    // The id's rank among those held, or -1 where it is not held.
    [[nodiscard]] int rankOf(std::uint64_t id) const {
        if (id < first_ || id - first_ >= size_)
            return -1;
        const std::uint64_t place = id - first_;
        const std::uint64_t word = words_[place / 64U];
        const std::uint64_t bit = std::uint64_t{1} << (place % 64U);
        if ((word & bit) == 0)
            return -1;
        return static_cast<int>(heldBefore_[place / 64U] + bitsSet(word & (bit - 1)));
    }

  private:
    std::uint64_t first_ = 0;
    std::uint64_t size_ = 0;
    std::vector<std::uint64_t> words_;
    std::vector<std::uint32_t> heldBefore_; // held ids in the words before each
};

} // namespace mcpp
