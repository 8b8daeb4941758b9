#pragma once

#include "io/GeoReference.hpp"

#include <thread>

namespace mcpp::app {

// While the planner runs, mostly on one core, takes the writers' slow first steps on another: the
// transformations to WGS84 their threads will borrow and the font database the picture needs. Started
// before planning; the destructor waits for it.
class WriterWarmUp {
  public:
    WriterWarmUp(const io::GeoReference& georeference, int writerThreads);
    ~WriterWarmUp();
    WriterWarmUp(const WriterWarmUp&) = delete;
    WriterWarmUp& operator=(const WriterWarmUp&) = delete;

  private:
    std::thread thread_;
};

} // namespace mcpp::app
