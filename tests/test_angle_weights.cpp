// SPDX-License-Identifier: MIT
// Angle-weighted vertex normals (docs/spec.md §9.2) bit for bit as the
// plain arithmetic gives them: the library computes two triangles' corner
// angles at a time in the lanes of double vectors, and must round exactly
// as the one-triangle formula written out here does (glm's cross and dot in
// double, the square root, corner_angle, the sums in triangle order).
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numbers>
#include <random>
#include <vector>

#include "geometry/corner_angle.hpp"  // internal
#include "geometry/weld.hpp"          // internal
#include "litkit/mesh.hpp"
#include "litkit/shapes.hpp"

namespace {

using litkit::Mesh;
using litkit::Normals;

// The reference: docs/spec.md §9.2's angle weighting, one triangle at a time.
std::vector<glm::vec3> angle_normals_by_hand(const Mesh& mesh) {
    const std::vector<std::uint32_t> vertex_of = litkit::detail::weld(mesh.positions);
    std::vector<glm::vec3> sums(mesh.positions.size(), glm::vec3(0.0f));
    for (const auto& triangle : mesh.triangles) {
        const std::uint32_t a = vertex_of[triangle[0]], b = vertex_of[triangle[1]],
                            c = vertex_of[triangle[2]];
        if (a == b || b == c || c == a) continue;
        const glm::dvec3 p[3] = {glm::dvec3(mesh.positions[triangle[0]]),
                                 glm::dvec3(mesh.positions[triangle[1]]),
                                 glm::dvec3(mesh.positions[triangle[2]])};
        const glm::dvec3 cross = glm::cross(p[1] - p[0], p[2] - p[0]);
        const double length = glm::length(cross);
        if (!(length > 0.0) || !std::isfinite(length)) continue;
        const glm::dvec3 unit = cross / length;
        const double angle0 = litkit::corner_angle(length, glm::dot(p[1] - p[0], p[2] - p[0]));
        const double angle1 = litkit::corner_angle(length, glm::dot(p[2] - p[1], p[0] - p[1]));
        const double angle2 = std::max(0.0, std::numbers::pi - angle0 - angle1);
        const double angles[3] = {angle0, angle1, angle2};
        for (int k = 0; k < 3; ++k) sums[vertex_of[triangle[k]]] += glm::vec3(angles[k] * unit);
    }
    std::vector<glm::vec3> normals(mesh.positions.size());
    for (std::size_t i = 0; i < normals.size(); ++i) {
        const glm::vec3 sum = sums[vertex_of[i]];
        const float length = glm::length(sum);
        normals[i] = length > 0.0f ? sum / length : glm::vec3(0.0f);
    }
    return normals;
}

bool same_bits(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof a[0]) == 0;
}

// Random triangles over a few shared points: obtuse and acute corners
// (both branches of the arctangent, either sign of the cosine), zero-area
// triangles (a repeated corner, three points on a line), and an odd count.
Mesh random_mesh() {
    std::mt19937 random(20261128);
    std::uniform_real_distribution<float> coordinate(-2.0f, 2.0f);
    Mesh mesh;
    for (int i = 0; i < 40; ++i)
        mesh.positions.emplace_back(coordinate(random), coordinate(random), coordinate(random));
    mesh.positions.emplace_back(0.0f, 0.0f, 0.0f);
    mesh.positions.emplace_back(1.0f, 1.0f, 1.0f);
    mesh.positions.emplace_back(2.0f, 2.0f, 2.0f);  // on the line through the two above
    std::uniform_int_distribution<std::uint32_t> index(0, 39);
    for (int t = 0; t < 301; ++t)
        mesh.triangles.push_back({index(random), index(random), index(random)});
    mesh.triangles.push_back({40, 41, 42});
    mesh.triangles.push_back({3, 3, 7});
    return mesh;
}

}  // namespace

TEST(AngleWeights, VertexNormalsAreTheOneTriangleFormulasBitForBit) {
    const Mesh meshes[] = {litkit::make_sphere(1.5f, 64, 33), litkit::make_torus(2.0f, 0.5f, 17, 9),
                           litkit::make_cube(2.0f), random_mesh()};
    for (const Mesh& mesh : meshes) {
        const std::vector<glm::vec3> expected = angle_normals_by_hand(mesh);
        EXPECT_TRUE(same_bits(litkit::vertex_normals(mesh, Normals::Angle), expected))
            << mesh.triangles.size() << " triangles";
    }
}
