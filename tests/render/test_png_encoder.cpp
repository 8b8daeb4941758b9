#include "render/PngEncoder.hpp"

#include <QImage>
#include <QtTest>
#include <cstdint>
#include <random>
#include <vector>

using namespace mcpp;

namespace {

QImage noise(int width, int height, QImage::Format format, unsigned seed) {
    QImage image(width, height, format);
    std::mt19937 random(seed);
    std::uniform_int_distribution<int> byte(0, 255);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            image.setPixelColor(x, y,
                                QColor(byte(random), byte(random), byte(random),
                                       format == QImage::Format_ARGB32 ? byte(random) : 255));
    return image;
}

std::uint32_t bigEndian(const QByteArray& bytes, qsizetype at) {
    std::uint32_t value = 0;
    for (int i = 0; i < 4; ++i)
        value = (value << 8) | static_cast<std::uint8_t>(bytes[at + i]);
    return value;
}

// CRC-32 as the PNG specification's sample code computes it, bit by bit: an oracle independent of the
// library the encoder uses.
std::uint32_t crc32(const char* data, std::size_t size) {
    std::uint32_t crc = 0xffffffffU;
    for (std::size_t i = 0; i < size; ++i) {
        crc ^= static_cast<std::uint8_t>(data[i]);
        for (int bit = 0; bit < 8; ++bit)
            crc = (crc & 1U) != 0 ? 0xedb88320U ^ (crc >> 1) : crc >> 1;
    }
    return crc ^ 0xffffffffU;
}

struct Chunk {
    QByteArray type;
    std::uint32_t length = 0;
    bool crcMatches = false;
};

std::vector<Chunk> chunksOf(const QByteArray& png) {
    std::vector<Chunk> chunks;
    for (qsizetype at = 8; at + 12 <= png.size();) {
        Chunk chunk;
        chunk.length = bigEndian(png, at);
        chunk.type = png.mid(at + 4, 4);
        const auto stored = bigEndian(png, at + 8 + static_cast<qsizetype>(chunk.length));
        chunk.crcMatches = stored == crc32(png.constData() + at + 4, chunk.length + 4);
        chunks.push_back(chunk);
        at += 12 + static_cast<qsizetype>(chunk.length);
    }
    return chunks;
}

} // namespace

class PngEncoderTest : public QObject {
    Q_OBJECT

  private slots:
    void opaqueImagesReadBackPixelForPixel_data() {
        QTest::addColumn<int>("width");
        QTest::addColumn<int>("height");
        QTest::newRow("one pixel") << 1 << 1;
        QTest::newRow("odd sizes") << 3 << 2;
        QTest::newRow("wide") << 257 << 13;
        QTest::newRow("tall") << 7 << 301;
    }
    void opaqueImagesReadBackPixelForPixel() {
        QFETCH(int, width);
        QFETCH(int, height);
        const QImage image = noise(width, height, QImage::Format_RGB32, 11);
        const QByteArray png = render::encodePng(image);
        QVERIFY(png.startsWith("\x89PNG\r\n\x1a\n"));
        const QImage decoded = QImage::fromData(png, "PNG");
        QCOMPARE(decoded.size(), image.size());
        QVERIFY(!decoded.hasAlphaChannel()); // written as RGB, three bytes a pixel
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x)
                QCOMPARE(decoded.pixel(x, y), image.pixel(x, y));
    }

    // Rows padded beyond their pixels (an image over a buffer of its own layout) are packed over the same.
    void paddedRowsReadBackPixelForPixel() {
        const QImage source = noise(9, 5, QImage::Format_RGB32, 15);
        constexpr qsizetype bytesPerLine = 9 * 4 + 12;
        std::vector<uchar> buffer(static_cast<std::size_t>(bytesPerLine) * 5, 0xAB);
        QImage padded(buffer.data(), 9, 5, bytesPerLine, QImage::Format_RGB32);
        for (int y = 0; y < 5; ++y)
            for (int x = 0; x < 9; ++x)
                padded.setPixel(x, y, source.pixel(x, y));
        const QImage decoded = QImage::fromData(render::encodePng(std::move(padded)), "PNG");
        QCOMPARE(decoded.convertToFormat(QImage::Format_RGB32), source);
    }

    void transparencyIsKept() {
        const QImage image = noise(64, 33, QImage::Format_ARGB32, 12);
        const QImage decoded = QImage::fromData(render::encodePng(image), "PNG");
        QVERIFY(decoded.hasAlphaChannel());
        const QImage comparable = decoded.convertToFormat(QImage::Format_ARGB32);
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x)
                QCOMPARE(comparable.pixel(x, y), image.pixel(x, y));
    }

    // Other formats are converted first: three-byte pixels, and a premultiplied picture (as the map canvas
    // paints) comes out with its colours and alpha unpremultiplied, as PNG stores them.
    void otherFormatsAreConverted() {
        QImage image(40, 20, QImage::Format_RGB888);
        image.fill(QColor(12, 200, 99));
        QCOMPARE(QImage::fromData(render::encodePng(image), "PNG").pixelColor(39, 19), QColor(12, 200, 99));

        QImage translucent(30, 10, QImage::Format_ARGB32_Premultiplied);
        translucent.fill(QColor(200, 100, 40, 128));
        const QImage decoded =
            QImage::fromData(render::encodePng(translucent), "PNG").convertToFormat(QImage::Format_ARGB32);
        const QColor expected = translucent.convertToFormat(QImage::Format_ARGB32).pixelColor(29, 9);
        QCOMPARE(decoded.pixelColor(29, 9), expected);
        QCOMPARE(decoded.pixelColor(29, 9).alpha(), 128);
        QVERIFY(std::abs(decoded.pixelColor(0, 0).red() - 200) <= 2); // not the premultiplied 100
    }

    // Chunks in order, each with a correct CRC; compressed data above a mebibyte in several IDAT chunks.
    void chunksAreWellFormed() {
        const QByteArray png = render::encodePng(noise(1000, 600, QImage::Format_RGB32, 13));
        const std::vector<Chunk> chunks = chunksOf(png);
        QVERIFY(chunks.size() >= 4);
        QCOMPARE(chunks.front().type, QByteArray("IHDR"));
        QCOMPARE(chunks.front().length, 13U);
        QCOMPARE(chunks.back().type, QByteArray("IEND"));
        int dataChunks = 0;
        for (const Chunk& chunk : chunks) {
            QVERIFY2(chunk.crcMatches, chunk.type.constData());
            if (chunk.type == "IDAT") {
                ++dataChunks;
                QVERIFY(chunk.length <= (1U << 20));
            }
        }
        QCOMPARE(dataChunks, static_cast<int>(chunks.size()) - 2);
        QVERIFY(dataChunks >= 2); // 1.8 MB of noise does not compress below a mebibyte
    }

    // Map pictures are flat colour: a banded picture compresses to a small fraction of its pixels (each
    // unfiltered row is a run of matches of the row above, at most 258 bytes each: under 2 %).
    void mapLikePicturesCompressWell() {
        QImage image(1200, 900, QImage::Format_RGB32);
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x)
                image.setPixel(x, y, (x / 50) % 2 == 0 ? 0x40a040 : 0x2060c0);
        const QByteArray png = render::encodePng(image);
        QVERIFY2(png.size() < 1200 * 900 * 3 / 50, qPrintable(QString::number(png.size())));
        QCOMPARE(QImage::fromData(png, "PNG").pixel(75, 450) & 0xffffffU, 0x2060c0U);
    }

    // The rows are packed over the pixels of the image encoded: an image the caller still holds keeps its
    // own.
    void callersImageIsUnchanged() {
        const QImage image = noise(31, 17, QImage::Format_RGB32, 14);
        const QImage before = image.copy();
        const QImage decoded = QImage::fromData(render::encodePng(image), "PNG");
        QCOMPARE(image, before);
        QCOMPARE(decoded.convertToFormat(QImage::Format_RGB32), before);
    }

    void nullImageGivesNoBytes() { QVERIFY(render::encodePng(QImage()).isEmpty()); }
};

QTEST_GUILESS_MAIN(PngEncoderTest)
#include "test_png_encoder.moc"
