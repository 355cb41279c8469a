// SPDX-License-Identifier: MIT
// docs/spec.md §10.1: whether a mesh is closed, the condition for an object
// that refracts. Welding and the triangles that take part are §2's (DD9):
// positions within 1e-6 × the bounding-box diagonal are one vertex, and
// zero-area triangles, and those two of whose corners are one vertex, are
// left out. The mesh is closed when every edge of the rest is used by exactly
// two triangles, once in each direction.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>

#include "litkit/mesh.hpp"

namespace litkit::detail {

// An edge that breaks the rule, as a triangle of the mesh runs along it.
struct UnclosedEdge {
    std::size_t triangle = 0;  // the first triangle, in order, that uses the edge
    std::uint32_t from = 0;    // its corners at the edge's ends, in its winding order
    std::uint32_t to = 0;      // (indices into mesh.positions)
    std::size_t forward = 0;   // how many triangles run along it from `from` to `to`
    std::size_t backward = 0;  // how many from `to` to `from`
};

// The first edge, in the order of the triangles and their corners, that is
// not used exactly once in each direction; nothing for a closed mesh (also
// for one whose triangles all take no part). Every index must be below
// positions.size() (check_mesh_data). O(n log n).
std::optional<UnclosedEdge> find_unclosed_edge(const Mesh& mesh);

}  // namespace litkit::detail
