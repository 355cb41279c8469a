// SPDX-License-Identifier: MIT
// The clip stage: a triangle that crosses a clip plane (near, far, or the
// guard band at the sides) is cut to the planes, Sutherland–Hodgman in
// homogeneous coordinates as OpenGL clips, and the polygon left is handed to
// setup as a fan of pieces in window coordinates, each carrying its own
// varyings. Triangles wholly inside pass untouched (setup tests that).
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "cpu/pipeline.hpp"

namespace litkit {

namespace {

using kernels::guard_band;
using kernels::largest_fixed_coordinate;

// A corner of the polygon being clipped: its clip-space position and varyings.
struct ClipVertex {
    glm::vec4 clip;
    Varyings varyings;
};

// Signed distances of a clip-space point to the six clip planes; ≥ 0 inside.
std::array<float, 6> plane_distances(const glm::vec4& c) {
    return {c.z + c.w,
            c.w - c.z,  // near, far
            c.x + guard_band * c.w,
            guard_band * c.w - c.x,
            c.y + guard_band * c.w,
            guard_band * c.w - c.y};
}

ClipVertex lerp(const ClipVertex& a, const ClipVertex& b, float t, int varying_count) {
    ClipVertex out;
    out.clip = a.clip + t * (b.clip - a.clip);
    for (int k = 0; k < varying_count; ++k)
        out.varyings[k] = a.varyings[k] + t * (b.varyings[k] - a.varyings[k]);
    return out;
}

// Clips a triangle against all six planes. Interpolating in homogeneous
// coordinates keeps the later perspective-correct interpolation exact.
// Returns the number of polygon vertices written to `polygon` (0 or ≥ 3).
int clip_polygon(const std::array<ClipVertex, 3>& triangle, int varying_count,
                 std::array<ClipVertex, 9>& polygon) {
    std::array<ClipVertex, 9> scratch;
    int count = 3;
    std::copy(triangle.begin(), triangle.end(), polygon.begin());
    for (int plane = 0; plane < 6; ++plane) {
        int out_count = 0;
        for (int i = 0; i < count; ++i) {
            const ClipVertex& current = polygon[i];
            const ClipVertex& next = polygon[(i + 1) % count];
            float d_current = plane_distances(current.clip)[plane];
            float d_next = plane_distances(next.clip)[plane];
            if (d_current >= 0.0f) scratch[out_count++] = current;
            if ((d_current >= 0.0f) != (d_next >= 0.0f)) {
                float t = d_current / (d_current - d_next);
                scratch[out_count++] = lerp(current, next, t, varying_count);
            }
        }
        count = out_count;
        if (count < 3) return 0;
        std::copy(scratch.begin(), scratch.begin() + count, polygon.begin());
    }
    return count;
}

// Nearest integer, halves up; |v| stays far below 2^31 thanks to the guard
// band. (std::llround is a library call; this is two instructions.)
std::int32_t round_to_int(double v) {
    const double shifted = v + 0.5;
    auto truncated = static_cast<std::int32_t>(shifted);
    return truncated - (shifted < static_cast<double>(truncated) ? 1 : 0);
}

// Perspective divide, viewport and fixed point of one clip-space corner.
WindowCorner to_window(const glm::vec4& c, float half_width, float half_height) {
    WindowCorner out;
    // plane_distances(c)[k] < 0, written out (the same sums and products).
    const float band_w = guard_band * c.w;
    out.outside =
        static_cast<std::uint8_t>((c.z + c.w < 0.0f ? 1 : 0) | (c.w - c.z < 0.0f ? 2 : 0) |
                                  (c.x + band_w < 0.0f ? 4 : 0) | (band_w - c.x < 0.0f ? 8 : 0) |
                                  (c.y + band_w < 0.0f ? 16 : 0) | (band_w - c.y < 0.0f ? 32 : 0));
    const float inverse_w = 1.0f / c.w;
    // NDC x → [0, W] left to right; NDC y → [0, H] top to bottom.
    const double window_x = (c.x * inverse_w + 1.0f) * half_width;
    const double window_y = (1.0f - c.y * inverse_w) * half_height;
    // The guard band keeps every corner within a few image sizes of the
    // picture; only degenerate input (coordinates near a float's limit,
    // where clipping loses all precision) can leave it, and a triangle
    // with such a corner is dropped rather than turned into an integer that
    // overflows.
    const double fixed_x = window_x * subpixel_one, fixed_y = window_y * subpixel_one;
    if (!(std::abs(fixed_x) < largest_fixed_coordinate &&
          std::abs(fixed_y) < largest_fixed_coordinate))
        return out;
    out.x = round_to_int(fixed_x);
    out.y = round_to_int(fixed_y);
    out.inverse_w = inverse_w;
    out.valid = true;
    return out;
}

}  // namespace

// The pieces of triangle `triangle` of object `object`: they carry their
// corners' normals (Phong; faceted takes the face's, and every per-pixel p
// comes from the pixel's ray) or colours (Gouraud), interpolated in clip
// space, which keeps the later perspective-correct interpolation exact.
void Pipeline::clip_triangle(std::uint32_t object_index, std::size_t triangle, int width,
                             int height, ClippedPieces& pieces) const {
    const PreparedObject& object = objects[object_index];
    const std::vector<glm::vec4>& clip = clip_positions[object_index];
    const bool per_pixel = object.shading == Shading::Phong || object.shading == Shading::Faceted;
    const int varying_count = per_pixel || object.shading == Shading::Gouraud ? 3 : 0;
    const float half_width = 0.5f * static_cast<float>(width);
    const float half_height = 0.5f * static_cast<float>(height);
    const auto& indices = object.triangles[triangle];
    std::array<ClipVertex, 3> input;
    for (int k = 0; k < 3; ++k) {
        const std::uint32_t v = indices[k];
        input[k].clip = clip[v];
        input[k].varyings.fill(0.0f);
        if (per_pixel) {
            const glm::vec3& n = object.normals[v];
            input[k].varyings = {n.x, n.y, n.z};
        } else if (object.shading == Shading::Gouraud) {
            const glm::vec3& c = vertex_colors[object_index][v];
            input[k].varyings = {c.x, c.y, c.z};
        }
    }
    std::array<ClipVertex, 9> polygon;
    const int count = clip_polygon(input, varying_count, polygon);
    pieces.count = 0;
    for (int k = 1; k + 1 < count; ++k) {  // a fan keeps the winding
        const ClipVertex* piece[3] = {&polygon[0], &polygon[k], &polygon[k + 1]};
        for (int m = 0; m < 3; ++m) {
            pieces.corners[pieces.count][m] = to_window(piece[m]->clip, half_width, half_height);
            pieces.varyings[pieces.count][m] = piece[m]->varyings;
        }
        ++pieces.count;
    }
}

}  // namespace litkit
