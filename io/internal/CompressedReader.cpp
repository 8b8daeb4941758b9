#include "io/internal/CompressedReader.hpp"

#include <algorithm>

namespace mcpp::io::internal {

std::string CompressedReader::getString() {
    const std::uint64_t size = get<std::uint64_t>();
    if (size > remainingBound())
        throw DamagedData("a text longer than the file");
    std::string text(static_cast<std::size_t>(size), '\0');
    take(text.data(), text.size());
    return text;
}

std::size_t CompressedReader::getCount(std::size_t minimumBytes) {
    const std::uint64_t count = get<std::uint64_t>();
    if (count > remainingBound() / std::max<std::size_t>(minimumBytes, 1))
        throw DamagedData("a count larger than the file holds");
    return static_cast<std::size_t>(count);
}

std::uint64_t CompressedReader::remainingBound() const {
    // Raw bytes left in this chunk plus an upper bound for the rest: a zlib stream inflates at most about
    // 1032 times, and the chunk headers state their raw sizes, which nextChunk checks.
    return (chunkSize() - position_) + static_cast<std::uint64_t>(input_.size() - inputPosition_) * 1032U;
}

void CompressedReader::take(void* destination, std::size_t bytes) {
    auto* out = static_cast<char*>(destination);
    while (bytes > 0) {
        if (position_ == chunkSize())
            nextChunk();
        const std::size_t available = std::min(bytes, chunkSize() - position_);
        std::memcpy(out, chunk_.constData() + position_, available);
        position_ += available;
        out += available;
        bytes -= available;
    }
}

void CompressedReader::nextChunk() {
    std::uint64_t sizes[2] = {0, 0};
    if (input_.size() - inputPosition_ < sizeof(sizes))
        throw DamagedData("the file ends early");
    std::memcpy(sizes, input_.data() + inputPosition_, sizeof(sizes));
    inputPosition_ += sizeof(sizes);
    const auto [rawSize, compressedSize] = std::pair{sizes[0], sizes[1]};
    if (compressedSize > input_.size() - inputPosition_ || rawSize == 0 ||
        rawSize > compressedSize * 1032U + 64U)
        throw DamagedData("a damaged block");
    chunk_ = qUncompress(reinterpret_cast<const uchar*>(input_.data() + inputPosition_),
                         static_cast<qsizetype>(compressedSize));
    position_ = 0;
    if (static_cast<std::uint64_t>(chunk_.size()) != rawSize)
        throw DamagedData("a block that does not inflate to its size");
    inputPosition_ += static_cast<std::size_t>(compressedSize);
}

} // namespace mcpp::io::internal
