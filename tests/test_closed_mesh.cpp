// SPDX-License-Identifier: MIT
// docs/spec.md §10.1's closed-mesh rule (src/geometry/closed_mesh.hpp): after
// §2's welding, with zero-area triangles left out, every edge is used by
// exactly two triangles, once in each direction. The built-in cube, sphere
// and torus are closed for every parameter; the teapot is not. Every expected
// edge below is worked out by hand in the comment above its check.
#include <gtest/gtest.h>

#include <filesystem>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <vector>

#include "geometry/closed_mesh.hpp"  // internal (src/)
#include "litkit/mesh.hpp"
#include "litkit/shapes.hpp"

namespace {

using litkit::Mesh;
using litkit::detail::find_unclosed_edge;
using litkit::detail::UnclosedEdge;

// The tetrahedron (0,0,0), (1,0,0), (0,1,0), (0,0,1), each face wound
// counter-clockwise seen from outside: (0,2,1) faces −z, (0,1,3) −y, (0,3,2)
// −x and (1,2,3) (1,1,1).
Mesh tetrahedron() {
    Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    return mesh;
}

std::string describe(const std::optional<UnclosedEdge>& edge) {
    if (!edge) return "closed";
    return "triangle " + std::to_string(edge->triangle) + ", " + std::to_string(edge->from) +
           " → " + std::to_string(edge->to) + ", forward " + std::to_string(edge->forward) +
           ", backward " + std::to_string(edge->backward);
}

void expect_edge(const Mesh& mesh, std::size_t triangle, std::uint32_t from, std::uint32_t to,
                 std::size_t forward, std::size_t backward) {
    const std::optional<UnclosedEdge> edge = find_unclosed_edge(mesh);
    ASSERT_TRUE(edge.has_value()) << "expected an unclosed edge";
    EXPECT_EQ(edge->triangle, triangle) << describe(edge);
    EXPECT_EQ(edge->from, from) << describe(edge);
    EXPECT_EQ(edge->to, to) << describe(edge);
    EXPECT_EQ(edge->forward, forward) << describe(edge);
    EXPECT_EQ(edge->backward, backward) << describe(edge);
}

TEST(ClosedMesh, TheTetrahedronIsClosed) {
    EXPECT_FALSE(find_unclosed_edge(tetrahedron()).has_value())
        << describe(find_unclosed_edge(tetrahedron()));
}

TEST(ClosedMesh, AMissingFaceLeavesItsEdgesOpen) {
    // Without (1,2,3), triangle 0's edge 0→2 is matched by 2→0 of (0,3,2),
    // but its edge 2→1 had its partner 1→2 in the missing face.
    Mesh mesh = tetrahedron();
    mesh.triangles.pop_back();
    expect_edge(mesh, 0, 2, 1, 1, 0);
}

TEST(ClosedMesh, AFaceWoundTheWrongWayUsesAnEdgeTwiceInOneDirection) {
    // (1,3,2) in place of (1,2,3) runs 2→1, as triangle 0 does, and nothing
    // runs 1→2.
    Mesh mesh = tetrahedron();
    mesh.triangles[3] = {1, 3, 2};
    expect_edge(mesh, 0, 2, 1, 2, 0);
}

TEST(ClosedMesh, AThirdTriangleAtAnEdgeBreaksIt) {
    // A fin (0,1,4) on the edge 0–1 of the closed tetrahedron: 0→1 is now
    // used by (0,1,3) and the fin, 1→0 by (0,2,1). Triangle 0 (0,2,1) is the
    // first to use the edge, from 1 to 0.
    Mesh mesh = tetrahedron();
    mesh.positions.push_back({0.5f, -1.0f, -1.0f});
    mesh.triangles.push_back({0, 1, 4});
    expect_edge(mesh, 0, 1, 0, 1, 2);
}

TEST(ClosedMesh, PositionsAreWeldedAsSection2Says) {
    // Each face with corners of its own (12 positions): closed once equal
    // positions count as one vertex.
    const Mesh shared = tetrahedron();
    Mesh separate;
    for (const auto& triangle : shared.triangles) {
        const auto first = static_cast<std::uint32_t>(separate.positions.size());
        for (const std::uint32_t corner : triangle)
            separate.positions.push_back(shared.positions[corner]);
        separate.triangles.push_back({first, first + 1, first + 2});
    }
    EXPECT_FALSE(find_unclosed_edge(separate).has_value())
        << describe(find_unclosed_edge(separate));

    // Within 1e-6 × the bounding-box diagonal (√3 here) positions weld:
    // moving a corner by 1e-7 keeps the mesh closed; by 1e-3 it opens it.
    Mesh near = separate;
    near.positions[11] += glm::vec3(1e-7f, 0.0f, 0.0f);
    EXPECT_FALSE(find_unclosed_edge(near).has_value()) << describe(find_unclosed_edge(near));
    Mesh apart = separate;
    apart.positions[11] += glm::vec3(1e-3f, 0.0f, 0.0f);
    EXPECT_TRUE(find_unclosed_edge(apart).has_value());
}

TEST(ClosedMesh, ZeroAreaTrianglesAndWeldedCornersTakeNoPart) {
    // A triangle along the edge 0–1 through its midpoint (zero area), and one
    // two of whose corners are the same position: both left out, so the
    // tetrahedron stays closed.
    Mesh mesh = tetrahedron();
    mesh.positions.push_back({0.5f, 0.0f, 0.0f});
    mesh.triangles.push_back({0, 4, 1});
    mesh.triangles.push_back({2, 3, 2});
    EXPECT_FALSE(find_unclosed_edge(mesh).has_value()) << describe(find_unclosed_edge(mesh));
}

TEST(ClosedMesh, TheBuiltInCubeSphereAndTorusAreClosedForEveryParameter) {
    for (const float size : {1.0f, 0.001f, 2.5f, 1000.0f})
        EXPECT_FALSE(find_unclosed_edge(litkit::make_cube(size)).has_value())
            << "cube " << size << ": " << describe(find_unclosed_edge(litkit::make_cube(size)));
    // The fewest segments and rings (3, 2: a triangular bipyramid, three
    // triangles at each pole and nothing between), odd and even counts, and
    // the default.
    const int spheres[][2] = {{3, 2}, {4, 2}, {3, 3}, {5, 4}, {7, 13}, {64, 32}, {6, 100}};
    for (const auto& [segments, rings] : spheres) {
        for (const float radius : {1.0f, 0.01f, 300.0f}) {
            const Mesh sphere = litkit::make_sphere(radius, segments, rings);
            EXPECT_FALSE(find_unclosed_edge(sphere).has_value())
                << "sphere " << radius << " " << segments << "×" << rings << ": "
                << describe(find_unclosed_edge(sphere));
        }
    }
    const int tori[][2] = {{3, 3}, {4, 5}, {5, 3}, {64, 32}, {100, 7}};
    for (const auto& [segments, sides] : tori) {
        for (const auto& [major, minor] :
             {std::pair(1.0f, 0.25f), std::pair(1.0f, 0.99f), std::pair(50.0f, 0.5f)}) {
            const Mesh torus = litkit::make_torus(major, minor, segments, sides);
            EXPECT_FALSE(find_unclosed_edge(torus).has_value())
                << "torus " << major << "/" << minor << " " << segments << "×" << sides << ": "
                << describe(find_unclosed_edge(torus));
        }
    }
}

TEST(ClosedMesh, TheTeapotIsNotClosed) {
    for (const int subdivisions : {1, 2, 10})
        EXPECT_TRUE(find_unclosed_edge(litkit::make_teapot(1.0f, subdivisions)).has_value())
            << "subdivisions " << subdivisions;
}

TEST(ClosedMesh, TheTestCubeFilesAreClosedAndOpen) {
    const std::filesystem::path folder = std::filesystem::path(LITKIT_TEST_DATA) / "obj";
    const Mesh closed = litkit::load_obj(folder / "closed_cube.obj");
    EXPECT_FALSE(find_unclosed_edge(closed).has_value()) << describe(find_unclosed_edge(closed));
    // Face 1 (f 5 6 7 8) is the fan (5,6,7), (5,7,8) (0-based positions 4,
    // 5, 6 and 4, 6, 7). Triangle 0's edges all have partners: 4→5 in the
    // bottom face (1 2 6 5), 5→6 in the +x face (6 2 3 7), 6→4 in triangle
    // 1. Triangle 1's 6→7, from (0.5, 0.5, 0.5) to (-0.5, 0.5, 0.5), had
    // its partner in the missing top face.
    const Mesh open = litkit::load_obj(folder / "open_cube.obj");
    expect_edge(open, 1, 6, 7, 1, 0);
    EXPECT_EQ(open.positions[6], glm::vec3(0.5f, 0.5f, 0.5f));
    EXPECT_EQ(open.positions[7], glm::vec3(-0.5f, 0.5f, 0.5f));
}

}  // namespace
