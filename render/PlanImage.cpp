#include "render/PlanImage.hpp"

#include "io/AtomicFile.hpp"
#include "render/PlanRenderer.hpp"
#include "render/PlanSheet.hpp"
#include "render/PngEncoder.hpp"
#include "render/PreparedPictureMemory.hpp"

#include <QBuffer>
#include <QDir>
#include <QFileInfo>
#include <QPainter>
#include <QSvgGenerator>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#ifdef __linux__
#include <sys/mman.h>
#endif

namespace mcpp::render {

namespace {

void setError(QString* error, const QString& message) {
    if (error != nullptr)
        *error = message;
}

bool checkInputs(const ClassGrid& grid, QSize maxSize, const QString& path, QString* error) {
    if (grid.columns <= 0 || grid.rows <= 0) {
        setError(error, QStringLiteral("cannot draw %1: the raster is empty").arg(path));
        return false;
    }
    if (maxSize.width() <= 0 || maxSize.height() <= 0) {
        setError(error, QStringLiteral("cannot draw %1: image size %2x%3 is not positive")
                            .arg(path)
                            .arg(maxSize.width())
                            .arg(maxSize.height()));
        return false;
    }
    return true;
}

// A picture's pixels in memory marked for transparent huge pages: a 1600-pixel sheet takes 13 MB, which the
// kernel would otherwise fault in 4 KiB at a time (a fifth of the time of drawing a small plan). In a batch
// run they are the block faulted in ahead during start-up (PreparedPictureMemory).
QImage blankPicture(QSize size) {
    constexpr std::size_t hugePage = PreparedPictureMemory::hugePage;
    const auto bytesPerLine = static_cast<std::size_t>(size.width()) * 4;
    const std::size_t bytes =
        (bytesPerLine * static_cast<std::size_t>(size.height()) + hugePage - 1) / hugePage * hugePage;
    void* block = PreparedPictureMemory::take(bytes);
    if (block == nullptr) {
        block = std::aligned_alloc(hugePage, bytes);
        if (block == nullptr)
            return {size, QImage::Format_RGB32};
#ifdef __linux__
        madvise(block, bytes, MADV_HUGEPAGE);
#endif
    }
    return {static_cast<uchar*>(block),
            size.width(),
            size.height(),
            static_cast<qsizetype>(bytesPerLine),
            QImage::Format_RGB32,
            [](void* pixels) { std::free(pixels); },
            block};
}

} // namespace

QImage renderPlanImage(const ClassGrid& grid, const ClassTable& classes, const Plan* plan, QSize maxSize,
                       const MapLayers& layers, const RegionOutlines* outlines, const ClassGrid* frame,
                       const AreaOutline* area) {
    if (grid.columns <= 0 || grid.rows <= 0 || maxSize.width() <= 0 || maxSize.height() <= 0)
        return {};
    const ClassGrid& shown = frame != nullptr ? *frame : grid;
    const QSize size = PlanSheet::fittedMapSize(shown, maxSize);
    QImage image(size, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::white);

    PlanRenderer renderer;
    renderer.setMap(&grid, &classes);
    renderer.setPlan(plan, outlines);
    if (area != nullptr)
        renderer.setArea(*area);
    renderer.setLayers(layers);
    QPainter painter(&image);
    renderer.paint(painter, PlanRenderer::fitTransform(shown, QSizeF(size)),
                   QRectF(QPointF(0, 0), QSizeF(size)));
    painter.end();
    return image;
}

namespace {

// The encoded picture written whole or not at all; a failure leaves the previous file as it was.
bool writeWhole(const QString& path, const QByteArray& bytes, QString* error) {
    const io::Status written = io::writeFileAtomically(
        path.toStdString(), std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())),
        io::Sync::BySystem);
    if (!written)
        setError(error, QString::fromStdString(written.error()));
    return written.ok();
}

} // namespace

bool writePlanPng(const ClassGrid& grid, const ClassTable& classes, const Plan& plan, const QString& path,
                  QSize maxSize, QString* error, const SheetExtras& extras) {
    if (!checkInputs(grid, maxSize, path, error))
        return false;
    const PlanSheet sheet(grid, classes, plan, extras, maxSize);
    // Painted on 32-bit pixels, the raster engine's fastest format; written as 8-bit RGB.
    QImage image = blankPicture(sheet.size());
    QPainter painter(&image);
    sheet.paint(painter);
    painter.end();
    const QByteArray encoded = encodePng(std::move(image));
    if (encoded.isEmpty()) {
        setError(error, QStringLiteral("cannot write %1: PNG encoding failed").arg(path));
        return false;
    }
    return writeWhole(path, encoded, error);
}

bool writePlanSvg(const ClassGrid& grid, const ClassTable& classes, const Plan& plan, const QString& path,
                  QSize maxSize, QString* error, const SheetExtras& extras) {
    if (!checkInputs(grid, maxSize, path, error))
        return false;
    const QFileInfo info(path);
    if (!info.absoluteDir().exists()) {
        setError(error,
                 QStringLiteral("cannot write %1: folder %2 does not exist").arg(path, info.absolutePath()));
        return false;
    }
    const PlanSheet sheet(grid, classes, plan, extras, maxSize);
    QBuffer drawing;
    drawing.open(QIODevice::WriteOnly);
    QSvgGenerator generator;
    generator.setOutputDevice(&drawing);
    generator.setSize(sheet.size());
    generator.setViewBox(QRect(QPoint(0, 0), sheet.size()));
    generator.setTitle(sheet.title());
    generator.setDescription(QString::fromStdString("Planner: " + plan.planner));
    QPainter painter;
    if (!painter.begin(&generator)) {
        setError(error, QStringLiteral("cannot write %1: the file could not be opened").arg(path));
        return false;
    }
    sheet.paint(painter);
    if (!painter.end()) {
        setError(error, QStringLiteral("cannot write %1: drawing failed").arg(path));
        return false;
    }
    return writeWhole(path, drawing.data(), error);
}

} // namespace mcpp::render
