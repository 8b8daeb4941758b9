#include "core/model/RankedIdSet.hpp"

namespace mcpp {

RankedIdSet::RankedIdSet(std::uint64_t first, std::uint64_t size)
    : first_(first), size_(size), words_((size + 63U) / 64U, 0) {}

void RankedIdSet::countRanks() {
    heldBefore_.resize(words_.size());
    std::uint32_t held = 0;
    for (std::size_t word = 0; word < words_.size(); ++word) {
        heldBefore_[word] = held;
        held += bitsSet(words_[word]);
    }
}

} // namespace mcpp
