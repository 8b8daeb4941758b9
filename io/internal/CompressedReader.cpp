#include "io/internal/CompressedReader.hpp"

#include <algorithm>

namespace mcpp::io::internal {

CompressedReader::CompressedReader(std::string_view compressed) : input_(compressed) {
    // What the chunks claim to hold bounds every count read later (nextChunk checks each claim), so a
    // damaged count is refused before it allocates.
    std::size_t position = 0;
    std::uint64_t sizes[2] = {0, 0};
    while (input_.size() - position >= sizeof(sizes)) {
        std::memcpy(sizes, input_.data() + position, sizeof(sizes));
        position += sizeof(sizes);
        if (sizes[1] > input_.size() - position)
            break;
        rawBytesAhead_ += std::min<std::uint64_t>(sizes[0], sizes[1] * 1032U + 64U);
        position += static_cast<std::size_t>(sizes[1]);
    }
}

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
    return (chunkSize() - position_) + rawBytesAhead_;
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
    // qUncompress allocates what the 4-byte size in front of the zlib stream says: it must be the chunk's.
    const auto* stream = reinterpret_cast<const unsigned char*>(input_.data() + inputPosition_);
    const std::uint64_t streamSize =
        compressedSize < 4 ? 0
                           : (std::uint64_t{stream[0]} << 24U) | (std::uint64_t{stream[1]} << 16U) |
                                 (std::uint64_t{stream[2]} << 8U) | std::uint64_t{stream[3]};
    if (streamSize != rawSize)
        throw DamagedData("a damaged block");
    chunk_ = qUncompress(reinterpret_cast<const uchar*>(input_.data() + inputPosition_),
                         static_cast<qsizetype>(compressedSize));
    position_ = 0;
    if (static_cast<std::uint64_t>(chunk_.size()) != rawSize)
        throw DamagedData("a block that does not inflate to its size");
    rawBytesAhead_ -= std::min(rawBytesAhead_, rawSize);
    inputPosition_ += static_cast<std::size_t>(compressedSize);
}

} // namespace mcpp::io::internal
