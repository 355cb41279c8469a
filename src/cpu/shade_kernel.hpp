// SPDX-License-Identifier: MIT
// The per-pixel stages that run on many pixels at once: Phong-shading a run
// of pixels and turning intensities into pixel values. Compiled once per
// instruction set (AVX-512, AVX2+FMA and a portable baseline) from the same
// template text; `select_kernels` picks one at run time.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "litkit/equations.hpp"
#include "litkit/lighting.hpp"
#include "litkit/limits.hpp"
#include "scene/camera.hpp"  // RowRays

namespace litkit::kernels {

// Window coordinates are fixed point with this many bits below the pixel.
constexpr int subpixel_bits = 8;
constexpr std::int64_t subpixel_one = std::int64_t{1} << subpixel_bits;

// Guard band: triangles are clipped at |x|, |y| ≤ guard_band · w, well outside
// the viewport, so fixed-point coordinates stay small while no pixel inside
// the viewport changes.
constexpr float guard_band = 2.0f;

// Window coordinates in fixed point stay below this (the guard band keeps
// them within 3 image sizes of max_image_side pixels, far less), so that edge
// functions never overflow.
constexpr double largest_fixed_coordinate = 0x1p30;

// A corner in window coordinates: fixed-point x, y and 1/w, and the clip
// planes it lies outside of (bit k: plane_distances(c)[k] < 0). Unclipped
// triangles take their corners from the vertex stage, which makes one per
// mesh vertex; clipped pieces make theirs in the clip stage (clip.cpp's
// to_window, which the kernels' transform_vertices follows exactly).
struct WindowCorner {
    std::int32_t x = 0, y = 0;
    float inverse_w = 0.0f;
    std::uint8_t outside = 0;  // clip planes, one bit each
    bool valid = false;        // false: beyond the fixed-point range (degenerate input)
};

// A run of consecutive pixels of one row in structure-of-arrays form: the
// view depth w of each (its world position is on its ray: RowRays,
// scene/camera.hpp) and its interpolated (not yet renormalised) normal.
struct SurfaceRun {
    const RowRays* rays;
    float first_k;  // k of the run's first pixel (RowRays): the next ones' are + 2, + 4, …
    const float* w;
    const float* nx;
    const float* ny;
    const float* nz;
    std::size_t count;
};

// Where interpolate writes a span's normals (structure of arrays).
struct NormalOut {
    float* nx;
    float* ny;
    float* nz;
};

struct ColorRun {
    float* r;
    float* g;
    float* b;
};

// A triangle as the visibility pass sees it (setup.cpp makes one
// per front-facing triangle or clipped piece): fixed-point window
// coordinates and the perspective weight of each corner, ordered so that
// its doubled area is positive, and its pixel bounds (inclusive, inside the
// image: at most max_image_side, so 16 bits).
static_assert(max_image_side <= 0x7fff, "RasterTriangle's pixel bounds are 15 bits");
struct RasterTriangle {
    std::array<std::int32_t, 3> x, y;
    std::array<float, 3> weight;  // 1/w of each corner over the doubled area
    std::int16_t min_x, max_x, min_y;
    std::uint16_t max_y_small;  // max_y (≤ max_image_side) and, in the top bit, small()
    int max_y() const { return max_y_small & 0x7fff; }
    // At most small_triangle (pipeline.hpp: 8 pixels, in fixed point) wide and
    // high: its edge functions fit 32 bits by far (|E| ≤ 2 · 2048² inside its
    // box, and a few pixels' steps beyond) and convert to float exactly.
    bool small() const { return (max_y_small >> 15) != 0; }
};

struct Kernels {
    const char* name;
    // docs/spec.md §3 Phong shading's normal along a span of pixels of one
    // triangle: N = q0·n0 + q1·n1 + q2·n2 from the corners' normals and the
    // pixels' perspective-correct weights (perspective_weights). The same
    // roundings as the scalar formulas in fragment.cpp: no fused multiply-add.
    void (*interpolate)(const float* q0, const float* q1, const float* q2, std::size_t count,
                        const float (*normal)[3], const NormalOut& out);
    // The vertex stage of `count` mesh vertices (positions x, y, z one after
    // another): clip = M · (p, 1) as glm multiplies, (M0·x + M1·y) +
    // (M2·z + M3) with M's columns (written x, y, z, w per vertex), and the
    // window corner clip.cpp's to_window makes of it: the clip planes
    // outside, 1/w, and x, y in fixed point, (x/w + 1)·half_width and
    // (1 − y/w)·half_height times subpixel_one rounded half up, valid where
    // both are below largest_fixed_coordinate in magnitude (otherwise x, y
    // and 1/w are 0). `matrix` is column-major (glm's).
    void (*transform_vertices)(const float* positions, std::size_t count, const float matrix[16],
                               float half_width, float half_height, float* clip,
                               WindowCorner* window);
    // The perspective-correct weights of a row of pixels, from the
    // visibility buffer's 1/w and b1/w1, b2/w2: w = 1 / (1/w), q1 = b1/w1 · w,
    // q2 = b2/w2 · w, q0 = (1 − q1) − q2 (docs/spec.md §3; where nothing was
    // drawn, 1/w is 0 and the weights are not numbers, unused); w too.
    void (*perspective_weights)(const float* inverse_w, const float* weight1, const float* weight2,
                                std::size_t count, float* w, float* q0, float* q1, float* q2);
    // docs/spec.md §3 Phong shading: renormalise the normal, light per pixel
    // at p = eye + w · d, d = centre + k · across (RowRays), each product
    // rounded on its own.
    void (*shade_phong)(Reflection reflection, std::span<const equations::PreparedLight> lights,
                        const Material& material, const SurfaceRun& surface, const ColorRun& out);
    // docs/spec.md §4 pixel values: round(255 · clamp(I, 0, 1)^(1/gamma)) per channel,
    // written as interleaved RGB bytes.
    void (*encode)(const float* r, const float* g, const float* b, std::size_t count, float gamma,
                   std::uint8_t* rgb);
    // docs/spec.md §11: one sample's light into the sums of several,
    // sum[i] += clamp(light[i], 0, 1) (NaN counts as 0, as encode has it).
    void (*accumulate)(const float* light, std::size_t count, float* sum);
    // The visibility test along one row of a wide triangle (rasterize.cpp),
    // pixel i of [0, count): the unbiased edge functions v[k] + i·step[k]
    // (integers; rasterize.cpp calls this only where they stay below 2^52 in
    // magnitude along the row, so that a double holds each exactly),
    // p_k = float(edge k) · weight[k] and 1/w = (p0 + p1) + p2. Where 1/w
    // is not ≤ depth[i] (nearer, or NaN), it writes depth[i] = 1/w,
    // visible[i] = triangle, weight1[i] = p1, weight2[i] = p2. The same
    // float operations, in the same order, in every set; only how many
    // pixels at a time differs.
    void (*visibility_row)(const std::int64_t v[3], const std::int64_t step[3],
                           const float weight[3], std::size_t count, float* depth,
                           const void** visible, const void* triangle, float* weight1,
                           float* weight2);
    // The visibility pass of a small triangle (RasterTriangle::small()) on
    // `rows` rows from pixel row `first_row` (within its box), columns
    // min_x to max_x: its edge functions, edge k from corner k+1 to corner
    // k+2, E(p) = (b.x − a.x)(p.y − a.y) − (b.y − a.y)(p.x − a.x) at the
    // pixel centres in fixed point, in 32 bits (exact for a small
    // triangle); a pixel is covered where E + bias ≥ 0 for all three, bias
    // 0 on a top or left edge (b.y < a.y, or b.y = a.y and b.x > a.x) and −1
    // on others (the top-left rule). Each covered pixel gets the test and
    // writes of visibility_row (p_k = float(E_k) · weight[k], `shade` to
    // `visible`); touched_begin/touched_end of the row widen to its covered
    // pixels. The buffers and the touched arrays start at row first_row
    // (and column 0); `stride` is the buffers' row length. Null in the
    // portable set, whose small triangles rasterize.cpp tests itself.
    void (*visibility_small)(const RasterTriangle& triangle, int first_row, int rows,
                             const void* shade, float* depth, const void** visible, float* weight1,
                             float* weight2, std::size_t stride, int* touched_begin,
                             int* touched_end);
};

// visibility_row one pixel at a time: the portable set's, and the other
// sets' for what is left of a row after their full vectors.
void visibility_row_scalar(const std::int64_t v[3], const std::int64_t step[3],
                           const float weight[3], std::size_t count, float* depth,
                           const void** visible, const void* triangle, float* weight1,
                           float* weight2);

extern const Kernels portable_kernels;
extern const Kernels avx2_kernels;    // only valid where the CPU has AVX2 and FMA
extern const Kernels avx512_kernels;  // only where it has AVX-512 F, BW, DQ, VL (and FMA)

bool cpu_has_avx2();
bool cpu_has_avx512();

// The fastest set this CPU runs: AVX-512, else AVX2, else portable.
const Kernels& select_kernels();

}  // namespace litkit::kernels
