// SPDX-License-Identifier: MIT
// The tracer's acceleration structure (docs/spec.md §10.2 item 8): nearest
// hits of rays against the scene's triangles in world space, with the face
// rules of refraction. A ray in the room's medium hits only front faces
// (d·N_g < 0, N_g = (p1 − p0) × (p2 − p0) from the winding, DD8) of any
// object; a ray inside an object hits only that object's back faces
// (d·N_g > 0). A triangle edge-on to the ray (d·N_g = 0) is hit by neither.
// Ray–triangle tests are watertight (S. Woop, C. Benthin and I. Wald,
// "Watertight Ray/Triangle Intersection", JCGT 2(1), 2013): a ray through an
// edge or a vertex shared by triangles of a closed mesh hits at least one of
// them. Between hits at the same distance the smaller (object, triangle)
// wins, so that the answer does not depend on the order of the hierarchy.
#pragma once

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <span>

#include "core/parallel.hpp"

namespace litkit::trace {

// One object's triangles in world space: views into its owner's arrays,
// which must outlive the Accel built over them.
struct MeshView {
    std::span<const glm::vec3> positions;
    std::span<const std::array<std::uint32_t, 3>> triangles;
};

// A ray: origin + t·direction for t in (t_min, t_max). `direction` need not
// be unit length; t is in its units.
struct Ray {
    glm::vec3 origin{0.0f};
    glm::vec3 direction{0.0f, 0.0f, -1.0f};
    float t_min = 0.0f;
    float t_max = std::numeric_limits<float>::infinity();
};

inline constexpr std::uint32_t no_object = ~std::uint32_t{0};

// The nearest hit of a ray, or none (object == no_object).
struct Hit {
    float t = std::numeric_limits<float>::infinity();
    std::uint32_t object = no_object;
    std::uint32_t triangle = 0;  // within the object
    // The hit point's barycentric weights of the triangle's corners 1 and
    // 2 (corner 0's is 1 − b1 − b2), each in [0, 1].
    float b1 = 0.0f, b2 = 0.0f;
    bool found() const { return object != no_object; }
};

// A bounding-volume hierarchy over the triangles of every object, built once
// (binned surface-area heuristic), queried from any number of threads.
class Accel {
  public:
    // Builds over `objects` (indices into it are the hits' `object`);
    // `parallel` lends threads to the build (empty: the calling thread).
    // The result does not depend on how the build was run.
    explicit Accel(std::span<const MeshView> objects, const ParallelFor& parallel = {});
    ~Accel();
    Accel(Accel&&) noexcept;
    Accel& operator=(Accel&&) noexcept;

    // The nearest front face of any object along `ray` (rays in the room's medium).
    Hit nearest_front(const Ray& ray) const;
    // The nearest back face of object `object` along `ray` (rays inside it).
    Hit nearest_back(const Ray& ray, std::uint32_t object) const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace litkit::trace
