#pragma once

#include <cstddef>
#include <thread>

namespace mcpp::render {

// The pixels of a batch run's plan.png, faulted in ahead on another thread. A page's first touch is the
// kernel clearing it, and on a virtual machine the host backing it too: a 2000-pixel sheet's 14 MB took
// 5-47 ms of the picture's writing on the benchmark machine, the longest writer on small maps, while the
// second core idled through start-up. Made before the raster is read; the picture takes the block once.
class PreparedPictureMemory {
  public:
    // Starts faulting in `bytes` on a thread of its own; the block is offered to the next picture.
    explicit PreparedPictureMemory(std::size_t bytes);
    // Waits for the thread; frees the block when no picture took it.
    ~PreparedPictureMemory();
    PreparedPictureMemory(const PreparedPictureMemory&) = delete;
    PreparedPictureMemory& operator=(const PreparedPictureMemory&) = delete;

    // The prepared block, once faulted in, when one is on offer and holds `bytes`; else nullptr. Aligned to
    // hugePage and marked for transparent huge pages; the caller frees it with std::free.
    [[nodiscard]] static void* take(std::size_t bytes);

    static constexpr std::size_t hugePage = std::size_t{2} << 20;

  private:
    void* block_ = nullptr;
    std::thread thread_;
};

} // namespace mcpp::render
