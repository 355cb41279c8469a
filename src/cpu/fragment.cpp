// SPDX-License-Identifier: MIT
// The fragment stage, one band of rows per job after the rasterize stage
// has filled its visibility buffer: each visible pixel once (no shading of
// pixels later hidden), row by row. Perspective-correct weights for a whole
// row at a time, then the shading model of each pixel's object: the
// triangle's colour (flat), the interpolated vertex colours (Gouraud), or
// the interpolated normal lit per pixel at the point on the pixel's ray
// (Phong; faceted, with the face normal), in runs through the kernel set's
// shade_phong; then clamp, gamma and the background.
#include <glm/vec3.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "cpu/pipeline.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace litkit {

namespace {

// Phong shading's normal at a pixel: N mixed from the corners' (the
// mesh's, or a clipped piece's) with the perspective-correct weights (p is
// the point on the pixel's ray: point_on_ray, scene/camera.hpp).
// `varyings`: the clipped piece's corners (Pipeline::varyings_of), or null.
inline glm::vec3 interpolate_normal(const PreparedObject& object, const ShadeTriangle& tri,
                                    const CornerVaryings* varyings, float q0, float q1, float q2) {
    // docs/spec.md §9.2 faceted: the same per-pixel lighting, with the
    // triangle's DD8 normal (front-facing: back faces are culled).
    if (object.shading == Shading::Faceted) return object.face_normals[tri.source];
    if (!varyings)
        return q0 * object.normals[tri.vertex[0]] + q1 * object.normals[tri.vertex[1]] +
               q2 * object.normals[tri.vertex[2]];
    const CornerVaryings& v = *varyings;
    auto mix = [&](int k) { return q0 * v[0][k] + q1 * v[1][k] + q2 * v[2][k]; };
    return {mix(0), mix(1), mix(2)};
}

// A span's corner normals for the kernel set's interpolate: the mesh
// vertices', or the clipped piece's own.
void span_normals(const PreparedObject& object, const ShadeTriangle& tri,
                  const CornerVaryings* varyings, float (&normal)[3][3]) {
    for (int k = 0; k < 3; ++k) {
        if (!varyings) {
            const glm::vec3& n = object.normals[tri.vertex[k]];
            normal[k][0] = n.x, normal[k][1] = n.y, normal[k][2] = n.z;
        } else {
            std::copy_n((*varyings)[k].begin(), 3, normal[k]);
        }
    }
}

#if defined(__SSE2__)
// The fragment stage's short spans, x, y and z in the lanes of one SSE
// vector: (v[0], v[1], v[2], 0), reading 3 floats; the lanes to three
// places; and q0·c0 + q1·c1 + q2·c2, interpolate_normal's products and
// sums in its order.
inline __m128 load3(const float* v) {
    const __m128 xy = _mm_loadl_pi(_mm_setzero_ps(), reinterpret_cast<const __m64*>(v));
    return _mm_movelh_ps(xy, _mm_load_ss(v + 2));
}
inline void store3(__m128 v, float* x, float* y, float* z) {
    _mm_store_ss(x, v);
    _mm_store_ss(y, _mm_shuffle_ps(v, v, 1));
    _mm_store_ss(z, _mm_movehl_ps(v, v));
}
inline __m128 mix3(__m128 q0, __m128 q1, __m128 q2, __m128 c0, __m128 c1, __m128 c2) {
    return _mm_add_ps(_mm_add_ps(_mm_mul_ps(q0, c0), _mm_mul_ps(q1, c1)), _mm_mul_ps(q2, c2));
}
#endif

// Gouraud shading at column x: the corners' unclamped colours, the mesh's
// or the clipped piece's, mixed with the perspective-correct weights.
glm::vec3 gouraud_color(const Pipeline& pipeline, const ShadeTriangle* tri, const BandScratch& s,
                        int x) {
    // Perspective-correct weights: (b_k / w_k) / Σ (b_j / w_j).
    const float q0 = s.q0[x], q1 = s.q1[x], q2 = s.q2[x];
    glm::vec3 c;
    if (!tri->clipped()) {
        const auto& colors = pipeline.vertex_colors[tri->object];
        c = q0 * colors[tri->vertex[0]] + q1 * colors[tri->vertex[1]] + q2 * colors[tri->vertex[2]];
    } else {
        const CornerVaryings& v = *pipeline.varyings_of(*tri);
        c = {q0 * v[0][0] + q1 * v[1][0] + q2 * v[2][0], q0 * v[0][1] + q1 * v[1][1] + q2 * v[2][1],
             q0 * v[0][2] + q1 * v[1][2] + q2 * v[2][2]};
    }
    return c;
}

#if defined(__SSE2__)
// Phong, the mesh's own corners: the normals of the span of `tri` that
// starts at column x and of the spans after it whose triangles are too, of
// this object, in one loop (a dense mesh's spans are one to three pixels:
// the checks and look-ups of the general path would be most of the work).
// The same formulas as surface_normals. Returns the column after the last.
int mesh_normals(const kernels::Kernels& kernels, const PreparedObject& object,
                 const ShadeTriangle* tri, std::size_t offset, int x, int end, BandScratch& s) {
    const ShadeTriangle* const* visible = s.visible.data() + offset;
    float* const out[3] = {s.nx.data(), s.ny.data(), s.nz.data()};
    const float* const q0 = s.q0.data();
    const float* const q1 = s.q1.data();
    const float* const q2 = s.q2.data();
    const glm::vec3* const normals = object.normals.data();
    const std::uint32_t object_index = tri->object;
    int at = x;
    const ShadeTriangle* span = tri;
    for (;;) {
        if (at + static_cast<int>(short_span) <= end && visible[at + short_span - 1] == span) {
            // A long span: the kernel set's interpolate.
            int span_end = at + 1;
            while (span_end < end && visible[span_end] == span) ++span_end;
            float normal[3][3];
            span_normals(object, *span, nullptr, normal);
            kernels.interpolate(q0 + at, q1 + at, q2 + at, static_cast<std::size_t>(span_end - at),
                                normal, {out[0] + at, out[1] + at, out[2] + at});
            at = span_end;
        } else {
            const __m128 n0 = load3(&normals[span->vertex[0]].x),
                         n1 = load3(&normals[span->vertex[1]].x),
                         n2 = load3(&normals[span->vertex[2]].x);
            // The triangle a few pixels on, fetched ahead (once a span).
            if (at + 12 < end) __builtin_prefetch(visible[at + 12]);
            do {
                const __m128 a = _mm_set1_ps(q0[at]), b = _mm_set1_ps(q1[at]),
                             c = _mm_set1_ps(q2[at]);
                store3(mix3(a, b, c, n0, n1, n2), out[0] + at, out[1] + at, out[2] + at);
                ++at;
            } while (at < end && visible[at] == span);
        }
        if (at >= end) break;
        const ShadeTriangle* const next = visible[at];
        if (!next || next->object != object_index || next->clipped()) break;
        span = next;
    }
    return at;
}
#endif

// Phong or faceted: the normals of one triangle's span of `count` pixels
// from column `first` at once (the formulas of interpolate_normal).
void surface_normals(const kernels::Kernels& kernels, const PreparedObject& object,
                     const ShadeTriangle* tri, const CornerVaryings* varyings, std::size_t first,
                     std::size_t count, BandScratch& s) {
    if (object.shading == Shading::Faceted) {
        // docs/spec.md §9.2 faceted: the triangle's DD8 normal.
        const glm::vec3& n = object.face_normals[tri->source];
        std::fill_n(&s.nx[first], count, n.x);
        std::fill_n(&s.ny[first], count, n.y);
        std::fill_n(&s.nz[first], count, n.z);
    } else
#if defined(__SSE2__)
        if (count < short_span) {
        // Small triangles: the formulas of interpolate_normal pixel by
        // pixel (a SIMD call across pixels would mostly pad), with x, y
        // and z in the lanes of one SSE vector: the same products and
        // sums, in the same order, as the scalar code and the kernel.
        __m128 corner[3];
        for (int k = 0; k < 3; ++k)
            corner[k] =
                varyings ? load3(&(*varyings)[k][0]) : load3(&object.normals[tri->vertex[k]].x);
        for (std::size_t at = first; at < first + count; ++at) {
            const __m128 a = _mm_set1_ps(s.q0[at]), b = _mm_set1_ps(s.q1[at]),
                         c = _mm_set1_ps(s.q2[at]);
            store3(mix3(a, b, c, corner[0], corner[1], corner[2]), &s.nx[at], &s.ny[at], &s.nz[at]);
        }
    } else
#endif
        if (count < short_span) {
        // Small triangles: the scalar formulas, pixel by pixel (a SIMD
        // call would mostly pad); the same roundings as the kernel.
        for (std::size_t at = first; at < first + count; ++at) {
            const glm::vec3 n =
                interpolate_normal(object, *tri, varyings, s.q0[at], s.q1[at], s.q2[at]);
            s.nx[at] = n.x, s.ny[at] = n.y, s.nz[at] = n.z;
        }
    } else {
        float normal[3][3];
        span_normals(object, *tri, varyings, normal);
        kernels.interpolate(&s.q0[first], &s.q1[first], &s.q2[first], count, normal,
                            {&s.nx[first], &s.ny[first], &s.nz[first]});
    }
}

}  // namespace

// Leave the visibility buffer cleared for the next band (or sample).
void clear_row(BandScratch& s, std::size_t offset, int begin, int end) {
    if (begin < end) {
        std::fill(s.depth.begin() + offset + begin, s.depth.begin() + offset + end, 0.0f);
        std::fill(s.visible.begin() + offset + begin, s.visible.begin() + offset + end, nullptr);
    }
}

namespace {

// Clamp, gamma and encode the row's covered pixels [begin, end), the
// background elsewhere; then clear what the row used of the visibility
// buffer. `background_between`: some pixel in [begin, end) has no triangle.
void encode_row(const Pipeline& pipeline, BandScratch& s, std::size_t offset, int begin, int end,
                bool background_between, int width, std::uint8_t* row) {
    // Background spans are copied from a row prepared once per frame.
    auto fill_background = [&](int from, int to) {
        if (from < to)
            std::memcpy(row + 3 * from, pipeline.background_row.data() + 3 * from,
                        3 * static_cast<std::size_t>(to - from));
    };
    fill_background(0, begin);
    fill_background(end, width);
    if (!background_between && begin < end) {  // one run: no need to look for its ends
        s.shaded_pixels += static_cast<std::size_t>(end - begin);
        pipeline.kernels.encode(s.r.data() + begin, s.g.data() + begin, s.b.data() + begin,
                                static_cast<std::size_t>(end - begin), pipeline.scene.output.gamma,
                                row + 3 * begin);
    }
    int x = background_between ? begin : end;
    while (x < end) {
        if (!s.visible[offset + x]) {
            fill_background(x, x + 1);
            ++x;
            continue;
        }
        int run_end = x;
        while (run_end < end && s.visible[offset + run_end]) ++run_end;
        s.shaded_pixels += static_cast<std::size_t>(run_end - x);
        pipeline.kernels.encode(s.r.data() + x, s.g.data() + x, s.b.data() + x,
                                static_cast<std::size_t>(run_end - x), pipeline.scene.output.gamma,
                                row + 3 * x);
        x = run_end;
    }
    clear_row(s, offset, begin, end);
}

}  // namespace

// Renderer::probe's record of one visible pixel, made after its row is
// shaded (so the hot loop carries no test for it), with the fragment stage's
// own formulas.
void Pipeline::record_probe(const BandScratch& s, std::size_t i, int x,
                            const SamplePass& pass) const {
    const ShadeTriangle* tri = s.visible[i];
    const float w = 1.0f / s.depth[i];
    const float q1 = s.weight1[i] * w, q2 = s.weight2[i] * w, q0 = 1.0f - q1 - q2;
    probed.hit = true;
    probed.object = tri->object;
    probed.triangle = tri->source;
    probed.clipped = tri->clipped();
    if (probed.clipped) {
        // Its vertices in the rasterizer's corner order, as setup puts them.
        const auto& v = objects[tri->object].triangles[tri->source];
        probed.vertices = {v[0], v[2], v[1]};
    } else {
        probed.vertices = tri->vertex;
    }
    probed.weights = {q0, q1, q2};
    probed.position =
        point_on_ray(camera.row_rays(probe_y, pass.position), scene.output.width, x, w);
    probed.normal = interpolate_normal(objects[tri->object], *tri, varyings_of(*tri), q0, q1, q2);
    probed.intensity = {s.r[static_cast<std::size_t>(x)], s.g[static_cast<std::size_t>(x)],
                        s.b[static_cast<std::size_t>(x)]};
}

void Pipeline::shade_band(int band, BandScratch& s, Image& image) const {
    const int row_begin = band * band_height;
    const int row_end = std::min(image.height, row_begin + band_height);
    const SamplePass centre;
    for (int y = row_begin; y < row_end; ++y) {
        const LitRow lit = light_row(y, image.width, s, centre);
        encode_row(*this, s, static_cast<std::size_t>(y % band_height) * image.width, lit.begin,
                   lit.end, lit.background_between, image.width, image.pixel(0, y));
    }
}

// One row of the visibility buffer: each visible pixel gets the shading
// model of its object, Phong and faceted pixels in runs through the SIMD
// kernel, lit along the rays through the pass's samples.
LitRow Pipeline::light_row(int y, int width, BandScratch& s, const SamplePass& pass) const {
    const std::size_t w = static_cast<std::size_t>(width);
    s.r.resize(w);
    s.g.resize(w);
    s.b.resize(w);
    for (auto* v : {&s.view_w, &s.nx, &s.ny, &s.nz, &s.q0, &s.q1, &s.q2}) v->resize(w);
    const std::size_t offset = static_cast<std::size_t>(y % band_height) * w;

    // A run: consecutive Phong or faceted pixels of one object, shaded
    // together; it is made of spans of one triangle each, interpolated
    // together (the corners are the same along a span). Its surfaces are in
    // s.view_w … s.nz by column; their positions are on the row's rays.
    const RowRays rays = camera.row_rays(y, pass.position);
    std::size_t run_length = 0;
    int run_first = 0;
    const PreparedObject* run_object = nullptr;
    auto flush = [&] {
        if (run_length == 0) return;
        const std::size_t at = static_cast<std::size_t>(run_first);
        const kernels::SurfaceRun surface{&rays,         pixel_k(run_first, width) + rays.k_shift,
                                          &s.view_w[at], &s.nx[at],
                                          &s.ny[at],     &s.nz[at],
                                          run_length};
        kernels.shade_phong(
            run_object->reflection, lights, run_object->raw_material, surface,
            {s.r.data() + run_first, s.g.data() + run_first, s.b.data() + run_first});
        run_length = 0;
    };

    const int band_row = y % band_height;
    const int begin = s.touched_begin[static_cast<std::size_t>(band_row)];
    const int end = std::max(begin, s.touched_end[static_cast<std::size_t>(band_row)]);
    // Every drawn pixel's view depth and perspective-correct weights, a
    // vector at a time.
    kernels.perspective_weights(&s.depth[offset + begin], &s.weight1[offset + begin],
                                &s.weight2[offset + begin], static_cast<std::size_t>(end - begin),
                                &s.view_w[begin], &s.q0[begin], &s.q1[begin], &s.q2[begin]);
    bool background_between = false;  // some pixel in [begin, end) has no triangle
    for (int x = begin; x < end; ++x) {
        const std::size_t i = offset + static_cast<std::size_t>(x);
        // The triangle a few pixels on, fetched ahead: the visibility buffer
        // points into the band's binned triangles in no order.
        if (x + 12 < end) __builtin_prefetch(s.visible[i + 12]);
        const ShadeTriangle* tri = s.visible[i];
        if (!tri) {
            background_between = true;
            flush();
            continue;
        }
        const PreparedObject& object = objects[tri->object];
        if (object.shading == Shading::Flat) {
            flush();
            const glm::vec3& c = flat_colors[tri->object][tri->source];
            s.r[x] = c.x, s.g[x] = c.y, s.b[x] = c.z;
            continue;
        }
        if (object.shading == Shading::Gouraud) {
            flush();
            const glm::vec3 c = gouraud_color(*this, tri, s, x);
            s.r[x] = c.x, s.g[x] = c.y, s.b[x] = c.z;
            continue;
        }
        if (run_object != &object ||
            (run_length > 0 && run_first + static_cast<int>(run_length) != x))
            flush();
        if (run_length == 0) run_first = x;
        run_object = &object;
#if defined(__SSE2__)
        if (object.shading == Shading::Phong && !tri->clipped()) {
            const int at = mesh_normals(kernels, object, tri, offset, x, end, s);
            run_length += static_cast<std::size_t>(at - x);
            x = at - 1;
            continue;
        }
#endif
        // Phong or faceted, one triangle's span.
        int span_end = x + 1;
        while (span_end < end && s.visible[offset + static_cast<std::size_t>(span_end)] == tri)
            ++span_end;
        const std::size_t count = static_cast<std::size_t>(span_end - x);
        surface_normals(kernels, object, tri, varyings_of(*tri), static_cast<std::size_t>(x), count,
                        s);
        run_length += count;
        x = span_end - 1;
    }
    flush();
    if (ray_tree) refract_row(y, width, begin, end, s, pass);
    if (y == probe_y && probe_x >= begin && probe_x < end && s.visible[offset + probe_x])
        record_probe(s, offset + static_cast<std::size_t>(probe_x), probe_x, pass);
    return {begin, end, background_between};
}

}  // namespace litkit
