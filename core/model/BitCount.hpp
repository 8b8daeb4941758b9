#pragma once

#include <cstdint>

namespace mcpp {

// The bits set in a word, counted in a few arithmetic steps: the build targets every x86-64, whose first
// chips lack a popcount instruction, and std::popcount's library call that stands in for it took 5 % of a
// large map's run.
[[nodiscard]] constexpr std::uint32_t bitsSet(std::uint64_t word) {
    word -= (word >> 1U) & 0x5555555555555555ULL;
    word = (word & 0x3333333333333333ULL) + ((word >> 2U) & 0x3333333333333333ULL);
    word = (word + (word >> 4U)) & 0x0f0f0f0f0f0f0f0fULL;
    return static_cast<std::uint32_t>((word * 0x0101010101010101ULL) >> 56U);
}

} // namespace mcpp
