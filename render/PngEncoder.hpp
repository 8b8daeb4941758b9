#pragma once

#include <QByteArray>
#include <QImage>

namespace mcpp::render {

// PNG bytes of an image, several times faster than QImage::save for map pictures: rows are stored
// unfiltered (map pictures are flat colour) and the whole image is compressed at once with libdeflate.
// Opaque images are written as 8-bit RGB, others as 8-bit RGBA (not premultiplied). The rows are packed
// over the image's own pixels: hand it over with std::move to spare a copy (an image still shared is copied
// first; one made over a buffer of the caller's is written over). Returns an empty array for a null image.
[[nodiscard]] QByteArray encodePng(QImage image);

} // namespace mcpp::render
