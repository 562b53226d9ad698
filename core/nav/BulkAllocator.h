#pragma once

#include <cstddef>
#include <cstdlib>
#include <new>
#include <utility>

#include <sys/mman.h>

namespace footpath {

/// Allocator for the large per-run arrays a pass over a recording fills once (the smoother's
/// records): elements are default-initialised, not zeroed (every element is written before it is
/// read, and zeroing 100 MB costs as much as filling it), and a block of several MB asks the kernel
/// for transparent huge pages, so touching it first costs one page fault per 2 MB instead of per
/// 4 kB (a 30-minute walk at 100 Hz stores about 110 MB; the faults were a sixth of its run).
template <typename T>
struct BulkAllocator {
    using value_type = T;
    static constexpr std::size_t kHugePage_bytes = std::size_t(2) << 20;

    BulkAllocator() = default;
    template <typename U>
    BulkAllocator(const BulkAllocator<U>&) noexcept {}

    T* allocate(std::size_t n)
    {
        const std::size_t bytes = n * sizeof(T);
        if (bytes < 2 * kHugePage_bytes) {
            if (void* p = std::malloc(bytes))
                return static_cast<T*>(p);
            throw std::bad_alloc();
        }
        const std::size_t rounded = (bytes + kHugePage_bytes - 1) / kHugePage_bytes * kHugePage_bytes;
        void* p = std::aligned_alloc(kHugePage_bytes, rounded);
        if (p == nullptr)
            throw std::bad_alloc();
        madvise(p, rounded, MADV_HUGEPAGE);  // a hint: without huge pages it is ordinary memory
        return static_cast<T*>(p);
    }
    void deallocate(T* p, std::size_t) noexcept { std::free(p); }

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
