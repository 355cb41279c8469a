// SPDX-License-Identifier: MIT
/// \file
/// Exact-enough tests between convex hulls of point sets, by GJK
/// (Gilbert–Johnson–Keerthi), for the overlap rules of docs/spec.md §6. Points are
/// used as given: the hull of a mesh is the hull of its vertices.
#pragma once

#include <glm/vec3.hpp>

#include <span>

namespace litkit {

/// True when the convex hulls of `a` and `b` share a point. Hulls that only
/// touch (share a face, an edge or a corner, within a relative 1e-6 of their
/// sizes) do not count as intersecting: two cubes side by side are allowed.
bool hulls_intersect(std::span<const glm::vec3> a, std::span<const glm::vec3> b);

/// True when `point` lies inside the convex hull of `hull` (on its boundary,
/// within the same tolerance, counts as inside).
bool hull_contains(std::span<const glm::vec3> hull, const glm::vec3& point);

}  // namespace litkit
