#include "app/BackgroundPrefault.hpp"

#include <cerrno>
#include <cstdint>

#ifdef __linux__
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace mcpp::app {

namespace {

// Steps of a huge page: each is one system call, and a block freed meanwhile is noticed between them.
constexpr std::uintptr_t stepBytes = std::uintptr_t{2} << 20;

} // namespace

BackgroundPrefault::~BackgroundPrefault() {
    {
        const std::lock_guard lock(mutex_);
        stopping_ = true;
        activeDropped_.store(true);
    }
    wake_.notify_all();
    if (thread_.joinable())
        thread_.join();
}

void BackgroundPrefault::request(void* block, std::size_t bytes) noexcept {
#ifdef MADV_POPULATE_WRITE
    if (block == nullptr || bytes == 0 || unsupported_.load(std::memory_order_relaxed))
        return;
    {
        const std::lock_guard lock(mutex_);
        if (stopping_)
            return;
        if (!thread_.joinable()) {
            try {
                thread_ = std::thread([this] { run(); });
            } catch (...) { // no thread to be had, or no memory for it
                unsupported_.store(true);
                return;
            }
        }
        // A block still waiting is dropped: its owner has most likely filled it by now.
        waiting_ = {static_cast<char*>(block), bytes};
        waitingStart_.store(block, std::memory_order_release);
    }
    wake_.notify_one();
#else
    (void)block;
    (void)bytes;
#endif
}

void BackgroundPrefault::forget(const void* block) noexcept {
    // The helper marks a block active before it stops marking it waiting: a block is always seen in one.
    if (block == nullptr || (block != waitingStart_.load(std::memory_order_acquire) &&
                             block != activeStart_.load(std::memory_order_acquire)))
        return;
    {
        const std::lock_guard lock(mutex_);
        if (waiting_.start == block) {
            waiting_ = {};
            waitingStart_.store(nullptr, std::memory_order_release);
        }
        // Noticed before the helper's next step; the step under way may still fault in a 2 MB range the
        // program maps anew meanwhile, which costs memory, never contents.
        if (activeStart_.load(std::memory_order_relaxed) == block)
            activeDropped_.store(true);
    }
    idle_.notify_all();
}

void BackgroundPrefault::waitUntilIdle() {
    std::unique_lock lock(mutex_);
    idle_.wait(lock, [this] { return waiting_.start == nullptr && !busy_; });
}

void BackgroundPrefault::run() {
    std::unique_lock lock(mutex_);
    while (true) {
        wake_.wait(lock, [this] { return stopping_ || waiting_.start != nullptr; });
        if (stopping_)
            return;
        const Range range = waiting_;
        activeDropped_.store(false);
        activeStart_.store(range.start, std::memory_order_release);
        waiting_ = {};
        waitingStart_.store(nullptr, std::memory_order_release);
        busy_ = true;
        lock.unlock();
        faultIn(range);
        lock.lock();
        activeStart_.store(nullptr, std::memory_order_release);
        busy_ = false;
        if (waiting_.start == nullptr)
            idle_.notify_all();
    }
}

void BackgroundPrefault::faultIn(Range range) {
#ifdef MADV_POPULATE_WRITE
    // Whole pages inside the block only: the pages at its ends may hold other blocks' bytes.
    static const auto pageBytes = static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
    const auto begin = (reinterpret_cast<std::uintptr_t>(range.start) + pageBytes - 1) & ~(pageBytes - 1);
    const auto end = (reinterpret_cast<std::uintptr_t>(range.start) + range.bytes) & ~(pageBytes - 1);
    for (std::uintptr_t stepEnd = end; stepEnd > begin && !activeDropped_.load();) {
        const std::uintptr_t stepBegin = stepEnd - begin > stepBytes ? stepEnd - stepBytes : begin;
        if (madvise(reinterpret_cast<void*>(stepBegin), stepEnd - stepBegin, MADV_POPULATE_WRITE) != 0) {
            if (errno == EINVAL) // a kernel without it
                unsupported_.store(true);
            return; // otherwise the range is no longer mapped as it was
        }
        stepEnd = stepBegin;
    }
#else
    (void)range;
#endif
}

} // namespace mcpp::app
