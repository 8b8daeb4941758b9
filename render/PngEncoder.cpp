#include "render/PngEncoder.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <libdeflate.h>
#include <memory>
#include <vector>

namespace mcpp::render {

namespace {

// libdeflate's level 4: as small as zlib's level 6 for map pictures at a fraction of its time.
constexpr int kCompressionLevel = 4;
constexpr std::uint8_t kFilterUp = 2;

// PNG stores its numbers most significant byte first.
std::array<std::uint8_t, 4> bigEndian(std::uint32_t value) {
    return {static_cast<std::uint8_t>(value >> 24), static_cast<std::uint8_t>(value >> 16),
            static_cast<std::uint8_t>(value >> 8), static_cast<std::uint8_t>(value)};
}

void appendBigEndian(QByteArray& bytes, std::uint32_t value) {
    const auto big = bigEndian(value);
    bytes.append(reinterpret_cast<const char*>(big.data()), 4);
}

// A chunk: length, type, data and the CRC-32 of type and data.
void appendChunk(QByteArray& bytes, const char (&type)[5], const std::uint8_t* data, std::size_t size) {
    appendBigEndian(bytes, static_cast<std::uint32_t>(size));
    const qsizetype typeAt = bytes.size();
    bytes.append(type, 4);
    if (size > 0)
        bytes.append(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size));
    const auto* checked = reinterpret_cast<const std::uint8_t*>(bytes.constData() + typeAt);
    appendBigEndian(bytes, libdeflate_crc32(0, checked, size + 4));
}

// Bytes left uninitialised: tens of megabytes are written over at once, and zeroing them first cost as
// much as the compression.
struct ByteBuffer {
    explicit ByteBuffer(std::size_t bytesWanted) : bytes(new std::uint8_t[bytesWanted]), size(bytesWanted) {}
    std::unique_ptr<std::uint8_t[]> bytes;
    std::size_t size;
};

// The rows as PNG stores them before compression: a filter byte, then each pixel's bytes minus those
// of the pixel above.
ByteBuffer filteredRows(const QImage& image, int channels) {
    const int width = image.width();
    const std::size_t rowBytes = static_cast<std::size_t>(width) * static_cast<std::size_t>(channels);
    ByteBuffer rows(static_cast<std::size_t>(image.height()) * (rowBytes + 1));
    std::vector<std::uint8_t> above(rowBytes, 0), current(rowBytes);
    std::uint8_t* out = rows.bytes.get();
    for (int y = 0; y < image.height(); ++y) {
        const auto* pixels = reinterpret_cast<const QRgb*>(image.constScanLine(y));
        std::uint8_t* byte = current.data();
        for (int x = 0; x < width; ++x) {
            *byte++ = static_cast<std::uint8_t>(qRed(pixels[x]));
            *byte++ = static_cast<std::uint8_t>(qGreen(pixels[x]));
            *byte++ = static_cast<std::uint8_t>(qBlue(pixels[x]));
            if (channels == 4)
                *byte++ = static_cast<std::uint8_t>(qAlpha(pixels[x]));
        }
        *out++ = kFilterUp;
        std::transform(
            current.begin(), current.end(), above.begin(), out,
            [](std::uint8_t pixel, std::uint8_t up) { return static_cast<std::uint8_t>(pixel - up); });
        out += rowBytes;
        above.swap(current);
    }
    return rows;
}

struct CompressorDeleter {
    void operator()(libdeflate_compressor* compressor) const { libdeflate_free_compressor(compressor); }
};

// The zlib stream of the filtered rows (its size is the bytes used); size 0 when compression fails.
ByteBuffer compressedRows(const ByteBuffer& rows) {
    const std::unique_ptr<libdeflate_compressor, CompressorDeleter> compressor(
        libdeflate_alloc_compressor(kCompressionLevel));
    if (!compressor)
        return ByteBuffer(0);
    ByteBuffer compressed(libdeflate_zlib_compress_bound(compressor.get(), rows.size));
    compressed.size = libdeflate_zlib_compress(compressor.get(), rows.bytes.get(), rows.size,
                                               compressed.bytes.get(), compressed.size);
    return compressed;
}

} // namespace

QByteArray encodePng(const QImage& image) {
    if (image.isNull())
        return {};
    const bool opaque = !image.hasAlphaChannel();
    const QImage pixels = image.convertToFormat(opaque ? QImage::Format_RGB32 : QImage::Format_ARGB32);
    const ByteBuffer compressed = compressedRows(filteredRows(pixels, opaque ? 3 : 4));
    const std::size_t compressedSize = compressed.size;
    if (compressedSize == 0)
        return {};

    QByteArray bytes;
    bytes.reserve(static_cast<qsizetype>(compressedSize) + 64);
    bytes.append("\x89PNG\r\n\x1a\n", 8);
    std::array<std::uint8_t, 13> header{}; // 8 bits a channel; compression, filtering, interlace all 0
    const auto width = bigEndian(static_cast<std::uint32_t>(pixels.width()));
    const auto height = bigEndian(static_cast<std::uint32_t>(pixels.height()));
    std::copy(width.begin(), width.end(), header.begin());
    std::copy(height.begin(), height.end(), header.begin() + 4);
    header[8] = 8;
    header[9] = opaque ? 2 : 6; // colour type: RGB or RGBA
    appendChunk(bytes, "IHDR", header.data(), header.size());
    // Several IDAT chunks of at most a mebibyte: readers are kinder to them than to one huge chunk.
    constexpr std::size_t kChunkBytes = std::size_t{1} << 20;
    for (std::size_t at = 0; at < compressedSize; at += kChunkBytes)
        appendChunk(bytes, "IDAT", compressed.bytes.get() + at, std::min(kChunkBytes, compressedSize - at));
    appendChunk(bytes, "IEND", nullptr, 0);
    return bytes;
}

} // namespace mcpp::render
