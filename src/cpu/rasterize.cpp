// SPDX-License-Identifier: MIT
// The rasterize stage, one band of rows per job: every triangle binned to
// the band is tested at the pixel centres (i + 0.5, j + 0.5), or at one of
// the pixels' samples (docs/spec.md §11) by moving it, with
// half-space edge functions and the top-left fill rule, and the nearest
// surface's triangle and perspective-correct weights (depth test on 1/w)
// go into the band's visibility buffer, which the fragment stage reads.
// Three ways to find a triangle's covered pixels, the same pixels and values
// from each: small triangles in 32-bit SIMD lanes (the kernel set's, or
// SSE2's here), narrow ones by stepping the edge functions pixel by pixel,
// wide ones by solving each row's span from them.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>

#include "cpu/pipeline.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace litkit {

namespace {

// A triangle's three edge functions, edge k opposite corner k (from corner
// k+1 to corner k+2): E(p) = (b.x − a.x)(p.y − a.y) − (b.y − a.y)(p.x − a.x)
// ≥ 0 inside, at the first pixel of its box on row y0 (origin), their steps
// per pixel along a row and down a column, and the top-left rule's bias.
struct EdgeFunctions {
    std::array<std::int64_t, 3> step_x, step_y, origin, bias;
};

EdgeFunctions edge_functions(const RasterTriangle& tri, int y0) {
    EdgeFunctions edges;
    std::array<std::int64_t, 3>& step_x = edges.step_x;
    std::array<std::int64_t, 3>& step_y = edges.step_y;
    std::array<std::int64_t, 3>& origin = edges.origin;
    std::array<std::int64_t, 3>& bias = edges.bias;
    const std::int64_t start_x = std::int64_t{tri.min_x} * subpixel_one + subpixel_one / 2;
    const std::int64_t start_y = std::int64_t{y0} * subpixel_one + subpixel_one / 2;
    for (int k = 0; k < 3; ++k) {
        const int a = (k + 1) % 3;
        const int b = (k + 2) % 3;
        const std::int64_t dx = tri.x[b] - tri.x[a];
        const std::int64_t dy = tri.y[b] - tri.y[a];
        step_x[k] = -dy * subpixel_one;
        step_y[k] = dx * subpixel_one;
        origin[k] = dx * (start_y - tri.y[a]) - dy * (start_x - tri.x[a]);
        // Top-left fill rule (in this winding): a pixel centre exactly
        // on a top or left edge belongs to the triangle, on others not.
        const bool top_left = dy < 0 || (dy == 0 && dx > 0);
        bias[k] = top_left ? 0 : -1;
    }
    return edges;
}

// Each of the three writes the covered pixels of rows y0 to y1 (within the
// band that starts at row_begin) whose 1/w is nearer than the buffer's (or
// NaN), and widens the rows' touched columns.

#if defined(__SSE2__)
// A small triangle where the kernel set has no visibility_small: the three
// edge functions in the lanes of one 32-bit SSE2 vector (exact: they stay
// far inside 32 bits for a small triangle, and a float made from the same
// integer is the same float).
void visibility_small_lanes(const RasterTriangle& tri, const ShadeTriangle* shade,
                            const EdgeFunctions& edges, int y0, int y1, int row_begin, int width,
                            BandScratch& s) {
    const std::array<std::int64_t, 3>& step_x = edges.step_x;
    const std::array<std::int64_t, 3>& step_y = edges.step_y;
    const std::array<std::int64_t, 3>& origin = edges.origin;
    const std::array<std::int64_t, 3>& bias = edges.bias;
    const float weight0 = tri.weight[0];
    const float weight1 = tri.weight[1];
    const float weight2 = tri.weight[2];
    auto lanes = [](const std::array<std::int64_t, 3>& v) {
        return _mm_setr_epi32(static_cast<std::int32_t>(v[0]), static_cast<std::int32_t>(v[1]),
                              static_cast<std::int32_t>(v[2]), 0);
    };
    const __m128i sx = lanes(step_x), sy = lanes(step_y), bv = lanes(bias);
    const __m128 wv = _mm_setr_ps(weight0, weight1, weight2, 0.0f);
    auto outside = [](__m128i e) {  // some edge function < 0
        return (_mm_movemask_ps(_mm_castsi128_ps(e)) & 7) != 0;
    };
    const int span = tri.max_x - tri.min_x;
    __m128i r = _mm_add_epi32(lanes(origin), bv);  // at the row's first pixel
    std::size_t row =
        static_cast<std::size_t>(y0 - row_begin) * width + static_cast<std::size_t>(tri.min_x);
    for (int band_row = y0 - row_begin; band_row <= y1 - row_begin; ++band_row) {
        __m128i e = r;
        r = _mm_add_epi32(r, sy);
        int x = 0;
        while (x <= span && outside(e)) {
            e = _mm_add_epi32(e, sx);
            ++x;
        }
        if (x <= span) {
            const int first = x;
            do {
                const __m128 p = _mm_mul_ps(_mm_cvtepi32_ps(_mm_sub_epi32(e, bv)), wv);
                const __m128 p1 = _mm_shuffle_ps(p, p, 1);
                const __m128 p2 = _mm_movehl_ps(p, p);
                // (p0 + p1) + p2, as visibility_narrow adds them
                const float inverse_w = _mm_cvtss_f32(_mm_add_ss(_mm_add_ss(p, p1), p2));
                const std::size_t i = row + static_cast<std::size_t>(x);
                if (!(inverse_w <= s.depth[i])) {  // nearer (or NaN)
                    s.depth[i] = inverse_w;
                    s.visible[i] = shade;
                    s.weight1[i] = _mm_cvtss_f32(p1);
                    s.weight2[i] = _mm_cvtss_f32(p2);
                }
                e = _mm_add_epi32(e, sx);
                ++x;
            } while (x <= span && !outside(e));
            s.touched_begin[band_row] = std::min(s.touched_begin[band_row], tri.min_x + first);
            s.touched_end[band_row] = std::max(s.touched_end[band_row], tri.min_x + x);
        }
        row += width;
    }
}
#endif

// A narrow triangle (all of them, in meshes of 100k triangles and more):
// found by stepping the edge functions from pixel to pixel (the covered ones
// of a row are consecutive) instead of three 64-bit divisions a row.
void visibility_narrow(const RasterTriangle& tri, const ShadeTriangle* shade,
                       const EdgeFunctions& edges, int y0, int y1, int row_begin, int width,
                       BandScratch& s) {
    const std::array<std::int64_t, 3>& step_x = edges.step_x;
    const std::array<std::int64_t, 3>& step_y = edges.step_y;
    const std::array<std::int64_t, 3>& origin = edges.origin;
    const std::array<std::int64_t, 3>& bias = edges.bias;
    const float weight0 = tri.weight[0];
    const float weight1 = tri.weight[1];
    const float weight2 = tri.weight[2];
    const std::int64_t sx0 = step_x[0], sx1 = step_x[1], sx2 = step_x[2];
    const std::int64_t b0 = bias[0], b1 = bias[1], b2 = bias[2];
    const int span = tri.max_x - tri.min_x;
    // The biased edge functions at the row's first pixel.
    std::int64_t r0 = origin[0] + b0, r1 = origin[1] + b1, r2 = origin[2] + b2;
    std::size_t row =
        static_cast<std::size_t>(y0 - row_begin) * width + static_cast<std::size_t>(tri.min_x);
    for (int band_row = y0 - row_begin; band_row <= y1 - row_begin; ++band_row) {
        std::int64_t e0 = r0, e1 = r1, e2 = r2;
        r0 += step_y[0], r1 += step_y[1], r2 += step_y[2];
        int x = 0;
        while (x <= span && (e0 | e1 | e2) < 0) {  // some edge < 0: outside
            e0 += sx0, e1 += sx1, e2 += sx2;
            ++x;
        }
        if (x <= span) {
            const int first = x;
            do {
                const float p0 = static_cast<float>(e0 - b0) * weight0;
                const float p1 = static_cast<float>(e1 - b1) * weight1;
                const float p2 = static_cast<float>(e2 - b2) * weight2;
                const float inverse_w = p0 + p1 + p2;
                const std::size_t i = row + static_cast<std::size_t>(x);
                if (!(inverse_w <= s.depth[i])) {  // nearer (or NaN)
                    s.depth[i] = inverse_w;
                    s.visible[i] = shade;
                    s.weight1[i] = p1;
                    s.weight2[i] = p2;
                }
                e0 += sx0, e1 += sx1, e2 += sx2;
                ++x;
            } while (x <= span && (e0 | e1 | e2) >= 0);
            s.touched_begin[band_row] = std::min(s.touched_begin[band_row], tri.min_x + first);
            s.touched_end[band_row] = std::max(s.touched_end[band_row], tri.min_x + x);
        }
        row += width;
    }
}

// A wide triangle: each row's covered span solved from the edge functions,
// then tested and written by the kernel set.
void visibility_wide(const RasterTriangle& tri, const ShadeTriangle* shade,
                     const EdgeFunctions& edges, int y0, int y1, int row_begin, int width,
                     BandScratch& s, const kernels::Kernels& kernels) {
    const std::array<std::int64_t, 3>& step_x = edges.step_x;
    const std::array<std::int64_t, 3>& step_y = edges.step_y;
    const std::array<std::int64_t, 3>& origin = edges.origin;
    const std::array<std::int64_t, 3>& bias = edges.bias;
    for (int y = y0; y <= y1; ++y) {
        const std::int64_t rows = y - y0;
        std::array<std::int64_t, 3> e;
        for (int k = 0; k < 3; ++k) e[k] = origin[k] + rows * step_y[k] + bias[k];
        // The covered span of this row, solved exactly from the edge
        // functions (each is linear in x): the pixels whose
        // e_k + step_x·(x − min_x) ≥ 0 for all k, so no per-pixel test.
        std::int64_t first = 0, last = tri.max_x - tri.min_x;
        for (int k = 0; k < 3 && first <= last; ++k) {
            if (step_x[k] > 0) {
                if (e[k] < 0) first = std::max(first, (-e[k] + step_x[k] - 1) / step_x[k]);
            } else if (step_x[k] < 0) {
                if (e[k] < 0)
                    last = -1;
                else
                    last = std::min(last, e[k] / -step_x[k]);
            } else if (e[k] < 0) {
                last = -1;
            }
        }
        if (first > last) continue;
        const int band_row = y - row_begin;
        s.touched_begin[band_row] =
            std::min(s.touched_begin[band_row], tri.min_x + static_cast<int>(first));
        s.touched_end[band_row] =
            std::max(s.touched_end[band_row], tri.min_x + static_cast<int>(last) + 1);
        const std::size_t row =
            static_cast<std::size_t>(band_row) * width + static_cast<std::size_t>(tri.min_x);
        // The unbiased edge functions at the span's first pixel,
        // stepped along the row by the kernel set (several pixels
        // at a time) where they stay within a double's exact
        // integers, as the guard band makes them in practice.
        const std::int64_t v[3] = {e[0] - bias[0] + first * step_x[0],
                                   e[1] - bias[1] + first * step_x[1],
                                   e[2] - bias[2] + first * step_x[2]};
        const std::int64_t count = last - first + 1;
        constexpr std::int64_t exact = std::int64_t{1} << 52;
        bool within = true;
        for (int k = 0; k < 3; ++k) {
            const std::int64_t end_value = v[k] + (count - 1) * step_x[k];
            within =
                within && v[k] < exact && v[k] > -exact && end_value < exact && end_value > -exact;
        }
        const std::size_t at = row + static_cast<std::size_t>(first);
        (within ? kernels.visibility_row : kernels::visibility_row_scalar)(
            v, step_x.data(), tri.weight.data(), static_cast<std::size_t>(count), &s.depth[at],
            reinterpret_cast<const void**>(&s.visible[at]), shade, &s.weight1[at], &s.weight2[at]);
    }
}

// A triangle moved by minus a sample's offset (SamplePass), with its pixel
// bounds at the moved place; false when it covers no pixel centre of the
// image there. Binned with bounds that hold every sample's (setup.cpp).
bool moved_triangle(const RasterTriangle& tri, const SamplePass& pass, int width, int height,
                    RasterTriangle& moved) {
    moved = tri;
    for (int k = 0; k < 3; ++k) {
        moved.x[k] -= pass.offset_x;
        moved.y[k] -= pass.offset_y;
    }
    const auto [min_x, max_x] = std::minmax({moved.x[0], moved.x[1], moved.x[2]});
    const auto [min_y, max_y] = std::minmax({moved.y[0], moved.y[1], moved.y[2]});
    const int left = std::max(0, first_pixel(min_x));
    const int right = std::min(width - 1, last_pixel(max_x));
    const int top = std::max(0, first_pixel(min_y));
    const int bottom = std::min(height - 1, last_pixel(max_y));
    if (left > right || top > bottom) return false;
    moved.min_x = static_cast<std::int16_t>(left);
    moved.max_x = static_cast<std::int16_t>(right);
    moved.min_y = static_cast<std::int16_t>(top);
    moved.max_y_small = static_cast<std::uint16_t>(bottom | (tri.small() ? 0x8000 : 0));
    return true;
}

}  // namespace

void Pipeline::rasterize_band(int band, BandScratch& s, int width, int height,
                              const SamplePass& pass) const {
    const int row_begin = band * band_height;
    const int row_end = std::min(height, row_begin + band_height);
    const std::size_t pixels = static_cast<std::size_t>(row_end - row_begin) * width;
    // The buffers arrive cleared (depth 0, nothing visible): shade_row clears
    // what it used, so a band costs only the pixels its triangles touch.
    if (s.depth.size() < pixels) {
        s.depth.assign(pixels, 0.0f);
        s.visible.assign(pixels, nullptr);
        s.weight1.resize(pixels);
        s.weight2.resize(pixels);
    }
    s.touched_begin.assign(band_height, width);
    s.touched_end.assign(band_height, 0);

    for (const SetupChunk& chunk : chunks) {
        const BinnedTriangle* const first_triangle = chunk.binned.data() + chunk.band_start[band];
        const BinnedTriangle* const end_triangle = chunk.binned.data() + chunk.band_start[band + 1];
        for (const BinnedTriangle* t = first_triangle; t != end_triangle; ++t) {
            RasterTriangle moved;
            if (!pass.at_centre() && !moved_triangle(t->raster, pass, width, height, moved))
                continue;
            const RasterTriangle& tri = pass.at_centre() ? t->raster : moved;
            const ShadeTriangle* const shade = &t->shade;
            const int y0 = std::max<int>(tri.min_y, row_begin);
            const int y1 = std::min<int>(tri.max_y(), row_end - 1);
            if (y0 > y1) continue;

            if (tri.small() && kernels.visibility_small) {
                // The kernel set's lanes set up its edge functions and test
                // a row (or two) at a time: the same pixels and values.
                const std::size_t first_row = static_cast<std::size_t>(y0 - row_begin) * width;
                kernels.visibility_small(tri, y0, y1 - y0 + 1, shade, &s.depth[first_row],
                                         reinterpret_cast<const void**>(&s.visible[first_row]),
                                         &s.weight1[first_row], &s.weight2[first_row], width,
                                         &s.touched_begin[y0 - row_begin],
                                         &s.touched_end[y0 - row_begin]);
                continue;
            }
            const EdgeFunctions edges = edge_functions(tri, y0);
#if defined(__SSE2__)
            if (tri.small()) {
                visibility_small_lanes(tri, shade, edges, y0, y1, row_begin, width, s);
                continue;
            }
#endif
            if (tri.max_x - tri.min_x < narrow_triangle)
                visibility_narrow(tri, shade, edges, y0, y1, row_begin, width, s);
            else
                visibility_wide(tri, shade, edges, y0, y1, row_begin, width, s, kernels);
        }
    }
}

}  // namespace litkit
