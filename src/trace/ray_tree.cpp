// SPDX-License-Identifier: MIT
// The ray tree (ray_tree.hpp), docs/spec.md §10.2 items 1–9, one ray at a
// time, depth first.
#include "trace/ray_tree.hpp"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

#include "geometry/corner_angle.hpp"
#include "litkit/mesh.hpp"
#include "litkit/refraction.hpp"

namespace litkit::trace {

namespace {

using equations::Vec3;

Vec3<float> to_vec3(const glm::vec3& v) { return {v.x, v.y, v.z}; }
glm::vec3 to_glm(const Vec3<float>& v) { return {v.x, v.y, v.z}; }

// Rays whose path weight is below this are not traced (item 9).
constexpr float least_weight = 1.0f / 1024.0f;

float largest(const glm::vec3& v) { return std::max({v.x, v.y, v.z}); }

// acos in degrees, by corner_angle rather than acosf: the same bits in every build.
float degrees_of(float cosine) {
    const double c = std::clamp(cosine, -1.0f, 1.0f);
    return static_cast<float>(glm::degrees(corner_angle(std::sqrt(1.0 - c * c), c)));
}

// I of the model at p with unit N and unit V (docs/spec.md §4), unclamped.
glm::vec3 shade(Reflection reflection, std::span<const equations::PreparedLight> lights,
                const equations::MaterialT<float>& material, const glm::vec3& point,
                const glm::vec3& normal, const glm::vec3& to_eye) {
    const Vec3<float> p = to_vec3(point), n = to_vec3(normal), v = to_vec3(to_eye);
    return to_glm(equations::with_reflection(reflection, [&](auto model) {
        return equations::shade_point<decltype(model)::value>(lights, material, p, n, v);
    }));
}

// Items 2–6 at one hit: the interface met by a ray of unit direction d on
// the side given by `entering`, with the shading normal N_s and the face
// normal N_g (both unit, outward).
struct Bend {
    equations::Interface<float> at;
    bool geometric = false;  // N_g stood in for N_s
};

bool opposite_signs(float a, float b) { return (a > 0.0f && b < 0.0f) || (a < 0.0f && b > 0.0f); }
bool same_signs(float a, float b) { return (a > 0.0f && b > 0.0f) || (a < 0.0f && b < 0.0f); }

Bend bend(const glm::vec3& d, const glm::vec3& shading_normal, const glm::vec3& face_normal,
          bool entering, float eta) {
    const float side = entering ? 1.0f : -1.0f;
    const Vec3<float> direction = to_vec3(d);
    const Vec3<float> geometric = to_vec3(side * face_normal);
    Vec3<float> normal = to_vec3(side * shading_normal);
    // Item 2: a shading normal that faces away from the ray gives way to N_g.
    if (-equations::dot(direction, normal) <= 0.0f)
        return {equations::refract_interface(direction, geometric, eta), true};
    Bend result{equations::refract_interface(direction, normal, eta), false};
    // Item 6: T must cross the face and R must not.
    const float d_n = glm::dot(d, face_normal);
    const bool crosses = result.at.total_internal_reflection ||
                         same_signs(glm::dot(to_glm(result.at.refracted), face_normal), d_n);
    const bool turns_back = opposite_signs(glm::dot(to_glm(result.at.reflected), face_normal), d_n);
    if (!crosses || !turns_back)
        result = {equations::refract_interface(direction, geometric, eta), true};
    return result;
}

// Items 1–6 of one interface, as a node shows them.
void record_interface(RayNode& node, const Bend& b, float n1, float n2) {
    node.outcome = RayNode::Outcome::Interface;
    node.n1 = n1;
    node.n2 = n2;
    node.theta1 = degrees_of(b.at.cos_incident);
    node.theta2 = b.at.total_internal_reflection ? 0.0f : degrees_of(b.at.cos_refracted);
    node.k = b.at.k;
    node.fresnel = b.at.fresnel;
    node.total_internal_reflection = b.at.total_internal_reflection;
    node.geometric_normal = b.geometric;
}

}  // namespace

// One ray still to trace: where it starts and goes, how deep it is and what
// multiplies its L (item 9), the object it travels in, and the record.
struct RayTree::Path {
    glm::vec3 origin;
    glm::vec3 direction;  // unit
    int depth;
    glm::vec3 weight;
    std::uint32_t inside;  // no_object: the room's medium
    RayNode::Kind kind;
    std::vector<RayNode>* record;
    std::uint64_t* rays;  // the count of rays cast
};

RayTree::RayTree(std::span<const TracedObject> objects,
                 std::span<const equations::PreparedLight> lights, const Accel& accel,
                 TraceSettings settings)
    : objects_(objects), lights_(lights), accel_(accel), settings_(settings) {
    no_specular_.reserve(objects.size());
    faces_.resize(objects.size());
    for (std::size_t o = 0; o < objects.size(); ++o) {
        const TracedObject& object = objects[o];
        equations::MaterialT<float> material = object.material;
        material.ks = 0.0f;
        no_specular_.push_back(material);
        faces_[o].reserve(object.triangles.size());
        for (const auto& t : object.triangles)
            faces_[o].push_back(face_normal(object.positions[t[0]], object.positions[t[1]],
                                            object.positions[t[2]]));
        clear_.push_back(object.absorption_color == glm::vec3(1.0f));
    }
}

RayTree::Local RayTree::local(std::uint32_t object, const glm::vec3& point, const glm::vec3& normal,
                              const glm::vec3& to_eye) const {
    const TracedObject& o = objects_[object];
    return {shade(o.reflection, lights_, no_specular_[object], point, normal, to_eye),
            shade(o.reflection, lights_, o.material, point, normal, to_eye)};
}

glm::vec3 RayTree::trace(const Path& path, int parent_node) const {
    int node = -1;
    if (path.record) {
        RayNode n;
        n.kind = path.kind;
        n.depth = path.depth;
        n.parent = parent_node;
        n.inside = path.inside != no_object;
        n.origin = path.origin;
        n.direction = path.direction;
        n.weight = path.weight;
        node = static_cast<int>(path.record->size());
        path.record->push_back(n);
    }
    // Item 9: too deep or too faint: not traced, L = 0.
    if (path.depth > settings_.max_depth || largest(path.weight) < least_weight) return {};
    ++*path.rays;
    const Ray ray{path.origin, path.direction, settings_.min_distance,
                  std::numeric_limits<float>::infinity()};
    const Hit hit = path.inside == no_object ? accel_.nearest_front(ray)
                                             : accel_.nearest_back(ray, path.inside);
    if (!hit.found()) {
        // Item 8: the background from the room's medium; nothing from inside.
        const glm::vec3 radiance = path.inside == no_object ? settings_.background : glm::vec3(0);
        if (path.record) {
            RayNode& n = (*path.record)[static_cast<std::size_t>(node)];
            n.outcome =
                path.inside == no_object ? RayNode::Outcome::Background : RayNode::Outcome::Lost;
            n.local = radiance;
            n.contribution = path.weight * radiance;
            n.radiance = radiance;
        }
        return radiance;
    }
    return interact(path, hit, node);
}

// F·L(R) + (1 − F)·L(T) at `point`, where `path` meets the interface `at`:
// the mirror ray stays on the path's side, the refracted one crosses into
// `beyond` (no_object: the room's medium). Each ray's weight is
// weight·(share·F) or weight·(share·(1 − F)): `weight` the path's (times A
// inside), `share` t entering from the room, else 1.
glm::vec3 RayTree::split(const Path& path, const glm::vec3& point,
                         const equations::Interface<float>& at, const glm::vec3& weight,
                         float share, std::uint32_t beyond, int node) const {
    const float fresnel = at.fresnel;
    const Path reflected{point,          glm::normalize(to_glm(at.reflected)),
                         path.depth + 1, weight * (share * fresnel),
                         path.inside,    RayNode::Kind::Reflected,
                         path.record,    path.rays};
    glm::vec3 light = fresnel > 0.0f ? fresnel * trace(reflected, node) : glm::vec3(0.0f);
    if (!at.total_internal_reflection) {
        const Path refracted{point,          glm::normalize(to_glm(at.refracted)),
                             path.depth + 1, weight * (share * (1.0f - fresnel)),
                             beyond,         RayNode::Kind::Refracted,
                             path.record,    path.rays};
        light += (1.0f - fresnel) * trace(refracted, node);
    }
    return light;
}

glm::vec3 RayTree::interact(const Path& path, const Hit& hit, int node) const {
    const TracedObject& object = objects_[hit.object];
    const auto& corners = object.triangles[hit.triangle];
    const float b0 = 1.0f - hit.b1 - hit.b2;
    const glm::vec3 point = b0 * object.positions[corners[0]] +
                            hit.b1 * object.positions[corners[1]] +
                            hit.b2 * object.positions[corners[2]];
    const glm::vec3& face = faces_[hit.object][hit.triangle];
    glm::vec3 normal = face;
    if (object.smooth) {
        // Surfaces reached by rays are lit per point: gouraud as phong.
        const glm::vec3 mixed = b0 * object.normals[corners[0]] +
                                hit.b1 * object.normals[corners[1]] +
                                hit.b2 * object.normals[corners[2]];
        const float length = glm::length(mixed);
        if (length > 0.0f) normal = mixed / length;
    }
    const bool entering = path.inside == no_object;
    auto record = [&]() -> RayNode* {
        return path.record ? &(*path.record)[static_cast<std::size_t>(node)] : nullptr;
    };
    if (RayNode* n = record()) {
        n->object = hit.object;
        n->triangle = hit.triangle;
        n->point = point;
        n->length = hit.t;
    }
    if (entering && !(object.transmission > 0.0f)) {
        // An opaque surface: its colour with V = −d.
        const glm::vec3 color =
            shade(object.reflection, lights_, object.material, point, normal, -path.direction);
        if (RayNode* n = record()) {
            n->outcome = RayNode::Outcome::Surface;
            n->local = color;
            n->contribution = path.weight * color;
            n->radiance = color;
        }
        return color;
    }
    glm::vec3 own{0.0f};  // the local part, entering from the room
    glm::vec3 absorbed{1.0f};
    glm::vec3 weight = path.weight;
    float share = 1.0f;  // t entering from the room; 1 inside
    if (entering) {
        const Local parts = local(hit.object, point, normal, -path.direction);
        own = (1.0f - object.transmission) * parts.ambient_diffuse +
              (parts.all - parts.ambient_diffuse);
        share = object.transmission;
    } else if (!clear_[hit.object]) {
        // Item 7: Beer–Lambert along the segment inside (1^x = 1: nothing to
        // do for a colourless glass).
        absorbed = to_glm(equations::absorption(to_vec3(object.absorption_color), hit.t,
                                                object.absorption_distance));
        weight = weight * absorbed;
    }
    const float n1 = entering ? settings_.room_ior : object.ior;
    const float n2 = entering ? object.ior : settings_.room_ior;
    const Bend b = bend(path.direction, normal, face, entering, n1 / n2);
    if (RayNode* n = record()) {
        record_interface(*n, b, n1, n2);
        n->absorption = absorbed;
        n->transmission = entering ? object.transmission : 0.0f;
        n->local = own;
        n->contribution = path.weight * own;
    }
    const glm::vec3 light =
        split(path, point, b.at, weight, share, entering ? hit.object : no_object, node);
    const glm::vec3 radiance = entering ? own + share * light : absorbed * light;
    if (RayNode* n = record()) n->radiance = radiance;
    return radiance;
}

glm::vec3 RayTree::first_hit(const FirstHit& hit, std::uint64_t& rays,
                             std::vector<RayNode>* record) const {
    const TracedObject& object = objects_[hit.object];
    const glm::vec3& face = faces_[hit.object][hit.triangle];
    const float share = object.transmission;
    const Bend b =
        bend(hit.direction, hit.shading_normal, face, true, settings_.room_ior / object.ior);
    int node = -1;
    if (record) {
        RayNode n;
        n.kind = RayNode::Kind::Camera;
        n.outcome = RayNode::Outcome::Interface;
        n.direction = hit.direction;
        n.object = hit.object;
        n.triangle = hit.triangle;
        n.point = hit.point;
        record_interface(n, b, settings_.room_ior, object.ior);
        n.transmission = share;
        node = static_cast<int>(record->size());
        record->push_back(n);
    }
    const Path camera{glm::vec3(0.0f), hit.direction,         1,      glm::vec3(1.0f),
                      no_object,       RayNode::Kind::Camera, record, &rays};
    const glm::vec3 light =
        split(camera, hit.point, b.at, glm::vec3(1.0f), share, hit.object, node);
    return share * light;
}

}  // namespace litkit::trace
