#pragma once

#include <QByteArray>
#include <QImage>

namespace mcpp::render {

// PNG bytes of an image, several times faster than QImage::save for map pictures: every row is filtered
// with "Up" (maps repeat the row above almost everywhere) and the whole image is compressed at once with
// libdeflate. Opaque images are written as 8-bit RGB, others as 8-bit RGBA (not premultiplied).
// Returns an empty array for a null image.
[[nodiscard]] QByteArray encodePng(const QImage& image);

} // namespace mcpp::render
