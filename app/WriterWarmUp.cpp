#include "app/WriterWarmUp.hpp"

#include "render/PlanSheet.hpp"

namespace mcpp::app {

WriterWarmUp::WriterWarmUp(const io::GeoReference& georeference, int writerThreads)
    : thread_([&georeference, writerThreads] {
          georeference.prepareTransformationsToWgs84(writerThreads);
          render::PlanSheet::prepareFonts();
      }) {}

WriterWarmUp::~WriterWarmUp() {
    if (thread_.joinable())
        thread_.join();
}

} // namespace mcpp::app
