// SPDX-License-Identifier: MIT
// Image tests of the CPU renderer (litkit::render) against an independent
// reference: a small ray caster in double precision over the same triangles.
//
// The reference takes nothing from the library but the local triangles of the
// objects (make_sphere, make_cube, make_torus for the built-in shapes, and
// object_mesh for teapots and mesh files; meshes have their own tests). The
// world transform (docs/spec.md §2), face and vertex normals (DD8, DD9, and
// §9.2: weightings, creases, a mesh file's normals),
// camera rays (§1), shading models (§3, and §9.2's faceted: the face normal
// at the hit point) and lighting (§4) are all computed
// here, by hand, in double, for a whole scene: the nearest hit over all
// objects, each with its own reflection and shading (or [lighting]'s).
//
// Besides hand-made scenes, every scene in examples/ is compared with the
// renderer at a small size, within 1/255 (RenderMatchesReferenceExample).
//
// Pixels next to a discontinuity of the picture are not compared, since there
// a sub-pixel difference in where an edge falls changes a pixel completely:
// silhouettes (the 3×3 neighbourhood does not hit one and the same object, or
// background), edges between flat-shaded triangles of different colours, and
// the edge of a spot light's cone. An occlusion edge inside one object (the
// teapot's rim against the surface behind it) is not excluded: where a pixel
// centre lies within float rounding of such an edge (a thousandth of a
// pixel), the two pictures may show different surfaces there, so a few such
// pixels may differ completely (one in teapot.toml at 200×150).
//
// Set LITKIT_REFERENCE_DUMP to a folder to get both images of every case as
// PPM files there.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <iomanip>
#include <limits>
#include <map>
#include <numbers>
#include <numeric>
#include <optional>
#include <ostream>
#include <span>
#include <sstream>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "litkit/image.hpp"
#include "litkit/lighting.hpp"
#include "litkit/mesh.hpp"
#include "litkit/render.hpp"
#include "litkit/scene.hpp"
#include "litkit/shapes.hpp"

namespace {

using glm::dvec3;

constexpr double pi = 3.14159265358979323846;

dvec3 to_double(const glm::vec3& v) { return {double(v.x), double(v.y), double(v.z)}; }

dvec3 normalize_or_zero(const dvec3& v) {
    double length = glm::length(v);
    return length > 0.0 ? v / length : dvec3(0.0);
}

// ---- Geometry (docs/spec.md §2) ----

// Rotations about the axes, right-handed, angle in degrees.
dvec3 rotate_x(const dvec3& v, double degrees) {
    double c = std::cos(degrees * pi / 180.0), s = std::sin(degrees * pi / 180.0);
    return {v.x, c * v.y - s * v.z, s * v.y + c * v.z};
}
dvec3 rotate_y(const dvec3& v, double degrees) {
    double c = std::cos(degrees * pi / 180.0), s = std::sin(degrees * pi / 180.0);
    return {c * v.x + s * v.z, v.y, -s * v.x + c * v.z};
}
dvec3 rotate_z(const dvec3& v, double degrees) {
    double c = std::cos(degrees * pi / 180.0), s = std::sin(degrees * pi / 180.0);
    return {c * v.x - s * v.y, s * v.x + c * v.y, v.z};
}

// world = T(position) · Rz · Ry · Rx · S(scale) · local (docs/spec.md §2).
dvec3 local_to_world(const litkit::SceneObject& object, const glm::vec3& local) {
    dvec3 rotation = to_double(object.rotation_degrees);
    dvec3 scaled = double(object.scale) * to_double(local);
    dvec3 rotated = rotate_z(rotate_y(rotate_x(scaled, rotation.x), rotation.y), rotation.z);
    return to_double(object.position) + rotated;
}

// The local triangles: the library's shape generators for the built-in
// shapes, object_mesh for the teapot and mesh files (positions and triangles
// only; everything else is computed here).
litkit::Mesh shape_mesh(const litkit::SceneObject& object) {
    return std::visit(
        [&](const auto& s) -> litkit::Mesh {
            using S = std::decay_t<decltype(s)>;
            if constexpr (std::is_same_v<S, litkit::CubeShape>) {
                return litkit::make_cube(s.size);
            } else if constexpr (std::is_same_v<S, litkit::SphereShape>) {
                return litkit::make_sphere(s.radius, s.segments, s.rings);
            } else if constexpr (std::is_same_v<S, litkit::TorusShape>) {
                return litkit::make_torus(s.major_radius, s.minor_radius, s.segments, s.sides);
            } else {
                return litkit::object_mesh(object);
            }
        },
        object.shape);
}

// DD9's "one vertex": positions within 1e-6 × the local bounding-box diagonal.
// Returns, for each position, the index of its group's representative.
std::vector<std::size_t> weld_positions(const litkit::Mesh& mesh) {
    const std::size_t count = mesh.positions.size();
    std::vector<std::size_t> parent(count);
    std::iota(parent.begin(), parent.end(), std::size_t{0});
    if (count == 0) return parent;

    dvec3 low(std::numeric_limits<double>::infinity());
    dvec3 high(-std::numeric_limits<double>::infinity());
    for (const glm::vec3& p : mesh.positions) {
        low = glm::min(low, to_double(p));
        high = glm::max(high, to_double(p));
    }
    const double tolerance = 1e-6 * glm::length(high - low);

    auto find = [&](std::size_t i) {
        while (parent[i] != i) i = parent[i] = parent[parent[i]];
        return i;
    };
    // Sweep along x: only positions whose x lie within the tolerance can weld.
    std::vector<std::size_t> order(count);
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return mesh.positions[a].x < mesh.positions[b].x;
    });
    for (std::size_t a = 0; a < count; ++a) {
        const dvec3 pa = to_double(mesh.positions[order[a]]);
        for (std::size_t b = a + 1; b < count; ++b) {
            const dvec3 pb = to_double(mesh.positions[order[b]]);
            if (pb.x - pa.x > tolerance) break;
            if (glm::length(pb - pa) <= tolerance) {
                std::size_t ra = find(order[a]), rb = find(order[b]);
                if (ra != rb) parent[std::max(ra, rb)] = std::min(ra, rb);
            }
        }
    }
    for (std::size_t i = 0; i < count; ++i) parent[i] = find(i);
    return parent;
}

// ---- Lights and materials in double (docs/spec.md §4) ----

struct RefLight {
    enum class Kind { Ambient, Directional, Point, Spot } kind = Kind::Ambient;
    dvec3 radiance{0.0};  // I_L = intensity · colour / 255
    dvec3 position{0.0};
    dvec3 travel{0.0};  // directional: unit travel direction; spot: unit axis
    dvec3 attenuation{0.0};
    double cos_cutoff = 0.0;
    double cos_inner = 0.0;  // docs/spec.md §9.3
    double exponent = 0.0;
};

RefLight to_reference(const litkit::Light& light) {
    RefLight result;
    result.radiance = double(light.intensity) * to_double(light.color);
    std::visit(
        [&](const auto& kind) {
            using K = std::decay_t<decltype(kind)>;
            if constexpr (std::is_same_v<K, litkit::AmbientLight>) {
                result.kind = RefLight::Kind::Ambient;
            } else if constexpr (std::is_same_v<K, litkit::DirectionalLight>) {
                result.kind = RefLight::Kind::Directional;
                result.travel = glm::normalize(to_double(kind.direction));
            } else if constexpr (std::is_same_v<K, litkit::PointLight>) {
                result.kind = RefLight::Kind::Point;
                result.position = to_double(kind.position);
                result.attenuation = to_double(kind.attenuation);
            } else {
                result.kind = RefLight::Kind::Spot;
                result.position = to_double(kind.position);
                result.attenuation = to_double(kind.attenuation);
                result.travel = glm::normalize(to_double(kind.direction));
                result.cos_cutoff = std::cos(double(kind.cutoff_degrees) * pi / 180.0);
                result.cos_inner = std::cos(double(kind.cutoff_degrees) *
                                            (1.0 - double(kind.penumbra)) * pi / 180.0);
                result.exponent = double(kind.exponent);
            }
        },
        light.kind);
    return result;
}

struct RefMaterial {
    dvec3 color;  // C
    double ka, kd, ks, shininess;
    double sigma_degrees, roughness, f0, bands, minnaert_k;  // docs/spec.md §9.1
};

RefMaterial to_reference(const litkit::Material& material) {
    return {to_double(material.color),  double(material.ka),        double(material.kd),
            double(material.ks),        double(material.shininess), double(material.sigma),
            double(material.roughness), double(material.f0),        double(material.bands),
            double(material.minnaert_k)};
}

// The colour at one point, with what the caller needs to find discontinuities.
struct Lit {
    dvec3 intensity{0.0};    // I, unclamped
    unsigned cone_mask = 0;  // bit k: the point is inside spot light k's cone
    // Smallest |c − cos(cutoff)| over the spot lights: near 0, float rounding
    // in the renderer may put the point on the other side of the cone's edge.
    // Likewise the distance from the steps of `toon` (bands·N·L, (N·H)^α − 0.5).
    double cone_margin = std::numeric_limits<double>::infinity();
};

// I = Σ_ambient k_a·C·I_L + Σ_others f·I_L·(k_d·D·C + k_s·S), docs/spec.md §4.
Lit light_point(litkit::Reflection reflection, const RefMaterial& material,
                const std::vector<RefLight>& lights, const dvec3& p, const dvec3& normal,
                const dvec3& eye) {
    using litkit::Reflection;
    Lit lit;
    const dvec3 to_eye = glm::normalize(eye - p);  // V
    unsigned spot_index = 0;
    for (const RefLight& light : lights) {
        if (light.kind == RefLight::Kind::Ambient) {
            lit.intensity += material.ka * material.color * light.radiance;
            continue;
        }
        dvec3 to_light;  // L
        double factor;   // f
        if (light.kind == RefLight::Kind::Directional) {
            to_light = -light.travel;
            factor = 1.0;
        } else {
            const dvec3 offset = light.position - p;
            const double d = glm::length(offset);
            to_light = offset / d;
            factor =
                1.0 / (light.attenuation.x + light.attenuation.y * d + light.attenuation.z * d * d);
            if (light.kind == RefLight::Kind::Spot) {
                const double c = -glm::dot(to_light, light.travel);
                lit.cone_margin = std::min(lit.cone_margin, std::abs(c - light.cos_cutoff));
                if (c >= light.cos_cutoff) {
                    lit.cone_mask |= 1u << spot_index;
                    factor *= light.exponent == 0.0 ? 1.0 : std::pow(c, light.exponent);
                    // docs/spec.md §9.3: the soft edge between the inner and outer cones.
                    if (c < light.cos_inner) {
                        const double t =
                            (c - light.cos_cutoff) / (light.cos_inner - light.cos_cutoff);
                        factor *= t * t * (3.0 - 2.0 * t);
                    }
                } else {
                    factor = 0.0;
                }
                ++spot_index;
            }
        }
        const double n_dot_l = glm::dot(normal, to_light);
        double diffuse = std::max(n_dot_l, 0.0);
        double specular = 0.0;
        switch (reflection) {
            case Reflection::Lambert:
                break;
            case Reflection::HalfLambert:
                diffuse = (0.5 * n_dot_l + 0.5) * (0.5 * n_dot_l + 0.5);
                break;
            case Reflection::Phong: {
                const dvec3 reflected = 2.0 * n_dot_l * normal - to_light;
                const double base = glm::dot(reflected, to_eye);
                if (n_dot_l > 0.0 && base > 0.0) specular = std::pow(base, material.shininess);
                break;
            }
            case Reflection::BlinnPhong: {
                const dvec3 halfway = glm::normalize(to_light + to_eye);
                const double base = glm::dot(normal, halfway);
                if (n_dot_l > 0.0 && base > 0.0) specular = std::pow(base, material.shininess);
                break;
            }
            // docs/spec.md §9.1, each written out again here in double.
            case Reflection::OrenNayar: {
                const double sigma = material.sigma_degrees * pi / 180.0;
                const double a = 1.0 - 0.5 * sigma * sigma / (sigma * sigma + 0.33);
                const double b = 0.45 * sigma * sigma / (sigma * sigma + 0.09);
                const double n_v = std::max(glm::dot(normal, to_eye), 0.0);
                const double s = glm::dot(to_light, to_eye) - n_dot_l * n_v;
                diffuse = n_dot_l > 0.0
                              ? n_dot_l * (a + b * std::max(0.0, s) / std::max(n_dot_l, n_v))
                              : 0.0;
                break;
            }
            case Reflection::CookTorrance: {
                if (n_dot_l <= 0.0) break;
                const double r = std::max(material.roughness, 0.045);
                const double a2 = r * r * r * r;
                const double m = std::max(glm::dot(normal, to_eye), 1e-4);
                const dvec3 halfway = glm::normalize(to_light + to_eye);
                const double n_h = std::max(glm::dot(normal, halfway), 0.0);
                const double q = n_h * n_h * (a2 - 1.0) + 1.0;
                const double d_ggx = a2 / (pi * q * q);
                const double vis = 0.5 / (n_dot_l * std::sqrt(m * m * (1.0 - a2) + a2) +
                                          m * std::sqrt(n_dot_l * n_dot_l * (1.0 - a2) + a2));
                const double fresnel =
                    material.f0 + (1.0 - material.f0) *
                                      std::pow(1.0 - std::max(glm::dot(to_eye, halfway), 0.0), 5);
                specular = pi * d_ggx * vis * fresnel * n_dot_l;
                break;
            }
            case Reflection::Toon: {
                if (n_dot_l <= 0.0) {
                    diffuse = 0.0;
                    break;
                }
                const double scaled = material.bands * n_dot_l;
                const double level = std::min(std::floor(scaled), material.bands - 1.0);
                diffuse = level / (material.bands - 1.0);
                const dvec3 halfway = glm::normalize(to_light + to_eye);
                const double n_h = std::max(glm::dot(normal, halfway), 0.0);
                const double lobe =
                    material.shininess == 0.0 ? 1.0 : std::pow(n_h, material.shininess);
                specular = lobe >= 0.5 ? 1.0 : 0.0;
                lit.cone_margin = std::min({lit.cone_margin,
                                            std::abs(scaled - std::round(scaled)) / material.bands,
                                            std::abs(lobe - 0.5)});
                break;
            }
            case Reflection::Minnaert: {
                if (n_dot_l <= 0.0) {
                    diffuse = 0.0;
                    break;
                }
                const double n_v = std::max(glm::dot(normal, to_eye), 0.0);
                double base = n_dot_l * n_v;
                if (material.minnaert_k < 1.0) base = std::max(base, 0.1);
                diffuse = material.minnaert_k == 1.0
                              ? n_dot_l
                              : n_dot_l * std::pow(base, material.minnaert_k - 1.0);
                break;
            }
            case Reflection::Gooch: {
                const dvec3 reflected = 2.0 * n_dot_l * normal - to_light;
                const double base = glm::dot(reflected, to_eye);
                if (n_dot_l > 0.0 && base > 0.0) specular = std::pow(base, material.shininess);
                const double t = (1.0 + n_dot_l) / 2.0;
                const dvec3 tinted = material.kd * material.color;
                const dvec3 cool = glm::min(0.2 * tinted + dvec3(0.0, 0.0, 0.4), dvec3(1.0));
                const dvec3 warm = glm::min(0.6 * tinted + dvec3(0.4, 0.4, 0.0), dvec3(1.0));
                lit.intensity += factor * light.radiance *
                                 (t * warm + (1.0 - t) * cool + dvec3(material.ks * specular));
                continue;
            }
        }
        lit.intensity += factor * light.radiance *
                         (material.kd * diffuse * material.color + dvec3(material.ks * specular));
    }
    return lit;
}

// round(255 · clamp(I, 0, 1)^(1/gamma)), docs/spec.md §4.
std::uint8_t to_byte(double intensity, double gamma) {
    const double clamped = std::clamp(intensity, 0.0, 1.0);
    return static_cast<std::uint8_t>(std::lround(255.0 * std::pow(clamped, 1.0 / gamma)));
}

// ---- The reference ray caster ----

// One object's triangles in world space with everything shading needs.
struct RefObject {
    litkit::Shading shading = litkit::Shading::Phong;
    litkit::Reflection reflection = litkit::Reflection::Phong;
    RefMaterial material{};
    std::vector<dvec3> positions;  // world
    // Per triangle corner (3·t + k): DD9, or docs/spec.md §9.2's weightings,
    // crease and file normals; world.
    std::vector<dvec3> corner_normals;
    std::vector<std::array<std::uint32_t, 3>> triangles;
    std::vector<dvec3> face_normals;   // DD8, world
    std::vector<std::uint32_t> front;  // triangles facing the eye
    std::vector<Lit> flat_colours;     // per triangle (flat shading)
    std::vector<Lit> corner_colours;   // per triangle corner (Gouraud shading)
    dvec3 centre{0.0};
    double radius = 0.0;  // bounding sphere, for a quick miss
};

struct ReferenceImage {
    int width = 0;
    int height = 0;
    std::vector<std::array<std::uint8_t, 3>> rgb;
    std::vector<dvec3> intensity;  // I before clamping (object pixels)
    std::vector<int> object;       // −1: background
    std::vector<long> triangle;    // the triangle hit, −1 for none
    std::vector<unsigned> cone_mask;
    std::vector<double> cone_margin;
    std::vector<litkit::Shading> shading;

    std::size_t index(int i, int j) const { return static_cast<std::size_t>(j) * width + i; }
};

RefObject prepare_object(const litkit::Scene& scene, const litkit::SceneObject& object,
                         const std::vector<RefLight>& lights, const dvec3& eye) {
    RefObject ref;
    ref.shading = object.shading.value_or(scene.shading.value_or(litkit::default_shading));
    ref.reflection =
        object.reflection.value_or(scene.reflection.value_or(litkit::default_reflection));
    ref.material = to_reference(object.material);

    const litkit::Mesh mesh = shape_mesh(object);
    for (const glm::vec3& p : mesh.positions) ref.positions.push_back(local_to_world(object, p));
    ref.triangles = mesh.triangles;

    // DD8 in world space.
    for (const auto& t : ref.triangles) {
        const dvec3 &a = ref.positions[t[0]], &b = ref.positions[t[1]], &c = ref.positions[t[2]];
        ref.face_normals.push_back(normalize_or_zero(glm::cross(b - a, c - a)));
    }

    // Which normals (docs/spec.md §9.2): the object's, else the scene's;
    // "file" from the scene only on mesh objects; a crease of 180 is none.
    const bool is_mesh = std::holds_alternative<litkit::MeshFileShape>(object.shape);
    litkit::Normals normals =
        object.normals.value_or(scene.normals.value_or(litkit::Normals::Mean));
    if (!object.normals && normals == litkit::Normals::File && !is_mesh)
        normals = litkit::Normals::Mean;
    const std::optional<float> crease =
        object.crease_angle_degrees ? object.crease_angle_degrees : scene.crease_angle_degrees;
    // What n̂_f·n̂_g must exceed for face g to count at a corner of face f:
    // -2 (every face) without a crease or with one of 180.
    const double limit =
        crease && *crease < 180.0f ? std::cos(double(*crease) * std::numbers::pi / 180.0) : -2.0;

    if (normals == litkit::Normals::File) {
        // The file's normals, turned as the object is (world = T·R·S, S uniform).
        for (std::size_t k = 0; k < ref.triangles.size(); ++k)
            for (int c = 0; c < 3; ++c) {
                const glm::vec3 n = mesh.file_normals.at(mesh.triangle_file_normals[k][c]);
                const glm::vec3 origin(0.0f);
                ref.corner_normals.push_back(
                    normalize_or_zero(local_to_world(object, n) - local_to_world(object, origin)));
            }
    } else {
        // Each corner's weighted normal; a triangle with two corners welded
        // together (or no area at all) takes no part.
        const std::vector<std::size_t> group = weld_positions(mesh);
        std::vector<dvec3> weight(3 * ref.triangles.size(), dvec3(0.0));
        std::vector<bool> usable(ref.triangles.size(), false);
        std::map<std::size_t, std::vector<std::size_t>> corners_of_group;  // → 3·t + c
        for (std::size_t k = 0; k < ref.triangles.size(); ++k) {
            const auto& t = ref.triangles[k];
            if (group[t[0]] == group[t[1]] || group[t[1]] == group[t[2]] ||
                group[t[0]] == group[t[2]] || ref.face_normals[k] == dvec3(0.0))
                continue;
            usable[k] = true;
            for (int c = 0; c < 3; ++c) {
                const dvec3 e1 = ref.positions[t[(c + 1) % 3]] - ref.positions[t[c]];
                const dvec3 e2 = ref.positions[t[(c + 2) % 3]] - ref.positions[t[c]];
                const dvec3 cross = glm::cross(e1, e2);
                dvec3& w = weight[3 * k + c];
                switch (normals) {
                    case litkit::Normals::Area:
                        w = cross;
                        break;
                    case litkit::Normals::Angle:
                        w = std::atan2(glm::length(cross), glm::dot(e1, e2)) * ref.face_normals[k];
                        break;
                    case litkit::Normals::Max:
                        w = cross / (glm::dot(e1, e1) * glm::dot(e2, e2));
                        break;
                    default:
                        w = ref.face_normals[k];
                        break;  // mean (DD9)
                }
                corners_of_group[group[t[c]]].push_back(3 * k + c);
            }
        }
        for (std::size_t k = 0; k < ref.triangles.size(); ++k)
            for (int c = 0; c < 3; ++c) {
                dvec3 sum(0.0);
                for (const std::size_t other : corners_of_group[group[ref.triangles[k][c]]]) {
                    const std::size_t h = other / 3;
                    // A crease counts only faces within its angle (and the
                    // corner's own); an unusable triangle takes the vertex normal.
                    if (!usable[k] || h == k ||
                        glm::dot(ref.face_normals[k], ref.face_normals[h]) > limit)
                        sum += weight[other];
                }
                ref.corner_normals.push_back(normalize_or_zero(sum));
            }
    }

    // Back faces are culled: keep triangles whose face normal points at the eye.
    for (std::size_t k = 0; k < ref.triangles.size(); ++k) {
        const dvec3& a = ref.positions[ref.triangles[k][0]];
        if (ref.face_normals[k] != dvec3(0.0) && glm::dot(ref.face_normals[k], eye - a) > 0.0)
            ref.front.push_back(static_cast<std::uint32_t>(k));
    }

    // docs/spec.md §3: flat lights each triangle once at its centroid with its face
    // normal; Gouraud lights each vertex with its vertex normal.
    for (std::size_t k = 0; k < ref.triangles.size(); ++k) {
        const auto& t = ref.triangles[k];
        const dvec3 centroid =
            (ref.positions[t[0]] + ref.positions[t[1]] + ref.positions[t[2]]) / 3.0;
        ref.flat_colours.push_back(
            light_point(ref.reflection, ref.material, lights, centroid, ref.face_normals[k], eye));
    }
    for (std::size_t k = 0; k < ref.triangles.size(); ++k)
        for (int c = 0; c < 3; ++c)
            ref.corner_colours.push_back(light_point(ref.reflection, ref.material, lights,
                                                     ref.positions[ref.triangles[k][c]],
                                                     ref.corner_normals[3 * k + c], eye));

    for (const dvec3& p : ref.positions) ref.centre += p;
    if (!ref.positions.empty()) ref.centre /= double(ref.positions.size());
    for (const dvec3& p : ref.positions)
        ref.radius = std::max(ref.radius, glm::length(p - ref.centre));
    return ref;
}

struct Hit {
    double t = std::numeric_limits<double>::infinity();
    long triangle = -1;
    double u = 0.0, v = 0.0;  // barycentrics of corners 1 and 2
};

// Möller–Trumbore against the front-facing triangles; the nearest hit with t in
// [t_min, t_max]. A hair of slack on the edges keeps shared edges crack-free.
void intersect(const RefObject& object, const dvec3& origin, const dvec3& direction, double t_min,
               double t_max, Hit& hit) {
    constexpr double edge_slack = 1e-10;
    for (std::uint32_t k : object.front) {
        const auto& tri = object.triangles[k];
        const dvec3& a = object.positions[tri[0]];
        const dvec3 e1 = object.positions[tri[1]] - a;
        const dvec3 e2 = object.positions[tri[2]] - a;
        const dvec3 p = glm::cross(direction, e2);
        const double det = glm::dot(e1, p);
        if (det == 0.0) continue;
        const double inverse = 1.0 / det;
        const dvec3 s = origin - a;
        const double u = glm::dot(s, p) * inverse;
        if (u < -edge_slack || u > 1.0 + edge_slack) continue;
        const dvec3 q = glm::cross(s, e1);
        const double v = glm::dot(direction, q) * inverse;
        if (v < -edge_slack || u + v > 1.0 + edge_slack) continue;
        const double t = glm::dot(e2, q) * inverse;
        if (t < t_min || t > t_max || t >= hit.t) continue;
        hit = {t, long(k), u, v};
    }
}

// The picture of one sample per pixel, at (i + sample_x, j + sample_y) of
// pixel (i, j): the centre by default (docs/spec.md §1, §11).
ReferenceImage reference_render(const litkit::Scene& scene, double sample_x = 0.5,
                                double sample_y = 0.5) {
    const litkit::Observer& observer = scene.observer;
    const int width = scene.output.width, height = scene.output.height;
    const double gamma = scene.output.gamma;
    const dvec3 eye = to_double(observer.position);

    std::vector<RefLight> lights;
    for (const litkit::SceneLight& light : scene.lights)
        lights.push_back(to_reference(light.light));
    std::vector<RefObject> objects;
    for (const litkit::SceneObject& object : scene.objects)
        objects.push_back(prepare_object(scene, object, lights, eye));

    // Camera basis: right-handed, looking down its −z axis.
    const dvec3 forward = glm::normalize(to_double(observer.look_at) - eye);
    const dvec3 right = glm::normalize(glm::cross(forward, to_double(observer.up)));
    const dvec3 up = glm::cross(right, forward);
    const double tan_half = std::tan(double(observer.fov_degrees) * pi / 360.0);
    const double aspect = double(width) / double(height);

    ReferenceImage image;
    image.width = width;
    image.height = height;
    const std::size_t count = static_cast<std::size_t>(width) * height;
    // The background's bytes, computed here (round(255·c) in double), not by litkit::to_rgb8.
    const glm::vec3& c = scene.output.background;
    auto byte = [](float v) { return static_cast<std::uint8_t>(std::lround(255.0 * v)); };
    image.rgb.assign(count, {byte(c.x), byte(c.y), byte(c.z)});
    image.intensity.assign(count, dvec3(0.0));
    image.object.assign(count, -1);
    image.triangle.assign(count, -1);
    image.cone_mask.assign(count, 0);
    image.cone_margin.assign(count, std::numeric_limits<double>::infinity());
    image.shading.assign(count, litkit::Shading::Phong);

    for (int j = 0; j < height; ++j) {
        for (int i = 0; i < width; ++i) {
            const double x = 2.0 * (i + sample_x) / width - 1.0;
            const double y = 1.0 - 2.0 * (j + sample_y) / height;
            // Camera-space (x·tan·aspect, y·tan, −1); its component along
            // `forward` is 1, so the ray parameter t is the view depth.
            const dvec3 direction = x * tan_half * aspect * right + y * tan_half * up + forward;
            const dvec3 unit = glm::normalize(direction);

            Hit nearest;
            int nearest_object = -1;
            for (std::size_t o = 0; o < objects.size(); ++o) {
                const RefObject& object = objects[o];
                // Bounding-sphere test first: most rays miss most objects.
                const dvec3 to_centre = object.centre - eye;
                const double along = glm::dot(to_centre, unit);
                const double miss2 = glm::dot(to_centre, to_centre) - along * along;
                if (miss2 > object.radius * object.radius * 1.0001 + 1e-12) continue;
                Hit hit;
                intersect(object, eye, direction, double(observer.near),
                          std::min(double(observer.far), nearest.t), hit);
                if (hit.triangle >= 0) {
                    nearest = hit;
                    nearest_object = int(o);
                }
            }
            if (nearest_object < 0) continue;

            const RefObject& object = objects[nearest_object];
            const auto& tri = object.triangles[nearest.triangle];
            const double w1 = nearest.u, w2 = nearest.v, w0 = 1.0 - w1 - w2;
            Lit lit;
            switch (object.shading) {
                case litkit::Shading::Flat:
                    lit = object.flat_colours[nearest.triangle];
                    break;
                case litkit::Shading::Gouraud: {
                    // Ray barycentrics are the perspective-correct ones.
                    const std::size_t first = 3 * static_cast<std::size_t>(nearest.triangle);
                    const Lit &c0 = object.corner_colours[first],
                              &c1 = object.corner_colours[first + 1],
                              &c2 = object.corner_colours[first + 2];
                    lit.intensity = w0 * c0.intensity + w1 * c1.intensity + w2 * c2.intensity;
                    lit.cone_margin = std::min({c0.cone_margin, c1.cone_margin, c2.cone_margin});
                    break;
                }
                case litkit::Shading::Phong: {
                    const dvec3 p = w0 * object.positions[tri[0]] + w1 * object.positions[tri[1]] +
                                    w2 * object.positions[tri[2]];
                    const std::size_t first = 3 * static_cast<std::size_t>(nearest.triangle);
                    const dvec3 normal = glm::normalize(w0 * object.corner_normals[first] +
                                                        w1 * object.corner_normals[first + 1] +
                                                        w2 * object.corner_normals[first + 2]);
                    lit = light_point(object.reflection, object.material, lights, p, normal, eye);
                    break;
                }
                case litkit::Shading::Faceted: {
                    // docs/spec.md §9.2: at the hit point, with the face normal
                    // (the triangle hit faces the eye).
                    const dvec3 p = w0 * object.positions[tri[0]] + w1 * object.positions[tri[1]] +
                                    w2 * object.positions[tri[2]];
                    lit = light_point(object.reflection, object.material, lights, p,
                                      object.face_normals[nearest.triangle], eye);
                    break;
                }
            }
            const std::size_t at = image.index(i, j);
            image.object[at] = nearest_object;
            image.triangle[at] = nearest.triangle;
            image.intensity[at] = lit.intensity;
            image.cone_mask[at] = lit.cone_mask;
            image.cone_margin[at] = lit.cone_margin;
            image.shading[at] = object.shading;
            image.rgb[at] = {to_byte(lit.intensity.x, gamma), to_byte(lit.intensity.y, gamma),
                             to_byte(lit.intensity.z, gamma)};
        }
    }
    return image;
}

// ---- Comparison ----

// Pixels near a discontinuity of the reference are not compared (see top).
bool is_comparable(const ReferenceImage& ref, int i, int j) {
    constexpr double cone_margin_limit = 1e-4;
    const std::size_t centre = ref.index(i, j);
    std::array<int, 3> low{255, 255, 255}, high{0, 0, 0};
    bool several_triangles = false;
    for (int dj = -1; dj <= 1; ++dj) {
        for (int di = -1; di <= 1; ++di) {
            const int ni = std::clamp(i + di, 0, ref.width - 1);
            const int nj = std::clamp(j + dj, 0, ref.height - 1);
            const std::size_t at = ref.index(ni, nj);
            if (ref.object[at] != ref.object[centre]) return false;  // silhouette
            if (ref.object[at] < 0) continue;
            if (ref.cone_mask[at] != ref.cone_mask[centre]) return false;  // spot cone edge
            if (ref.cone_margin[at] < cone_margin_limit) return false;
            several_triangles |= ref.triangle[at] != ref.triangle[centre];
            for (int c = 0; c < 3; ++c) {
                low[c] = std::min(low[c], int(ref.rgb[at][c]));
                high[c] = std::max(high[c], int(ref.rgb[at][c]));
            }
        }
    }
    const bool per_face_normal = ref.shading[centre] == litkit::Shading::Flat ||
                                 ref.shading[centre] == litkit::Shading::Faceted;
    if (ref.object[centre] >= 0 && per_face_normal && several_triangles) {
        for (int c = 0; c < 3; ++c)
            if (high[c] - low[c] > 2) return false;  // edge between flat colours
    }
    return true;
}

struct Comparison {
    long pixels = 0;
    long counted = 0;
    long matching = 0;    // counted pixels within 2/255 in every channel
    long within_one = 0;  // counted pixels within 1/255 in every channel
    long reference_object_pixels = 0;
    long rendered_object_pixels = 0;      // of those, how many the render did not leave background
    std::vector<long> pixels_per_object;  // reference pixels of each object
    int worst_difference = -1;
    int worst_i = 0, worst_j = 0;
    std::string worst;

    double matching_fraction() const { return counted ? double(matching) / double(counted) : 0.0; }
    double within_one_fraction() const {
        return counted ? double(within_one) / double(counted) : 0.0;
    }
    double counted_fraction() const { return pixels ? double(counted) / double(pixels) : 0.0; }
};

std::string describe_pixel(const ReferenceImage& ref, const litkit::Image& image, int i, int j) {
    const std::size_t at = ref.index(i, j);
    const std::uint8_t* got = image.pixel(i, j);
    std::ostringstream out;
    out << "pixel (" << i << ", " << j << "): render (" << int(got[0]) << ", " << int(got[1])
        << ", " << int(got[2]) << "), reference (" << int(ref.rgb[at][0]) << ", "
        << int(ref.rgb[at][1]) << ", " << int(ref.rgb[at][2]) << ")";
    if (ref.object[at] >= 0) {
        out << ", reference I = (" << ref.intensity[at].x << ", " << ref.intensity[at].y << ", "
            << ref.intensity[at].z << ") on object " << ref.object[at] << " triangle "
            << ref.triangle[at];
    } else {
        out << ", reference background";
    }
    return out.str();
}

Comparison compare(const ReferenceImage& ref, const litkit::Image& image,
                   const litkit::Rgb8& background, std::size_t object_count = 0) {
    Comparison result;
    result.pixels = long(ref.width) * ref.height;
    result.pixels_per_object.assign(object_count, 0);
    for (int j = 0; j < ref.height; ++j) {
        for (int i = 0; i < ref.width; ++i) {
            const std::size_t at = ref.index(i, j);
            const std::uint8_t* got = image.pixel(i, j);
            if (ref.object[at] >= 0) {
                ++result.reference_object_pixels;
                if (std::size_t(ref.object[at]) < object_count)
                    ++result.pixels_per_object[std::size_t(ref.object[at])];
                if (got[0] != background[0] || got[1] != background[1] || got[2] != background[2])
                    ++result.rendered_object_pixels;
            }
            if (!is_comparable(ref, i, j)) continue;
            ++result.counted;
            int difference = 0;
            for (int c = 0; c < 3; ++c)
                difference = std::max(difference, std::abs(int(got[c]) - int(ref.rgb[at][c])));
            if (difference <= 2) ++result.matching;
            if (difference <= 1) ++result.within_one;
            if (difference > result.worst_difference) {
                result.worst_difference = difference;
                result.worst_i = i;
                result.worst_j = j;
            }
        }
    }
    if (result.worst_difference >= 0)
        result.worst = describe_pixel(ref, image, result.worst_i, result.worst_j);
    return result;
}

void write_ppm(const std::filesystem::path& path, int width, int height,
               const std::vector<std::uint8_t>& rgb) {
    std::ofstream out(path, std::ios::binary);
    out << "P6\n" << width << ' ' << height << "\n255\n";
    out.write(reinterpret_cast<const char*>(rgb.data()), std::streamsize(rgb.size()));
}

void dump_if_asked(const std::string& name, const ReferenceImage& ref, const litkit::Image& image) {
    const char* folder = std::getenv("LITKIT_REFERENCE_DUMP");
    if (folder == nullptr || *folder == '\0') return;
    std::filesystem::create_directories(folder);
    std::vector<std::uint8_t> ref_rgb;
    for (const auto& p : ref.rgb) ref_rgb.insert(ref_rgb.end(), p.begin(), p.end());
    write_ppm(std::filesystem::path(folder) / (name + "_reference.ppm"), ref.width, ref.height,
              ref_rgb);
    write_ppm(std::filesystem::path(folder) / (name + "_render.ppm"), image.width, image.height,
              image.rgb);
}

// Renders `scene` with the library and checks it against the reference: at
// least 99.5% of the compared pixels within 1/255 in every channel.
void expect_render_matches_reference(const litkit::Scene& scene, const std::string& name) {
    using clock = std::chrono::steady_clock;
    const auto start = clock::now();
    const ReferenceImage ref = reference_render(scene);
    const auto referenced = clock::now();
    litkit::RenderOptions options;
    options.threads = 2;
    const litkit::Image image = litkit::render(scene, options);
    const auto rendered = clock::now();
    ASSERT_EQ(image.width, scene.output.width);
    ASSERT_EQ(image.height, scene.output.height);
    ASSERT_EQ(image.rgb.size(), std::size_t(image.width) * image.height * 3);
    dump_if_asked(name, ref, image);

    const Comparison result =
        compare(ref, image, litkit::to_rgb8(scene.output.background), scene.objects.size());
    const auto ms = [](clock::duration duration) {
        return std::chrono::duration<double, std::milli>(duration).count();
    };
    std::printf(
        "[ reference ] %-40s %dx%d, counted %5.1f%% of pixels, %7.3f%% within 1/255, %7.3f%% "
        "within 2/255, worst %d (reference %.0f ms, render %.0f ms)\n",
        name.c_str(), image.width, image.height, 100.0 * result.counted_fraction(),
        100.0 * result.within_one_fraction(), 100.0 * result.matching_fraction(),
        result.worst_difference, ms(referenced - start), ms(rendered - referenced));
    if (result.worst_difference > 1)
        std::printf("[ reference ]   worst %s\n", result.worst.c_str());

    // The objects must be there, in both pictures: every one of them in the
    // reference, and the render must not leave their pixels at the background.
    EXPECT_GE(result.reference_object_pixels, result.pixels / 20)
        << name << ": the reference sees too little of the objects";
    for (std::size_t o = 0; o < scene.objects.size(); ++o)
        EXPECT_GE(result.pixels_per_object[o], 20) << name << ": the reference barely sees object "
                                                   << o << " '" << scene.objects[o].name << "'";
    EXPECT_GE(result.rendered_object_pixels, result.reference_object_pixels * 9 / 10)
        << name << ": the render leaves the objects' pixels at the background colour";
    // Not vacuous: most of the picture is compared.
    EXPECT_GE(result.counted_fraction(), 0.30) << name << ": too few pixels away from edges";
    EXPECT_GE(result.within_one_fraction(), 0.995)
        << name << ": " << (result.counted - result.within_one) << " of " << result.counted
        << " compared pixels (" << std::fixed << std::setprecision(3)
        << 100.0 * (1.0 - result.within_one_fraction()) << "%) differ by more than 1/255; worst "
        << result.worst_difference << ", " << result.worst;
}

// ---- Scenes ----

enum class ShapeKind { Sphere, Cube };

constexpr litkit::Rgb8 background_colour{30, 60, 90};

litkit::Light make_light(litkit::LightKind kind, glm::vec3 color255, float intensity) {
    litkit::Light light;
    light.kind = kind;
    light.color = color255 / 255.0f;
    light.intensity = intensity;
    return light;
}

litkit::SceneObject make_object(ShapeKind shape) {
    litkit::SceneObject object;
    if (shape == ShapeKind::Sphere) {
        object.name = "ball";
        object.shape = litkit::SphereShape{1.3f, 40, 20};
        object.position = {0.1f, -0.1f, 0.0f};
        object.rotation_degrees = {0.0f, 20.0f, 0.0f};
    } else {
        object.name = "box";
        object.shape = litkit::CubeShape{1.5f};
        object.position = {-0.1f, 0.0f, 0.2f};
        // Turned so that three faces (front, top, side) face the camera.
        object.rotation_degrees = {25.0f, 35.0f, 10.0f};
        object.scale = 1.1f;
    }
    object.material.color = glm::vec3(200.0f, 120.0f, 60.0f) / 255.0f;
    object.material.ka = 0.3f;
    object.material.kd = 0.7f;
    object.material.ks = 0.5f;
    object.material.shininess = 24.0f;
    return object;
}

// Off-axis camera, a coloured point light with all three attenuation terms
// and an ambient light.
litkit::Scene make_scene(ShapeKind shape, litkit::Reflection reflection, litkit::Shading shading) {
    litkit::Scene scene;
    scene.room = {12.0f, 12.0f, 16.0f};
    scene.observer.position = {1.0f, 1.5f, 5.0f};
    scene.observer.look_at = {0.0f, 0.0f, 0.0f};
    scene.observer.fov_degrees = 45.0f;
    scene.output.width = 160;
    scene.output.height = 120;
    scene.output.background = litkit::from_rgb8(background_colour);
    scene.reflection = reflection;
    scene.shading = shading;
    scene.lights.push_back(
        {"fill", make_light(litkit::AmbientLight{}, {255.0f, 255.0f, 230.0f}, 0.6f)});
    scene.lights.push_back(
        {"key", make_light(litkit::PointLight{{2.5f, 2.0f, 3.5f}, {0.5f, 0.1f, 0.05f}},
                           {255.0f, 240.0f, 220.0f}, 3.0f)});
    scene.objects.push_back(make_object(shape));
    return scene;
}

litkit::DirectionalLight directional(glm::vec3 direction) {
    litkit::DirectionalLight light;
    light.direction = direction;
    return light;
}

// A spot from above-front whose cone edge runs across the object.
litkit::SpotLight spot_across_object() {
    litkit::SpotLight spot;
    spot.position = {0.5f, 3.0f, 2.5f};
    spot.attenuation = {0.2f, 0.1f, 0.05f};
    spot.direction = glm::vec3(0.3f, 0.0f, 0.0f) - spot.position;
    spot.cutoff_degrees = 16.0f;
    spot.exponent = 2.0f;
    return spot;
}

std::string name_of(ShapeKind shape) { return shape == ShapeKind::Sphere ? "sphere" : "cube"; }
std::string name_of(litkit::Reflection reflection) {
    std::string name(litkit::to_string(reflection));
    std::replace(name.begin(), name.end(), '-', '_');
    return name;
}
std::string name_of(litkit::Shading shading) { return std::string(litkit::to_string(shading)); }

// ---- The reference itself ----

// One hand-computed pixel. Sphere of radius 1 at the origin, eye at (0, 0, 5),
// 101 × 101 pixels: the centre pixel (50, 50) has x = y = 0, so its ray runs
// straight down −z and meets the sphere at p ≈ (0, 0, 1), where N ≈ (0, 0, 1).
// The point light sits at the eye: d = 4, f = 1/(0 + 0·4 + 1·16) = 1/16, and
// intensity 16 makes f·I_L = (1, 1, 1). L = V = N, so N·L = 1 and
// R = 2(N·L)N − L = N, R·V = 1, S = 1^32 = 1. With the white ambient light,
//   I = k_a·C + k_d·C·1 + k_s·1 = 0.8·C + 0.25, C = (200, 100, 50)/255
//     = (0.877451, 0.563725, 0.406863)
// and the pixel is round(255·I) = round(223.75, 143.75, 103.75) = (224, 144, 104).
TEST(ReferenceRayCaster, CentrePixelOfSphereLitFromTheEyeMatchesHandComputation) {
    litkit::Scene scene;
    scene.room = {10.0f, 10.0f, 20.0f};
    scene.observer.position = {0.0f, 0.0f, 5.0f};
    scene.output.width = 101;
    scene.output.height = 101;
    scene.output.background = litkit::from_rgb8(background_colour);
    scene.reflection = litkit::Reflection::Phong;
    scene.shading = litkit::Shading::Phong;
    scene.lights.push_back(
        {"", make_light(litkit::AmbientLight{}, {255.0f, 255.0f, 255.0f}, 1.0f)});
    scene.lights.push_back(
        {"", make_light(litkit::PointLight{{0.0f, 0.0f, 5.0f}, {0.0f, 0.0f, 1.0f}},
                        {255.0f, 255.0f, 255.0f}, 16.0f)});
    litkit::SceneObject ball;
    ball.shape = litkit::SphereShape{1.0f, 128, 64};
    ball.material.color = glm::vec3(200.0f, 100.0f, 50.0f) / 255.0f;
    ball.material.ka = 0.1f;
    ball.material.kd = 0.7f;
    ball.material.ks = 0.25f;
    ball.material.shininess = 32.0f;
    scene.objects.push_back(ball);

    const ReferenceImage ref = reference_render(scene);
    const std::size_t centre = ref.index(50, 50);
    ASSERT_EQ(ref.object[centre], 0);
    // The tessellation moves p and N by well under 1e-3.
    EXPECT_NEAR(ref.intensity[centre].x, 0.877451, 2e-3);
    EXPECT_NEAR(ref.intensity[centre].y, 0.563725, 2e-3);
    EXPECT_NEAR(ref.intensity[centre].z, 0.406863, 2e-3);
    EXPECT_EQ(int(ref.rgb[centre][0]), 224);
    EXPECT_EQ(int(ref.rgb[centre][1]), 144);
    EXPECT_EQ(int(ref.rgb[centre][2]), 104);

    // The sphere spans ±atan(1/√24) ≈ ±11.5° of the ±22.5° view: corners miss.
    const std::size_t corner = ref.index(0, 0);
    EXPECT_EQ(ref.object[corner], -1);
    EXPECT_EQ(ref.rgb[corner], (std::array<std::uint8_t, 3>{30, 60, 90}));
}

// The reference's vertex normals of a cube are the pillowed corners of DD9.
TEST(ReferenceRayCaster, CubeVertexNormalsArePillowedCorners) {
    litkit::Scene scene;
    litkit::SceneObject box;
    box.shape = litkit::CubeShape{2.0f};
    const RefObject ref = prepare_object(scene, box, {}, dvec3(0.0, 0.0, 5.0));
    ASSERT_FALSE(ref.positions.empty());
    for (std::size_t k = 0; k < ref.triangles.size(); ++k)
        for (int c = 0; c < 3; ++c) {
            const dvec3 expected = glm::sign(ref.positions[ref.triangles[k][c]]) / std::sqrt(3.0);
            EXPECT_NEAR(glm::length(ref.corner_normals[3 * k + c] - expected), 0.0, 1e-6)
                << "triangle " << k << " corner " << c;
        }
}

// ---- The renderer against the reference ----

constexpr std::array all_shapes{ShapeKind::Sphere, ShapeKind::Cube};
// Every model of the family (docs/spec.md §4 and §9.1).
constexpr std::array all_reflections{
    litkit::Reflection::Lambert,   litkit::Reflection::HalfLambert,
    litkit::Reflection::Phong,     litkit::Reflection::BlinnPhong,
    litkit::Reflection::OrenNayar, litkit::Reflection::CookTorrance,
    litkit::Reflection::Toon,      litkit::Reflection::Minnaert,
    litkit::Reflection::Gooch};
static_assert(all_reflections.size() == litkit::reflection_count);
constexpr std::array all_shadings{litkit::Shading::Flat, litkit::Shading::Gouraud,
                                  litkit::Shading::Phong, litkit::Shading::Faceted};

struct ModelCase {
    ShapeKind shape;
    litkit::Reflection reflection;
    litkit::Shading shading;

    std::string name() const {
        return name_of(shape) + "_" + name_of(reflection) + "_" + name_of(shading);
    }
    friend void PrintTo(const ModelCase& c, std::ostream* out) { *out << c.name(); }
};

std::vector<ModelCase> every_model() {
    std::vector<ModelCase> cases;
    for (ShapeKind shape : all_shapes)
        for (litkit::Reflection reflection : all_reflections)
            for (litkit::Shading shading : all_shadings)
                cases.push_back({shape, reflection, shading});
    return cases;
}

class RenderMatchesReference : public ::testing::TestWithParam<ModelCase> {};

// Every reflection × shading model, point + ambient light.
TEST_P(RenderMatchesReference, UnderPointAndAmbientLight) {
    const ModelCase& c = GetParam();
    expect_render_matches_reference(make_scene(c.shape, c.reflection, c.shading),
                                    c.name() + "_point");
}

INSTANTIATE_TEST_SUITE_P(AllModels, RenderMatchesReference, ::testing::ValuesIn(every_model()),
                         [](const ::testing::TestParamInfo<ModelCase>& info) {
                             return info.param.name();
                         });

struct LightCase {
    ShapeKind shape;
    litkit::Shading shading;

    std::string name() const { return name_of(shape) + "_" + name_of(shading); }
    friend void PrintTo(const LightCase& c, std::ostream* out) { *out << c.name(); }
};

std::vector<LightCase> every_shape_and_shading() {
    std::vector<LightCase> cases;
    for (ShapeKind shape : all_shapes)
        for (litkit::Shading shading : all_shadings) cases.push_back({shape, shading});
    return cases;
}

class OtherLightsMatchReference : public ::testing::TestWithParam<LightCase> {};

// A directional light (with ambient), Phong reflection.
TEST_P(OtherLightsMatchReference, UnderDirectionalLight) {
    const auto [shape, shading] = GetParam();
    litkit::Scene scene = make_scene(shape, litkit::Reflection::Phong, shading);
    scene.lights[1] = {
        "sun", make_light(directional({-1.0f, -0.8f, -1.5f}), {250.0f, 250.0f, 255.0f}, 0.9f)};
    expect_render_matches_reference(scene,
                                    name_of(shape) + "_phong_" + name_of(shading) + "_directional");
}

// A spot light whose cone edge crosses the object, Blinn-Phong reflection.
TEST_P(OtherLightsMatchReference, UnderSpotLightCrossingTheObject) {
    const auto [shape, shading] = GetParam();
    litkit::Scene scene = make_scene(shape, litkit::Reflection::BlinnPhong, shading);
    scene.lights[1] = {"spot", make_light(spot_across_object(), {255.0f, 255.0f, 255.0f}, 1.6f)};
    expect_render_matches_reference(scene,
                                    name_of(shape) + "_blinn_phong_" + name_of(shading) + "_spot");
}

// The same spot with a soft edge over the outer 60% of its cone (docs/spec.md §9.3).
TEST_P(OtherLightsMatchReference, UnderSoftSpotLight) {
    const auto [shape, shading] = GetParam();
    litkit::Scene scene = make_scene(shape, litkit::Reflection::BlinnPhong, shading);
    litkit::SpotLight spot = spot_across_object();
    spot.penumbra = 0.6f;
    scene.lights[1] = {"spot", make_light(spot, {255.0f, 255.0f, 255.0f}, 1.6f)};
    expect_render_matches_reference(
        scene, name_of(shape) + "_blinn_phong_" + name_of(shading) + "_soft_spot");
}

// All four kinds of light at once, with gamma 2.2 and a rolled camera.
TEST_P(OtherLightsMatchReference, UnderAllLightKindsWithGamma) {
    const auto [shape, shading] = GetParam();
    litkit::Scene scene = make_scene(shape, litkit::Reflection::Phong, shading);
    scene.output.gamma = 2.2f;
    scene.observer.up = {0.3f, 1.0f, 0.1f};
    scene.lights[0].light.intensity = 0.3f;
    scene.lights.push_back(
        {"sun", make_light(directional({1.0f, -0.5f, -1.0f}), {120.0f, 140.0f, 255.0f}, 0.5f)});
    scene.lights.push_back(
        {"spot", make_light(spot_across_object(), {255.0f, 200.0f, 200.0f}, 1.0f)});
    expect_render_matches_reference(scene,
                                    name_of(shape) + "_phong_" + name_of(shading) + "_all_gamma");
}

// Gamma 2.2 under the plain point light, for a second reflection model.
TEST_P(OtherLightsMatchReference, WithGammaCorrection) {
    const auto [shape, shading] = GetParam();
    litkit::Scene scene = make_scene(shape, litkit::Reflection::HalfLambert, shading);
    scene.output.gamma = 2.2f;
    expect_render_matches_reference(
        scene, name_of(shape) + "_half_lambert_" + name_of(shading) + "_gamma");
}

INSTANTIATE_TEST_SUITE_P(AllShadings, OtherLightsMatchReference,
                         ::testing::ValuesIn(every_shape_and_shading()),
                         [](const ::testing::TestParamInfo<LightCase>& info) {
                             return info.param.name();
                         });

// A coarse sphere, where the plain mean of DD9 and an area-weighted mean
// differ by much more than 2/255 (the ring next to a pole touches thin and wide
// triangles), so the vertex normals are checked closely.
TEST(RenderMatchesReferenceScene, CoarseSphereVertexNormals) {
    for (litkit::Shading shading : all_shadings) {
        SCOPED_TRACE(name_of(shading));
        litkit::Scene scene = make_scene(ShapeKind::Sphere, litkit::Reflection::Phong, shading);
        scene.objects[0].shape = litkit::SphereShape{1.3f, 9, 5};
        scene.objects[0].rotation_degrees = {50.0f, 20.0f, -15.0f};  // a pole in view
        expect_render_matches_reference(scene, "coarse_sphere_phong_" + name_of(shading));
    }
}

// Several objects with their own models, overriding [lighting].
TEST(RenderMatchesReferenceScene, PerObjectModelOverrides) {
    litkit::Scene scene =
        make_scene(ShapeKind::Sphere, litkit::Reflection::Phong, litkit::Shading::Phong);
    scene.objects[0].shape = litkit::SphereShape{0.8f, 32, 16};
    scene.objects[0].position = {-1.3f, 0.0f, 0.0f};
    scene.objects[0].shading = litkit::Shading::Gouraud;
    litkit::SceneObject box = make_object(ShapeKind::Cube);
    box.position = {1.2f, 0.0f, -0.5f};
    box.scale = 0.7f;
    box.reflection = litkit::Reflection::BlinnPhong;
    box.shading = litkit::Shading::Flat;
    scene.objects.push_back(box);
    expect_render_matches_reference(scene, "sphere_gouraud_cube_flat_overrides");
}

// ---- Every example scene against the reference ----

// One scene of examples/: a *.toml directly in the folder, or a sub-folder
// whose *.toml files together make one scene (examples/multi-file/).
struct ExampleCase {
    std::string name;
    std::vector<std::filesystem::path> files;  // in sorted order

    friend void PrintTo(const ExampleCase& c, std::ostream* out) { *out << c.name; }
};

std::vector<std::filesystem::path> toml_files_in(const std::filesystem::path& folder) {
    std::vector<std::filesystem::path> files;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(folder, error))
        if (entry.is_regular_file() && entry.path().extension() == ".toml")
            files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

std::string test_name_of(std::string name) {
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return name;
}

// Whether some object of the scene is glass (docs/spec.md §10): this file's
// reference casts no rays through glass; tests/test_glass.cpp checks those
// examples against its own reference, which does.
bool has_glass(const std::vector<std::filesystem::path>& files) {
    const litkit::Scene scene = litkit::load_scene(files);
    return std::any_of(scene.objects.begin(), scene.objects.end(),
                       [](const litkit::SceneObject& o) { return o.material.transmission > 0.0f; });
}

std::vector<ExampleCase> every_example() {
    const std::filesystem::path examples = std::filesystem::path(LITKIT_SOURCE_DIR) / "examples";
    std::vector<ExampleCase> cases;
    for (const auto& file : toml_files_in(examples))
        if (!has_glass({file})) cases.push_back({test_name_of(file.stem().string()), {file}});
    // Sub-folders holding a scene split over several files.
    std::vector<std::filesystem::path> folders;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(examples, error))
        if (entry.is_directory()) folders.push_back(entry.path());
    std::sort(folders.begin(), folders.end());
    for (const auto& folder : folders) {
        std::vector<std::filesystem::path> files = toml_files_in(folder);
        if (!files.empty()) cases.push_back({test_name_of(folder.filename().string()), files});
    }
    return cases;
}

// The examples are all there: a scene missing from the listing would go
// untested without this.
TEST(RenderMatchesReferenceExample, FindsEveryExampleScene) {
    const std::vector<ExampleCase> cases = every_example();
    EXPECT_GE(cases.size(), 18u);
    bool multi_file = false;
    for (const ExampleCase& c : cases) multi_file |= c.name == "multi_file" && c.files.size() == 2;
    EXPECT_TRUE(multi_file) << "examples/multi-file/ should be one scene of two files";
}

class RenderMatchesReferenceExample : public ::testing::TestWithParam<ExampleCase> {};

// The fast path draws the same picture: every example, at a small size with
// its aspect ratio kept, within 1/255 away from edges.
TEST_P(RenderMatchesReferenceExample, Within1Of255AwayFromEdges) {
    const ExampleCase& c = GetParam();
    litkit::Scene scene = litkit::load_scene(c.files);
    ASSERT_FALSE(scene.objects.empty()) << c.name;
    const double aspect = double(scene.output.width) / double(scene.output.height);
    scene.output.width = 200;
    scene.output.height = int(std::lround(200.0 / aspect));
    expect_render_matches_reference(scene, "example_" + c.name);
}

INSTANTIATE_TEST_SUITE_P(Examples, RenderMatchesReferenceExample,
                         ::testing::ValuesIn(every_example()),
                         [](const ::testing::TestParamInfo<ExampleCase>& info) {
                             return info.param.name;
                         });

// ---- Anti-aliasing (docs/spec.md §11) ----

// The sample positions as SPEC.md §11's table prints them, copied here by
// hand (not from the library, whose table is checked against this one).
const std::map<int, std::vector<std::pair<double, double>>>& spec_sample_table() {
    static const std::map<int, std::vector<std::pair<double, double>>> table{
        {1, {{0.5, 0.5}}},
        {4, {{0.375, 0.125}, {0.875, 0.375}, {0.125, 0.625}, {0.625, 0.875}}},
        {8,
         {{0.5625, 0.3125},
          {0.4375, 0.6875},
          {0.8125, 0.5625},
          {0.3125, 0.1875},
          {0.1875, 0.8125},
          {0.0625, 0.4375},
          {0.6875, 0.9375},
          {0.9375, 0.0625}}},
        {16,
         {{0.5625, 0.5625},
          {0.4375, 0.3125},
          {0.3125, 0.625},
          {0.75, 0.4375},
          {0.1875, 0.375},
          {0.625, 0.8125},
          {0.8125, 0.6875},
          {0.6875, 0.1875},
          {0.375, 0.875},
          {0.5, 0.0625},
          {0.25, 0.125},
          {0.125, 0.75},
          {0.0, 0.5},
          {0.9375, 0.25},
          {0.875, 0.9375},
          {0.0625, 0.0}}},
    };
    return table;
}

TEST(SamplePattern, IsTheTableOfTheSpec) {
    for (const auto& [count, positions] : spec_sample_table()) {
        const std::span<const litkit::SamplePosition> pattern = litkit::sample_pattern(count);
        ASSERT_EQ(pattern.size(), positions.size()) << count << " samples";
        for (std::size_t k = 0; k < positions.size(); ++k) {
            EXPECT_EQ(double(pattern[k].x), positions[k].first) << count << " samples, k = " << k;
            EXPECT_EQ(double(pattern[k].y), positions[k].second) << count << " samples, k = " << k;
        }
        EXPECT_TRUE(litkit::valid_sample_count(count));
    }
    for (int count : {0, 2, 3, 5, 32, -4}) {
        EXPECT_FALSE(litkit::valid_sample_count(count)) << count;
        EXPECT_TRUE(litkit::sample_pattern(count).empty()) << count;
    }
}

// The reference of a picture with several samples per pixel: one reference
// picture per sample, L_k = clamp(I, 0, 1) where it sees an object and
// (background/255)^γ where not, averaged in linear light, then gamma.
// Where an edge crosses a pixel (a silhouette, or between flat-shaded
// faces), a sample within float rounding (or the rasterizer's 1/256 pixel
// grid) of the edge may fall on the other side: the pixel's values with one
// sample's light replaced by any sample's of the pixel and its eight
// neighbours, or by the background's, bound it.
struct SupersampledReference {
    std::vector<std::array<std::uint8_t, 3>> rgb;
    std::vector<int> covered;  // samples that saw an object, per pixel
    std::vector<std::array<std::uint8_t, 3>> one_flip_low, one_flip_high;
};

SupersampledReference reference_supersampled(const litkit::Scene& scene) {
    const auto& positions = spec_sample_table().at(scene.output.samples);
    const std::size_t count = std::size_t(scene.output.width) * scene.output.height;
    const double gamma = scene.output.gamma;
    const glm::vec3& b = scene.output.background;
    const dvec3 background_light(std::pow(double(b.x), gamma), std::pow(double(b.y), gamma),
                                 std::pow(double(b.z), gamma));
    const std::size_t samples = positions.size();
    std::vector<dvec3> sum(count, dvec3(0.0));
    std::vector<dvec3> light(count * samples);  // L_k, pixel after pixel
    SupersampledReference result;
    result.covered.assign(count, 0);
    for (std::size_t k = 0; k < samples; ++k) {
        const ReferenceImage sample =
            reference_render(scene, positions[k].first, positions[k].second);
        for (std::size_t at = 0; at < count; ++at) {
            dvec3& l = light[at * samples + k];
            if (sample.object[at] < 0) {
                l = background_light;
            } else {
                ++result.covered[at];
                l = glm::clamp(sample.intensity[at], 0.0, 1.0);
            }
            sum[at] += l;
        }
    }
    result.rgb.resize(count);
    result.one_flip_low.resize(count);
    result.one_flip_high.resize(count);
    const double n = double(positions.size());
    // Each pixel's smallest and largest L_k, per channel.
    std::vector<dvec3> smallest(count, dvec3(1.0)), largest(count, dvec3(0.0));
    for (std::size_t at = 0; at < count; ++at) {
        for (std::size_t k = 0; k < samples; ++k) {
            smallest[at] = glm::min(smallest[at], light[at * samples + k]);
            largest[at] = glm::max(largest[at], light[at * samples + k]);
        }
    }
    const int width = scene.output.width, height = scene.output.height;
    for (int j = 0; j < height; ++j) {
        for (int i = 0; i < width; ++i) {
            const std::size_t at = std::size_t(j) * width + i;
            dvec3 low_other = background_light, high_other = background_light;
            for (int dj = -1; dj <= 1; ++dj) {
                for (int di = -1; di <= 1; ++di) {
                    const int ni = std::clamp(i + di, 0, width - 1);
                    const int nj = std::clamp(j + dj, 0, height - 1);
                    low_other = glm::min(low_other, smallest[std::size_t(nj) * width + ni]);
                    high_other = glm::max(high_other, largest[std::size_t(nj) * width + ni]);
                }
            }
            for (int c = 0; c < 3; ++c) {
                // One L_k replaced: the sum falls most when the largest goes
                // for the smallest other, and rises most the other way.
                const double low = sum[at][c] - largest[at][c] + low_other[c];
                const double high = sum[at][c] - smallest[at][c] + high_other[c];
                result.rgb[at][c] = to_byte(sum[at][c] / n, gamma);
                result.one_flip_low[at][c] = to_byte(std::min(low, sum[at][c]) / n, gamma);
                result.one_flip_high[at][c] = to_byte(std::max(high, sum[at][c]) / n, gamma);
            }
        }
    }
    return result;
}

// Renders `scene` (several samples per pixel) with the library and checks it
// against reference_supersampled, every pixel compared, silhouettes
// included: at least 99.5% of all pixels, and 95% of those that an edge
// crosses (some samples see an object, some not), within 1/255; and every
// pixel within 1/255 of the range that one sample moved across an edge
// gives (SupersampledReference).
void expect_supersampled_matches_reference(const litkit::Scene& scene, const std::string& name) {
    const SupersampledReference ref = reference_supersampled(scene);
    litkit::RenderOptions options;
    options.threads = 2;
    const litkit::Image image = litkit::render(scene, options);
    ASSERT_EQ(image.rgb.size(), ref.rgb.size() * 3);
    long within_one = 0, edge = 0, edge_within_one = 0, beyond_one_flip = 0, object = 0;
    int worst = 0;
    std::size_t worst_at = 0;
    for (std::size_t at = 0; at < ref.rgb.size(); ++at) {
        int difference = 0;
        for (int c = 0; c < 3; ++c)
            difference =
                std::max(difference, std::abs(int(image.rgb[3 * at + c]) - ref.rgb[at][c]));
        const bool crossed = ref.covered[at] > 0 && ref.covered[at] < scene.output.samples;
        within_one += difference <= 1;
        edge += crossed;
        edge_within_one += crossed && difference <= 1;
        for (int c = 0; c < 3; ++c) {
            const int got = image.rgb[3 * at + c];
            if (got < ref.one_flip_low[at][c] - 1 || got > ref.one_flip_high[at][c] + 1) {
                ++beyond_one_flip;
                break;
            }
        }
        object += ref.covered[at] > 0;
        if (difference > worst) worst = difference, worst_at = at;
    }
    const long pixels = long(ref.rgb.size());
    std::printf(
        "[ reference ] %-40s %d samples: %7.3f%% within 1/255, edges %ld (%7.3f%%), worst "
        "%d at (%zu, %zu)\n",
        name.c_str(), scene.output.samples, 100.0 * double(within_one) / double(pixels), edge,
        100.0 * double(edge_within_one) / double(std::max(edge, 1L)), worst,
        worst_at % std::size_t(scene.output.width), worst_at / std::size_t(scene.output.width));
    // Not vacuous: the objects are there, and so are edges.
    EXPECT_GE(object, pixels / 20) << name;
    EXPECT_GE(edge, 50) << name << ": too few pixels crossed by an edge";
    EXPECT_GE(double(within_one), 0.995 * double(pixels)) << name;
    EXPECT_GE(double(edge_within_one), 0.95 * double(edge)) << name;
    EXPECT_EQ(beyond_one_flip, 0) << name
                                  << ": pixels beyond one sample's difference from the "
                                     "reference";
}

class SupersampledMatchesReference : public ::testing::TestWithParam<ModelCase> {};

// Every reflection × shading model at 4 samples.
TEST_P(SupersampledMatchesReference, FourSamples) {
    const ModelCase& c = GetParam();
    litkit::Scene scene = make_scene(c.shape, c.reflection, c.shading);
    scene.output.samples = 4;
    expect_supersampled_matches_reference(scene, c.name() + "_4");
}

std::vector<ModelCase> every_model_on_the_cube() {
    std::vector<ModelCase> cases;
    for (const ModelCase& c : every_model())
        if (c.shape == ShapeKind::Cube) cases.push_back(c);
    return cases;
}

INSTANTIATE_TEST_SUITE_P(AllModels, SupersampledMatchesReference,
                         ::testing::ValuesIn(every_model_on_the_cube()),
                         [](const ::testing::TestParamInfo<ModelCase>& info) {
                             return info.param.name();
                         });

// 8 and 16 samples, a spot whose cone edge crosses the object, gamma: the
// sphere in each shading model.
TEST(SupersampledMatchesReferenceScene, EightAndSixteenSamplesSpotAndGamma) {
    for (litkit::Shading shading : all_shadings) {
        for (int samples : {8, 16}) {
            litkit::Scene scene =
                make_scene(ShapeKind::Sphere, litkit::Reflection::BlinnPhong, shading);
            scene.lights[1] = {"spot",
                               make_light(spot_across_object(), {255.0f, 255.0f, 255.0f}, 1.6f)};
            scene.output.gamma = 2.2f;
            scene.output.samples = samples;
            expect_supersampled_matches_reference(
                scene, "sphere_spot_gamma_" + name_of(shading) + "_" + std::to_string(samples));
        }
    }
}

}  // namespace
