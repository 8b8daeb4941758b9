// The program's operator new and delete: malloc and free, with one addition. A large map's plan lives in a
// few vectors of hundreds of megabytes, and the kernel faults them in 4 KiB at a time: on a 5-million-cell
// map a third of the run went to page faults. Blocks of several megabytes are therefore marked for
// transparent huge pages (2 MiB), which the kernel honours where it is set to "madvise", as Debian ships
// it; nothing changes where huge pages are off. The largest are also faulted in ahead on another thread
// (BackgroundPrefault). Sanitizer builds keep their own allocator.

#if !defined(__SANITIZE_ADDRESS__)

#include "app/BackgroundPrefault.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <new>
#include <sys/mman.h>

namespace {

constexpr std::size_t hugePage = std::size_t{2} << 20;
constexpr std::size_t largeBlock = std::size_t{8} << 20;

void adviseHugePages(void* block, std::size_t size) {
    const auto begin = reinterpret_cast<std::uintptr_t>(block);
    const std::uintptr_t first = (begin + hugePage - 1) & ~(hugePage - 1);
    const std::uintptr_t last = (begin + size) & ~(hugePage - 1);
    if (last > first)
        madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
}

// Blocks the size of a large plan's arrays (tens of millions of cells) are faulted in on another thread;
// smaller ones are filled before the other thread would get far.
constexpr std::size_t prefaultedBlock = std::size_t{64} << 20;

// Never destroyed: blocks are freed until the very end of the program, after static destructors.
mcpp::app::BackgroundPrefault& prefault() {
    static auto* const shared = new mcpp::app::BackgroundPrefault;
    return *shared;
}

void adviseLargeBlock(void* block, std::size_t size) {
    adviseHugePages(block, size);
    if (size >= prefaultedBlock)
        prefault().request(block, size);
}

void release(void* block) noexcept {
    if (block != nullptr)
        prefault().forget(block);
    std::free(block);
}

void* allocate(std::size_t size) noexcept {
    void* block = std::malloc(size == 0 ? 1 : size);
    if (block != nullptr && size >= largeBlock)
        adviseLargeBlock(block, size);
    return block;
}

void* allocateAligned(std::size_t size, std::align_val_t alignment) noexcept {
    const auto align = std::max(static_cast<std::size_t>(alignment), sizeof(void*));
    void* block = nullptr;
    if (posix_memalign(&block, align, size == 0 ? 1 : size) != 0)
        return nullptr;
    if (size >= largeBlock)
        adviseLargeBlock(block, size);
    return block;
}

} // namespace

void* operator new(std::size_t size) {
    if (void* block = allocate(size))
        return block;
    throw std::bad_alloc();
}
void* operator new[](std::size_t size) {
    if (void* block = allocate(size))
        return block;
    throw std::bad_alloc();
}
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
    return allocate(size);
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
    return allocate(size);
}
void* operator new(std::size_t size, std::align_val_t alignment) {
    if (void* block = allocateAligned(size, alignment))
        return block;
    throw std::bad_alloc();
}
void* operator new[](std::size_t size, std::align_val_t alignment) {
    if (void* block = allocateAligned(size, alignment))
        return block;
    throw std::bad_alloc();
}
void* operator new(std::size_t size, std::align_val_t alignment, const std::nothrow_t&) noexcept {
    return allocateAligned(size, alignment);
}
void* operator new[](std::size_t size, std::align_val_t alignment, const std::nothrow_t&) noexcept {
    return allocateAligned(size, alignment);
}

void operator delete(void* block) noexcept {
    release(block);
}
void operator delete[](void* block) noexcept {
    release(block);
}
void operator delete(void* block, std::size_t) noexcept {
    release(block);
}
void operator delete[](void* block, std::size_t) noexcept {
    release(block);
}
void operator delete(void* block, const std::nothrow_t&) noexcept {
    release(block);
}
void operator delete[](void* block, const std::nothrow_t&) noexcept {
    release(block);
}
void operator delete(void* block, std::align_val_t) noexcept {
    release(block);
}
void operator delete[](void* block, std::align_val_t) noexcept {
    release(block);
}
void operator delete(void* block, std::size_t, std::align_val_t) noexcept {
    release(block);
}
void operator delete[](void* block, std::size_t, std::align_val_t) noexcept {
    release(block);
}
void operator delete(void* block, std::align_val_t, const std::nothrow_t&) noexcept {
    release(block);
}
void operator delete[](void* block, std::align_val_t, const std::nothrow_t&) noexcept {
    release(block);
}

#endif
