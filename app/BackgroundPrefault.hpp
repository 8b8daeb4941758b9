#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <thread>

namespace mcpp::app {

// Faults in the pages of a freshly allocated large block on a thread of its own, from the block's end
// backwards, while its owner fills it from the front or computes what it will put there. A page's first
// touch is the kernel clearing it, and on a virtual machine the host backing it too: 2.4 s a GB on the
// benchmark machine, a quarter of a large plan's time, done on one core while the other waited. The pages
// come in as if written and keep what they hold, so nothing the program computes changes.
//
// One block at a time, the newest asked for first; a block freed before or while it is faulted in is
// dropped (forget), and a range the program no longer maps only makes the system call fail. Where the
// kernel cannot fault ahead (before Linux 5.14), requests are ignored.
class BackgroundPrefault {
  public:
    BackgroundPrefault() = default;
    ~BackgroundPrefault();
    BackgroundPrefault(const BackgroundPrefault&) = delete;
    BackgroundPrefault& operator=(const BackgroundPrefault&) = delete;

    // Called from operator new: allocates nothing but the thread, the first time.
    void request(void* block, std::size_t bytes) noexcept;
    // Called from operator delete for every block: two relaxed loads unless `block` is the one in hand.
    void forget(const void* block) noexcept;
    // Returns once no block is waiting or being faulted in (for tests).
    void waitUntilIdle();

  private:
    struct Range {
        char* start = nullptr;
        std::size_t bytes = 0;
    };

    void run();
    void faultIn(Range range);

    std::mutex mutex_;
    std::condition_variable wake_;
    std::condition_variable idle_;
    Range waiting_;
    bool busy_ = false;
    bool stopping_ = false;
    std::atomic<const void*> waitingStart_{nullptr};
    std::atomic<const void*> activeStart_{nullptr};
    std::atomic<bool> activeDropped_{false};
    std::atomic<bool> unsupported_{false};
    std::thread thread_;
};

} // namespace mcpp::app
