// SPDX-License-Identifier: MIT
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

#ifdef MADV_COLLAPSE
constexpr int madv_collapse = MADV_COLLAPSE;
#else
constexpr int madv_collapse = 25;  // Linux's value; glibc 2.36's headers lack the name
#endif

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

    // The heap's end moved up to a 2 MiB boundary, so that the growth below
    // starts on one: glibc takes a moved break as another user's memory and
    // starts its new top there. Otherwise up to 2 MiB at the start of the
    // growth (where the first large blocks go) would stay in small pages.
    const auto end = reinterpret_cast<std::uintptr_t>(sbrk(0));
    const std::uintptr_t begin = (end + huge_page - 1) & ~(huge_page - 1);
    const bool aligned = begin == end || sbrk(static_cast<std::intptr_t>(begin - end)) !=
                                             reinterpret_cast<void*>(-1);
    // A block larger than the free space left in the heap (a few hundred
    // KiB at start-up) forces the growth; freeing it leaves the reserve as
    // the heap's free top. Its size keeps both headers malloc writes (the
    // block's and the top's after it) in the first 2 MiB, the only range
    // touched before the advice. (volatile: a malloc whose block is freed
    // unused may be left out.)
    void* volatile block = std::malloc(huge_page - 64);
    std::free(block);
    const auto after = reinterpret_cast<std::uintptr_t>(sbrk(0));
    if (aligned && after > begin) {
        // A refusal (THP disabled, an old kernel) changes nothing.
        madvise(reinterpret_cast<void*>(begin), after - begin, MADV_HUGEPAGE);
        // That first range already has a small page (the headers), so a
        // fault there would not bring a huge page: collapse it into one
        // (Linux 6.1 and later; refused harmlessly before).
        madvise(reinterpret_cast<void*>(begin), huge_page, madv_collapse);
    }
    mallopt(M_TOP_PAD, 128 << 10);  // glibc's default again for later growth
}

#else

void use_large_pages_for_the_heap() {}

#endif

}  // namespace litkit_cli
