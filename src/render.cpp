// The CPU rasterizer. The stages carry the names of the OpenGL pipeline so
// that this file and the generated GLSL read alike:
//   vertex    world → clip space; Gouraud lighting per vertex
//   clip      Sutherland–Hodgman in homogeneous coordinates (near, far and a
//             guard band at the sides), as OpenGL clips
//   setup     perspective divide, viewport, back-face culling, fixed point
//   rasterize half-space edge functions with the top-left fill rule, over
//             bands of rows spread across the thread pool
//   fragment  depth test, perspective-correct varyings, lighting per pixel
//             (Phong) or interpolated colours (Gouraud) or one colour (flat)
#include "litkit/render.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "litkit/equations.hpp"
#include "thread_pool.hpp"

namespace litkit {

namespace {

using equations::PreparedLight;
using equations::Vec3;

Vec3<float> to_vec3(const glm::vec3& v) { return {v.x, v.y, v.z}; }
glm::vec3 to_glm(const Vec3<float>& v) { return {v.x, v.y, v.z}; }

// Per-vertex data after the vertex stage. `varyings` holds the world position
// and normal (Phong shading) or the unclamped colour (Gouraud; 3 used).
constexpr int max_varyings = 6;
struct ClipVertex {
    glm::vec4 clip;
    std::array<float, max_varyings> varyings;
};

// A triangle ready to rasterize: fixed-point window coordinates, 1/w and
// varyings per vertex, ordered so that its doubled area is positive.
constexpr int subpixel_bits = 8;
constexpr std::int64_t subpixel_one = std::int64_t{1} << subpixel_bits;
struct RasterTriangle {
    std::array<std::int64_t, 3> x, y;
    std::array<float, 3> inverse_w;
    std::array<std::array<float, max_varyings>, 3> varyings;
    glm::vec3 flat_color;  // flat shading: the one colour of the whole triangle
    std::uint32_t object;
    int min_x, max_x, min_y, max_y;  // pixel bounds, inclusive, inside the image
};

// An object's geometry in world space, built once per Renderer ("uploaded").
struct PreparedObject {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;       // DD9, world space
    std::vector<glm::vec3> face_normals;  // DD8, world space, per triangle
    std::vector<std::array<std::uint32_t, 3>> triangles;
    equations::MaterialT<float> material;
    Reflection reflection;
    Shading shading;
};

// Guard band: triangles are clipped at |x|, |y| ≤ guard_band · w, well outside
// the viewport, so fixed-point coordinates stay small while no pixel inside
// the viewport changes.
constexpr float guard_band = 2.0f;

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

template <Reflection R>
glm::vec3 light_at(std::span<const PreparedLight> lights, const equations::MaterialT<float>& m,
                   const glm::vec3& p, const glm::vec3& n, const glm::vec3& eye) {
    Vec3<float> position = to_vec3(p);
    Vec3<float> to_eye = equations::normalize(to_vec3(eye) - position);
    return to_glm(equations::shade_point<R>(lights, m, position, to_vec3(n), to_eye));
}

glm::vec3 light_with(Reflection reflection, std::span<const PreparedLight> lights,
                     const equations::MaterialT<float>& m, const glm::vec3& p, const glm::vec3& n,
                     const glm::vec3& eye) {
    switch (reflection) {
        case Reflection::Lambert: return light_at<Reflection::Lambert>(lights, m, p, n, eye);
        case Reflection::HalfLambert:
            return light_at<Reflection::HalfLambert>(lights, m, p, n, eye);
        case Reflection::Phong: return light_at<Reflection::Phong>(lights, m, p, n, eye);
        case Reflection::BlinnPhong: return light_at<Reflection::BlinnPhong>(lights, m, p, n, eye);
    }
    return {};
}

// Colour of one pixel value per channel for each intensity (SPEC §4). Gamma 1
// skips pow entirely.
struct PixelEncoder {
    float gamma;
    void operator()(const glm::vec3& intensity, std::uint8_t* out) const {
        out[0] = to_pixel(intensity.x, gamma);
        out[1] = to_pixel(intensity.y, gamma);
        out[2] = to_pixel(intensity.z, gamma);
    }
};

constexpr int band_height = 16;

}  // namespace

struct Renderer::Impl {
    Scene scene;
    RenderOptions options;
    ThreadPool pool;
    std::vector<PreparedLight> lights;
    std::vector<PreparedObject> objects;
    glm::mat4 view_projection{1.0f};

    // Per-frame scratch, kept between frames to avoid reallocating.
    std::vector<RasterTriangle> triangles;
    std::vector<std::vector<std::uint32_t>> bands;  // triangle indices per band
    std::vector<float> depth;                       // 1/w per pixel; 0 = nothing yet
    std::vector<std::vector<glm::vec3>> vertex_colors;  // Gouraud, per object

    Impl(const Scene& s, RenderOptions o) : scene(s), options(o), pool(o.threads) {}

    void prepare();
    void vertex_and_setup(int width, int height);
    void rasterize_band(int band, Image& image) const;
};

void Renderer::Impl::prepare() {
    for (const SceneLight& light : scene.lights) lights.push_back(equations::prepare_light(light.light));
    const Reflection scene_reflection = scene.reflection.value_or(options.fallback_reflection);
    const Shading scene_shading = scene.shading.value_or(options.fallback_shading);

    for (const SceneObject& object : scene.objects) {
        Mesh mesh = object_mesh(object);
        std::vector<glm::vec3> local_normals = vertex_normals(mesh);
        const glm::mat4 model = object_to_world(object);
        // Rotation only: scale is uniform and positive, so normals just rotate.
        const glm::mat3 rotation = glm::mat3(model) * (1.0f / object.scale);

        PreparedObject prepared;
        prepared.positions.reserve(mesh.positions.size());
        prepared.normals.reserve(mesh.positions.size());
        for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
            prepared.positions.push_back(glm::vec3(model * glm::vec4(mesh.positions[i], 1.0f)));
            glm::vec3 n = rotation * local_normals[i];
            float length = glm::length(n);
            prepared.normals.push_back(length > 0.0f ? n / length : n);
        }
        prepared.triangles = std::move(mesh.triangles);
        prepared.face_normals.reserve(prepared.triangles.size());
        for (const auto& t : prepared.triangles) {
            prepared.face_normals.push_back(face_normal(
                prepared.positions[t[0]], prepared.positions[t[1]], prepared.positions[t[2]]));
        }
        prepared.material = equations::splat<float>(object.material);
        prepared.reflection = object.reflection.value_or(scene_reflection);
        prepared.shading = object.shading.value_or(scene_shading);
        objects.push_back(std::move(prepared));
    }
}

void Renderer::Impl::vertex_and_setup(int width, int height) {
    const Observer& observer = scene.observer;
    const glm::vec3 eye = observer.position;
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    const glm::mat4 view = glm::lookAt(observer.position, observer.look_at, observer.up);
    const glm::mat4 projection =
        glm::perspective(glm::radians(observer.fov_degrees), aspect, observer.near, observer.far);
    view_projection = projection * view;

    // Vertex stage, Gouraud part: lighting at every vertex of Gouraud objects.
    vertex_colors.resize(objects.size());
    for (std::size_t o = 0; o < objects.size(); ++o) {
        const PreparedObject& object = objects[o];
        if (object.shading != Shading::Gouraud) continue;
        std::vector<glm::vec3>& colors = vertex_colors[o];
        colors.resize(object.positions.size());
        constexpr std::size_t chunk = 4096;
        pool.parallel_for((colors.size() + chunk - 1) / chunk, [&](std::size_t c) {
            std::size_t end = std::min(colors.size(), (c + 1) * chunk);
            for (std::size_t i = c * chunk; i < end; ++i)
                colors[i] = light_with(object.reflection, lights, object.material,
                                       object.positions[i], object.normals[i], eye);
        });
    }

    // Vertex, clip and setup stages, triangle by triangle.
    triangles.clear();
    const float half_width = 0.5f * static_cast<float>(width);
    const float half_height = 0.5f * static_cast<float>(height);
    for (std::size_t o = 0; o < objects.size(); ++o) {
        const PreparedObject& object = objects[o];
        const int varying_count = object.shading == Shading::Phong ? 6 : 3;
        for (std::size_t t = 0; t < object.triangles.size(); ++t) {
            const auto& indices = object.triangles[t];
            glm::vec3 flat_color{0.0f};
            if (object.shading == Shading::Flat) {
                const glm::vec3 centroid = (object.positions[indices[0]] +
                                            object.positions[indices[1]] +
                                            object.positions[indices[2]]) /
                                           3.0f;
                flat_color = light_with(object.reflection, lights, object.material, centroid,
                                        object.face_normals[t], eye);
            }
            std::array<ClipVertex, 3> corners;
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t v = indices[k];
                corners[k].clip = view_projection * glm::vec4(object.positions[v], 1.0f);
                corners[k].varyings.fill(0.0f);
                if (object.shading == Shading::Phong) {
                    const glm::vec3& p = object.positions[v];
                    const glm::vec3& n = object.normals[v];
                    corners[k].varyings = {p.x, p.y, p.z, n.x, n.y, n.z};
                } else if (object.shading == Shading::Gouraud) {
                    const glm::vec3& c = vertex_colors[o][v];
                    corners[k].varyings[0] = c.x;
                    corners[k].varyings[1] = c.y;
                    corners[k].varyings[2] = c.z;
                }
            }
            std::array<ClipVertex, 9> polygon;
            const int count = clip_triangle(corners, varying_count, polygon);
            // Fan the clipped polygon; every piece keeps the triangle's winding.
            for (int k = 1; k + 1 < count; ++k) {
                const ClipVertex* piece[3] = {&polygon[0], &polygon[k], &polygon[k + 1]};
                RasterTriangle raster;
                for (int m = 0; m < 3; ++m) {
                    const glm::vec4& c = piece[m]->clip;
                    const float inverse_w = 1.0f / c.w;
                    // Viewport: NDC x → [0, W] left to right, NDC y → [0, H] top to bottom.
                    const double window_x = (c.x * inverse_w + 1.0f) * half_width;
                    const double window_y = (1.0f - c.y * inverse_w) * half_height;
                    raster.x[m] = std::llround(window_x * static_cast<double>(subpixel_one));
                    raster.y[m] = std::llround(window_y * static_cast<double>(subpixel_one));
                    raster.inverse_w[m] = inverse_w;
                    raster.varyings[m] = piece[m]->varyings;
                }
                // Doubled signed area in y-down window coordinates: a triangle
                // counter-clockwise on screen (front-facing) has a negative one.
                const std::int64_t area = (raster.x[1] - raster.x[0]) * (raster.y[2] - raster.y[0]) -
                                          (raster.y[1] - raster.y[0]) * (raster.x[2] - raster.x[0]);
                if (area >= 0) continue;  // back face or zero area: culled
                std::swap(raster.x[1], raster.x[2]);
                std::swap(raster.y[1], raster.y[2]);
                std::swap(raster.inverse_w[1], raster.inverse_w[2]);
                std::swap(raster.varyings[1], raster.varyings[2]);

                // Pixel bounds: pixel i covers centres at i + 0.5.
                auto first_pixel = [](std::int64_t lo) {
                    return static_cast<int>((lo - subpixel_one / 2 + subpixel_one - 1) >> subpixel_bits);
                };
                auto last_pixel = [](std::int64_t hi) {
                    return static_cast<int>((hi - subpixel_one / 2) >> subpixel_bits);
                };
                const auto [min_x, max_x] = std::minmax({raster.x[0], raster.x[1], raster.x[2]});
                const auto [min_y, max_y] = std::minmax({raster.y[0], raster.y[1], raster.y[2]});
                raster.min_x = std::max(0, first_pixel(min_x));
                raster.max_x = std::min(width - 1, last_pixel(max_x));
                raster.min_y = std::max(0, first_pixel(min_y));
                raster.max_y = std::min(height - 1, last_pixel(max_y));
                if (raster.min_x > raster.max_x || raster.min_y > raster.max_y) continue;
                raster.flat_color = flat_color;
                raster.object = static_cast<std::uint32_t>(o);
                triangles.push_back(raster);
            }
        }
    }

    // Binning: each band of rows lists the triangles that may touch it.
    const int band_count = (height + band_height - 1) / band_height;
    bands.resize(static_cast<std::size_t>(band_count));
    for (auto& band : bands) band.clear();
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        const int first = triangles[t].min_y / band_height;
        const int last = triangles[t].max_y / band_height;
        for (int b = first; b <= last; ++b) bands[b].push_back(static_cast<std::uint32_t>(t));
    }
}

void Renderer::Impl::rasterize_band(int band, Image& image) const {
    const int width = image.width;
    const int row_begin = band * band_height;
    const int row_end = std::min(image.height, row_begin + band_height);
    const glm::vec3 eye = scene.observer.position;
    const PixelEncoder encode{scene.output.gamma};
    float* const depth_rows = const_cast<float*>(depth.data());

    // Clear the band: background colour as given (no gamma), depth "nothing".
    for (int y = row_begin; y < row_end; ++y) {
        for (int x = 0; x < width; ++x) {
            std::uint8_t* p = image.pixel(x, y);
            p[0] = scene.output.background[0];
            p[1] = scene.output.background[1];
            p[2] = scene.output.background[2];
            depth_rows[static_cast<std::size_t>(y) * width + x] = 0.0f;
        }
    }

    for (std::uint32_t index : bands[band]) {
        const RasterTriangle& tri = triangles[index];
        const PreparedObject& object = objects[tri.object];
        const int y0 = std::max(tri.min_y, row_begin);
        const int y1 = std::min(tri.max_y, row_end - 1);
        if (y0 > y1) continue;

        // Edge k is opposite vertex k: from vertex k+1 to vertex k+2.
        // E(p) = (b.x − a.x)(p.y − a.y) − (b.y − a.y)(p.x − a.x) ≥ 0 inside.
        std::array<std::int64_t, 3> step_x, step_y, origin;
        std::array<std::int64_t, 3> bias;
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
            // Top-left fill rule (in this winding): a pixel centre exactly on a
            // top or left edge belongs to the triangle, on others it does not.
            const bool top_left = dy < 0 || (dy == 0 && dx > 0);
            bias[k] = top_left ? 0 : -1;
        }
        const std::int64_t doubled_area =
            (tri.x[1] - tri.x[0]) * (tri.y[2] - tri.y[0]) - (tri.y[1] - tri.y[0]) * (tri.x[2] - tri.x[0]);
        const float inverse_area = 1.0f / static_cast<float>(doubled_area);

        for (int y = y0; y <= y1; ++y) {
            const std::int64_t row_offset = std::int64_t{y - y0};
            std::array<std::int64_t, 3> e;
            for (int k = 0; k < 3; ++k) e[k] = origin[k] + row_offset * step_y[k];
            float* depth_row = depth_rows + static_cast<std::size_t>(y) * width;
            for (int x = tri.min_x; x <= tri.max_x;
                 ++x, e[0] += step_x[0], e[1] += step_x[1], e[2] += step_x[2]) {
                if ((e[0] + bias[0]) < 0 || (e[1] + bias[1]) < 0 || (e[2] + bias[2]) < 0) continue;
                // Screen-space barycentrics, then perspective-correct weights.
                const float b0 = static_cast<float>(e[0]) * inverse_area;
                const float b1 = static_cast<float>(e[1]) * inverse_area;
                const float b2 = static_cast<float>(e[2]) * inverse_area;
                const float p0 = b0 * tri.inverse_w[0];
                const float p1 = b1 * tri.inverse_w[1];
                const float p2 = b2 * tri.inverse_w[2];
                const float inverse_w = p0 + p1 + p2;  // 1 / view depth, linear on screen
                // Depth test on 1/w: larger is nearer (orders like OpenGL's z).
                if (inverse_w <= depth_row[x]) continue;
                depth_row[x] = inverse_w;

                glm::vec3 color;
                if (object.shading == Shading::Flat) {
                    color = tri.flat_color;
                } else {
                    const float w = 1.0f / inverse_w;
                    const float q0 = p0 * w, q1 = p1 * w, q2 = p2 * w;
                    auto varying = [&](int k) {
                        return q0 * tri.varyings[0][k] + q1 * tri.varyings[1][k] +
                               q2 * tri.varyings[2][k];
                    };
                    if (object.shading == Shading::Gouraud) {
                        color = {varying(0), varying(1), varying(2)};
                    } else {
                        const glm::vec3 position{varying(0), varying(1), varying(2)};
                        const glm::vec3 normal =
                            glm::normalize(glm::vec3{varying(3), varying(4), varying(5)});
                        color = light_with(object.reflection, lights, object.material, position,
                                           normal, eye);
                    }
                }
                encode(color, image.pixel(x, y));
            }
        }
    }
}

Renderer::Renderer(const Scene& scene, RenderOptions options)
    : impl_(std::make_unique<Impl>(scene, options)) {
    impl_->prepare();
}

Renderer::~Renderer() = default;

std::size_t Renderer::triangle_count() const {
    std::size_t count = 0;
    for (const PreparedObject& object : impl_->objects) count += object.triangles.size();
    return count;
}

void Renderer::render_into(Image& image) {
    const int width = impl_->scene.output.width;
    const int height = impl_->scene.output.height;
    if (image.width != width || image.height != height) image = Image(width, height);
    impl_->depth.resize(static_cast<std::size_t>(width) * height);
    impl_->vertex_and_setup(width, height);
    impl_->pool.parallel_for(impl_->bands.size(), [&](std::size_t band) {
        impl_->rasterize_band(static_cast<int>(band), image);
    });
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
