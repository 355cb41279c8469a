// SPDX-License-Identifier: MIT
// An independent reference for pictures with glass (docs/spec.md §10.2): a
// Whitted ray tracer in double precision, written from the specification's
// formulas, to check the CPU renderer's pictures against (tests/test_glass.cpp).
//
// It takes from the library only what other suites test: the objects'
// triangles and vertex normals in world space (litkit::world_mesh with
// litkit::normal_options) and the colour I of a reflection model at a point
// (litkit::shade, §4 and §9). Everything of §10 is computed here: the camera
// rays (§1), the nearest hit (Möller–Trumbore in double, over every triangle),
// the face rules (rays in the room's medium hit front faces, rays inside an
// object its back faces), the side, Snell's law, the mirror, exact Fresnel,
// total internal reflection, the guard of item 6, Beer–Lambert, the stopping
// rules of item 9, the split of I into I_ad and I_s (I_s computed here, from
// §4's and §9.1's specular terms) and the first hit's shading model. Nothing
// of src/trace/ or litkit/refraction.hpp is used.
#pragma once

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <variant>
#include <vector>

#include "litkit/lighting.hpp"
#include "litkit/scene.hpp"

namespace glass_reference {

using glm::dvec3;

inline dvec3 to_double(const glm::vec3& v) { return {double(v.x), double(v.y), double(v.z)}; }
inline glm::vec3 to_float(const dvec3& v) { return {float(v.x), float(v.y), float(v.z)}; }
inline double largest(const dvec3& v) { return std::max({v.x, v.y, v.z}); }

// One object in world space, with what §10.2 needs of it.
struct Object {
    std::vector<dvec3> positions;
    std::vector<dvec3> normals;  // per vertex (DD9, §9.2), unit or zero
    std::vector<std::array<std::uint32_t, 3>> triangles;
    std::vector<dvec3> face_normals;  // DD8, from the winding, computed here
    litkit::Material material;
    litkit::Reflection reflection = litkit::Reflection::Phong;
    litkit::Shading shading = litkit::Shading::Phong;
    // Bounding spheres, to skip what a ray misses: the object's, and those
    // of runs of `chunk` consecutive triangles (the shapes make their
    // triangles strip by strip, so a run lies close together).
    dvec3 centre{0.0};
    double radius = 0.0;
    static constexpr std::size_t chunk = 16;
    std::vector<dvec3> chunk_centres;
    std::vector<double> chunk_radii;
};

// Whether the line through `origin` along the unit `direction` passes
// within `radius` of `centre` (with a margin: only ever a false yes).
inline bool passes_near(const dvec3& origin, const dvec3& direction, const dvec3& centre,
                        double radius) {
    const dvec3 to_centre = centre - origin;
    const double along = glm::dot(to_centre, direction);
    const double miss2 = glm::dot(to_centre, to_centre) - along * along;
    return miss2 <= radius * radius * 1.0001 + 1e-12;
}

struct Hit {
    double t = std::numeric_limits<double>::infinity();
    int object = -1;
    long triangle = -1;
    double b1 = 0.0, b2 = 0.0;  // barycentric weights of corners 1 and 2
    bool found() const { return object >= 0; }
};

// What one pixel's tree gave, and how many rays it took.
struct PixelResult {
    int object = -1;  // the first hit's object; −1: background
    dvec3 light{0.0};
    std::array<std::uint8_t, 3> rgb{};
    int rays = 0;  // rays traced (depth and weight within the limits)
};

class Tracer {
  public:
    explicit Tracer(const litkit::Scene& scene) : scene_(scene) {
        for (const litkit::SceneLight& light : scene.lights) lights_.push_back(light.light);
        for (const litkit::SceneObject& object : scene.objects) add(object);
        const litkit::Room& room = scene.room;
        min_distance_ =
            1e-6 * std::sqrt(double(room.width) * room.width + double(room.height) * room.height +
                             double(room.depth) * room.depth);
        const double gamma = scene.output.gamma;
        const dvec3 bg = to_double(scene.output.background);
        background_ = {std::pow(bg.x, gamma), std::pow(bg.y, gamma), std::pow(bg.z, gamma)};
        eye_ = to_double(scene.observer.position);
        forward_ = glm::normalize(to_double(scene.observer.look_at) - eye_);
        right_ = glm::normalize(glm::cross(forward_, to_double(scene.observer.up)));
        up_ = glm::cross(right_, forward_);
    }

    // The §1 ray through (i + sx, j + sy) (the centre by default; a sample
    // of §11 otherwise), scaled so that its component along the view
    // direction is 1 (its parameter is the view depth).
    dvec3 camera_ray(int i, int j, double sx = 0.5, double sy = 0.5) const {
        const int width = scene_.output.width, height = scene_.output.height;
        const double tan_half = std::tan(double(scene_.observer.fov_degrees) * pi / 360.0);
        const double aspect = double(width) / double(height);
        const double x = 2.0 * (i + sx) / width - 1.0;
        const double y = 1.0 - 2.0 * (j + sy) / height;
        return x * tan_half * aspect * right_ + y * tan_half * up_ + forward_;
    }

    // Pixel (i, j) with the scene's samples (§11): the mean of the samples'
    // clamped light, then gamma; `light` is that mean, `object` the first
    // sample's.
    PixelResult supersampled(int i, int j) const {
        PixelResult result;
        const auto pattern = litkit::sample_pattern(scene_.output.samples);
        bool first = true;
        for (const litkit::SamplePosition& sample : pattern) {
            const PixelResult one = pixel(i, j, sample.x, sample.y);
            if (first) result.object = one.object;
            first = false;
            result.rays += one.rays;
            const dvec3 light = one.object < 0 ? background_ : glm::clamp(one.light, 0.0, 1.0);
            result.light += light / double(pattern.size());
        }
        const double gamma = scene_.output.gamma;
        for (int c = 0; c < 3; ++c)
            result.rgb[c] = static_cast<std::uint8_t>(
                std::lround(255.0 * std::pow(result.light[c], 1.0 / gamma)));
        return result;
    }

    PixelResult pixel(int i, int j, double sx = 0.5, double sy = 0.5) const {
        PixelResult result;
        const dvec3 ray = camera_ray(i, j, sx, sy);
        const Hit hit =
            nearest(eye_, ray, -1, double(scene_.observer.near), double(scene_.observer.far));
        if (!hit.found()) {
            const glm::vec3& bg = scene_.output.background;  // as given, no gamma
            for (int c = 0; c < 3; ++c)
                result.rgb[c] = static_cast<std::uint8_t>(std::lround(255.0 * bg[c]));
            return result;
        }
        result.object = hit.object;
        const Object& o = objects_[hit.object];
        const dvec3 d = glm::normalize(ray);
        const dvec3 p = eye_ + hit.t * ray;
        const auto& tri = o.triangles[hit.triangle];
        const double w0 = 1.0 - hit.b1 - hit.b2;
        const dvec3 ng = o.face_normals[hit.triangle];
        // The local colour by the shading model (§3): I and its I_s.
        Local local;
        switch (o.shading) {
            case litkit::Shading::Flat: {
                const dvec3 centroid =
                    (o.positions[tri[0]] + o.positions[tri[1]] + o.positions[tri[2]]) / 3.0;
                local = lit(o, centroid, ng, eye_);
                break;
            }
            case litkit::Shading::Gouraud:
                for (int k = 0; k < 3; ++k) {
                    const double w = k == 0 ? w0 : k == 1 ? hit.b1 : hit.b2;
                    const Local at = lit(o, o.positions[tri[k]], o.normals[tri[k]], eye_);
                    local.all += w * at.all;
                    local.specular += w * at.specular;
                }
                break;
            case litkit::Shading::Phong:
            case litkit::Shading::Faceted:
                local = lit(o, p, shading_normal(o, hit), eye_);
                break;
        }
        const double t = o.material.transmission;
        int rays = 1;
        if (t > 0.0) {
            // §10.2 item 8, with the bracket per pixel at p with N_s.
            const dvec3 ad = local.all - local.specular;
            result.light = (1.0 - t) * ad + local.specular +
                           t * bracket(o, hit.object, p, d, ng, shading_normal(o, hit), true, 1,
                                       dvec3(t), rays);
        } else {
            result.light = local.all;
        }
        result.rays = rays;
        const double gamma = scene_.output.gamma;
        for (int c = 0; c < 3; ++c)
            result.rgb[c] = static_cast<std::uint8_t>(
                std::lround(255.0 * std::pow(std::clamp(result.light[c], 0.0, 1.0), 1.0 / gamma)));
        return result;
    }

  private:
    static constexpr double pi = 3.14159265358979323846;
    static constexpr double least_weight = 1.0 / 1024.0;  // 2⁻¹⁰

    struct Local {
        dvec3 all{0.0};       // I
        dvec3 specular{0.0};  // I_s
    };

    void add(const litkit::SceneObject& object) {
        const litkit::WorldMesh mesh =
            litkit::world_mesh(object, litkit::normal_options(scene_, object));
        Object o;
        for (const glm::vec3& p : mesh.positions) o.positions.push_back(to_double(p));
        for (const glm::vec3& n : mesh.normals) o.normals.push_back(to_double(n));
        o.triangles = mesh.triangles;
        for (const auto& t : o.triangles) {
            const dvec3 cross = glm::cross(o.positions[t[1]] - o.positions[t[0]],
                                           o.positions[t[2]] - o.positions[t[0]]);
            const double length = glm::length(cross);
            o.face_normals.push_back(length > 0.0 ? cross / length : dvec3(0.0));
        }
        o.material = object.material;
        o.reflection =
            object.reflection.value_or(scene_.reflection.value_or(litkit::default_reflection));
        o.shading = object.shading.value_or(scene_.shading.value_or(litkit::default_shading));
        for (const dvec3& p : o.positions) o.centre += p;
        o.centre /= double(o.positions.size());
        for (const dvec3& p : o.positions) o.radius = std::max(o.radius, glm::length(p - o.centre));
        for (std::size_t first = 0; first < o.triangles.size(); first += Object::chunk) {
            const std::size_t last = std::min(first + Object::chunk, o.triangles.size());
            dvec3 centre(0.0);
            for (std::size_t k = first; k < last; ++k)
                for (std::uint32_t v : o.triangles[k]) centre += o.positions[v];
            centre /= 3.0 * double(last - first);
            double radius = 0.0;
            for (std::size_t k = first; k < last; ++k)
                for (std::uint32_t v : o.triangles[k])
                    radius = std::max(radius, glm::length(o.positions[v] - centre));
            o.chunk_centres.push_back(centre);
            o.chunk_radii.push_back(radius);
        }
        objects_.push_back(std::move(o));
    }

    // N_s: the renormalised interpolated vertex normal (phong, gouraud), else N_g.
    static dvec3 shading_normal(const Object& o, const Hit& hit) {
        const dvec3 ng = o.face_normals[hit.triangle];
        if (o.shading == litkit::Shading::Flat || o.shading == litkit::Shading::Faceted) return ng;
        const auto& tri = o.triangles[hit.triangle];
        const dvec3 mixed = (1.0 - hit.b1 - hit.b2) * o.normals[tri[0]] +
                            hit.b1 * o.normals[tri[1]] + hit.b2 * o.normals[tri[2]];
        const double length = glm::length(mixed);
        return length > 0.0 ? mixed / length : ng;
    }

    // I at p (litkit::shade: §4, §9), and I_s = Σ f·I_L·k_s·S computed here.
    Local lit(const Object& o, const dvec3& p, const dvec3& n, const dvec3& eye) const {
        Local local;
        local.all = to_double(litkit::shade(o.reflection, o.material, lights_, to_float(p),
                                            to_float(n), to_float(eye)));
        const dvec3 v = glm::normalize(eye - p);
        const double ks = o.material.ks, alpha = o.material.shininess;
        for (const litkit::Light& light : lights_) {
            dvec3 l;
            double f = 1.0;
            if (const auto* directional = std::get_if<litkit::DirectionalLight>(&light.kind)) {
                l = -glm::normalize(to_double(directional->direction));
            } else if (const auto* point = std::get_if<litkit::PointLight>(&light.kind)) {
                const dvec3 offset = to_double(point->position) - p;
                const double dist = glm::length(offset);
                l = offset / dist;
                const dvec3 k = to_double(point->attenuation);
                f = 1.0 / (k.x + k.y * dist + k.z * dist * dist);
            } else if (std::holds_alternative<litkit::AmbientLight>(light.kind)) {
                continue;
            } else {
                throw std::logic_error("glass_reference: spot lights are not modelled");
            }
            const double nl = glm::dot(n, l);
            if (nl <= 0.0) continue;  // S = 0 where N·L ≤ 0 (every model used here)
            double s = 0.0;
            switch (o.reflection) {
                case litkit::Reflection::Phong:
                case litkit::Reflection::Gooch: {
                    const double base = glm::dot(2.0 * nl * n - l, v);
                    if (base > 0.0) s = std::pow(base, alpha);
                    break;
                }
                case litkit::Reflection::BlinnPhong: {
                    const double base = glm::dot(n, glm::normalize(l + v));
                    if (base > 0.0) s = std::pow(base, alpha);
                    break;
                }
                case litkit::Reflection::Toon: {
                    const double nh = std::max(glm::dot(n, glm::normalize(l + v)), 0.0);
                    s = (alpha == 0.0 ? 1.0 : std::pow(nh, alpha)) >= 0.5 ? 1.0 : 0.0;
                    break;
                }
                case litkit::Reflection::Lambert:
                case litkit::Reflection::HalfLambert:
                case litkit::Reflection::OrenNayar:
                case litkit::Reflection::Minnaert:
                    break;
                default:
                    throw std::logic_error("glass_reference: reflection model not modelled");
            }
            local.specular += f * to_double(light.radiance()) * (ks * s);
        }
        return local;
    }

    // Items 2–6 at one interface: the ray's unit direction d, the outward
    // unit normals N_s and N_g, the side and η = n₁/n₂.
    struct Interface {
        dvec3 reflected{0.0}, refracted{0.0};
        double fresnel = 1.0;
        bool tir = false;
    };
    static Interface bend(const dvec3& d, const dvec3& ns, const dvec3& ng, bool entering,
                          double eta) {
        const double side = entering ? 1.0 : -1.0;
        const dvec3 n = side * ns;
        if (-glm::dot(d, n) <= 0.0) return snell(d, side * ng, eta);  // item 2
        const Interface with_ns = snell(d, n, eta);
        // Item 6: sign(T·N_g) = sign(d·N_g) (without TIR), sign(R·N_g) = −sign(d·N_g).
        const double dn = glm::dot(d, ng);
        const bool crosses = with_ns.tir || glm::dot(with_ns.refracted, ng) * dn > 0.0;
        const bool stays = glm::dot(with_ns.reflected, ng) * dn < 0.0;
        return crosses && stays ? with_ns : snell(d, side * ng, eta);
    }

    // Items 3–5 with the unit normal n facing the ray.
    static Interface snell(const dvec3& d, const dvec3& n, double eta) {
        Interface result;
        const double c1 = -glm::dot(d, n);
        result.reflected = d + 2.0 * c1 * n;
        const double k = 1.0 - eta * eta * (1.0 - c1 * c1);
        if (k <= 0.0) {
            result.tir = true;
            result.fresnel = 1.0;
            return result;
        }
        const double c2 = std::sqrt(k);
        result.refracted = eta * d + (eta * c1 - c2) * n;
        const double rs = (eta * c1 - c2) / (eta * c1 + c2);
        const double rp = (c1 - eta * c2) / (c1 + eta * c2);
        result.fresnel = (rs * rs + rp * rp) / 2.0;
        return result;
    }

    // The nearest hit along origin + t·ray, t in [t_min, t_max]: front faces
    // of every object from the room's medium (inside < 0), else the back
    // faces of object `inside`. Möller–Trumbore; a hair of slack on the edges
    // so that shared edges leave no crack.
    Hit nearest(const dvec3& origin, const dvec3& ray, int inside, double t_min,
                double t_max) const {
        constexpr double slack = 1e-10;
        Hit best;
        best.t = t_max;
        const dvec3 unit = glm::normalize(ray);
        for (std::size_t index = 0; index < objects_.size(); ++index) {
            if (inside >= 0 && int(index) != inside) continue;
            const Object& o = objects_[index];
            if (!passes_near(origin, unit, o.centre, o.radius)) continue;
            for (std::size_t k = 0; k < o.triangles.size(); ++k) {
                if (k % Object::chunk == 0 &&
                    !passes_near(origin, unit, o.chunk_centres[k / Object::chunk],
                                 o.chunk_radii[k / Object::chunk])) {
                    k += Object::chunk - 1;
                    continue;
                }
                const double facing = glm::dot(ray, o.face_normals[k]);
                if (inside < 0 ? !(facing < 0.0) : !(facing > 0.0)) continue;
                const auto& tri = o.triangles[k];
                const dvec3& a = o.positions[tri[0]];
                const dvec3 e1 = o.positions[tri[1]] - a, e2 = o.positions[tri[2]] - a;
                const dvec3 pv = glm::cross(ray, e2);
                const double det = glm::dot(e1, pv);
                if (det == 0.0) continue;
                const double inverse = 1.0 / det;
                const dvec3 s = origin - a;
                const double u = glm::dot(s, pv) * inverse;
                if (u < -slack || u > 1.0 + slack) continue;
                const dvec3 q = glm::cross(s, e1);
                const double v = glm::dot(ray, q) * inverse;
                if (v < -slack || u + v > 1.0 + slack) continue;
                const double t = glm::dot(e2, q) * inverse;
                if (t < t_min || t > best.t) continue;
                best = {t, int(index), long(k), u, v};
            }
        }
        if (best.triangle < 0) best.t = std::numeric_limits<double>::infinity();
        return best;
    }

    // L of a ray (item 8), or 0 when item 9 stops it. `inside`: the object it
    // travels in, −1 for the room's medium.
    dvec3 radiance(const dvec3& origin, const dvec3& d, int inside, int depth, const dvec3& weight,
                   int& rays) const {
        if (depth > scene_.max_depth || largest(weight) < least_weight) return dvec3(0.0);
        ++rays;
        const Hit hit =
            nearest(origin, d, inside, min_distance_, std::numeric_limits<double>::infinity());
        if (!hit.found()) return inside < 0 ? background_ : dvec3(0.0);
        const Object& o = objects_[hit.object];
        const dvec3 p = origin + hit.t * d;
        const dvec3 ng = o.face_normals[hit.triangle];
        const dvec3 ns = shading_normal(o, hit);
        const double t = o.material.transmission;
        if (inside < 0) {
            const Local local = lit(o, p, ns, p - d);  // V = −d
            if (!(t > 0.0)) return local.all;
            return (1.0 - t) * (local.all - local.specular) + local.specular +
                   t * bracket(o, hit.object, p, d, ng, ns, true, depth, weight * t, rays);
        }
        // Inside: Beer–Lambert over ℓ = hit.t (item 7), in the weights beyond.
        const dvec3 a = to_double(o.material.absorption_color);
        const double x = hit.t / double(o.material.absorption_distance);
        const dvec3 absorbed{absorb(a.x, x), absorb(a.y, x), absorb(a.z, x)};
        return absorbed *
               bracket(o, hit.object, p, d, ng, ns, false, depth, weight * absorbed, rays);
    }

    static double absorb(double a, double x) {
        if (x == 0.0) return 1.0;
        return a == 0.0 ? 0.0 : std::pow(a, x);
    }

    // F·L(R) + (1 − F)·L(T) at an interface of object `index` met at depth
    // `depth`; `weight`: the factors in front of the bracket.
    dvec3 bracket(const Object& o, int index, const dvec3& p, const dvec3& d, const dvec3& ng,
                  const dvec3& ns, bool entering, int depth, const dvec3& weight, int& rays) const {
        const double n_room = scene_.room.ior, n_object = o.material.ior;
        const double eta = entering ? n_room / n_object : n_object / n_room;
        const Interface at = bend(d, ns, ng, entering, eta);
        const int side = entering ? -1 : index;  // where R travels
        dvec3 sum = at.fresnel * radiance(p, glm::normalize(at.reflected), side, depth + 1,
                                          weight * at.fresnel, rays);
        if (!at.tir) {
            sum += (1.0 - at.fresnel) * radiance(p, glm::normalize(at.refracted),
                                                 entering ? index : -1, depth + 1,
                                                 weight * (1.0 - at.fresnel), rays);
        }
        return sum;
    }

    const litkit::Scene& scene_;
    std::vector<litkit::Light> lights_;
    std::vector<Object> objects_;
    double min_distance_ = 0.0;
    dvec3 background_{0.0};
    dvec3 eye_{0.0}, forward_{0.0}, right_{0.0}, up_{0.0};
};

}  // namespace glass_reference
