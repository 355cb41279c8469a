// SPDX-License-Identifier: MIT
// The ray tree of docs/spec.md §10.2 (T. Whitted, "An Improved Illumination
// Model for Shaded Display", Communications of the ACM 23(6), 1980): the
// light that comes back along a ray through a scene of opaque and glass
// objects, with Snell's law, exact Fresnel, total internal reflection and
// Beer–Lambert absorption (litkit/refraction.hpp), nearest hits found by
// the acceleration structure (accel.hpp). The rasterizer finds what each
// pixel sees first; for a pixel on glass it lights the surface's local part
// itself and asks first_hit for the rest, t·[F·L(R) + (1 − F)·L(T)].
#pragma once

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "litkit/equations.hpp"
#include "litkit/lighting.hpp"
#include "litkit/ray_tree.hpp"
#include "litkit/refraction.hpp"
#include "trace/accel.hpp"

namespace litkit::trace {

// What the ray tree needs of an object: its triangles in world space with
// their vertex normals (views into its owner's arrays; face normals, DD8,
// the ray tree finds once), its surface and its glass.
struct TracedObject {
    std::span<const glm::vec3> positions;
    std::span<const glm::vec3> normals;  // per vertex, unit or zero (DD9, §9.2)
    std::span<const std::array<std::uint32_t, 3>> triangles;
    equations::MaterialT<float> material;
    Reflection reflection = Reflection::Phong;
    // N_s is the interpolated vertex normal (phong, gouraud), else the face
    // normal (flat, faceted).
    bool smooth = true;
    float transmission = 0.0f;  // t
    float ior = 1.5f;           // n_o
    glm::vec3 absorption_color{1.0f};
    float absorption_distance = 1.0f;  // D, in the same units as the positions
};

struct TraceSettings {
    float room_ior = 1.0f;  // n_r
    int max_depth = 8;
    // Hits of secondary rays closer than this to their origin are ignored
    // (10⁻⁶ × the room's diagonal).
    float min_distance = 0.0f;
    // L of a ray that hits nothing: (background/255)^γ per channel.
    glm::vec3 background{0.0f};
};

// The surface a pixel sees first, as the rasterizer found it.
struct FirstHit {
    std::uint32_t object = 0;
    std::uint32_t triangle = 0;
    glm::vec3 point{0.0f};           // p, on the pixel's ray
    glm::vec3 direction{0.0f};       // d, unit, from the eye through p
    glm::vec3 shading_normal{0.0f};  // N_s, unit, outward
};

// The light of a scene's rays; holds views of the objects, the lights and
// the hierarchy, which must outlive it. Queried from any number of threads.
class RayTree {
  public:
    RayTree(std::span<const TracedObject> objects, std::span<const equations::PreparedLight> lights,
            const Accel& accel, TraceSettings settings);

    // The part of a first hit's L that is traced: t·[F·L(R) + (1 − F)·L(T)]
    // (the object's t > 0). Adds the rays it casts to `rays`. `record`:
    // where to put the tree's nodes (its first node the camera's ray, to be
    // completed by the caller with the local part), or null.
    glm::vec3 first_hit(const FirstHit& hit, std::uint64_t& rays,
                        std::vector<RayNode>* record = nullptr) const;

    // The I_ad of docs/spec.md §10.2 item 8 (everything but the specular
    // part) and the whole I of `object` at p, with V = `to_eye`: the local
    // part is (1 − t)·I_ad + (I − I_ad).
    struct Local {
        glm::vec3 ambient_diffuse;
        glm::vec3 all;
    };
    Local local(std::uint32_t object, const glm::vec3& point, const glm::vec3& normal,
                const glm::vec3& to_eye) const;

    // N_g of an object's triangle (face_normal, litkit/mesh.hpp), found once
    // for all its hits.
    const glm::vec3& face(std::uint32_t object, std::uint32_t triangle) const {
        return faces_[object][triangle];
    }

  private:
    struct Path;
    glm::vec3 trace(const Path& path, int parent_node) const;
    glm::vec3 interact(const Path& path, const Hit& hit, int node) const;
    glm::vec3 split(const Path& path, const glm::vec3& point, const equations::Interface<float>& at,
                    const glm::vec3& weight, float share, std::uint32_t beyond, int node) const;

    std::span<const TracedObject> objects_;
    std::span<const equations::PreparedLight> lights_;
    const Accel& accel_;
    TraceSettings settings_;
    std::vector<equations::MaterialT<float>> no_specular_;  // per object: k_s = 0
    std::vector<std::vector<glm::vec3>> faces_;             // per object, per triangle: N_g
    std::vector<bool> clear_;  // per object: its absorption colour is (1, 1, 1)
};

}  // namespace litkit::trace
