// libFuzzer harness: the plan saved beside a mission, read back from any bytes; never a crash, never an
// allocation beyond what the bytes can hold. The first byte chooses what the rest is: the compressed body as
// it is on disk (mostly refused by zlib's checksum), or the plan's raw fields, compressed here, so that
// every structural check of the reader is reached; its second to fourth bits, which format (MCPP-PLAN 8, 3,
// 4, 5, 6 or 7). A plan read is drawn on its sub-cell grid, as exports and the window draw it.
#include "core/coverage/StraightRunMerging.hpp"
#include "core/outlines/RegionLabels.hpp"
#include "io/PlanFile.hpp"

#include <QByteArray>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <string>

namespace {

std::string compressedChunk(const std::uint8_t* data, std::size_t size) {
    const QByteArray compressed = qCompress(data, static_cast<qsizetype>(size), 1);
    std::string chunk(16, '\0');
    const std::uint64_t sizes[2] = {size, static_cast<std::uint64_t>(compressed.size())};
    std::memcpy(chunk.data(), sizes, sizeof(sizes));
    chunk.append(compressed.constData(), static_cast<std::size_t>(compressed.size()));
    return chunk;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 2)
        return 0;
    const bool raw = (data[0] & 1) != 0;
    const std::string body = raw ? compressedChunk(data + 1, size - 1)
                                 : std::string(reinterpret_cast<const char*>(data) + 1, size - 1);
    // The body of a file of this format or of one before, by bits 1-3 of the first byte.
    constexpr int versions[] = {mcpp::io::planFormatVersion, 3, 4, 5, 6, 7};
    const int version = versions[((data[0] >> 1) & 7) % std::size(versions)];
    auto plan = mcpp::io::parsePlanBody(body, "fuzz.mcpp-plan", version);
    if (plan.ok() && plan.value().cells.size() > 0) {
        // What the window does with a restored plan first: find cells.
        const mcpp::Cell& cell = plan.value().cells.cell(0);
        (void)plan.value().cells.cellAt({cell.centreX(), cell.centreY()});
        // What a dense export does with a path whose straight runs were merged: put them back.
        for (const mcpp::CoveragePath& path : plan.value().paths)
            (void)mcpp::walkedWaypoints(path, plan.value().cells);
        // What exports and the picture do: label the regions and the land beyond reach (on small grids: a
        // grid the reader takes for plannable may take gigabytes to draw, as planned).
        const mcpp::GridFrame& frame = plan.value().cells.frame();
        if (static_cast<double>(frame.columns) * frame.rows <= 65536.0)
            (void)mcpp::regionLabels(plan.value());
    }
    return 0;
}
