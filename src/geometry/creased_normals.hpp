// SPDX-License-Identifier: MIT
// docs/spec.md §9.2 crease normals in the form world_mesh splits positions
// by: a normal per position where nothing can split, and a normal per
// corner only at the vertices where faces may part (corner_normals in
// mesh.hpp gives the same normals as one per corner).
#pragma once

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

#include "core/parallel.hpp"
#include "litkit/mesh.hpp"

namespace litkit {

struct CreasedNormals {
    // Per position, the welded vertex it belongs to; per vertex (indexed
    // like positions, by the vertex's first position), its normal and
    // whether the faces at it may have different normals (then its corners
    // are listed below). Kept per vertex, not copied per position: on a
    // 261k-triangle mesh every megabyte of fresh memory is measurable.
    std::vector<std::uint32_t> vertex_of_position;
    std::vector<glm::vec3> vertex_normals;
    std::vector<std::uint8_t> may_split;

    const glm::vec3& position_normal(std::uint32_t position) const {
        return vertex_normals[vertex_of_position[position]];
    }
    bool position_may_split(std::uint32_t position) const {
        return may_split[vertex_of_position[position]] != 0;
    }
    // The corners (3·t + k) at those vertices, in increasing order, and
    // each one's normal.
    std::vector<std::uint32_t> split_corners;
    std::vector<glm::vec3> split_normals;
};

// Throws as corner_normals does.
CreasedNormals creased_normals(const Mesh& mesh, Normals weighting, float crease_angle_degrees);

// vertex_normals(mesh, weighting), its independent parts run through
// `parallel`: the welding beside the triangles' weights (Mean and Area, one
// vector a triangle), and the normalising. The same normals, bit for bit:
// the weights are summed in triangle order on the calling thread.
std::vector<glm::vec3> vertex_normals(const Mesh& mesh, Normals weighting,
                                      const ParallelFor& parallel);

}  // namespace litkit
