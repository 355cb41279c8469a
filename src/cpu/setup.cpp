// SPDX-License-Identifier: MIT
// The setup stage, one chunk of an object's triangles per job: trivial
// accept and reject against the clip planes (from the vertex stage's
// outcodes), clipping for the triangles that cross a plane (clip.cpp),
// back-face culling, each front face's pixel bounds and perspective weights
// (RasterTriangle), flat shading's one colour, and binning to bands of rows.
#include <glm/vec3.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "cpu/pipeline.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace litkit {

namespace {

// Doubled signed area in y-down window coordinates: a triangle
// counter-clockwise on screen (front-facing) has a negative one.
std::int64_t doubled_area(const WindowCorner& c0, const WindowCorner& c1, const WindowCorner& c2) {
    return std::int64_t{c1.x - c0.x} * (c2.y - c0.y) - std::int64_t{c1.y - c0.y} * (c2.x - c0.x);
}

// One setup job's making of triangles from window corners, into the
// thread's `pending` list (and, for clipped pieces, the chunk's `clipped`),
// each counted for the band of rows it may touch.
struct SetupJob {
    Pipeline& pipeline;
    SetupChunk& chunk;
    const PreparedObject& object;
    int width, height;
    // Half a pixel in fixed point with several samples per pixel, else 0:
    // the pixel bounds are then those of every pixel some sample of which
    // may be covered (rasterize_band finds each sample's own).
    std::int64_t margin;
    std::vector<BinnedTriangle>& pending;
    std::vector<std::uint32_t>& counts;  // triangles per band of rows, counts[b + 1] for band b
    bool flat_done = false;              // the current source triangle's flat colour is computed

    // Setup of a front-facing (area < 0) piece with valid corners; nothing
    // when it covers no pixel centre (no sample) of the image.
    void emit_front(const WindowCorner& c0, const WindowCorner& c1, const WindowCorner& c2,
                    std::int64_t area, std::uint32_t source,
                    const std::array<std::uint32_t, 3>& vertex, const CornerVaryings* varyings) {
        RasterTriangle raster;
        raster.x = {c0.x, c2.x, c1.x};
        raster.y = {c0.y, c2.y, c1.y};
        const auto [min_x, max_x] = std::minmax({raster.x[0], raster.x[1], raster.x[2]});
        const auto [min_y, max_y] = std::minmax({raster.y[0], raster.y[1], raster.y[2]});
        const int left = std::max(0, first_pixel(min_x - margin));
        const int right = std::min(width - 1, last_pixel(max_x + margin));
        const int top = std::max(0, first_pixel(min_y - margin));
        const int bottom = std::min(height - 1, last_pixel(max_y + margin));
        if (left > right || top > bottom) return;
        // The doubled area in the rasterizer's order of corners is −area.
        const float inverse_area = 1.0f / static_cast<float>(-area);
        raster.weight = {inverse_area * c0.inverse_w, inverse_area * c2.inverse_w,
                         inverse_area * c1.inverse_w};
        raster.min_x = static_cast<std::int16_t>(left);
        raster.max_x = static_cast<std::int16_t>(right);
        raster.min_y = static_cast<std::int16_t>(top);
        const bool small = std::int64_t{max_x} - min_x <= small_triangle &&
                           std::int64_t{max_y} - min_y <= small_triangle;
        raster.max_y_small = static_cast<std::uint16_t>(bottom | (small ? 0x8000 : 0));
        if (object.shading == Shading::Flat && !flat_done) {
            // docs/spec.md §3 flat: lit once, at the centroid of the whole (unclipped)
            // triangle, with its face normal.
            const auto& v = object.triangles[source];
            const glm::vec3 centroid =
                (object.positions[v[0]] + object.positions[v[1]] + object.positions[v[2]]) / 3.0f;
            pipeline.flat_colors[chunk.object][source] = equations::shade_scalar(
                object.reflection, pipeline.lights, object.material, centroid,
                object.face_normals[source], pipeline.scene.observer.position);
            flat_done = true;
        }
        ShadeTriangle shade;
        shade.object = chunk.object;
        shade.source = source;
        shade.vertex = {vertex[0], vertex[2], vertex[1]};
        if (varyings) {
            shade.vertex = {static_cast<std::uint32_t>(chunk.clipped.size()),
                            static_cast<std::uint32_t>(&chunk - pipeline.chunks.data()),
                            ShadeTriangle::clipped_piece};
            chunk.clipped.push_back({(*varyings)[0], (*varyings)[2], (*varyings)[1]});
        }
        pending.push_back({raster, shade});
        // Counted for binning (below) as it is made.
        for (int b = top / band_height; b <= bottom / band_height; ++b)
            ++counts[static_cast<std::size_t>(b) + 1];
    }

    // Setup of one (piece of a) triangle from its window corners; nothing
    // when culled.
    void emit(const WindowCorner& c0, const WindowCorner& c1, const WindowCorner& c2,
              std::uint32_t source, const std::array<std::uint32_t, 3>& vertex,
              const CornerVaryings* varyings) {
        if (!(c0.valid && c1.valid && c2.valid)) return;
        const std::int64_t area = doubled_area(c0, c1, c2);
        if (area >= 0) return;  // back face or zero area: culled
        emit_front(c0, c1, c2, area, source, vertex, varyings);
    }
};

// Binning: each band of rows gets a copy of the triangles that may touch
// it, in setup order (counted as they were made, so the chunk's one
// array is sized exactly).
void bin(SetupChunk& chunk, const std::vector<BinnedTriangle>& pending,
         std::vector<std::uint32_t>& counts, std::size_t bands) {
    chunk.band_start.resize(bands + 1);
    chunk.band_start[0] = 0;
    for (std::size_t b = 0; b < bands; ++b) {
        chunk.band_start[b + 1] = chunk.band_start[b] + counts[b + 1];
        counts[b] = chunk.band_start[b];  // from here on: the next free place in band b
    }
    chunk.binned.resize(chunk.band_start[bands]);
    // The copies are written around the cache (non-temporal): the 261k
    // sphere's binned triangles are about 11 MB, read again only when every
    // chunk is set up, so caching them on the way out only costs the reads
    // of their lines before the writes (measured: frame 0.99x).
    for (const BinnedTriangle& binned : pending) {
        const RasterTriangle& tri = binned.raster;
#if defined(__SSE2__)
        const auto* from = reinterpret_cast<const __m128i*>(&binned);
        const __m128i q0 = _mm_load_si128(from), q1 = _mm_load_si128(from + 1),
                      q2 = _mm_load_si128(from + 2), q3 = _mm_load_si128(from + 3);
        for (int b = tri.min_y / band_height; b <= tri.max_y() / band_height; ++b) {
            auto* to = reinterpret_cast<__m128i*>(&chunk.binned[counts[b]++]);
            _mm_stream_si128(to, q0);
            _mm_stream_si128(to + 1, q1);
            _mm_stream_si128(to + 2, q2);
            _mm_stream_si128(to + 3, q3);
        }
#else
        for (int b = tri.min_y / band_height; b <= tri.max_y() / band_height; ++b)
            chunk.binned[counts[b]++] = binned;
#endif
    }
#if defined(__SSE2__)
    _mm_sfence();  // the streamed copies are seen before the pool reports this job done
#endif
}

}  // namespace

void Pipeline::setup(SetupChunk& chunk, BandScratch& scratch, int width, int height) {
    const PreparedObject& object = objects[chunk.object];
    const std::vector<WindowCorner>& window = window_corners[chunk.object];
    std::vector<BinnedTriangle>& pending = scratch.pending;
    pending.clear();
    chunk.clipped.clear();
    const std::size_t bands = static_cast<std::size_t>(band_count);
    std::vector<std::uint32_t>& counts = scratch.band_count;
    counts.assign(bands + 1, 0);
    const std::int64_t margin = scene.output.samples > 1 ? subpixel_one / 2 : 0;
    SetupJob job{*this, chunk, object, width, height, margin, pending, counts};
    ClippedPieces pieces;

    // Welded meshes number their vertices in no order the triangles follow,
    // so the corners' loads would miss the cache: fetch them ahead.
    constexpr std::size_t prefetch_ahead = 16;
    for (std::size_t t = chunk.begin; t < chunk.end; ++t) {
        if (t + prefetch_ahead < chunk.end) {
            const auto& ahead = object.triangles[t + prefetch_ahead];
            for (const std::uint32_t v : ahead) __builtin_prefetch(&window[v]);
        }
        const auto& indices = object.triangles[t];
        const WindowCorner& w0 = window[indices[0]];
        const WindowCorner& w1 = window[indices[1]];
        const WindowCorner& w2 = window[indices[2]];
        // Trivial reject (all three corners outside one plane) and accept
        // (no corner outside any) against the six clip planes.
        if (w0.outside & w1.outside & w2.outside) continue;
        const std::uint32_t source = static_cast<std::uint32_t>(t);
        job.flat_done = false;
        if ((w0.outside | w1.outside | w2.outside) == 0) {
            // emit(), with the back faces (half of a closed mesh) culled here.
            if (!(w0.valid && w1.valid && w2.valid)) continue;
            const std::int64_t area = doubled_area(w0, w1, w2);
            if (area >= 0) continue;  // back face or zero area: culled
            job.emit_front(w0, w1, w2, area, source, indices, nullptr);
            continue;
        }
        // The clip stage: its pieces carry their own varyings.
        clip_triangle(chunk.object, t, width, height, pieces);
        for (int k = 0; k < pieces.count; ++k) {
            const std::array<WindowCorner, 3>& c = pieces.corners[k];
            job.emit(c[0], c[1], c[2], source, indices, &pieces.varyings[k]);
        }
    }
    bin(chunk, pending, counts, bands);
}

}  // namespace litkit
