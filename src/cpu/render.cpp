// The CPU rasterizer. The stages carry the names of the OpenGL pipeline so
// that this file and the generated GLSL read alike:
//   vertex    world → clip space; Gouraud lighting per vertex
//   clip      Sutherland–Hodgman in homogeneous coordinates (near, far and a
//             guard band at the sides), as OpenGL clips
//   setup     perspective divide, viewport, back-face culling, fixed point
//   rasterize half-space edge functions with the top-left fill rule, over
//             bands of rows spread across the thread pool
//   fragment  depth test, perspective-correct varyings, lighting per pixel
//             (Phong; faceted, with the face normal) or interpolated colours
//             (Gouraud) or one colour (flat)
#include "litkit/render.hpp"
#include "litkit/error.hpp"
#include "litkit/validate.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <variant>
#include <utility>
#include <vector>

#include "litkit/equations.hpp"
#include "cpu/shade_kernel.hpp"
#include "cpu/thread_pool.hpp"
#include "scene/float_range.hpp"
#include "scene/world_mesh.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace litkit {

namespace {

using equations::PreparedLight;


// Per-vertex data after the vertex stage. `varyings` holds the normal
// (Phong shading) or the unclamped colour (Gouraud).
constexpr int max_varyings = 3;
struct ClipVertex {
    glm::vec4 clip;
    std::array<float, max_varyings> varyings;
};

using kernels::subpixel_bits;
using kernels::subpixel_one;
using kernels::WindowCorner;

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

using kernels::guard_band;

// Signed distances of a clip-space point to the six clip planes; ≥ 0 inside.
std::array<float, 6> plane_distances(const glm::vec4& c) {
    return {c.z + c.w,  c.w - c.z,  // near, far
            c.x + guard_band * c.w, guard_band * c.w - c.x,
            c.y + guard_band * c.w, guard_band * c.w - c.y};
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
int clip_triangle(const std::array<ClipVertex, 3>& triangle, int varying_count,
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

// Lighting of one point with plain floats (vertex and flat stages).
glm::vec3 light_with(Reflection reflection, std::span<const PreparedLight> lights,
                     const equations::MaterialT<float>& m, const glm::vec3& p, const glm::vec3& n,
                     const glm::vec3& eye) {
    return equations::shade_scalar(reflection, lights, m, p, n, eye);
}

constexpr int band_height = 16;
// Spans of one triangle shorter than this are interpolated pixel by pixel.
constexpr std::size_t short_span = 8;
constexpr std::size_t setup_chunk = 2048;  // triangles per setup job
// Triangles at most this many pixels wide find each row's covered pixels by
// testing them; wider ones solve the span from the edge functions.
constexpr std::int64_t narrow_triangle = 8;
// Triangles whose corners lie within this many fixed-point units of each
// other, both ways (8 pixels), step their edge functions in 32-bit SIMD lanes.
constexpr std::int32_t small_triangle = 8 * static_cast<std::int32_t>(subpixel_one);

using kernels::largest_fixed_coordinate;

// Nearest integer, halves up; |v| stays far below 2^31 thanks to the guard
// band. (std::llround is a library call; this is two instructions.)
std::int32_t round_to_int(double v) {
    const double shifted = v + 0.5;
    auto truncated = static_cast<std::int32_t>(shifted);
    return truncated - (shifted < static_cast<double>(truncated) ? 1 : 0);
}

// Varyings of the corners of a piece of a clipped triangle.
using CornerVaryings = std::array<std::array<float, max_varyings>, 3>;

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

using kernels::RasterTriangle;  // what the visibility pass needs of a triangle

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

// Perspective divide, viewport and fixed point of one clip-space corner.
WindowCorner to_window(const glm::vec4& c, float half_width, float half_height) {
    WindowCorner out;
    // plane_distances(c)[k] < 0, written out (the same sums and products).
    const float band_w = guard_band * c.w;
    out.outside = static_cast<std::uint8_t>(
        (c.z + c.w < 0.0f ? 1 : 0) | (c.w - c.z < 0.0f ? 2 : 0) | (c.x + band_w < 0.0f ? 4 : 0) |
        (band_w - c.x < 0.0f ? 8 : 0) | (c.y + band_w < 0.0f ? 16 : 0) | (band_w - c.y < 0.0f ? 32 : 0));
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

// Per-thread scratch for one band: the visibility buffer (nearest triangle
// and its perspective-correct weights per pixel) and one row of colours.
struct BandScratch {
    std::vector<float> depth;                    // 1/w; 0 = nothing drawn
    std::vector<const ShadeTriangle*> visible;   // nullptr = background
    std::vector<float> weight1, weight2;         // b1/w1, b2/w2 (perspective weights × 1/w)
    std::vector<float> r, g, b;                  // one row of intensities
    std::vector<float> q0, q1, q2;               // one row of perspective-correct weights
    std::vector<float> view_w, nx, ny, nz;     // one row of Phong surfaces (view depth, normal)
    std::vector<int> touched_begin, touched_end;  // per band row: columns drawn
    std::size_t shaded_pixels = 0;               // this frame, by this thread
    // Setup's triangles of the chunk at hand, before they are binned.
    std::vector<BinnedTriangle> pending;
    std::vector<std::uint32_t> band_count;
};

const kernels::Kernels& pick_kernels(RenderOptions::Kernels set) {
    if (!kernel_set_available(set))
        throw ArgumentError(std::string("this CPU lacks the instructions of the ") +
                            (set == RenderOptions::Kernels::Avx512 ? "AVX-512" : "AVX2") +
                            " kernel set");
    switch (set) {
        case RenderOptions::Kernels::Portable: return kernels::portable_kernels;
#if defined(__x86_64__) || defined(__i386__)  // the other sets exist on x86 only
        case RenderOptions::Kernels::Avx2: return kernels::avx2_kernels;
        case RenderOptions::Kernels::Avx512: return kernels::avx512_kernels;
#else
        case RenderOptions::Kernels::Avx2:
        case RenderOptions::Kernels::Avx512: break;  // refused above
#endif
        case RenderOptions::Kernels::Best: break;
    }
    return kernels::select_kernels();
}

}  // namespace

bool kernel_set_available(RenderOptions::Kernels set) {
    switch (set) {
        case RenderOptions::Kernels::Avx2: return kernels::cpu_has_avx2();
        case RenderOptions::Kernels::Avx512: return kernels::cpu_has_avx512();
        default: return true;
    }
}

struct Renderer::Impl {
    float length_scale;
    Scene scene;
    RenderOptions options;
    ThreadPool pool;
    const kernels::Kernels& kernels;
    std::vector<PreparedLight> lights;
    std::vector<PreparedObject> objects;

    // Per-frame state, kept between frames to avoid reallocating.
    std::vector<std::vector<glm::vec4>> clip_positions;  // per object, per vertex
    std::vector<std::vector<WindowCorner>> window_corners;  // per object, per vertex
    std::vector<std::vector<glm::vec3>> vertex_colors;   // Gouraud, per object
    std::vector<std::vector<glm::vec3>> flat_colors;     // flat, per object, per triangle
    std::vector<SetupChunk> chunks;
    std::vector<BandScratch> scratch;  // one per thread
    std::vector<std::uint8_t> background_row;  // one image row of background colour
    int band_count = 0;
    // The pixels' rays (docs/spec.md §1), for the world position at each
    // pixel: d = forward + y · ray_up + k · ray_across (kernels::RowRays),
    // set by vertex_stage.
    glm::vec3 ray_forward{0.0f}, ray_up{0.0f}, ray_across{0.0f};
    // Set while Renderer::probe draws: the pixel to record, and the record.
    int probe_x = -1, probe_y = -1;
    mutable PixelProbe probed;

    // The scene as drawn: its lengths brought into a float's comfortable
    // range by a power of two (scene/float_range.hpp; 1 for ordinary scenes).
    Impl(const Scene& s, RenderOptions o)
        : length_scale(float_safe_length_scale(s)),
          scene(scale_lengths(s, length_scale)),
          options(o),
          pool(o.threads),
          kernels(pick_kernels(o.kernels)) {}

    std::size_t mesh_builds = 0;  // how often prepare() built the meshes

    void prepare();
    void prepare_surfaces();
    void vertex_stage(int width, int height);
    void setup(SetupChunk& chunk, BandScratch& scratch, int width, int height);
    void rasterize_band(int band, BandScratch& scratch, Image& image) const;
    void shade_row(int y, int width, BandScratch& scratch, std::uint8_t* row) const;
    void record_probe(const BandScratch& scratch, std::size_t i, int x) const;
    kernels::RowRays row_rays(int y) const;
    // A clipped piece's corners (ShadeTriangle::vertex says where), or null.
    const CornerVaryings* varyings_of(const ShadeTriangle& tri) const {
        return tri.clipped() ? &chunks[tri.vertex[1]].clipped[tri.vertex[0]] : nullptr;
    }
};

namespace {

// Phong shading's normal at a pixel: N mixed from the corners' (the
// mesh's, or a clipped piece's) with the perspective-correct weights; p is
// the point on the pixel's ray (kernels::RowRays).
// `varyings`: the clipped piece's corners (Impl::varyings_of), or null.
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

// The world position at column x of a row whose rays are `rays`, at view
// depth w: the kernels' shade_phong's formula, one pixel (each product
// rounded on its own: x86-64's baseline, which this file is built for, has
// no FMA; the kernels are built with -ffp-contract=off).
glm::vec3 ray_point(const kernels::RowRays& rays, int width, int x, float w) {
    const float k = static_cast<float>(2 * x + 1 - width);
    glm::vec3 p;
    for (int c = 0; c < 3; ++c) p[c] = rays.eye[c] + w * (k * rays.across[c] + rays.centre[c]);
    return p;
}

// A span's corner normals for the kernel set's interpolate: the mesh
// vertices', or the clipped piece's own.
void span_normals(const PreparedObject& object, const ShadeTriangle& tri, const CornerVaryings* varyings,
                  float (&normal)[3][3]) {
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

}  // namespace

// Renderer::probe's record of one visible pixel, made after its row is
// shaded (so the hot loop carries no test for it), with the fragment stage's
// own formulas.
void Renderer::Impl::record_probe(const BandScratch& s, std::size_t i, int x) const {
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
    probed.position = ray_point(row_rays(probe_y), scene.output.width, x, w);
    probed.normal = interpolate_normal(objects[tri->object], *tri, varyings_of(*tri), q0, q1, q2);
    probed.intensity = {s.r[static_cast<std::size_t>(x)], s.g[static_cast<std::size_t>(x)],
                        s.b[static_cast<std::size_t>(x)]};
}

// Everything of the scene but its meshes: lights, materials and models.
void Renderer::Impl::prepare_surfaces() {
    lights.clear();
    for (const SceneLight& light : scene.lights) lights.push_back(equations::prepare_light(light.light));
    const Reflection scene_reflection = scene.reflection.value_or(options.fallback_reflection);
    const Shading scene_shading = scene.shading.value_or(options.fallback_shading);
    for (std::size_t o = 0; o < objects.size(); ++o) {
        const SceneObject& object = scene.objects[o];
        PreparedObject& prepared = objects[o];
        prepared.material = equations::splat<float>(object.material);
        prepared.raw_material = object.material;
        prepared.reflection = object.reflection.value_or(scene_reflection);
        prepared.shading = object.shading.value_or(scene_shading);
        // Face normals only for the shadings that use them (a 261k-triangle
        // mesh under Phong shading would compute 3 MB for nothing); kept once
        // computed, since the mesh is.
        const bool uses_faces =
            prepared.shading == Shading::Flat || prepared.shading == Shading::Faceted;
        if (uses_faces && prepared.face_normals.empty()) {
            prepared.face_normals.reserve(prepared.triangles.size());
            for (const auto& t : prepared.triangles) {
                prepared.face_normals.push_back(face_normal(
                    prepared.positions[t[0]], prepared.positions[t[1]], prepared.positions[t[2]]));
            }
        }
    }
}

void Renderer::Impl::prepare() {
    ++mesh_builds;
    objects.clear();
    chunks.clear();
    // Mesh building borrows the pool's threads (the same meshes, bit for bit).
    const ParallelFor parallel = [this](std::size_t count, const ParallelJob& job) {
        pool.parallel_for(count, [&](std::size_t index, int) { job(index); });
    };
    for (const SceneObject& object : scene.objects) {
        WorldMesh mesh =
            world_mesh(object, normal_options(scene, object), parallel, scene.built_meshes.get());
        PreparedObject prepared;
        prepared.positions = std::move(mesh.positions);
        prepared.normals = std::move(mesh.normals);
        prepared.triangles = std::move(mesh.triangles);
        objects.push_back(std::move(prepared));
    }
    prepare_surfaces();

    // Setup jobs: fixed triangle ranges, so their output buffers are reused.
    for (std::size_t o = 0; o < objects.size(); ++o) {
        const std::size_t count = objects[o].triangles.size();
        for (std::size_t begin = 0; begin < count; begin += setup_chunk) {
            SetupChunk chunk;
            chunk.object = static_cast<std::uint32_t>(o);
            chunk.begin = begin;
            chunk.end = std::min(count, begin + setup_chunk);
            chunks.push_back(std::move(chunk));
        }
    }
    clip_positions.resize(objects.size());
    window_corners.resize(objects.size());
    vertex_colors.resize(objects.size());
    flat_colors.resize(objects.size());
    scratch.resize(static_cast<std::size_t>(pool.size()));
}

// Vertex stage: every vertex to clip space once; Gouraud objects lit per
// vertex, flat objects per triangle (at the centroid, with the face normal).
void Renderer::Impl::vertex_stage(int width, int height) {
    const Observer& observer = scene.observer;
    const glm::vec3 eye = observer.position;
    // The projection in double, rounded once to float: float tanf rounds
    // differently in glibc and in the WebAssembly build's C library (for a
    // fov of 32 degrees, enough to move a pixel), double tan rounded to
    // float does not, so every build draws the same bytes (docs/web.md).
    const glm::mat4 projection(glm::perspective(glm::radians(double(observer.fov_degrees)),
                                                double(width) / double(height),
                                                double(observer.near), double(observer.far)));
    const glm::mat4 view_projection =
        projection * glm::lookAt(observer.position, observer.look_at, observer.up);
    // The pixels' rays (docs/spec.md §1) in world space, with glm::lookAt's
    // axes: forward f, right s = f × up, up u = s × f; NDC (x, y) looks along
    // f + x · tan(fov/2) · aspect · s + y · tan(fov/2) · u, whose component
    // along f is 1, so that the point at view depth w is eye + w · d.
    {
        const glm::dvec3 f = glm::normalize(glm::dvec3(observer.look_at) - glm::dvec3(eye));
        const glm::dvec3 right = glm::normalize(glm::cross(f, glm::dvec3(observer.up)));
        const glm::dvec3 up = glm::cross(right, f);
        const double tan_half = std::tan(glm::radians(double(observer.fov_degrees)) / 2.0);
        const double aspect = double(width) / double(height);
        ray_forward = glm::vec3(f);
        ray_up = glm::vec3(tan_half * up);
        ray_across = glm::vec3(tan_half * aspect / double(width) * right);  // per unit of k
    }

    constexpr std::size_t chunk = 4096;
    for (std::size_t o = 0; o < objects.size(); ++o) {
        const PreparedObject& object = objects[o];
        std::vector<glm::vec4>& clip = clip_positions[o];
        clip.resize(object.positions.size());
        std::vector<WindowCorner>& window = window_corners[o];
        window.resize(object.positions.size());
        const float half_width = 0.5f * static_cast<float>(width);
        const float half_height = 0.5f * static_cast<float>(height);
        std::vector<glm::vec3>& colors = vertex_colors[o];
        if (object.shading == Shading::Gouraud) colors.resize(object.positions.size());
        pool.parallel_for((clip.size() + chunk - 1) / chunk, [&](std::size_t c, int) {
            const std::size_t begin = c * chunk;
            const std::size_t end = std::min(clip.size(), begin + chunk);
            // clip = view_projection · (p, 1) and to_window(clip), a vector
            // of vertices at a time.
            kernels.transform_vertices(&object.positions[begin].x, end - begin,
                                       &view_projection[0][0], half_width, half_height,
                                       &clip[begin].x, &window[begin]);
            if (object.shading == Shading::Gouraud) {
                for (std::size_t i = begin; i < end; ++i)
                    colors[i] = light_with(object.reflection, lights, object.material,
                                           object.positions[i], object.normals[i], eye);
            }
        });
        // Flat colours are computed in setup, only for triangles that
        // survive culling and clipping.
        if (object.shading == Shading::Flat) flat_colors[o].resize(object.triangles.size());
    }
}

// Row y's rays (kernels::RowRays): NDC y = 1 − 2(y + 0.5)/H.
kernels::RowRays Renderer::Impl::row_rays(int y) const {
    const int height = scene.output.height;
    const float ndc_y = static_cast<float>(double(height - 2 * y - 1) / double(height));
    const glm::vec3 centre = ray_forward + ndc_y * ray_up;
    const glm::vec3& eye = scene.observer.position;
    return {{eye.x, eye.y, eye.z}, {centre.x, centre.y, centre.z}, {ray_across.x, ray_across.y, ray_across.z}};
}

// Clip and setup stages for one range of triangles, then binning to bands.
void Renderer::Impl::setup(SetupChunk& chunk, BandScratch& scratch, int width, int height) {
    const PreparedObject& object = objects[chunk.object];
    const std::vector<glm::vec4>& clip = clip_positions[chunk.object];
    const std::vector<WindowCorner>& window = window_corners[chunk.object];
    const bool per_pixel = object.shading == Shading::Phong || object.shading == Shading::Faceted;
    // Clipped pieces carry their corners' normals (Phong; faceted takes the
    // face's, and every per-pixel p comes from the pixel's ray) or colours
    // (Gouraud).
    const int varying_count = per_pixel || object.shading == Shading::Gouraud ? 3 : 0;
    const float half_width = 0.5f * static_cast<float>(width);
    const float half_height = 0.5f * static_cast<float>(height);
    std::vector<BinnedTriangle>& pending = scratch.pending;
    pending.clear();
    chunk.clipped.clear();
    // Triangles per band of rows, counts[b + 1] for band b.
    const std::size_t bands = static_cast<std::size_t>(band_count);
    std::vector<std::uint32_t>& counts = scratch.band_count;
    counts.assign(bands + 1, 0);

    bool flat_done = false;  // the current source triangle's flat colour is computed
    // Setup of one (piece of a) triangle from its window corners; nothing
    // when culled.
    // Doubled signed area in y-down window coordinates: a triangle
    // counter-clockwise on screen (front-facing) has a negative one.
    auto doubled_area = [](const WindowCorner& c0, const WindowCorner& c1, const WindowCorner& c2) {
        return std::int64_t{c1.x - c0.x} * (c2.y - c0.y) - std::int64_t{c1.y - c0.y} * (c2.x - c0.x);
    };
    // Setup of a front-facing (area < 0) piece with valid corners.
    auto emit_front = [&](const WindowCorner& c0, const WindowCorner& c1, const WindowCorner& c2,
                          std::int64_t area, std::uint32_t source,
                          const std::array<std::uint32_t, 3>& vertex, const CornerVaryings* varyings) {
        RasterTriangle raster;
        raster.x = {c0.x, c2.x, c1.x};
        raster.y = {c0.y, c2.y, c1.y};

        // Pixel i covers the centre i + 0.5.
        auto first_pixel = [](std::int64_t lo) {
            return static_cast<int>((lo - subpixel_one / 2 + subpixel_one - 1) >> subpixel_bits);
        };
        auto last_pixel = [](std::int64_t hi) {
            return static_cast<int>((hi - subpixel_one / 2) >> subpixel_bits);
        };
        const auto [min_x, max_x] = std::minmax({raster.x[0], raster.x[1], raster.x[2]});
        const auto [min_y, max_y] = std::minmax({raster.y[0], raster.y[1], raster.y[2]});
        const int left = std::max(0, first_pixel(min_x));
        const int right = std::min(width - 1, last_pixel(max_x));
        const int top = std::max(0, first_pixel(min_y));
        const int bottom = std::min(height - 1, last_pixel(max_y));
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
            flat_colors[chunk.object][source] =
                light_with(object.reflection, lights, object.material, centroid,
                           object.face_normals[source], scene.observer.position);
            flat_done = true;
        }
        ShadeTriangle shade;
        shade.object = chunk.object;
        shade.source = source;
        shade.vertex = {vertex[0], vertex[2], vertex[1]};
        if (varyings) {
            shade.vertex = {static_cast<std::uint32_t>(chunk.clipped.size()),
                            static_cast<std::uint32_t>(&chunk - chunks.data()), ShadeTriangle::clipped_piece};
            chunk.clipped.push_back({(*varyings)[0], (*varyings)[2], (*varyings)[1]});
        }
        pending.push_back({raster, shade});
        // Counted for binning (below) as it is made.
        for (int b = top / band_height; b <= bottom / band_height; ++b) ++counts[static_cast<std::size_t>(b) + 1];
    };
    auto emit = [&](const WindowCorner& c0, const WindowCorner& c1, const WindowCorner& c2,
                    std::uint32_t source, const std::array<std::uint32_t, 3>& vertex,
                    const CornerVaryings* varyings) {
        if (!(c0.valid && c1.valid && c2.valid)) return;
        const std::int64_t area = doubled_area(c0, c1, c2);
        if (area >= 0) return;  // back face or zero area: culled
        emit_front(c0, c1, c2, area, source, vertex, varyings);
    };

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
        flat_done = false;
        if ((w0.outside | w1.outside | w2.outside) == 0) {
            // emit(), with the back faces (half of a closed mesh) culled here.
            if (!(w0.valid && w1.valid && w2.valid)) continue;
            const std::int64_t area = doubled_area(w0, w1, w2);
            if (area >= 0) continue;  // back face or zero area: culled
            emit_front(w0, w1, w2, area, source, indices, nullptr);
            continue;
        }
        // Clipping: the pieces carry their own varyings, interpolated in
        // clip space.
        std::array<ClipVertex, 3> input;
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t v = indices[k];
            input[k].clip = clip[v];
            input[k].varyings.fill(0.0f);
            if (per_pixel) {
                const glm::vec3& n = object.normals[v];
                input[k].varyings = {n.x, n.y, n.z};
            } else if (object.shading == Shading::Gouraud) {
                const glm::vec3& c = vertex_colors[chunk.object][v];
                input[k].varyings = {c.x, c.y, c.z};
            }
        }
        std::array<ClipVertex, 9> polygon;
        const int count = clip_triangle(input, varying_count, polygon);
        for (int k = 1; k + 1 < count; ++k) {  // a fan keeps the winding
            const ClipVertex* piece[3] = {&polygon[0], &polygon[k], &polygon[k + 1]};
            CornerVaryings varyings;
            for (int m = 0; m < 3; ++m) varyings[m] = piece[m]->varyings;
            emit(to_window(piece[0]->clip, half_width, half_height),
                 to_window(piece[1]->clip, half_width, half_height),
                 to_window(piece[2]->clip, half_width, half_height), source, indices, &varyings);
        }
    }

    // Binning: each band of rows gets a copy of the triangles that may touch
    // it, in setup order (counted as they were made, so the chunk's one
    // array is sized exactly).
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
    // of their lines before the writes (session 11: frame 0.99x).
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

// Rasterize stage for one band: the visibility buffer holds, per pixel, the
// nearest triangle and its perspective-correct weights; then shade row by row.
void Renderer::Impl::rasterize_band(int band, BandScratch& s, Image& image) const {
    const int width = image.width;
    const int row_begin = band * band_height;
    const int row_end = std::min(image.height, row_begin + band_height);
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
            const RasterTriangle& tri = t->raster;
            const ShadeTriangle* const shade = &t->shade;
            const int y0 = std::max<int>(tri.min_y, row_begin);
            const int y1 = std::min<int>(tri.max_y(), row_end - 1);
            if (y0 > y1) continue;

            if (tri.small() && kernels.visibility_small) {
                // The kernel set's lanes set up its edge functions and test
                // a row (or two) at a time: the same pixels and values as below.
                const std::size_t first_row = static_cast<std::size_t>(y0 - row_begin) * width;
                kernels.visibility_small(tri, y0, y1 - y0 + 1, shade, &s.depth[first_row],
                                         reinterpret_cast<const void**>(&s.visible[first_row]),
                                         &s.weight1[first_row], &s.weight2[first_row], width,
                                         &s.touched_begin[y0 - row_begin], &s.touched_end[y0 - row_begin]);
                continue;
            }

            // Edge k is opposite corner k: from corner k+1 to corner k+2.
            // E(p) = (b.x − a.x)(p.y − a.y) − (b.y − a.y)(p.x − a.x) ≥ 0 inside.
            std::array<std::int64_t, 3> step_x, step_y, origin, bias;
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
            const float weight0 = tri.weight[0];
            const float weight1 = tri.weight[1];
            const float weight2 = tri.weight[2];

#if defined(__SSE2__)
            if (tri.small()) {
                // The same pixels and values as below, with the three edge
                // functions in the lanes of one 32-bit vector (exact: they
                // stay far inside 32 bits for a small triangle, and a float
                // made from the same integer is the same float).
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
                std::size_t row = static_cast<std::size_t>(y0 - row_begin) * width +
                                  static_cast<std::size_t>(tri.min_x);
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
                            // (p0 + p1) + p2, as below
                            const float inverse_w = _mm_cvtss_f32(_mm_add_ss(_mm_add_ss(p, p1), p2));
                            const std::size_t i = row + static_cast<std::size_t>(x);
                            if (!(inverse_w <= s.depth[i])) {  // nearer (or NaN), as below
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
                continue;
            }
#endif
            if (tri.max_x - tri.min_x < narrow_triangle) {
                // A narrow triangle (all of them, in meshes of 100k
                // triangles and more): the same pixels and values as below,
                // found by stepping the edge functions from pixel to pixel
                // (the covered ones of a row are consecutive) instead of
                // three 64-bit divisions a row.
                const std::int64_t sx0 = step_x[0], sx1 = step_x[1], sx2 = step_x[2];
                const std::int64_t b0 = bias[0], b1 = bias[1], b2 = bias[2];
                const int span = tri.max_x - tri.min_x;
                // The biased edge functions at the row's first pixel.
                std::int64_t r0 = origin[0] + b0, r1 = origin[1] + b1, r2 = origin[2] + b2;
                std::size_t row = static_cast<std::size_t>(y0 - row_begin) * width +
                                  static_cast<std::size_t>(tri.min_x);
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
                            if (!(inverse_w <= s.depth[i])) {  // nearer (or NaN), as below
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
                continue;
            }
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
                        if (e[k] < 0) last = -1;
                        else last = std::min(last, e[k] / -step_x[k]);
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
                const std::size_t row = static_cast<std::size_t>(band_row) * width +
                                        static_cast<std::size_t>(tri.min_x);
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
                    within = within && v[k] < exact && v[k] > -exact && end_value < exact && end_value > -exact;
                }
                const std::size_t at = row + static_cast<std::size_t>(first);
                (within ? kernels.visibility_row : kernels::visibility_row_scalar)(
                    v, step_x.data(), tri.weight.data(), static_cast<std::size_t>(count), &s.depth[at],
                    reinterpret_cast<const void**>(&s.visible[at]), shade, &s.weight1[at], &s.weight2[at]);
            }
        }
    }
    for (int y = row_begin; y < row_end; ++y) shade_row(y, width, s, image.pixel(0, y));
}

// Fragment stage for one row of the visibility buffer: each visible pixel
// gets the shading model of its object, Phong and faceted pixels in runs through the
// SIMD kernel; then clamp and gamma, and the background where nothing is.
void Renderer::Impl::shade_row(int y, int width, BandScratch& s, std::uint8_t* row) const {
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
    const kernels::RowRays rays = row_rays(y);
    std::size_t run_length = 0;
    int run_first = 0;
    const PreparedObject* run_object = nullptr;
    auto flush = [&] {
        if (run_length == 0) return;
        const std::size_t at = static_cast<std::size_t>(run_first);
        const kernels::SurfaceRun surface{&rays,     static_cast<float>(2 * run_first + 1 - width),
                                          &s.view_w[at], &s.nx[at], &s.ny[at], &s.nz[at], run_length};
        kernels.shade_phong(run_object->reflection, lights, run_object->raw_material, surface,
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
        // Varyings of the three corners: the mesh's, or the clipped piece's.
        if (object.shading == Shading::Gouraud) {
            flush();
            // Perspective-correct weights: (b_k / w_k) / Σ (b_j / w_j).
            const float q0 = s.q0[x], q1 = s.q1[x], q2 = s.q2[x];
            glm::vec3 c;
            if (!tri->clipped()) {
                const auto& colors = vertex_colors[tri->object];
                c = q0 * colors[tri->vertex[0]] + q1 * colors[tri->vertex[1]] +
                    q2 * colors[tri->vertex[2]];
            } else {
                const CornerVaryings& v = *varyings_of(*tri);
                c = {q0 * v[0][0] + q1 * v[1][0] + q2 * v[2][0],
                     q0 * v[0][1] + q1 * v[1][1] + q2 * v[2][1],
                     q0 * v[0][2] + q1 * v[1][2] + q2 * v[2][2]};
            }
            s.r[x] = c.x, s.g[x] = c.y, s.b[x] = c.z;
            continue;
        }
#if defined(__SSE2__)
        if (object.shading == Shading::Phong && !tri->clipped()) {
            // Phong, the mesh's own corners: this pixel's span and those
            // after it whose triangles are too, of this object, in one loop
            // (a dense mesh's spans are one to three pixels: the checks and
            // look-ups of the general path below would be most of the work).
            // The same formulas as there.
            if (run_object != &object || (run_length > 0 && run_first + static_cast<int>(run_length) != x))
                flush();
            if (run_length == 0) run_first = x;
            run_object = &object;
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
                    const __m128 n0 = load3(&normals[span->vertex[0]].x), n1 = load3(&normals[span->vertex[1]].x),
                                 n2 = load3(&normals[span->vertex[2]].x);
                    // The triangle a few pixels on, fetched ahead (once a span).
                    if (at + 12 < end) __builtin_prefetch(visible[at + 12]);
                    do {
                        const __m128 a = _mm_set1_ps(q0[at]), b = _mm_set1_ps(q1[at]), c = _mm_set1_ps(q2[at]);
                        store3(mix3(a, b, c, n0, n1, n2), out[0] + at, out[1] + at, out[2] + at);
                        ++at;
                    } while (at < end && visible[at] == span);
                }
                if (at >= end) break;
                const ShadeTriangle* const next = visible[at];
                if (!next || next->object != object_index || next->clipped()) break;
                span = next;
            }
            run_length += static_cast<std::size_t>(at - x);
            x = at - 1;
            continue;
        }
#endif
        // Phong or faceted: the span of this triangle's normals at once (the
        // formulas of interpolate_normal).
        int span_end = x + 1;
        while (span_end < end && s.visible[offset + static_cast<std::size_t>(span_end)] == tri)
            ++span_end;
        if (run_object != &object || (run_length > 0 && run_first + static_cast<int>(run_length) != x))
            flush();
        if (run_length == 0) run_first = x;
        run_object = &object;
        const std::size_t count = static_cast<std::size_t>(span_end - x);
        const CornerVaryings* const varyings = varyings_of(*tri);  // a clipped piece's, or null
        const std::size_t first = static_cast<std::size_t>(x);
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
                corner[k] = varyings ? load3(&(*varyings)[k][0]) : load3(&object.normals[tri->vertex[k]].x);
            for (std::size_t at = first; at < first + count; ++at) {
                const __m128 a = _mm_set1_ps(s.q0[at]), b = _mm_set1_ps(s.q1[at]), c = _mm_set1_ps(s.q2[at]);
                store3(mix3(a, b, c, corner[0], corner[1], corner[2]), &s.nx[at], &s.ny[at], &s.nz[at]);
            }
        } else
#endif
        if (count < short_span) {
            // Small triangles: the scalar formulas, pixel by pixel (a SIMD
            // call would mostly pad); the same roundings as the kernel.
            for (std::size_t at = first; at < first + count; ++at) {
                const glm::vec3 n = interpolate_normal(object, *tri, varyings, s.q0[at], s.q1[at], s.q2[at]);
                s.nx[at] = n.x, s.ny[at] = n.y, s.nz[at] = n.z;
            }
        } else {
            float normal[3][3];
            span_normals(object, *tri, varyings, normal);
            kernels.interpolate(&s.q0[first], &s.q1[first], &s.q2[first], count, normal,
                                {&s.nx[first], &s.ny[first], &s.nz[first]});
        }
        run_length += count;
        x = span_end - 1;
    }
    flush();
    if (y == probe_y && probe_x >= begin && probe_x < end && s.visible[offset + probe_x])
        record_probe(s, offset + static_cast<std::size_t>(probe_x), probe_x);

    // Clamp, gamma and encode the covered pixels; background as given.
    // Background spans are copied from a row prepared once per frame.
    auto fill_background = [&](int from, int to) {
        if (from < to)
            std::memcpy(row + 3 * from, background_row.data() + 3 * from,
                        3 * static_cast<std::size_t>(to - from));
    };
    fill_background(0, begin);
    fill_background(end, width);
    if (!background_between && begin < end) {  // one run: no need to look for its ends
        s.shaded_pixels += static_cast<std::size_t>(end - begin);
        kernels.encode(s.r.data() + begin, s.g.data() + begin, s.b.data() + begin,
                       static_cast<std::size_t>(end - begin), scene.output.gamma, row + 3 * begin);
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
        kernels.encode(s.r.data() + x, s.g.data() + x, s.b.data() + x,
                       static_cast<std::size_t>(run_end - x), scene.output.gamma, row + 3 * x);
        x = run_end;
    }
    // Leave the visibility buffer cleared for the next band.
    if (begin < end) {
        std::fill(s.depth.begin() + offset + begin, s.depth.begin() + offset + end, 0.0f);
        std::fill(s.visible.begin() + offset + begin, s.visible.begin() + offset + end, nullptr);
    }
}

namespace {

// The renderer's preconditions (render.hpp), checked before anything is built.
void check_preconditions(const Scene& scene, const RenderOptions& options) {
    if (options.threads < 0 || options.threads > max_render_threads)
        throw ArgumentError("RenderOptions::threads must be 0 (one per hardware thread) to " +
                            std::to_string(max_render_threads) + ", found " +
                            std::to_string(options.threads));
    check_renderable(scene);
}

}  // namespace

Renderer::Renderer(const Scene& scene, RenderOptions options)
    : impl_((check_preconditions(scene, options), std::make_unique<Impl>(scene, options))) {
    impl_->prepare();
}

Renderer::~Renderer() = default;

std::size_t Renderer::triangle_count() const {
    std::size_t count = 0;
    for (const PreparedObject& object : impl_->objects) count += object.triangles.size();
    return count;
}

int Renderer::thread_count() const { return impl_->pool.size(); }

const char* Renderer::kernel_set() const { return impl_->kernels.name; }

std::size_t Renderer::shaded_pixel_count() const {
    std::size_t count = 0;
    for (const BandScratch& scratch : impl_->scratch) count += scratch.shaded_pixels;
    return count;
}

void Renderer::render_into(Image& image) {
    const int width = impl_->scene.output.width;
    const int height = impl_->scene.output.height;
    if (image.width != width || image.height != height) image = Image(width, height);
    Impl& impl = *impl_;
    impl.band_count = (height + band_height - 1) / band_height;
    impl.background_row.resize(3 * static_cast<std::size_t>(width));
    const Rgb8 background = to_rgb8(impl.scene.output.background);
    for (std::size_t i = 0; i < impl.background_row.size(); ++i)
        impl.background_row[i] = background[i % 3];
    for (BandScratch& scratch : impl.scratch) scratch.shaded_pixels = 0;
    impl.vertex_stage(width, height);
    impl.pool.parallel_for(impl.chunks.size(), [&](std::size_t c, int worker) {
        impl.setup(impl.chunks[c], impl.scratch[static_cast<std::size_t>(worker)], width, height);
    });
    if (impl.probe_y >= 0) {
        // probe(): the pixel's band alone. A band's rows depend only on the
        // triangles binned to it, so the pixel comes out as in a whole frame.
        impl.rasterize_band(impl.probe_y / band_height, impl.scratch[0], image);
        return;
    }
    impl.pool.parallel_for(static_cast<std::size_t>(impl.band_count), [&](std::size_t band, int worker) {
        impl.rasterize_band(static_cast<int>(band), impl.scratch[static_cast<std::size_t>(worker)], image);
    });
}

void Renderer::update(const Scene& new_scene) {
    check_renderable(new_scene);  // before anything of the old scene is replaced
    Impl& impl = *impl_;
    const float length_scale = float_safe_length_scale(new_scene);
    Scene scene = scale_lengths(new_scene, length_scale);
    bool same = scene.objects.size() == impl.scene.objects.size();
    for (std::size_t o = 0; same && o < scene.objects.size(); ++o)
        same = same_geometry(scene.objects[o], impl.scene.objects[o]) &&
               normal_options(scene, scene.objects[o]) ==
                   normal_options(impl.scene, impl.scene.objects[o]);
    impl.scene = std::move(scene);  // one copy of the scene per update, as before
    impl.length_scale = length_scale;
    if (same) {
        impl.prepare_surfaces();
    } else {
        impl.prepare();
    }
}

std::size_t Renderer::mesh_builds() const { return impl_->mesh_builds; }

PixelProbe Renderer::probe(int x, int y) {
    const OutputSettings& output = impl_->scene.output;
    if (x < 0 || y < 0 || x >= output.width || y >= output.height) {
        throw ArgumentError("pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                                ") is outside the " + std::to_string(output.width) + "x" +
                                std::to_string(output.height) + " image");
    }
    impl_->probed = PixelProbe{};
    impl_->probe_x = x;
    impl_->probe_y = y;
    Image image;
    try {
        render_into(image);
    } catch (...) {
        impl_->probe_x = impl_->probe_y = -1;
        throw;
    }
    impl_->probe_x = impl_->probe_y = -1;
    PixelProbe result = impl_->probed;
    result.position /= impl_->length_scale;  // in the scene's own lengths
    const std::uint8_t* pixel = image.pixel(x, y);
    result.rgb = {pixel[0], pixel[1], pixel[2]};
    return result;
}

Image Renderer::render() {
    Image image;
    render_into(image);
    return image;
}

Image render(const Scene& scene, RenderOptions options) {
    Renderer renderer(scene, options);
    return renderer.render();
}

}  // namespace litkit
