// SPDX-License-Identifier: MIT
// The four-wide SIMD batches of the hierarchy (its nodes' boxes and its
// blocks of triangles are four wide): SSE2 on x86-64 (and in the
// WebAssembly build, whose SSE2 headers map onto SIMD128), NEON on ARM.
#pragma once

#include <xsimd/xsimd.hpp>

namespace litkit::trace::simd {

#if XSIMD_WITH_SSE2
using Arch = xsimd::sse2;
#elif XSIMD_WITH_NEON64
using Arch = xsimd::neon64;
#elif XSIMD_WITH_NEON
using Arch = xsimd::neon;
#else
#error "the tracer's hierarchy needs four-wide SIMD (SSE2 or NEON)"
#endif

using Floats = xsimd::batch<float, Arch>;
using Mask = xsimd::batch_bool<float, Arch>;
static_assert(Floats::size == 4);

// Bit i set where lane i of `mask` is.
inline unsigned bits(const Mask& mask) {
#if XSIMD_WITH_SSE2
    return static_cast<unsigned>(_mm_movemask_ps(mask));
#else
    alignas(16) bool lanes[4];
    mask.store_aligned(lanes);
    return unsigned(lanes[0]) | unsigned(lanes[1]) << 1 | unsigned(lanes[2]) << 2 |
           unsigned(lanes[3]) << 3;
#endif
}

}  // namespace litkit::trace::simd
