// Triangle meshes (AB4) and their normals (docs/spec.md §2, DD8, DD9).
#pragma once

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace litkit {

// An indexed triangle mesh. Triangles wind counter-clockwise seen from
// outside. Positions that coincide may appear more than once (a sphere's
// seam, a cube's face corners); normals treat them as one vertex.
struct Mesh {
    std::vector<glm::vec3> positions;
    std::vector<std::array<std::uint32_t, 3>> triangles;
};

// DD8: normalize((b − a) × (c − a)); the zero vector for a zero-area triangle.
glm::vec3 face_normal(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c);

// DD9: for each entry of mesh.positions, the normalised plain mean of the face
// normals of every triangle touching that position, where positions within
// 1e-6 × the bounding-box diagonal count as one (transitively: a chain of such
// positions is one vertex). Zero-area triangles take no part, nor do
// triangles two of whose corners count as one. A position touched by no
// usable triangle gets the zero vector. O(n log n); throws ArgumentError
// for a triangle index beyond the positions.
std::vector<glm::vec3> vertex_normals(const Mesh& mesh);

// Axis-aligned bounding box of the positions (both zero for an empty mesh).
struct Bounds {
    glm::vec3 min{0.0f};
    glm::vec3 max{0.0f};
};
Bounds bounds(const Mesh& mesh);

}  // namespace litkit
