// SPDX-License-Identifier: MIT
// The CPU rasterizer's pipeline: its state, what prepare builds once per
// Renderer (the objects in world space, their lights and materials) and
// what the stages hand each other within a frame, kept between frames to
// reuse its memory; and its stages, Pipeline's member functions, each stage
// in its own file (declared below, in the order they run). Renderer (the
// public class, render.cpp) holds one and runs the stages in order:
//   prepare    (prepare.cpp) once per Renderer, like uploading buffers
//   vertex     (vertex.cpp) world → clip space and window corners; Gouraud
//              lighting per vertex
//   clip       (clip.cpp) Sutherland–Hodgman in homogeneous coordinates
//              (near, far and a guard band at the sides), as OpenGL clips
//   setup      (setup.cpp) perspective divide, viewport, back-face culling,
//              fixed point, binning to bands of rows
//   rasterize  (rasterize.cpp) half-space edge functions with the top-left
//              fill rule into a band's visibility buffer, bands spread
//              across the thread pool
//   fragment   (fragment.cpp) perspective-correct varyings, lighting per
//              pixel (Phong; faceted, with the face normal) or interpolated
//              colours (Gouraud) or one colour (flat), clamp and gamma;
//              pixels that see glass get the rest of their light from the
//              ray tree (glass.cpp, with src/trace/)
// With several samples per pixel (docs/spec.md §11; samples.cpp) the
// vertex and setup stages run once, and each band is rasterized and shaded
// once per sample, its samples' light summed in the band and resolved.
// The stages carry the names of the OpenGL pipeline so that these files
// and the generated GLSL read alike.
#pragma once

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/thread_pool.hpp"
#include "cpu/shade_kernel.hpp"
#include "litkit/equations.hpp"
#include "litkit/image.hpp"
#include "litkit/render.hpp"
#include "litkit/samples.hpp"
#include "scene/camera.hpp"
#include "trace/accel.hpp"
#include "trace/ray_tree.hpp"

namespace litkit {

using kernels::RasterTriangle;  // what the visibility pass needs of a triangle
using kernels::subpixel_bits;
using kernels::subpixel_one;
using kernels::WindowCorner;

constexpr int band_height = 16;  // rows per band (of the binning and the visibility buffer)
// Spans of one triangle shorter than this are interpolated pixel by pixel.
constexpr std::size_t short_span = 8;
constexpr std::size_t setup_chunk = 2048;  // triangles per setup job
// Triangles at most this many pixels wide find each row's covered pixels by
// testing them; wider ones solve the span from the edge functions.
constexpr std::int64_t narrow_triangle = 8;
// Triangles whose corners lie within this many fixed-point units of each
// other, both ways (8 pixels), step their edge functions in 32-bit SIMD lanes.
constexpr std::int32_t small_triangle = 8 * static_cast<std::int32_t>(subpixel_one);

// Pixel i covers the centre i + 0.5: the first and last pixel whose centre
// is at or after `lo`, at or before `hi` (fixed point).
inline int first_pixel(std::int64_t lo) {
    return static_cast<int>((lo - subpixel_one / 2 + subpixel_one - 1) >> subpixel_bits);
}
inline int last_pixel(std::int64_t hi) {
    return static_cast<int>((hi - subpixel_one / 2) >> subpixel_bits);
}

// One sample of every pixel (docs/spec.md §11): its place in the pixel and,
// in fixed point, its offset from the centre (exact: the places are
// multiples of 1/16, subpixel_one a multiple of 16). The rasterizer tests a
// triangle moved by minus the offset at the pixels' centres, which is the
// triangle tested at the samples; the fragment stage lights along the
// samples' rays.
struct SamplePass {
    SamplePosition position{0.5f, 0.5f};
    std::int32_t offset_x = 0, offset_y = 0;
    explicit SamplePass(SamplePosition p = {0.5f, 0.5f})
        : position(p),
          offset_x(static_cast<std::int32_t>((p.x - 0.5f) * float(subpixel_one))),
          offset_y(static_cast<std::int32_t>((p.y - 0.5f) * float(subpixel_one))) {}
    bool at_centre() const { return offset_x == 0 && offset_y == 0; }
};
static_assert(subpixel_one % 16 == 0, "sample places are exact in fixed point");

// What the fragment stage drew of a row: the columns [begin, end) it lit
// (s.r, s.g, s.b), and whether some pixel among them has no triangle.
struct LitRow {
    int begin = 0, end = 0;
    bool background_between = false;
};

// A vertex's varyings: the normal (Phong shading) or the unclamped colour
// (Gouraud).
constexpr int max_varyings = 3;
using Varyings = std::array<float, max_varyings>;
// Varyings of the corners of a piece of a clipped triangle.
using CornerVaryings = std::array<Varyings, 3>;

// An object's geometry in world space, built once per Renderer ("uploaded").
struct PreparedObject {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;       // DD9, world space
    std::vector<glm::vec3> face_normals;  // DD8, world space, per triangle (flat, faceted)
    std::vector<std::array<std::uint32_t, 3>> triangles;
    equations::MaterialT<float> material;
    Material raw_material;
    Reflection reflection = Reflection::Phong;  // set by prepare_surfaces
    Shading shading = Shading::Phong;
};

// What the fragment stage needs of a triangle: where its varyings come from
// (the mesh's vertices, or a clipped polygon's own).
struct ShadeTriangle {
    std::uint32_t object;
    std::uint32_t source;  // triangle index within the object
    // The mesh's vertices, corner by corner; for a piece of a clipped
    // triangle, {its place in its chunk's `clipped`, the chunk, clipped_piece}
    // (no vertex has that index: 32-bit indices reach one fewer vertex).
    std::array<std::uint32_t, 3> vertex;
    static constexpr std::uint32_t clipped_piece = ~std::uint32_t{0};
    bool clipped() const { return vertex[2] == clipped_piece; }
};

// A triangle ready to rasterize, as binned: setup copies it into every band
// it may touch, so that a band's triangles are read in one stream, and the
// visibility buffer points at the copy's ShadeTriangle, read again (from
// cache, not memory) when the band is shaded.
struct alignas(64) BinnedTriangle {
    RasterTriangle raster;
    ShadeTriangle shade;
};
// One cache line each: the visibility pass reads the raster part, the
// fragment stage the shade part, of the same line.
static_assert(sizeof(BinnedTriangle) == 64);

// One setup job's output, kept between frames to reuse its memory.
struct SetupChunk {
    std::uint32_t object = 0;
    std::size_t begin = 0, end = 0;  // triangle range within the object
    std::vector<CornerVaryings> clipped;
    // The triangles of each band of rows, band after band, each band's in
    // setup order: band b's are binned[band_start[b] .. band_start[b + 1]).
    std::vector<BinnedTriangle> binned;
    std::vector<std::uint32_t> band_start;
};

// The pieces the clip stage cuts a triangle into (a fan of the clipped
// polygon, at most 9 corners after six planes): window corners and varyings.
struct ClippedPieces {
    int count = 0;
    std::array<std::array<WindowCorner, 3>, 7> corners;
    std::array<CornerVaryings, 7> varyings;
};

// Per-thread scratch for one band: the visibility buffer (nearest triangle
// and its perspective-correct weights per pixel) and one row of colours.
struct BandScratch {
    std::vector<float> depth;                     // 1/w; 0 = nothing drawn
    std::vector<const ShadeTriangle*> visible;    // nullptr = background
    std::vector<float> weight1, weight2;          // b1/w1, b2/w2 (perspective weights × 1/w)
    std::vector<float> r, g, b;                   // one row of intensities
    std::vector<float> q0, q1, q2;                // one row of perspective-correct weights
    std::vector<float> view_w, nx, ny, nz;        // one row of Phong surfaces (view depth, normal)
    std::vector<int> touched_begin, touched_end;  // per band row: columns drawn
    // Several samples per pixel: the band's sums of the samples' clamped
    // light, and how many samples of each pixel saw the background.
    std::vector<float> sum_r, sum_g, sum_b;
    std::vector<std::uint8_t> background_samples;
    std::size_t shaded_pixels = 0;  // this frame, by this thread
    std::uint64_t traced_rays = 0;  // this frame, by this thread (glass)
    // Setup's triangles of the chunk at hand, before they are binned.
    std::vector<BinnedTriangle> pending;
    std::vector<std::uint32_t> band_count;
};

// fragment.cpp: clears what a row used of the visibility buffer, for the
// next band or sample ([begin, end) of the row at `offset`).
void clear_row(BandScratch& s, std::size_t offset, int begin, int end);

struct Pipeline {
    float length_scale;
    Scene scene;
    RenderOptions options;
    ThreadPool pool;
    const kernels::Kernels& kernels;
    std::vector<equations::PreparedLight> lights;
    std::vector<PreparedObject> objects;

    // Per-frame state, kept between frames to avoid reallocating.
    Camera camera;                                       // docs/spec.md §1, for this frame's size
    std::vector<std::vector<glm::vec4>> clip_positions;  // per object, per vertex
    std::vector<std::vector<WindowCorner>> window_corners;  // per object, per vertex
    std::vector<std::vector<glm::vec3>> vertex_colors;      // Gouraud, per object
    std::vector<std::vector<glm::vec3>> flat_colors;        // flat, per object, per triangle
    std::vector<SetupChunk> chunks;
    std::vector<BandScratch> scratch;          // one per thread
    std::vector<std::uint8_t> background_row;  // one image row of background colour
    float background_light[3] = {};            // a sample's light where nothing is (§11)
    int band_count = 0;
    // Set while Renderer::probe draws: the pixel to record, and the record.
    int probe_x = -1, probe_y = -1;
    // The samples per pixel of the frame whose vertex and setup stages the
    // buffers above still hold (0: none, or the scene has changed since), so
    // that probe() after probe() draws only the pixel's band.
    int stages_hold_samples = 0;
    mutable PixelProbe probed;

    // The tracer, only while some object has t > 0 (docs/spec.md §10): the
    // objects as it sees them, the hierarchy over their triangles (kept
    // while the meshes are) and the ray tree.
    std::vector<trace::TracedObject> traced;
    std::unique_ptr<trace::Accel> accel;
    std::unique_ptr<trace::RayTree> ray_tree;

    // The scene as drawn: its lengths brought into a float's comfortable
    // range by a power of two (scene/float_range.hpp; 1 for ordinary scenes).
    Pipeline(const Scene& s, RenderOptions o);

    std::size_t mesh_builds = 0;  // how often prepare() built the meshes

    // prepare.cpp: the meshes, then everything else of the scene.
    void prepare();
    void prepare_surfaces();
    // glass.cpp: the tracer for the scene's glass (or none).
    void prepare_tracer();
    // render.cpp: the camera, the bands and the background of a frame.
    void begin_frame(int width, int height);
    // vertex.cpp
    void vertex_stage(int width, int height);
    // clip.cpp: the pieces of one triangle that crosses a clip plane (setup
    // calls it for those).
    void clip_triangle(std::uint32_t object, std::size_t triangle, int width, int height,
                       ClippedPieces& pieces) const;
    // setup.cpp: setup and binning of one chunk of an object's triangles.
    void setup(SetupChunk& chunk, BandScratch& scratch, int width, int height);
    // rasterize.cpp: one band's visibility buffer, at one sample of each
    // pixel (its centre, with one sample per pixel).
    void rasterize_band(int band, BandScratch& scratch, int width, int height,
                        const SamplePass& pass = SamplePass()) const;
    // fragment.cpp: one band's pixels from its visibility buffer, row by
    // row: the light of a row's samples, then (one sample per pixel) clamp,
    // gamma and the background.
    void shade_band(int band, BandScratch& scratch, Image& image) const;
    LitRow light_row(int y, int width, BandScratch& scratch, const SamplePass& pass) const;
    void record_probe(const BandScratch& scratch, std::size_t i, int x,
                      const SamplePass& pass) const;
    // samples.cpp: one band with several samples per pixel, and the probed
    // pixel's sample of one pass (PixelProbe::samples).
    void draw_band_samples(int band, BandScratch& scratch, Image& image) const;
    void record_sample(const BandScratch& scratch, std::size_t offset, const LitRow& lit,
                       const SamplePass& pass) const;
    // glass.cpp: the row's pixels that see glass, their local part and the
    // ray tree's light in place of what light_row gave them.
    void refract_row(int y, int width, int begin, int end, BandScratch& scratch,
                     const SamplePass& pass) const;
    // A clipped piece's corners (ShadeTriangle::vertex says where), or null.
    const CornerVaryings* varyings_of(const ShadeTriangle& tri) const {
        return tri.clipped() ? &chunks[tri.vertex[1]].clipped[tri.vertex[0]] : nullptr;
    }
};

}  // namespace litkit
