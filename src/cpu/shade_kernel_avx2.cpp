// The kernels for AVX2 with FMA: 8 pixels per instruction. This file alone
// is compiled with -mavx2 -mfma; it runs only where select_kernels finds them.
#include <immintrin.h>

#include <cstdint>

#include "cpu/shade_kernel_impl.hpp"

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
    const __m256i tri = _mm256_set1_epi64x(static_cast<long long>(reinterpret_cast<std::intptr_t>(triangle)));
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
        visibility_row_scalar(rest, step, weight, count - i, depth + i, visible + i, triangle, weight1 + i,
                              weight2 + i);
    }
}

}  // namespace

const Kernels avx2_kernels{"avx2", &Avx2Impl::interpolate, &Avx2Impl::shade_phong, &Avx2Impl::encode,
                           &visibility_row};

}  // namespace litkit::kernels
