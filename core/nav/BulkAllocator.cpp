#include "nav/BulkAllocator.h"

#include <algorithm>
#include <mutex>
#include <unordered_map>
#include <vector>

#include <sys/mman.h>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace footpath::bulk {

namespace {

struct Block {
    void* address;
    std::size_t bytes;
};

/// Every block handed out (its size, which deallocate() is not told) and the freed ones kept.
struct Blocks {
    std::mutex mutex;
    std::unordered_map<void*, std::size_t> inUse;
    std::vector<Block> cached;  ///< oldest first
    std::size_t cachedBytes = 0;
};

/// Never destroyed: a vector in a static object may free its block after any destructor here ran.
Blocks& blocks()
{
    static Blocks* const instance = new Blocks;
    return *instance;
}

/// The smallest cached block that fits bytes without wasting more than its size; nullptr if none.
void* takeCached(Blocks& all, std::size_t bytes)
{
    auto best = all.cached.end();
    for (auto it = all.cached.begin(); it != all.cached.end(); ++it)
        if (it->bytes >= bytes && it->bytes <= 2 * bytes && (best == all.cached.end() || it->bytes < best->bytes))
            best = it;
    if (best == all.cached.end())
        return nullptr;
    const Block block = *best;
    all.cached.erase(best);
    all.cachedBytes -= block.bytes;
    all.inUse.emplace(block.address, block.bytes);
    return block.address;
}

}  // namespace

void* allocate(std::size_t bytes)
{
    const std::size_t rounded = (bytes + kHugePage_bytes - 1) / kHugePage_bytes * kHugePage_bytes;
    Blocks& all = blocks();
    {
        const std::lock_guard<std::mutex> lock(all.mutex);
        if (void* reused = takeCached(all, rounded))
            return reused;
    }
    void* fresh = std::aligned_alloc(kHugePage_bytes, rounded);
    if (fresh == nullptr)
        return nullptr;
    madvise(fresh, rounded, MADV_HUGEPAGE);  // a hint: without huge pages it is ordinary memory
    const std::lock_guard<std::mutex> lock(all.mutex);
    all.inUse.emplace(fresh, rounded);
    return fresh;
}

void deallocate(void* block) noexcept
{
    if (block == nullptr)
        return;
    Blocks& all = blocks();
    std::vector<void*> released;
    {
        const std::lock_guard<std::mutex> lock(all.mutex);
        const auto found = all.inUse.find(block);
        const std::size_t bytes = found == all.inUse.end() ? kMaxCached_bytes + 1 : found->second;
        if (found != all.inUse.end())
            all.inUse.erase(found);
        if (bytes > kMaxCached_bytes) {
            released.push_back(block);
        } else {
            all.cached.push_back({block, bytes});
            all.cachedBytes += bytes;
            while (all.cachedBytes > kMaxCached_bytes || all.cached.size() > kMaxCachedBlocks) {
                released.push_back(all.cached.front().address);
                all.cachedBytes -= all.cached.front().bytes;
                all.cached.erase(all.cached.begin());
            }
        }
    }
    for (void* address : released)
        std::free(address);
}

std::size_t cachedBytes()
{
    Blocks& all = blocks();
    const std::lock_guard<std::mutex> lock(all.mutex);
    return all.cachedBytes;
}

void releaseCached() noexcept
{
    Blocks& all = blocks();
    std::vector<Block> released;
    {
        const std::lock_guard<std::mutex> lock(all.mutex);
        released.swap(all.cached);
        all.cachedBytes = 0;
    }
    for (const Block& block : released)
        std::free(block.address);
}

}  // namespace footpath::bulk

namespace footpath {

void keepFreedMemoryForReruns()
{
#if defined(__GLIBC__)
    // Setting either threshold also stops glibc from moving them with the sizes it sees freed.
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TRIM_THRESHOLD, 256 << 20);
#endif
}

}  // namespace footpath
