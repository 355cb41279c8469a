// SPDX-License-Identifier: MIT
// The kernels for AVX2 with FMA: 8 pixels per instruction. This file alone
// is compiled with -mavx2 -mfma; it runs only where select_kernels finds them.
#include <immintrin.h>

#include <algorithm>
#include <cstdint>

#include "cpu/shade_kernel_impl.hpp"
#include "cpu/small_triangle.hpp"

namespace litkit::kernels {

using Avx2Impl = detail::Impl<xsimd::avx2>;
namespace {

// visibility_row four pixels at a time: the edge functions in double lanes
// (exact: integers below 2^52), rounded once to float as the scalar
// int64 → float conversion rounds them; then the same float products and
// sums, and the writes blended in where the test passes.
void visibility_row(const std::int64_t v[3], const std::int64_t step[3], const float weight[3],
                    std::size_t count, float* depth, const void** visible, const void* triangle,
                    float* weight1, float* weight2) {
    const __m256d lane = _mm256_setr_pd(0.0, 1.0, 2.0, 3.0);
    __m256d edge[3], step4[3];
    __m128 w[3];
    for (int k = 0; k < 3; ++k) {
        const __m256d s = _mm256_set1_pd(static_cast<double>(step[k]));
        edge[k] = _mm256_add_pd(_mm256_set1_pd(static_cast<double>(v[k])), _mm256_mul_pd(lane, s));
        step4[k] = _mm256_mul_pd(_mm256_set1_pd(4.0), s);
        w[k] = _mm_set1_ps(weight[k]);
    }
    const __m256i tri =
        _mm256_set1_epi64x(static_cast<long long>(reinterpret_cast<std::intptr_t>(triangle)));
    std::size_t i = 0;
    for (; i + 4 <= count; i += 4) {
        const __m128 p0 = _mm_mul_ps(_mm256_cvtpd_ps(edge[0]), w[0]);
        const __m128 p1 = _mm_mul_ps(_mm256_cvtpd_ps(edge[1]), w[1]);
        const __m128 p2 = _mm_mul_ps(_mm256_cvtpd_ps(edge[2]), w[2]);
        const __m128 inverse_w = _mm_add_ps(_mm_add_ps(p0, p1), p2);
        const __m128 old_depth = _mm_loadu_ps(depth + i);
        const __m128 nearer = _mm_cmpnle_ps(inverse_w, old_depth);  // !(1/w ≤ depth): NaN too
        if (_mm_movemask_ps(nearer)) {
            _mm_storeu_ps(depth + i, _mm_blendv_ps(old_depth, inverse_w, nearer));
            _mm_storeu_ps(weight1 + i, _mm_blendv_ps(_mm_loadu_ps(weight1 + i), p1, nearer));
            _mm_storeu_ps(weight2 + i, _mm_blendv_ps(_mm_loadu_ps(weight2 + i), p2, nearer));
            auto* at = reinterpret_cast<__m256i*>(visible + i);
            const __m256i wide = _mm256_cvtepi32_epi64(_mm_castps_si128(nearer));
            _mm256_storeu_si256(at, _mm256_castpd_si256(_mm256_blendv_pd(
                                        _mm256_castsi256_pd(_mm256_loadu_si256(at)),
                                        _mm256_castsi256_pd(tri), _mm256_castsi256_pd(wide))));
        }
        for (int k = 0; k < 3; ++k) edge[k] = _mm256_add_pd(edge[k], step4[k]);
    }
    if (i < count) {
        const std::int64_t rest[3] = {v[0] + static_cast<std::int64_t>(i) * step[0],
                                      v[1] + static_cast<std::int64_t>(i) * step[1],
                                      v[2] + static_cast<std::int64_t>(i) * step[2]};
        visibility_row_scalar(rest, step, weight, count - i, depth + i, visible + i, triangle,
                              weight1 + i, weight2 + i);
    }
}

// visibility_small eight pixels of a row at a time (a row has at most 9).
void visibility_small(const RasterTriangle& t, int first_row, int rows, const void* shade,
                      float* depth, const void** visible, float* weight1, float* weight2,
                      std::size_t stride, int* touched_begin, int* touched_end) {
    const SmallEdges edges = small_edges(t, first_row);
    const int span = t.max_x - t.min_x;
    const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    __m256i along[3], bias[3];
    __m256 w[3];
    for (int k = 0; k < 3; ++k) {
        along[k] = _mm256_mullo_epi32(lane, _mm256_set1_epi32(edges.step_x[k]));
        bias[k] = _mm256_set1_epi32(edges.bias[k]);
        w[k] = _mm256_set1_ps(t.weight[k]);
    }
    const __m256i tri =
        _mm256_set1_epi64x(static_cast<long long>(reinterpret_cast<std::intptr_t>(shade)));
    std::int32_t row_origin[3] = {edges.origin[0], edges.origin[1], edges.origin[2]};
    for (int row = 0; row < rows; ++row) {
        unsigned row_covered = 0;  // bit x: pixel min_x + x is covered
        for (int first = 0; first <= span; first += 8) {
            __m256i e[3];
            // A lane is out where some edge function is < 0 or it is past the box.
            __m256i out = _mm256_cmpgt_epi32(lane, _mm256_set1_epi32(span - first));
            for (int k = 0; k < 3; ++k) {
                e[k] = _mm256_add_epi32(_mm256_set1_epi32(row_origin[k] + first * edges.step_x[k]),
                                        along[k]);
                out = _mm256_or_si256(out, e[k]);  // the sign bit: < 0
            }
            const unsigned covered =
                ~static_cast<unsigned>(_mm256_movemask_ps(_mm256_castsi256_ps(out))) & 0xffu;
            if (!covered) continue;
            row_covered |= covered << first;
            const __m256 take =
                _mm256_castsi256_ps(_mm256_cmpgt_epi32(out, _mm256_set1_epi32(-1)));  // covered
            const std::size_t at =
                static_cast<std::size_t>(row) * stride + static_cast<std::size_t>(t.min_x + first);
            const __m256 p0 =
                _mm256_mul_ps(_mm256_cvtepi32_ps(_mm256_sub_epi32(e[0], bias[0])), w[0]);
            const __m256 p1 =
                _mm256_mul_ps(_mm256_cvtepi32_ps(_mm256_sub_epi32(e[1], bias[1])), w[1]);
            const __m256 p2 =
                _mm256_mul_ps(_mm256_cvtepi32_ps(_mm256_sub_epi32(e[2], bias[2])), w[2]);
            const __m256 inverse_w = _mm256_add_ps(_mm256_add_ps(p0, p1), p2);
            const __m256i take_i = _mm256_castps_si256(take);
            const __m256 old_depth = _mm256_maskload_ps(depth + at, take_i);
            const __m256 nearer =
                _mm256_and_ps(take, _mm256_cmp_ps(inverse_w, old_depth, _CMP_NLE_UQ));
            if (_mm256_movemask_ps(nearer)) {
                const __m256i nearer_i = _mm256_castps_si256(nearer);
                _mm256_maskstore_ps(depth + at, nearer_i, inverse_w);
                _mm256_maskstore_ps(weight1 + at, nearer_i, p1);
                _mm256_maskstore_ps(weight2 + at, nearer_i, p2);
                auto* pointers = reinterpret_cast<long long*>(visible + at);
                _mm256_maskstore_epi64(
                    pointers, _mm256_cvtepi32_epi64(_mm256_castsi256_si128(nearer_i)), tri);
                _mm256_maskstore_epi64(pointers + 4,
                                       _mm256_cvtepi32_epi64(_mm256_extracti128_si256(nearer_i, 1)),
                                       tri);
            }
        }
        for (int k = 0; k < 3; ++k) row_origin[k] += edges.step_y[k];
        if (row_covered) {
            touched_begin[row] = std::min(touched_begin[row], t.min_x + __builtin_ctz(row_covered));
            touched_end[row] =
                std::max(touched_end[row], t.min_x + 32 - __builtin_clz(row_covered));
        }
    }
}

}  // namespace

const Kernels avx2_kernels{"avx2",
                           &Avx2Impl::interpolate,
                           &Avx2Impl::transform_vertices,
                           &Avx2Impl::perspective_weights,
                           &Avx2Impl::shade_phong,
                           &Avx2Impl::encode,
                           &Avx2Impl::accumulate,
                           &visibility_row,
                           &visibility_small};

}  // namespace litkit::kernels
