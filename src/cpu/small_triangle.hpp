// SPDX-License-Identifier: MIT
// The edge functions of a small triangle (shade_kernel.hpp's
// visibility_small) set up in the lanes of SSE vectors, for the kernel sets
// with SSE4.1 (AVX2, AVX-512). Included by those files alone: the function
// has internal linkage, one copy per instruction set (an inline function
// shared by the linker could be the AVX-512 copy for every caller).
#pragma once

#include <immintrin.h>

#include <cstdint>

#include "cpu/shade_kernel.hpp"

namespace litkit::kernels {
namespace {

// Edge k's biased function at the centre of pixel (min_x, first_row), and
// its steps one pixel right and one down, in element k (element 3 unused).
struct SmallEdges {
    alignas(16) std::int32_t origin[4];
    alignas(16) std::int32_t step_x[4];
    alignas(16) std::int32_t step_y[4];
    alignas(16) std::int32_t bias[4];
};

SmallEdges small_edges(const RasterTriangle& t, int first_row) {
    static_assert(offsetof(RasterTriangle, y) == offsetof(RasterTriangle, x) + 12 &&
                      offsetof(RasterTriangle, weight) == offsetof(RasterTriangle, y) + 12,
                  "x, y and weight follow each other: 16-byte loads from x and y stay inside");
    // (x0, x1, x2, ·) and (y0, y1, y2, ·); a = corner k + 1 and b = corner
    // k + 2 in element k.
    const __m128i x = _mm_loadu_si128(reinterpret_cast<const __m128i*>(t.x.data()));
    const __m128i y = _mm_loadu_si128(reinterpret_cast<const __m128i*>(t.y.data()));
    const __m128i ax = _mm_shuffle_epi32(x, _MM_SHUFFLE(3, 0, 2, 1)),
                  bx = _mm_shuffle_epi32(x, _MM_SHUFFLE(3, 1, 0, 2));
    const __m128i ay = _mm_shuffle_epi32(y, _MM_SHUFFLE(3, 0, 2, 1)),
                  by = _mm_shuffle_epi32(y, _MM_SHUFFLE(3, 1, 0, 2));
    const __m128i dx = _mm_sub_epi32(bx, ax), dy = _mm_sub_epi32(by, ay);
    const __m128i zero = _mm_setzero_si128();
    // The pixel centre (min_x, first_row) in fixed point.
    const auto half = static_cast<std::int32_t>(subpixel_one / 2);
    const __m128i start_x = _mm_set1_epi32((std::int32_t{t.min_x} << subpixel_bits) + half);
    const __m128i start_y = _mm_set1_epi32((first_row << subpixel_bits) + half);
    const __m128i origin = _mm_sub_epi32(_mm_mullo_epi32(dx, _mm_sub_epi32(start_y, ay)),
                                         _mm_mullo_epi32(dy, _mm_sub_epi32(start_x, ax)));
    // Top or left: dy < 0, or dy = 0 and dx > 0; bias 0 there, −1 elsewhere.
    const __m128i top_left =
        _mm_or_si128(_mm_cmplt_epi32(dy, zero),
                     _mm_and_si128(_mm_cmpeq_epi32(dy, zero), _mm_cmpgt_epi32(dx, zero)));
    const __m128i bias = _mm_andnot_si128(top_left, _mm_set1_epi32(-1));
    SmallEdges edges;
    _mm_store_si128(reinterpret_cast<__m128i*>(edges.origin), _mm_add_epi32(origin, bias));
    _mm_store_si128(reinterpret_cast<__m128i*>(edges.step_x),
                    _mm_slli_epi32(_mm_sub_epi32(zero, dy), subpixel_bits));
    _mm_store_si128(reinterpret_cast<__m128i*>(edges.step_y), _mm_slli_epi32(dx, subpixel_bits));
    _mm_store_si128(reinterpret_cast<__m128i*>(edges.bias), bias);
    return edges;
}

}  // namespace
}  // namespace litkit::kernels
