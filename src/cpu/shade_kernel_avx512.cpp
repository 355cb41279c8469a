// SPDX-License-Identifier: MIT
// The kernels for AVX-512 (F, BW, DQ, VL) with FMA: 16 pixels per
// instruction. This file alone is compiled with those flags; it runs only
// where select_kernels finds them (and the OS saves the ZMM registers).
#include <immintrin.h>

#include <algorithm>
#include <cstdint>

#include "cpu/shade_kernel_impl.hpp"
#include "cpu/small_triangle.hpp"

namespace litkit::kernels {

using Avx512Impl = detail::Impl<xsimd::avx512bw>;
namespace {

// visibility_row eight pixels at a time: AVX-512 DQ converts the 64-bit
// edge functions to float directly, rounding as the scalar conversion
// does; then the same float products and sums in 8 lanes, and masked
// writes where the test passes (the last, partial vector too).
void visibility_row(const std::int64_t v[3], const std::int64_t step[3], const float weight[3],
                    std::size_t count, float* depth, const void** visible, const void* triangle,
                    float* weight1, float* weight2) {
    const __m512i lane = _mm512_setr_epi64(0, 1, 2, 3, 4, 5, 6, 7);
    __m512i edge[3], step8[3];
    __m256 w[3];
    for (int k = 0; k < 3; ++k) {
        const __m512i s = _mm512_set1_epi64(step[k]);
        edge[k] = _mm512_add_epi64(_mm512_set1_epi64(v[k]), _mm512_mullo_epi64(lane, s));
        step8[k] = _mm512_slli_epi64(s, 3);
        w[k] = _mm256_set1_ps(weight[k]);
    }
    const __m512i tri =
        _mm512_set1_epi64(static_cast<long long>(reinterpret_cast<std::intptr_t>(triangle)));
    for (std::size_t i = 0; i < count; i += 8) {
        const __mmask8 lanes =
            count - i >= 8 ? __mmask8(0xff) : static_cast<__mmask8>((1u << (count - i)) - 1u);
        const __m256 p0 = _mm256_mul_ps(_mm512_cvtepi64_ps(edge[0]), w[0]);
        const __m256 p1 = _mm256_mul_ps(_mm512_cvtepi64_ps(edge[1]), w[1]);
        const __m256 p2 = _mm256_mul_ps(_mm512_cvtepi64_ps(edge[2]), w[2]);
        const __m256 inverse_w = _mm256_add_ps(_mm256_add_ps(p0, p1), p2);
        const __m256 old_depth = _mm256_maskz_loadu_ps(lanes, depth + i);
        // !(1/w ≤ depth): nearer, or NaN.
        const __mmask8 nearer = _mm256_mask_cmp_ps_mask(lanes, inverse_w, old_depth, _CMP_NLE_UQ);
        if (nearer) {
            _mm256_mask_storeu_ps(depth + i, nearer, inverse_w);
            _mm256_mask_storeu_ps(weight1 + i, nearer, p1);
            _mm256_mask_storeu_ps(weight2 + i, nearer, p2);
            _mm512_mask_storeu_epi64(visible + i, nearer, tri);
        }
        for (int k = 0; k < 3; ++k) edge[k] = _mm512_add_epi64(edge[k], step8[k]);
    }
}

// visibility_small of a box at most 8 pixels wide, two rows at a time:
// lanes 0-7 the first row's pixels, lanes 8-15 the next row's.
void visibility_small_pairs(const SmallEdges& edges, const RasterTriangle& t, int rows,
                            const void* shade, float* depth, const void** visible, float* weight1,
                            float* weight2, std::size_t stride, int* touched_begin,
                            int* touched_end) {
    const int span = t.max_x - t.min_x;
    const __m512i column = _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 0, 1, 2, 3, 4, 5, 6, 7);
    const __m512i second = _mm512_setr_epi32(0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1, 1, 1);
    const __mmask16 in_box = _mm512_cmple_epi32_mask(column, _mm512_set1_epi32(span));
    __m512i offset[3], bias[3];
    __m512 w[3];
    for (int k = 0; k < 3; ++k) {
        offset[k] =
            _mm512_add_epi32(_mm512_mullo_epi32(column, _mm512_set1_epi32(edges.step_x[k])),
                             _mm512_mullo_epi32(second, _mm512_set1_epi32(edges.step_y[k])));
        bias[k] = _mm512_set1_epi32(edges.bias[k]);
        w[k] = _mm512_set1_ps(t.weight[k]);
    }
    const __m512i tri =
        _mm512_set1_epi64(static_cast<long long>(reinterpret_cast<std::intptr_t>(shade)));
    std::int32_t row_origin[3] = {edges.origin[0], edges.origin[1], edges.origin[2]};
    for (int row = 0; row < rows; row += 2) {
        __m512i e[3];
        // The second row only where there is one.
        __mmask16 covered = row + 1 < rows ? in_box : static_cast<__mmask16>(in_box & 0xffu);
        for (int k = 0; k < 3; ++k) {
            e[k] = _mm512_add_epi32(_mm512_set1_epi32(row_origin[k]), offset[k]);
            covered = _mm512_mask_cmpge_epi32_mask(covered, e[k], _mm512_setzero_si512());
            row_origin[k] += 2 * edges.step_y[k];
        }
        if (!covered) continue;
        const std::size_t at =
            static_cast<std::size_t>(row) * stride + static_cast<std::size_t>(t.min_x);
        // The second row's place; where there is none (its lanes are all
        // masked off), the first row's, so that no address is past the
        // buffers.
        const std::size_t next = row + 1 < rows ? at + stride : at;
        const auto first_half = static_cast<__mmask8>(covered),
                   second_half = static_cast<__mmask8>(covered >> 8);
        const __m512 p0 = _mm512_mul_ps(_mm512_cvtepi32_ps(_mm512_sub_epi32(e[0], bias[0])), w[0]);
        const __m512 p1 = _mm512_mul_ps(_mm512_cvtepi32_ps(_mm512_sub_epi32(e[1], bias[1])), w[1]);
        const __m512 p2 = _mm512_mul_ps(_mm512_cvtepi32_ps(_mm512_sub_epi32(e[2], bias[2])), w[2]);
        const __m512 inverse_w = _mm512_add_ps(_mm512_add_ps(p0, p1), p2);
        const __m512 old_depth = _mm512_insertf32x8(
            _mm512_castps256_ps512(_mm256_maskz_loadu_ps(first_half, depth + at)),
            _mm256_maskz_loadu_ps(second_half, depth + next), 1);
        const __mmask16 nearer =
            _mm512_mask_cmp_ps_mask(covered, inverse_w, old_depth, _CMP_NLE_UQ);
        if (nearer) {
            const auto nearer_first = static_cast<__mmask8>(nearer),
                       nearer_second = static_cast<__mmask8>(nearer >> 8);
            auto store = [&](float* buffer, __m512 value) {
                _mm256_mask_storeu_ps(buffer + at, nearer_first, _mm512_castps512_ps256(value));
                // Extracted into a register first: GCC would otherwise fuse
                // extract and store into one vextractf32x8 to memory, which
                // faults on the masked-off lanes' addresses (seen here, mask
                // 0 or 1, at a page's end: GlBackend.MatchesCpuOnEveryExample
                // and the guard pages of Kernels.SmallTriangles...), where a
                // masked vmovups does not.
                __m256 upper = _mm512_extractf32x8_ps(value, 1);
                asm("" : "+v"(upper));
                _mm256_mask_storeu_ps(buffer + next, nearer_second, upper);
            };
            store(depth, inverse_w);
            store(weight1, p1);
            store(weight2, p2);
            _mm512_mask_storeu_epi64(visible + at, nearer_first, tri);
            _mm512_mask_storeu_epi64(visible + next, nearer_second, tri);
        }
        for (int half = 0; half < 2; ++half) {
            const unsigned bits = (static_cast<unsigned>(covered) >> (8 * half)) & 0xffu;
            if (!bits) continue;
            touched_begin[row + half] =
                std::min(touched_begin[row + half], t.min_x + __builtin_ctz(bits));
            touched_end[row + half] =
                std::max(touched_end[row + half], t.min_x + 32 - __builtin_clz(bits));
        }
    }
}

// visibility_small a row at a time: a row's (at most 9) pixels in the
// lanes of one vector; boxes at most 8 pixels wide two rows at a time.
void visibility_small(const RasterTriangle& t, int first_row, int rows, const void* shade,
                      float* depth, const void** visible, float* weight1, float* weight2,
                      std::size_t stride, int* touched_begin, int* touched_end) {
    const SmallEdges edges = small_edges(t, first_row);
    const int span = t.max_x - t.min_x;
    if (span < 8 && rows > 1) {
        visibility_small_pairs(edges, t, rows, shade, depth, visible, weight1, weight2, stride,
                               touched_begin, touched_end);
        return;
    }
    const __m512i lane = _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
    const __mmask16 in_box = _mm512_cmple_epi32_mask(lane, _mm512_set1_epi32(span));
    __m512i along[3], bias[3];
    __m512 w[3];
    for (int k = 0; k < 3; ++k) {
        along[k] = _mm512_mullo_epi32(lane, _mm512_set1_epi32(edges.step_x[k]));
        bias[k] = _mm512_set1_epi32(edges.bias[k]);
        w[k] = _mm512_set1_ps(t.weight[k]);
    }
    const __m512i tri =
        _mm512_set1_epi64(static_cast<long long>(reinterpret_cast<std::intptr_t>(shade)));
    std::int32_t row_origin[3] = {edges.origin[0], edges.origin[1], edges.origin[2]};
    for (int row = 0; row < rows; ++row) {
        __m512i e[3];
        __mmask16 covered = in_box;
        for (int k = 0; k < 3; ++k) {
            e[k] = _mm512_add_epi32(_mm512_set1_epi32(row_origin[k]), along[k]);
            covered = _mm512_mask_cmpge_epi32_mask(covered, e[k], _mm512_setzero_si512());
            row_origin[k] += edges.step_y[k];
        }
        if (!covered) continue;
        const std::size_t at =
            static_cast<std::size_t>(row) * stride + static_cast<std::size_t>(t.min_x);
        const __m512 p0 = _mm512_mul_ps(_mm512_cvtepi32_ps(_mm512_sub_epi32(e[0], bias[0])), w[0]);
        const __m512 p1 = _mm512_mul_ps(_mm512_cvtepi32_ps(_mm512_sub_epi32(e[1], bias[1])), w[1]);
        const __m512 p2 = _mm512_mul_ps(_mm512_cvtepi32_ps(_mm512_sub_epi32(e[2], bias[2])), w[2]);
        const __m512 inverse_w = _mm512_add_ps(_mm512_add_ps(p0, p1), p2);
        const __m512 old_depth = _mm512_maskz_loadu_ps(covered, depth + at);
        const __mmask16 nearer =
            _mm512_mask_cmp_ps_mask(covered, inverse_w, old_depth, _CMP_NLE_UQ);
        if (nearer) {
            _mm512_mask_storeu_ps(depth + at, nearer, inverse_w);
            _mm512_mask_storeu_ps(weight1 + at, nearer, p1);
            _mm512_mask_storeu_ps(weight2 + at, nearer, p2);
            _mm512_mask_storeu_epi64(visible + at, static_cast<__mmask8>(nearer), tri);
            _mm512_mask_storeu_epi64(visible + at + 8, static_cast<__mmask8>(nearer >> 8), tri);
        }
        const unsigned bits = covered;
        touched_begin[row] = std::min(touched_begin[row], t.min_x + __builtin_ctz(bits));
        touched_end[row] = std::max(touched_end[row], t.min_x + 32 - __builtin_clz(bits));
    }
}

// encode's levels as the other sets compute them (Impl::to_levels), packed
// to RGB bytes in registers: each pixel's levels as one word (r in the
// lowest byte), each 128-bit lane's four words squeezed to its first 12
// bytes, the lanes' 12-byte pieces moved together, and 3 bytes a pixel
// written under a byte mask (no word stores through memory, whose narrow
// reloads stall on store forwarding).
void encode(const float* r, const float* g, const float* b, std::size_t count, float gamma,
            std::uint8_t* rgb) {
    // Bytes 0-2, 4-6, 8-10, 12-14 of each 128-bit lane, then zeros.
    const __m512i squeeze =
        _mm512_set4_epi32(static_cast<int>(0x80808080u), 0x0e0d0c0a, 0x09080605, 0x04020100);
    const __m512i together =
        _mm512_setr_epi32(0, 1, 2, 4, 5, 6, 8, 9, 10, 12, 13, 14, 3, 7, 11, 15);
    const float* const channels[3] = {r, g, b};
    for (std::size_t i = 0; i < count; i += 16) {
        const std::size_t lanes = count - i < 16 ? count - i : 16;
        // Lanes past the end load 0 (masked: no read past the arrays) and are not written.
        const auto in = static_cast<__mmask16>((1u << lanes) - 1u);
        __m512i word = _mm512_setzero_si512();
        for (int c = 0; c < 3; ++c) {
            const Avx512Impl::Batch level = Avx512Impl::to_levels(
                Avx512Impl::Batch(_mm512_maskz_loadu_ps(in, channels[c] + i)), gamma);
            word = _mm512_or_si512(word, _mm512_slli_epi32(_mm512_cvttps_epi32(level), 8 * c));
        }
        const __m512i packed =
            _mm512_permutexvar_epi32(together, _mm512_shuffle_epi8(word, squeeze));
        _mm512_mask_storeu_epi8(rgb + 3 * i, (__mmask64{1} << (3 * lanes)) - 1u, packed);
    }
}

}  // namespace

const Kernels avx512_kernels{"avx512",
                             &Avx512Impl::interpolate,
                             &Avx512Impl::transform_vertices,
                             &Avx512Impl::perspective_weights,
                             &Avx512Impl::shade_phong,
                             &encode,
                             &Avx512Impl::accumulate,
                             &visibility_row,
                             &visibility_small};

}  // namespace litkit::kernels
