#pragma once

#include <cstddef>
#include <cstdlib>
#include <new>
#include <utility>

namespace footpath {

/// The large blocks behind BulkAllocator, which keep the few last freed ones for the next run: a
/// slider re-runs the estimate on the same recording, and a fresh block costs the kernel's zeroing
/// of every page on first touch (a quarter of a 30-minute walk's re-estimate in the window). At most
/// kMaxCached_bytes (and kMaxCachedBlocks blocks) stay held, the most recently freed first.
namespace bulk {
constexpr std::size_t kHugePage_bytes = std::size_t(2) << 20;
constexpr std::size_t kMaxCached_bytes = std::size_t(1) << 30;
constexpr std::size_t kMaxCachedBlocks = 8;
/// A block of at least bytes (a multiple of 2 MB), aligned to a huge page; nullptr if there is no
/// memory. A cached block is reused if it is at most twice as large.
void* allocate(std::size_t bytes);
/// Returns a block from allocate() to the cache, or to the system if the cache is full.
void deallocate(void* block) noexcept;
/// Bytes held in freed blocks now (for tests and the memory figures).
std::size_t cachedBytes();
/// Frees every cached block.
void releaseCached() noexcept;
}  // namespace bulk

/// Tells the C library (glibc) to keep the memory a run frees for the next run instead of handing
/// it back to the kernel: by default it returns a freed block of more than 128 kB at once, and the
/// next run in the process then pays a page fault and the zeroing of every page it touches again
/// (1141 faults, a third of the time, of a 32 s walk's run). Blocks up to 32 MB come from the
/// heap, and up to 256 MB freed at its top stay with the process; larger ones are still returned.
/// Call once at program start, before any thread (the applications and the benchmarks do);
/// elsewhere than glibc it does nothing.
void keepFreedMemoryForReruns();

/// Allocator for the large per-run arrays a pass over a recording fills once (the smoother's
/// records): elements are default-initialised, not zeroed (every element is written before it is
/// read, and zeroing 100 MB costs as much as filling it), and a block of several MB asks the kernel
/// for transparent huge pages, so touching it first costs one page fault per 2 MB instead of per
/// 4 kB (a 30-minute walk at 100 Hz stores about 110 MB; the faults were a sixth of its run), and
/// is reused by the next run (bulk::allocate).
template <typename T>
struct BulkAllocator {
    using value_type = T;

    BulkAllocator() = default;
    template <typename U>
    BulkAllocator(const BulkAllocator<U>&) noexcept {}

    T* allocate(std::size_t n)
    {
        const std::size_t bytes = n * sizeof(T);
        void* p = isBulk(n) ? bulk::allocate(bytes) : std::malloc(bytes);
        if (p == nullptr)
            throw std::bad_alloc();
        return static_cast<T*>(p);
    }
    void deallocate(T* p, std::size_t n) noexcept
    {
        if (isBulk(n))
            bulk::deallocate(p);
        else
            std::free(p);
    }
    /// Blocks of two huge pages or more come from bulk::, smaller ones from malloc; allocate and
    /// deallocate must agree.
    static bool isBulk(std::size_t n) { return n * sizeof(T) >= 2 * bulk::kHugePage_bytes; }

    /// resize() default-initialises instead of zeroing.
    template <typename U>
    void construct(U* p) noexcept
    {
        ::new (static_cast<void*>(p)) U;
    }
    template <typename U, typename... Args>
    void construct(U* p, Args&&... args)
    {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }

    template <typename U>
    bool operator==(const BulkAllocator<U>&) const noexcept { return true; }
    template <typename U>
    bool operator!=(const BulkAllocator<U>&) const noexcept { return false; }
};

}  // namespace footpath
