#include "io/internal/CompressedWriter.hpp"

#include <QByteArray>

namespace mcpp::io::internal {

namespace {

constexpr std::size_t chunkBytes = 32U << 20U;

void appendSize(std::string& output, std::uint64_t size) {
    output.append(reinterpret_cast<const char*>(&size), sizeof(size));
}

} // namespace

void CompressedWriter::put(const std::string& text) {
    put(static_cast<std::uint64_t>(text.size()));
    buffer_ += text;
    flushIfFull();
}

void CompressedWriter::flushIfFull() {
    if (buffer_.size() >= chunkBytes)
        flush();
}

void CompressedWriter::flush() {
    if (buffer_.empty())
        return;
    // Level 1: a plan of millions of cells compresses in about a second, a third of its raw size.
    const QByteArray compressed =
        qCompress(reinterpret_cast<const uchar*>(buffer_.data()), static_cast<qsizetype>(buffer_.size()), 1);
    appendSize(output_, buffer_.size());
    appendSize(output_, static_cast<std::uint64_t>(compressed.size()));
    output_.append(compressed.constData(), static_cast<std::size_t>(compressed.size()));
    buffer_.clear();
}

std::string CompressedWriter::finish() {
    flush();
    return std::move(output_);
}

} // namespace mcpp::io::internal
