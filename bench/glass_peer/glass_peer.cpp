// SPDX-License-Identifier: MIT
// litkit_glass_peer: the glass scene drawn the way a graphics programmer
// would with Intel Embree (Debian's libembree-dev 3.13), the peer of
// litkit's ray tree in bench/glass.sh. Every ray, the pixels' own included,
// goes through rtcIntersect1; the face rules of docs/spec.md §10.2 (rays in
// the room's medium hit front faces only, rays inside an object that
// object's back faces only) are an intersection-context filter; the tree is
// §10.2's (Snell, exact Fresnel, total internal reflection, Beer–Lambert,
// max_depth and the 2⁻¹⁰ path weight), in float, on T threads taking rows
// in turn. The scene's meshes and lights come from litkit's loader and its
// per-point lighting equations (litkit/equations.hpp: the same §4 model);
// everything that finds rays' hits is Embree's.
//
//   litkit_glass_peer SCENE.toml [--threads T] [--frames K] [-o PICTURE.png]
//
// Prints setup_ms (meshes, Embree's scene and hierarchy), median_frame_ms
// over K frames after a warm-up frame, the rays of one frame (primary and
// secondary) and the millions of rays per second.
#include <embree3/rtcore.h>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <thread>
#include <vector>

#include "litkit/equations.hpp"
#include "litkit/image.hpp"
#include "litkit/mesh.hpp"
#include "litkit/scene.hpp"

namespace {

using litkit::equations::Vec3;
constexpr unsigned none = RTC_INVALID_GEOMETRY_ID;

struct Object {
    std::vector<glm::vec3> positions, normals;
    std::vector<std::array<std::uint32_t, 3>> triangles;
    litkit::equations::MaterialT<float> material, no_specular;
    litkit::Reflection reflection;
    bool smooth;
    float transmission, ior, distance;
    glm::vec3 absorption;
};

// The face rules, through the intersection context: the object the ray
// travels in (none: the room's medium).
struct Context {
    RTCIntersectContext base;
    unsigned inside;
};

// Embree's geometric normal points one way or the other of litkit's
// (p1 − p0) × (p2 − p0); found once at start.
float embree_normal_sign = 1.0f;

void face_filter(const RTCFilterFunctionNArguments* args) {
    const Context* context = reinterpret_cast<const Context*>(args->context);
    RTCRayN* ray = args->ray;
    RTCHitN* hit = args->hit;
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] == 0) continue;
        const float d_ng =
            embree_normal_sign * (RTCRayN_dir_x(ray, args->N, i) * RTCHitN_Ng_x(hit, args->N, i) +
                                  RTCRayN_dir_y(ray, args->N, i) * RTCHitN_Ng_y(hit, args->N, i) +
                                  RTCRayN_dir_z(ray, args->N, i) * RTCHitN_Ng_z(hit, args->N, i));
        const bool keep = context->inside == none
                              ? d_ng < 0.0f
                              : RTCHitN_geomID(hit, args->N, i) == context->inside && d_ng > 0.0f;
        if (!keep) args->valid[i] = 0;
    }
}

struct Peer {
    std::vector<Object> objects;
    std::vector<litkit::equations::PreparedLight> lights;
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    float room_ior = 1.0f, min_distance = 0.0f;
    int max_depth = 8;
    glm::vec3 background{0.0f};

    struct Hit {
        unsigned object = none;
        unsigned triangle = 0;
        float t = 0.0f, u = 0.0f, v = 0.0f;
    };

    Hit intersect(const glm::vec3& origin, const glm::vec3& direction, float t_min, unsigned inside,
                  std::uint64_t& rays) const {
        ++rays;
        Context context;
        rtcInitIntersectContext(&context.base);
        context.base.filter = face_filter;
        context.inside = inside;
        RTCRayHit rh{};
        rh.ray.org_x = origin.x, rh.ray.org_y = origin.y, rh.ray.org_z = origin.z;
        rh.ray.dir_x = direction.x, rh.ray.dir_y = direction.y, rh.ray.dir_z = direction.z;
        rh.ray.tnear = t_min;
        rh.ray.tfar = std::numeric_limits<float>::infinity();
        rh.ray.mask = ~0u;
        rh.hit.geomID = none;
        rtcIntersect1(scene, &context.base, &rh);
        return {rh.hit.geomID, rh.hit.primID, rh.ray.tfar, rh.hit.u, rh.hit.v};
    }

    glm::vec3 shade(const Object& o, const litkit::equations::MaterialT<float>& material,
                    const glm::vec3& p, const glm::vec3& n, const glm::vec3& v) const {
        const Vec3<float> color = litkit::equations::with_reflection(o.reflection, [&](auto model) {
            return litkit::equations::shade_point<decltype(model)::value>(
                lights, material, {p.x, p.y, p.z}, {n.x, n.y, n.z}, {v.x, v.y, v.z});
        });
        return {color.x, color.y, color.z};
    }

    // L of a ray (docs/spec.md §10.2 item 8); `weight` the product of the
    // factors in front of it.
    glm::vec3 radiance(const glm::vec3& origin, const glm::vec3& d, int depth,
                       const glm::vec3& weight, unsigned inside, std::uint64_t& rays) const {
        if (depth > max_depth || std::max({weight.x, weight.y, weight.z}) < 1.0f / 1024.0f)
            return glm::vec3(0.0f);
        return shade_hit(d, depth, weight, inside, intersect(origin, d, min_distance, inside, rays),
                         rays);
    }

    // L of a ray that found `hit` (or none).
    glm::vec3 shade_hit(const glm::vec3& d, int depth, const glm::vec3& weight, unsigned inside,
                        const Hit& hit, std::uint64_t& rays) const {
        if (hit.object == none) return inside == none ? background : glm::vec3(0.0f);
        const Object& o = objects[hit.object];
        const auto& c = o.triangles[hit.triangle];
        const float w0 = 1.0f - hit.u - hit.v;
        const glm::vec3 p =
            w0 * o.positions[c[0]] + hit.u * o.positions[c[1]] + hit.v * o.positions[c[2]];
        const glm::vec3 face = glm::normalize(glm::cross(o.positions[c[1]] - o.positions[c[0]],
                                                         o.positions[c[2]] - o.positions[c[0]]));
        glm::vec3 n = face;
        if (o.smooth) {
            const glm::vec3 m =
                w0 * o.normals[c[0]] + hit.u * o.normals[c[1]] + hit.v * o.normals[c[2]];
            if (glm::length(m) > 0.0f) n = glm::normalize(m);
        }
        const bool entering = inside == none;
        if (entering && o.transmission <= 0.0f) return shade(o, o.material, p, n, -d);
        glm::vec3 own(0.0f), through(1.0f), w = weight;
        float share = 1.0f;
        if (entering) {
            const glm::vec3 ad = shade(o, o.no_specular, p, n, -d);
            own = (1.0f - o.transmission) * ad + (shade(o, o.material, p, n, -d) - ad);
            share = o.transmission;
        } else {
            for (int k = 0; k < 3; ++k)
                through[k] = hit.t > 0.0f ? (o.absorption[k] > 0.0f
                                                 ? std::pow(o.absorption[k], hit.t / o.distance)
                                                 : 0.0f)
                                          : 1.0f;
            w *= through;
        }
        // Snell and Fresnel (items 2–6).
        const float eta = entering ? room_ior / o.ior : o.ior / room_ior;
        const float side = entering ? 1.0f : -1.0f;
        auto interface = [&](const glm::vec3& normal, glm::vec3& r, glm::vec3& t, float& f) {
            const float c1 = -glm::dot(d, normal);
            const float k = 1.0f - eta * eta * (1.0f - c1 * c1);
            r = d + 2.0f * c1 * normal;
            if (k <= 0.0f) {
                f = 1.0f;
                return true;
            }
            const float c2 = std::sqrt(k);
            t = eta * d + (eta * c1 - c2) * normal;
            const float rs = (eta * c1 - c2) / (eta * c1 + c2);
            const float rp = (c1 - eta * c2) / (c1 + eta * c2);
            f = 0.5f * (rs * rs + rp * rp);
            return false;
        };
        glm::vec3 r(0.0f), t(0.0f);
        float f = 1.0f;
        glm::vec3 normal = side * n;
        bool tir;
        if (-glm::dot(d, normal) <= 0.0f) {
            tir = interface(side * face, r, t, f);
        } else {
            tir = interface(normal, r, t, f);
            const float dn = glm::dot(d, face);
            const float tn = glm::dot(t, face), rn = glm::dot(r, face);
            const bool crosses = tir || (tn > 0.0f && dn > 0.0f) || (tn < 0.0f && dn < 0.0f);
            const bool back = (rn > 0.0f && dn < 0.0f) || (rn < 0.0f && dn > 0.0f);
            if (!crosses || !back) tir = interface(side * face, r, t, f);
        }
        glm::vec3 light(0.0f);
        if (f > 0.0f)
            light += f * radiance(p, glm::normalize(r), depth + 1, w * (share * f), inside, rays);
        if (!tir)
            light +=
                (1.0f - f) * radiance(p, glm::normalize(t), depth + 1, w * (share * (1.0f - f)),
                                      entering ? hit.object : none, rays);
        return entering ? own + share * light : through * light;
    }
};

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s SCENE.toml [--threads T] [--frames K] [-o PICTURE.png]\n",
                     argv[0]);
        return 2;
    }
    int threads = 2, frames = 10;
    std::string output;
    for (int i = 2; i + 1 < argc; i += 2) {
        const std::string flag = argv[i];
        if (flag == "--threads")
            threads = std::atoi(argv[i + 1]);
        else if (flag == "--frames")
            frames = std::atoi(argv[i + 1]);
        else if (flag == "-o")
            output = argv[i + 1];
    }
    using clock = std::chrono::steady_clock;
    const auto setup_start = clock::now();
    const std::filesystem::path path = argv[1];
    const litkit::Scene scene = litkit::load_scene(std::span(&path, 1));
    Peer peer;
    for (const litkit::SceneLight& light : scene.lights)
        peer.lights.push_back(litkit::equations::prepare_light(light.light));
    const litkit::Reflection reflection = scene.reflection.value_or(litkit::Reflection::Phong);
    const litkit::Shading shading = scene.shading.value_or(litkit::Shading::Phong);
    for (const litkit::SceneObject& object : scene.objects) {
        litkit::WorldMesh mesh = litkit::world_mesh(object, litkit::normal_options(scene, object));
        Object o;
        o.positions = std::move(mesh.positions);
        o.normals = std::move(mesh.normals);
        o.triangles = std::move(mesh.triangles);
        o.material = litkit::equations::splat<float>(object.material);
        o.no_specular = o.material;
        o.no_specular.ks = 0.0f;
        o.reflection = object.reflection.value_or(reflection);
        const litkit::Shading s = object.shading.value_or(shading);
        o.smooth = s == litkit::Shading::Phong || s == litkit::Shading::Gouraud;
        o.transmission = object.material.transmission;
        o.ior = object.material.ior;
        o.absorption = object.material.absorption_color;
        o.distance = object.material.absorption_distance;
        peer.objects.push_back(std::move(o));
    }
    peer.room_ior = scene.room.ior;
    peer.max_depth = scene.max_depth;
    const litkit::Room& room = scene.room;
    peer.min_distance = 1e-6f * std::sqrt(room.width * room.width + room.height * room.height +
                                          room.depth * room.depth);
    for (int k = 0; k < 3; ++k)
        peer.background[k] = std::pow(scene.output.background[k], scene.output.gamma);

    peer.device = rtcNewDevice(("threads=" + std::to_string(threads)).c_str());
    // Which way Embree's normal points, from one triangle of litkit's winding.
    {
        RTCScene probe = rtcNewScene(peer.device);
        RTCGeometry g = rtcNewGeometry(peer.device, RTC_GEOMETRY_TYPE_TRIANGLE);
        float* v = static_cast<float*>(rtcSetNewGeometryBuffer(
            g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 3));
        const float corners[9] = {-1, -1, 0, 1, -1, 0, 0, 1, 0};  // normal +z by the winding
        std::memcpy(v, corners, sizeof corners);
        unsigned* index = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
            g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), 1));
        index[0] = 0, index[1] = 1, index[2] = 2;
        rtcCommitGeometry(g);
        rtcAttachGeometry(probe, g);
        rtcReleaseGeometry(g);
        rtcCommitScene(probe);
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRayHit rh{};
        rh.ray.org_z = 5.0f, rh.ray.dir_z = -1.0f, rh.ray.tfar = 100.0f, rh.ray.mask = ~0u;
        rh.hit.geomID = none;
        rtcIntersect1(probe, &context, &rh);
        embree_normal_sign = rh.hit.Ng_z > 0.0f ? 1.0f : -1.0f;
        rtcReleaseScene(probe);
    }
    peer.scene = rtcNewScene(peer.device);
    rtcSetSceneFlags(peer.scene, RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);
    for (std::size_t i = 0; i < peer.objects.size(); ++i) {
        const Object& o = peer.objects[i];
        RTCGeometry g = rtcNewGeometry(peer.device, RTC_GEOMETRY_TYPE_TRIANGLE);
        float* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0,
                                                               RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                               o.positions.size()));
        std::memcpy(v, o.positions.data(), o.positions.size() * sizeof(glm::vec3));
        unsigned* index = static_cast<unsigned*>(
            rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                    3 * sizeof(unsigned), o.triangles.size()));
        std::memcpy(index, o.triangles.data(), o.triangles.size() * 3 * sizeof(unsigned));
        rtcCommitGeometry(g);
        rtcAttachGeometryByID(peer.scene, g, static_cast<unsigned>(i));
        rtcReleaseGeometry(g);
    }
    rtcCommitScene(peer.scene);
    const double setup_ms =
        std::chrono::duration<double, std::milli>(clock::now() - setup_start).count();

    // The pixels' rays (docs/spec.md §1).
    const int width = scene.output.width, height = scene.output.height;
    const litkit::Observer& eye = scene.observer;
    const glm::vec3 forward = glm::normalize(eye.look_at - eye.position);
    const glm::vec3 right = glm::normalize(glm::cross(forward, eye.up));
    const glm::vec3 up = glm::cross(right, forward);
    const float tan_half = std::tan(glm::radians(eye.fov_degrees) * 0.5f);
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    litkit::Image image(width, height);
    std::atomic<std::uint64_t> frame_rays{0};
    auto draw = [&] {
        std::atomic<int> next_row{0};
        frame_rays = 0;
        auto work = [&] {
            std::uint64_t rays = 0;
            for (int y; (y = next_row.fetch_add(1)) < height;) {
                const float sy = 1.0f - 2.0f * (static_cast<float>(y) + 0.5f) / height;
                std::uint8_t* row = image.pixel(0, y);
                for (int x = 0; x < width; ++x) {
                    const float sx = 2.0f * (static_cast<float>(x) + 0.5f) / width - 1.0f;
                    const glm::vec3 d = glm::normalize(forward + (sx * tan_half * aspect) * right +
                                                       (sy * tan_half) * up);
                    // A pixel that sees nothing shows the background without gamma.
                    const Peer::Hit first = peer.intersect(eye.position, d, 0.0f, none, rays);
                    if (first.object == none) {
                        const litkit::Rgb8 bg = litkit::to_rgb8(scene.output.background);
                        row[3 * x] = bg[0], row[3 * x + 1] = bg[1], row[3 * x + 2] = bg[2];
                        continue;
                    }
                    const glm::vec3 l = peer.shade_hit(d, 1, glm::vec3(1.0f), none, first, rays);
                    for (int k = 0; k < 3; ++k)
                        row[3 * x + k] = static_cast<std::uint8_t>(
                            std::lround(255.0f * std::pow(std::clamp(l[k], 0.0f, 1.0f),
                                                          1.0f / scene.output.gamma)));
                }
            }
            frame_rays += rays;
        };
        std::vector<std::thread> pool;
        for (int t = 1; t < threads; ++t) pool.emplace_back(work);
        work();
        for (std::thread& t : pool) t.join();
    };
    draw();  // warm-up
    std::vector<double> times;
    for (int f = 0; f < frames; ++f) {
        const auto start = clock::now();
        draw();
        times.push_back(std::chrono::duration<double, std::milli>(clock::now() - start).count());
    }
    std::sort(times.begin(), times.end());
    const double median = times[times.size() / 2];
    std::printf("setup_ms %.2f\nmedian_frame_ms %.2f\nrays %llu\nmrays_per_s %.2f\n", setup_ms,
                median, static_cast<unsigned long long>(frame_rays.load()),
                static_cast<double>(frame_rays.load()) / (median * 1e3));
    if (!output.empty()) litkit::write_png(image, output);
    rtcReleaseScene(peer.scene);
    rtcReleaseDevice(peer.device);
    return 0;
}
