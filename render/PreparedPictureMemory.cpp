#include "render/PreparedPictureMemory.hpp"

#include <cstdlib>
#include <mutex>
#include <system_error>
#ifdef __linux__
#include <sys/mman.h>
#endif

namespace mcpp::render {

namespace {

std::mutex offerMutex;
PreparedPictureMemory* offered = nullptr; // the one block on offer, guarded by offerMutex
void* offeredBlock = nullptr;
std::size_t offeredBytes = 0;

void touchEveryPage(void* block, std::size_t bytes) {
    constexpr std::size_t page = 4096;
    auto* bytesOf = static_cast<volatile char*>(block);
    for (std::size_t at = 0; at < bytes; at += page)
        bytesOf[at] = 0;
}

} // namespace

PreparedPictureMemory::PreparedPictureMemory(std::size_t bytes) {
    bytes = (bytes + hugePage - 1) / hugePage * hugePage;
    void* block = std::aligned_alloc(hugePage, bytes);
    if (block == nullptr)
        return;
#ifdef __linux__
    madvise(block, bytes, MADV_HUGEPAGE);
#endif
    try {
        thread_ = std::thread(touchEveryPage, block, bytes);
    } catch (const std::system_error&) {
        std::free(block); // no thread to be had: the picture faults its own pages in
        return;
    }
    block_ = block;
    const std::lock_guard lock(offerMutex);
    if (offered == nullptr) {
        offered = this;
        offeredBlock = block;
        offeredBytes = bytes;
    }
}

PreparedPictureMemory::~PreparedPictureMemory() {
    bool taken = false;
    {
        const std::lock_guard lock(offerMutex);
        if (offered == this) {
            taken = offeredBlock == nullptr;
            offered = nullptr;
            offeredBlock = nullptr;
        }
    }
    if (thread_.joinable())
        thread_.join();
    if (!taken)
        std::free(block_);
}

void* PreparedPictureMemory::take(std::size_t bytes) {
    const std::lock_guard lock(offerMutex);
    if (offered == nullptr || offeredBlock == nullptr || bytes > offeredBytes)
        return nullptr;
    if (offered->thread_.joinable())
        offered->thread_.join();
    void* block = offeredBlock;
    offeredBlock = nullptr;
    return block;
}

} // namespace mcpp::render
