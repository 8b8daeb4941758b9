#include "app/WriterWarmUp.hpp"

#include "render/PlanSheet.hpp"

#include <algorithm>
#include <system_error>

namespace mcpp::app {

namespace {

// The writers seldom transform on more threads at once than this; a thread beyond it makes its own.
constexpr int mostPreparedTransformations = 4;

} // namespace

WriterWarmUp::WriterWarmUp(const io::GeoReference& georeference, int writerThreads) {
    if (writerThreads <= 1)
        return; // no spare core: the writers take these steps themselves
    const int transformations = std::min(writerThreads, mostPreparedTransformations);
    try {
        thread_ = std::thread([&georeference, transformations] {
            try {
                georeference.prepareTransformationsToWgs84(transformations);
                render::PlanSheet::prepareFonts();
            } catch (...) {
                // Only a head start: whatever failed here, the writers do it again and say why.
            }
        });
    } catch (const std::system_error&) {
        // No thread to be had: the writers take these steps themselves.
    }
}

WriterWarmUp::~WriterWarmUp() {
    if (thread_.joinable())
        thread_.join();
}

} // namespace mcpp::app
