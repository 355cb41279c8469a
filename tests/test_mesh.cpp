// SPDX-License-Identifier: MIT
// Unit tests for face normals, vertex normals and bounds (docs/spec.md §2, DD8, DD9).
// Every expected value is worked out by hand in the comment above its check.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <random>
#include <stdexcept>
#include <vector>

#include "geometry/mesh_formats.hpp"  // internal (src/)
#include "litkit/error.hpp"
#include "litkit/mesh.hpp"
#include "litkit/shapes.hpp"

namespace {

using litkit::bounds;
using litkit::face_normal;
using litkit::Mesh;
using litkit::vertex_normals;

constexpr float tolerance = 1e-6f;

void expect_near(const glm::vec3& actual, const glm::vec3& expected, float within = tolerance) {
    EXPECT_NEAR(actual.x, expected.x, within);
    EXPECT_NEAR(actual.y, expected.y, within);
    EXPECT_NEAR(actual.z, expected.z, within);
}

// A mesh of unconnected triangles: every corner gets its own position, so any
// sharing must come from welding by position.
Mesh triangle_soup(const std::vector<std::array<glm::vec3, 3>>& triangles) {
    Mesh mesh;
    for (const auto& corners : triangles) {
        const auto first = static_cast<std::uint32_t>(mesh.positions.size());
        mesh.positions.insert(mesh.positions.end(), corners.begin(), corners.end());
        mesh.triangles.push_back({first, first + 1, first + 2});
    }
    return mesh;
}

TEST(FaceNormal, CounterClockwiseInXyPlanePointsAlongPlusZ) {
    // (b − a) × (c − a) = (1, 0, 0) × (0, 1, 0) = (0, 0, 1).
    expect_near(face_normal({0, 0, 0}, {1, 0, 0}, {0, 1, 0}), {0, 0, 1});
}

TEST(FaceNormal, ClockwiseWindingFlipsTheNormal) {
    // (0, 1, 0) × (1, 0, 0) = (0, 0, −1).
    expect_near(face_normal({0, 0, 0}, {0, 1, 0}, {1, 0, 0}), {0, 0, -1});
}

TEST(FaceNormal, TiltedTriangleGivesUnitNormal) {
    // b − a = (−1, 2, 0), c − a = (−1, 0, 3);
    // cross = (2·3 − 0·0, 0·(−1) − (−1)·3, (−1)·0 − 2·(−1)) = (6, 3, 2), length 7.
    expect_near(face_normal({1, 0, 0}, {0, 2, 0}, {0, 0, 3}), {6.0f / 7, 3.0f / 7, 2.0f / 7});
}

TEST(FaceNormal, DoesNotDependOnTheTrianglesSizeOrPlace) {
    // The same shape as above, scaled by 1e-20 (its cross product, 1e-40,
    // underflows single precision) and moved far away.
    expect_near(face_normal({1e-20f, 0, 0}, {0, 2e-20f, 0}, {0, 0, 3e-20f}),
                {6.0f / 7, 3.0f / 7, 2.0f / 7});
    expect_near(face_normal({1001, 1000, 1000}, {1000, 1002, 1000}, {1000, 1000, 1003}),
                {6.0f / 7, 3.0f / 7, 2.0f / 7}, 1e-5f);
}

TEST(FaceNormal, ZeroAreaTriangleGivesZeroVector) {
    // Collinear corners: (1, 1, 1) × (2, 2, 2) = 0.
    expect_near(face_normal({0, 0, 0}, {1, 1, 1}, {2, 2, 2}), {0, 0, 0}, 0.0f);
    // Two equal corners.
    expect_near(face_normal({1, 2, 3}, {1, 2, 3}, {4, 5, 7}), {0, 0, 0}, 0.0f);
}

TEST(VertexNormals, SingleTriangleGivesItsFaceNormalAtEveryCorner) {
    const Mesh mesh = triangle_soup({{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}});
    const std::vector<glm::vec3> normals = vertex_normals(mesh);
    ASSERT_EQ(normals.size(), 3u);
    for (const glm::vec3& normal : normals) expect_near(normal, {0, 0, 1});
}

TEST(VertexNormals, IsThePlainMeanNotWeightedByAreaOrAngle) {
    // The origin O is a corner of
    //   T1 = (O, (10, 0, 0), (0, 10, 0)): normal (0, 0, 1), area 50, angle at O 90°;
    //   T2 = (O, (0, 1, 0), (0, 1, 1)): (0, 1, 0) × (0, 1, 1) = (1, 0, 0),
    //        area 0.5, angle at O 45°.
    // Plain mean: normalize((0, 0, 1) + (1, 0, 0)) = (1/√2, 0, 1/√2).
    // (Area weighting would give normalize(0.5, 0, 50), angle weighting
    // normalize(45, 0, 90): both far from this.) O appears twice in the
    // positions, so the two triangles share it only through welding.
    const Mesh mesh =
        triangle_soup({{{{0, 0, 0}, {10, 0, 0}, {0, 10, 0}}}, {{{0, 0, 0}, {0, 1, 0}, {0, 1, 1}}}});
    const std::vector<glm::vec3> normals = vertex_normals(mesh);
    ASSERT_EQ(normals.size(), 6u);
    const float half_sqrt2 = std::sqrt(0.5f);
    expect_near(normals[0], {half_sqrt2, 0, half_sqrt2});
    expect_near(normals[3], {half_sqrt2, 0, half_sqrt2});
    // The other corners belong to one triangle each: (0, 10, 0) and (0, 1, 0)
    // are distinct positions.
    expect_near(normals[1], {0, 0, 1});
    expect_near(normals[2], {0, 0, 1});
    expect_near(normals[4], {1, 0, 0});
    expect_near(normals[5], {1, 0, 0});
}

TEST(VertexNormals, EqualPositionsAreOneVertexWhetherIndexedOnceOrTwice) {
    // A "roof" of two triangles on the edge from O = (0, 0, 0) to X = (1, 0, 0):
    //   (O, X, (0, 1, 0)): (1, 0, 0) × (0, 1, 0) = (0, 0, 1);
    //   (O, X, (0, 0, −1)): (1, 0, 0) × (0, 0, −1) = (0·(−1) − 0·0, 0·0 − 1·(−1), 0) = (0, 1, 0).
    // O and X get normalize((0, 0, 1) + (0, 1, 0)) = (0, 1/√2, 1/√2), the
    // same whether the mesh shares them by index or repeats them.
    const float half_sqrt2 = std::sqrt(0.5f);
    Mesh indexed;
    indexed.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, -1}};
    indexed.triangles = {{0, 1, 2}, {0, 1, 3}};
    const Mesh repeated =
        triangle_soup({{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}, {{{0, 0, 0}, {1, 0, 0}, {0, 0, -1}}}});

    const std::vector<glm::vec3> from_indexed = vertex_normals(indexed);
    expect_near(from_indexed[0], {0, half_sqrt2, half_sqrt2});
    expect_near(from_indexed[1], {0, half_sqrt2, half_sqrt2});
    expect_near(from_indexed[2], {0, 0, 1});
    expect_near(from_indexed[3], {0, 1, 0});

    const std::vector<glm::vec3> from_repeated = vertex_normals(repeated);
    expect_near(from_repeated[0], {0, half_sqrt2, half_sqrt2});
    expect_near(from_repeated[1], {0, half_sqrt2, half_sqrt2});
    expect_near(from_repeated[3], {0, half_sqrt2, half_sqrt2});
    expect_near(from_repeated[4], {0, half_sqrt2, half_sqrt2});
}

// Two triangles meeting near the origin: A = (O, (1,0,0), (0,1,0)) with
// normal (0, 0, 1), and B = (P, P + (0,−1,1), P + (0,−1,0)) with
// (0,−1,1) × (0,−1,0) = (−1·0 − 1·(−1), 1·0 − 0·0, 0) = (1, 0, 0), where
// P = (offset, 0, 0). The bounding box is [0, 1] × [−1, 1] × [0, 1] (offset
// is far below 1), so the diagonal is √(1 + 4 + 1) = √6 and the weld
// distance 1e-6·√6 ≈ 2.449e-6.
Mesh two_triangles_meeting_near_origin(float offset) {
    const glm::vec3 p{offset, 0, 0};
    return triangle_soup({{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}},
                          {{p, p + glm::vec3(0, -1, 1), p + glm::vec3(0, -1, 0)}}});
}

TEST(VertexNormals, PositionsWithinTheWeldDistanceAreOneVertex) {
    // 2e-6 < 2.449e-6: O and P weld, both get normalize((0,0,1) + (1,0,0)).
    const std::vector<glm::vec3> normals = vertex_normals(two_triangles_meeting_near_origin(2e-6f));
    const float half_sqrt2 = std::sqrt(0.5f);
    expect_near(normals[0], {half_sqrt2, 0, half_sqrt2});
    expect_near(normals[3], {half_sqrt2, 0, half_sqrt2});
}

TEST(VertexNormals, PositionsBeyondTheWeldDistanceStayApart) {
    // 3e-6 > 2.449e-6: O keeps A's normal, P keeps B's.
    const std::vector<glm::vec3> normals = vertex_normals(two_triangles_meeting_near_origin(3e-6f));
    expect_near(normals[0], {0, 0, 1});
    expect_near(normals[3], {1, 0, 0});
}

TEST(VertexNormals, WeldDistanceScalesWithTheBoundingBox) {
    // The same mesh scaled by 1000: the weld distance becomes 2.449e-3, so an
    // offset of 2e-3 welds and 3e-3 does not.
    auto scaled = [](float offset) {
        Mesh mesh = two_triangles_meeting_near_origin(offset / 1000.0f);
        for (glm::vec3& position : mesh.positions) position *= 1000.0f;
        return vertex_normals(mesh);
    };
    const float half_sqrt2 = std::sqrt(0.5f);
    expect_near(scaled(2e-3f)[3], {half_sqrt2, 0, half_sqrt2}, 1e-5f);
    expect_near(scaled(3e-3f)[3], {1, 0, 0}, 1e-5f);
}

TEST(VertexNormals, WeldingIsTransitiveAlongAChainOfClosePositions) {
    // Weld distance as above, 2.449e-6 (the third triangle stays inside the
    // box). Corners at x = 0 (A), 2e-6 (B) and 4e-6 (a copy of A moved
    // along x, normal (0, 0, 1)): neighbours are within the weld distance,
    // the two ends (4e-6 apart) are not, yet the chain makes them one vertex.
    // Sum of the three face normals: 2·(0, 0, 1) + (1, 0, 0) → (1, 0, 2)/√5.
    Mesh mesh = two_triangles_meeting_near_origin(2e-6f);
    const glm::vec3 q{4e-6f, 0, 0};
    const auto first = static_cast<std::uint32_t>(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(),
                          {q, q + glm::vec3(1, 0, 0), q + glm::vec3(0, 1, 0)});
    mesh.triangles.push_back({first, first + 1, first + 2});

    const std::vector<glm::vec3> normals = vertex_normals(mesh);
    const glm::vec3 expected = glm::vec3(1, 0, 2) / std::sqrt(5.0f);
    expect_near(normals[0], expected);
    expect_near(normals[3], expected);
    expect_near(normals[first], expected);
}

TEST(VertexNormals, WeldingFindsNeighboursAcrossAnyGridCellBorder) {
    // 20000 pairs of small triangles scattered over the unit cube, each pair
    // meeting at two positions 0.5 weld distances apart in a random
    // direction, and 20000 more pairs whose positions are 1.5 weld distances
    // apart. Wherever the grid of a spatial search puts its cell borders,
    // some pairs straddle them (with cells of 1024 weld distances, five of
    // the close pairs: leaving out the search across borders fails this
    // test): every close pair must weld (normal of the two faces' mean) and
    // no distant pair may (each keeps its own normal).
    std::mt19937 random(20240611u);
    std::uniform_real_distribution<float> coordinate(0.01f, 0.99f);
    std::normal_distribution<float> gaussian(0.0f, 1.0f);

    Mesh mesh;
    // Two corners that bound the mesh: the box is exactly the unit cube
    // (diagonal √3, weld distance 1e-6·√3 ≈ 1.732e-6).
    mesh.positions = {{0, 0, 0}, {1, 1, 1}};
    const float weld_distance = 1e-6f * std::sqrt(3.0f);
    const float edge = 1e-4f;  // small triangles, far from other pairs

    struct Pair {
        std::uint32_t first_corner;
        std::uint32_t second_corner;
        bool close;
    };
    std::vector<Pair> pairs;
    for (int pair = 0; pair < 40000; ++pair) {
        const bool close = pair % 2 == 0;
        const glm::vec3 corner{coordinate(random), coordinate(random), coordinate(random)};
        const glm::vec3 direction =
            glm::normalize(glm::vec3(gaussian(random), gaussian(random), gaussian(random)));
        const glm::vec3 other = corner + direction * weld_distance * (close ? 0.5f : 1.5f);
        const auto first = static_cast<std::uint32_t>(mesh.positions.size());
        // Normal (0, 0, 1) at `corner`, normal (1, 0, 0) at `other` (as in
        // two_triangles_meeting_near_origin).
        mesh.positions.insert(
            mesh.positions.end(),
            {corner, corner + glm::vec3(edge, 0, 0), corner + glm::vec3(0, edge, 0), other,
             other + glm::vec3(0, -edge, edge), other + glm::vec3(0, -edge, 0)});
        mesh.triangles.push_back({first, first + 1, first + 2});
        mesh.triangles.push_back({first + 3, first + 4, first + 5});
        pairs.push_back({first, first + 3, close});
    }

    const std::vector<glm::vec3> normals = vertex_normals(mesh);
    const float half_sqrt2 = std::sqrt(0.5f);
    int wrong = 0;
    for (const Pair& pair : pairs) {
        const glm::vec3 expected_first =
            pair.close ? glm::vec3(half_sqrt2, 0, half_sqrt2) : glm::vec3(0, 0, 1);
        const glm::vec3 expected_second =
            pair.close ? glm::vec3(half_sqrt2, 0, half_sqrt2) : glm::vec3(1, 0, 0);
        if (glm::length(normals[pair.first_corner] - expected_first) > 1e-5f ||
            glm::length(normals[pair.second_corner] - expected_second) > 1e-5f) {
            ++wrong;
        }
    }
    EXPECT_EQ(wrong, 0);
}

TEST(VertexNormals, ZeroAreaTrianglesTakeNoPart) {
    // A proper triangle with normal (0, 0, 1) and, sharing its corner O, a
    // zero-area one (collinear corners). O keeps (0, 0, 1); the far corners of
    // the degenerate triangle, touched by no usable triangle, get zero.
    const Mesh mesh =
        triangle_soup({{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}, {{{0, 0, 0}, {0, 0, 1}, {0, 0, 2}}}});
    const std::vector<glm::vec3> normals = vertex_normals(mesh);
    expect_near(normals[0], {0, 0, 1});
    expect_near(normals[3], {0, 0, 1});
    expect_near(normals[4], {0, 0, 0}, 0.0f);
    expect_near(normals[5], {0, 0, 0}, 0.0f);
}

TEST(VertexNormals, TriangleCollapsedByWeldingTakesNoPart) {
    // A sliver (O, (1e-6, 0, 0), (0, −1, 1)): not zero-area as given (its
    // normal is (0, −1/√2, −1/√2)), but two of its corners weld (1e-6 < weld distance 2.449e-6 of
    // the box [0,1] × [−1,1] × [0,1]), so in the welded mesh it is zero-area and O keeps the normal
    // (0, 0, 1) of the proper triangle.
    const Mesh mesh = triangle_soup(
        {{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}, {{{0, 0, 0}, {1e-6f, 0, 0}, {0, -1, 1}}}});
    const std::vector<glm::vec3> normals = vertex_normals(mesh);
    expect_near(normals[0], {0, 0, 1});
    expect_near(normals[3], {0, 0, 1});
    expect_near(normals[4], {0, 0, 1});
}

TEST(VertexNormals, OppositeFacesCancelToZero) {
    // The same triangle twice, once each way round: (0,0,1) + (0,0,−1) = 0.
    const Mesh mesh =
        triangle_soup({{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}, {{{0, 0, 0}, {0, 1, 0}, {1, 0, 0}}}});
    for (const glm::vec3& normal : vertex_normals(mesh)) expect_near(normal, {0, 0, 0}, 0.0f);
}

TEST(VertexNormals, EmptyMeshAndUnusedPositions) {
    EXPECT_TRUE(vertex_normals(Mesh{}).empty());
    Mesh mesh;
    mesh.positions = {{5, 5, 5}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.triangles = {{1, 2, 3}};
    const std::vector<glm::vec3> normals = vertex_normals(mesh);
    ASSERT_EQ(normals.size(), 4u);
    expect_near(normals[0], {0, 0, 0}, 0.0f);  // no triangle touches (5, 5, 5)
    expect_near(normals[1], {0, 0, 1});
}

TEST(VertexNormals, IndexOutOfRangeThrows) {
    Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.triangles = {{0, 1, 3}};
    EXPECT_THROW(vertex_normals(mesh), litkit::ArgumentError);
}

TEST(Bounds, AreTheSmallestAndLargestCoordinates) {
    Mesh mesh;
    mesh.positions = {{1, -2, 3}, {-4, 5, 0.5f}, {2, 0, -6}};
    const litkit::Bounds box = bounds(mesh);
    expect_near(box.min, {-4, -2, -6}, 0.0f);
    expect_near(box.max, {2, 5, 3}, 0.0f);
}

TEST(Bounds, OfEmptyMeshAreZero) {
    const litkit::Bounds box = bounds(Mesh{});
    expect_near(box.min, {0, 0, 0}, 0.0f);
    expect_near(box.max, {0, 0, 0}, 0.0f);
}

// Mesh files are read by their extension's reader (geometry/mesh_formats.cpp),
// without regard to case; OBJ reads a file of any other extension too, and
// an object's format key overrides the extension.
TEST(MeshFormats, TheExtensionChoosesTheReaderWithoutRegardToCase) {
    using litkit::MeshFileFormat;
    const std::pair<const char*, MeshFileFormat> cases[] = {
        {"a.obj", MeshFileFormat::Obj},     {"b.OBJ", MeshFileFormat::Obj},
        {"e", MeshFileFormat::Obj},         {"f.obj.txt", MeshFileFormat::Obj},
        {"g.ply", MeshFileFormat::Ply},     {"h.PlY", MeshFileFormat::Ply},
        {"d.stl", MeshFileFormat::Stl},     {"i.STL", MeshFileFormat::Stl},
        {"j.gltf", MeshFileFormat::Gltf},   {"k.GLB", MeshFileFormat::Gltf},
        {"dir.stl/l", MeshFileFormat::Obj}, {"m.ply.obj", MeshFileFormat::Obj},
    };
    for (const auto& [name, expected] : cases) {
        EXPECT_EQ(litkit::mesh_file_format(name), expected) << name;
        EXPECT_EQ(litkit::detail::mesh_format(name).format, expected) << name;
    }
    EXPECT_EQ(litkit::detail::mesh_format("a.obj").read, &litkit::load_obj);
    EXPECT_EQ(litkit::detail::mesh_format("a.obj").line_of_face, &litkit::line_of_face);
    EXPECT_EQ(litkit::detail::mesh_format("a.ply").read, &litkit::load_ply);
    EXPECT_EQ(litkit::detail::mesh_format("a.stl").read, &litkit::load_stl);
    EXPECT_EQ(litkit::detail::mesh_format("a.glb").read, &litkit::load_gltf);
}

TEST(MeshFormats, AGivenFormatOverridesTheExtension) {
    using litkit::MeshFileFormat;
    EXPECT_EQ(litkit::detail::mesh_format("a.obj", MeshFileFormat::Stl).read, &litkit::load_stl);
    EXPECT_EQ(litkit::detail::mesh_format("scan.txt", MeshFileFormat::Ply).read, &litkit::load_ply);
    EXPECT_EQ(litkit::detail::mesh_format("a.ply", MeshFileFormat::Obj).read, &litkit::load_obj);
}

TEST(MeshFormats, NamesRoundTripInTheEnumerationsOrder) {
    EXPECT_EQ(litkit::mesh_file_format_names.size(), 4u);
    for (std::size_t i = 0; i < litkit::mesh_file_format_names.size(); ++i) {
        const auto format = static_cast<litkit::MeshFileFormat>(i);
        EXPECT_EQ(litkit::to_string(format), litkit::mesh_file_format_names[i]);
        EXPECT_EQ(litkit::parse_mesh_file_format(litkit::mesh_file_format_names[i]), format);
    }
    EXPECT_EQ(litkit::parse_mesh_file_format("glb"), std::nullopt);
    EXPECT_EQ(litkit::parse_mesh_file_format("PLY"), std::nullopt);
}

}  // namespace
