#include "heap.hpp"

#include <cstdint>
#include <cstdlib>  // first: defines __GLIBC__ where the C library is glibc

#if defined(__linux__) && defined(__GLIBC__)
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace litkit_cli {

#if defined(__linux__) && defined(__GLIBC__) && defined(MADV_HUGEPAGE)

void use_large_pages_for_the_heap() {
    constexpr std::uintptr_t huge_page = std::uintptr_t{2} << 20;
    // Virtual address space only: pages are touched (and counted) as used.
    constexpr std::size_t reserve = std::size_t{256} << 20;

    // Every block comes from the one main heap, whatever its size or
    // thread, so that every block lies in the advised range below: no
    // separate mappings for large blocks, no per-thread arenas.
    mallopt(M_MMAP_MAX, 0);
    mallopt(M_ARENA_MAX, 1);
    // Never hand the top of the heap back: grown again, it would be a new
    // mapping without the advice (and its pages would fault again).
    mallopt(M_TRIM_THRESHOLD, static_cast<int>((std::size_t{1} << 31) - 1));
    // Grow the heap by the whole reserve at once.
    mallopt(M_TOP_PAD, static_cast<int>(reserve));

    const auto before = reinterpret_cast<std::uintptr_t>(sbrk(0));
    // A block larger than any free space left at the top forces the growth;
    // freeing it leaves the reserve as the heap's free top.
    // (volatile: a malloc whose block is freed unused may be left out.)
    void* volatile block = std::malloc(std::size_t{1} << 20);
    std::free(block);
    const auto after = reinterpret_cast<std::uintptr_t>(sbrk(0));
    // From the next 2 MiB boundary: the pages below it already hold data.
    const std::uintptr_t begin = (before + huge_page - 1) & ~(huge_page - 1);
    if (after > begin) {
        // A refusal (THP disabled, an old kernel) changes nothing.
        madvise(reinterpret_cast<void*>(begin), after - begin, MADV_HUGEPAGE);
    }
    mallopt(M_TOP_PAD, 128 << 10);  // glibc's default again for later growth
}

#else

void use_large_pages_for_the_heap() {}

#endif

}  // namespace litkit_cli
