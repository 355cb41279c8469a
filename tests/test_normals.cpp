// SPDX-License-Identifier: MIT
// Vertex normals weighted by area, angle and Max's weights, creases, and a
// mesh file's own normals (docs/spec.md §9.2). Every expected value is worked
// out by hand in the comment above its check.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/parallel.hpp"             // internal (src/)
#include "core/thread_pool.hpp"          // internal
#include "geometry/corner_angle.hpp"     // internal
#include "geometry/creased_normals.hpp"  // internal
#include "litkit/error.hpp"
#include "litkit/mesh.hpp"
#include "litkit/render.hpp"
#include "litkit/scene.hpp"
#include "litkit/shapes.hpp"
#include "litkit/validate.hpp"
#include "scene/world_mesh.hpp"  // internal

namespace {

namespace fs = std::filesystem;
using litkit::corner_normals;
using litkit::Mesh;
using litkit::Normals;
using litkit::vertex_normals;

constexpr std::array<Normals, 4> weightings{Normals::Mean, Normals::Area, Normals::Angle,
                                            Normals::Max};

void expect_near(const glm::vec3& actual, const glm::vec3& expected, float within = 1e-6f) {
    EXPECT_NEAR(actual.x, expected.x, within)
        << "actual " << actual.x << ", " << actual.y << ", " << actual.z;
    EXPECT_NEAR(actual.y, expected.y, within);
    EXPECT_NEAR(actual.z, expected.z, within);
}

std::uint32_t add(Mesh& mesh, const glm::vec3& position) {
    mesh.positions.push_back(position);
    return static_cast<std::uint32_t>(mesh.positions.size() - 1);
}

// A square face given by its corners counter-clockwise seen from outside,
// split on its first diagonal (v0, v2): triangles (v0, v1, v2), (v0, v2, v3).
// Every face has its own positions, so that sharing comes from welding.
void add_face(Mesh& mesh, const std::array<glm::vec3, 4>& corners) {
    std::array<std::uint32_t, 4> index{};
    for (int i = 0; i < 4; ++i) index[i] = add(mesh, corners[i]);
    mesh.triangles.push_back({index[0], index[1], index[2]});
    mesh.triangles.push_back({index[0], index[2], index[3]});
}

// The three faces of the cube [−1, 1]³ at its corner P = (1, −1, −1), each
// with its corners counter-clockwise seen from outside. P is v0 of the +x face
// (on its diagonal: 2 triangles), v1 of the −y face and v3 of the −z face
// (1 triangle each).
Mesh cube_corner() {
    Mesh mesh;
    // +x: in (y, z), e_y × e_z = +e_x: (−1, −1), (1, −1), (1, 1), (−1, 1).
    add_face(mesh, {{{1, -1, -1}, {1, 1, -1}, {1, 1, 1}, {1, -1, 1}}});
    // −y: in (x, z), e_x × e_z = −e_y: (−1, −1), (1, −1), (1, 1), (−1, 1).
    add_face(mesh, {{{-1, -1, -1}, {1, -1, -1}, {1, -1, 1}, {-1, -1, 1}}});
    // −z: in (y, x), e_y × e_x = −e_z: (−1, −1), (1, −1), (1, 1), (−1, 1).
    add_face(mesh, {{{-1, -1, -1}, {-1, 1, -1}, {1, 1, -1}, {1, -1, -1}}});
    return mesh;
}

TEST(NormalWeighting, CubeCornerSplitOnFirstDiagonalsMeanAndAreaLeanToTheSplitFace) {
    const Mesh mesh = cube_corner();
    // The faces wind outwards: each triangle's DD8 normal is its face's.
    EXPECT_EQ(litkit::face_normal(mesh.positions[0], mesh.positions[1], mesh.positions[2]),
              glm::vec3(1, 0, 0));
    EXPECT_EQ(litkit::face_normal(mesh.positions[4], mesh.positions[5], mesh.positions[6]),
              glm::vec3(0, -1, 0));
    EXPECT_EQ(litkit::face_normal(mesh.positions[8], mesh.positions[9], mesh.positions[10]),
              glm::vec3(0, 0, -1));
    // P is position 0 (+x face), 5 (−y face) and 11 (−z face).
    // mean: +x counted twice, −y and −z once: normalize(2, −1, −1)
    //   = (2, −1, −1)/√6 = (0.816, −0.408, −0.408).
    // area: +x: two triangles of area 2 (e1 × e2 of length 4 each), −y and
    //   −z one each: (8, −4, −4) ∝ (2, −1, −1), the same.
    const glm::vec3 lean = glm::vec3(2, -1, -1) / std::sqrt(6.0f);
    for (const Normals weighting : {Normals::Mean, Normals::Area}) {
        const std::vector<glm::vec3> normals = vertex_normals(mesh, weighting);
        for (const int p : {0, 5, 11}) expect_near(normals[p], lean);
    }
}

TEST(NormalWeighting, CubeCornerSplitOnFirstDiagonalsAngleAndMaxWeighFacesEqually) {
    const Mesh mesh = cube_corner();
    // angle: +x: two corners of 45° (π/4 each), −y and −z one of 90° (π/2):
    //   π/2 per face, so normalize(1, −1, −1) = (0.577, −0.577, −0.577).
    // max: +x: edges of lengths 2 and 2√2, ‖e1 × e2‖ = 4: 4/(4·8) = 1/8 per
    //   triangle, 1/4 per face; −y, −z: edges 2 and 2: 4/(4·4) = 1/4. Equal.
    const glm::vec3 even = glm::vec3(1, -1, -1) / std::sqrt(3.0f);
    for (const Normals weighting : {Normals::Angle, Normals::Max}) {
        const std::vector<glm::vec3> normals = vertex_normals(mesh, weighting);
        for (const int p : {0, 5, 11}) expect_near(normals[p], even);
    }
}

TEST(NormalWeighting, BuiltInCubeCornersPointDiagonallyUnderEveryWeighting) {
    // The built-in cube's diagonals (shapes.hpp, docs/scene-format.md) join
    // the corners with x·y·z > 0: such a corner lies in two triangles on each
    // of its three faces, every other corner in one on each. So at any
    // corner the three faces weigh alike under every weighting (mean: 2 or 1
    // each; area: 2 or 1 triangles with ‖e1 × e2‖ = s²; angle: 45° + 45° or
    // 90°; Max: 2·s²/(s²·2s²) or s²/(s²·s²), 1/s² either way), and the
    // normal is normalize(sign x, sign y, sign z).
    const Mesh cube = litkit::make_cube(2.0f);
    for (const Normals weighting : weightings) {
        SCOPED_TRACE(std::string(litkit::to_string(weighting)));
        const std::vector<glm::vec3> normals = vertex_normals(cube, weighting);
        for (std::size_t i = 0; i < cube.positions.size(); ++i)
            expect_near(normals[i], glm::sign(cube.positions[i]) / std::sqrt(3.0f));
    }
}

// Two triangles at the origin, welded there (each has its own copy of it):
// A = (0,0,0), (1,0,0), (1,1,0): e1 = (1,0,0), e2 = (1,1,0), e1 × e2 = (0,0,1),
//   corner angle atan2(1, 1) = 45°, ‖e1‖²‖e2‖² = 1·2 = 2;
// B = (0,0,0), (0,3,0), (0,0,1): e1 × e2 = (3,0,0), corner angle 90°,
//   ‖e1‖²‖e2‖² = 9·1 = 9.
Mesh two_triangles() {
    Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 0, 0}, {0, 3, 0}, {0, 0, 1}};
    mesh.triangles = {{0, 1, 2}, {3, 4, 5}};
    return mesh;
}

// The normal at the origin under each weighting.
struct HandValue {
    Normals weighting;
    glm::vec3 normal;
};
const std::array<HandValue, 4>& two_triangle_values() {
    static const std::array<HandValue, 4> values{{
        // mean: (0,0,1) + (1,0,0) → (1,0,1)/√2.
        {Normals::Mean, glm::vec3(1, 0, 1) / std::sqrt(2.0f)},
        // area: (0,0,1) + (3,0,0) → (3,0,1)/√10.
        {Normals::Area, glm::vec3(3, 0, 1) / std::sqrt(10.0f)},
        // angle: π/4·(0,0,1) + π/2·(1,0,0) ∝ (2,0,1) → (2,0,1)/√5.
        {Normals::Angle, glm::vec3(2, 0, 1) / std::sqrt(5.0f)},
        // max: (0,0,1)/2 + (3,0,0)/9 = (1/3, 0, 1/2) ∝ (2,0,3) → (2,0,3)/√13.
        {Normals::Max, glm::vec3(2, 0, 3) / std::sqrt(13.0f)},
    }};
    return values;
}

TEST(NormalWeighting, EachWeightingOnTwoHandMadeTriangles) {
    const Mesh mesh = two_triangles();
    for (const HandValue& value : two_triangle_values()) {
        SCOPED_TRACE(std::string(litkit::to_string(value.weighting)));
        const std::vector<glm::vec3> normals = vertex_normals(mesh, value.weighting);
        expect_near(normals[0], value.normal);
        expect_near(normals[3], value.normal);  // welded with position 0
        // Corners in one triangle only take its own normal.
        expect_near(normals[1], {0, 0, 1});
        expect_near(normals[4], {1, 0, 0});
    }
}

// corner_angle is std::atan2 for y > 0, written with + − × ÷ (the same bits
// in every build). Against glibc's atan2 (within a few units in the last
// place, of π) on a grid over every branch: steep and shallow, x of either
// sign, each quarter's neighbourhood, and the ends (x = 0, y ≪ |x|, y = |x|).
TEST(NormalWeighting, CornerAngleIsAtan2) {
    double worst = 0.0;
    std::uint32_t state = 12345;
    auto next = [&state] {
        state = state * 1664525u + 1013904223u;
        return static_cast<double>(state >> 8) / 16777216.0;  // [0, 1)
    };
    std::vector<std::array<double, 2>> cases = {
        {1.0, 0.0}, {1.0, 1.0},  {1.0, -1.0}, {1e-30, 1.0}, {1e-30, -1.0}, {1.0, 1e-30},
        {3.0, 4.0}, {4.0, -3.0}, {0.25, 1.0}, {0.125, 1.0}, {0.375, -1.0}, {1e30, 3e29}};
    for (int i = 0; i < 200000; ++i) {
        const double scale = std::ldexp(1.0, static_cast<int>(next() * 40.0) - 20);
        cases.push_back({(next() + 1e-9) * scale, (2.0 * next() - 1.0) * scale});
    }
    for (const auto& [y, x] : cases) {
        const double difference = std::abs(litkit::corner_angle(y, x) - std::atan2(y, x));
        worst = std::max(worst, difference);
        ASSERT_LE(difference, 2e-15) << "y " << y << " x " << x;
    }
    EXPECT_GT(worst, 0.0);  // not std::atan2 itself
    EXPECT_EQ(litkit::corner_angle(1.0, 0.0), std::numbers::pi / 2);
    EXPECT_EQ(litkit::corner_angle(1.0, 1.0), std::numbers::pi / 4);
}

TEST(NormalWeighting, WeldingJoinsPositionsCloserThanTheWeldDistance) {
    // B's copy of the origin moved by 1e-7, below 1e-6 × the bounding-box
    // diagonal (√(1 + 9 + 1) ≈ 3.3): still one vertex; B's own normal and
    // weights change by about 1e-7, far below the 1e-5 allowed.
    Mesh mesh = two_triangles();
    mesh.positions[3] = {1e-7f, 0, 0};
    for (const HandValue& value : two_triangle_values()) {
        SCOPED_TRACE(std::string(litkit::to_string(value.weighting)));
        const std::vector<glm::vec3> normals = vertex_normals(mesh, value.weighting);
        expect_near(normals[0], value.normal, 1e-5f);
        expect_near(normals[3], value.normal, 1e-5f);
    }
}

TEST(NormalWeighting, TrianglesWithAZeroLengthEdgeTakeNoPart) {
    // (0,0,0), (0,0,0), (0,1,1): its first edge has length 0. Added at the
    // origin, it must change none of the values above.
    Mesh mesh = two_triangles();
    const std::uint32_t first = static_cast<std::uint32_t>(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(), {{0, 0, 0}, {0, 0, 0}, {0, 1, 1}});
    mesh.triangles.push_back({first, first + 1, first + 2});
    for (const HandValue& value : two_triangle_values()) {
        SCOPED_TRACE(std::string(litkit::to_string(value.weighting)));
        expect_near(vertex_normals(mesh, value.weighting)[0], value.normal);
    }
}

TEST(NormalWeighting, MeanIsExactlyTheDd9VertexNormals) {
    // The default must not move a single bit (docs/spec.md §9.2: a scene
    // without the new keys renders as before).
    const Mesh sphere = litkit::make_sphere(1.0f, 17, 9);
    EXPECT_EQ(vertex_normals(sphere, Normals::Mean), vertex_normals(sphere));
}

TEST(NormalWeighting, FileIsNotAWeighting) {
    EXPECT_THROW(vertex_normals(two_triangles(), Normals::File), litkit::ArgumentError);
}

TEST(NormalWeighting, NamesRoundTrip) {
    for (const char* name : {"mean", "area", "angle", "max", "file"}) {
        const auto normals = litkit::parse_normals(name);
        ASSERT_TRUE(normals.has_value()) << name;
        EXPECT_EQ(litkit::to_string(*normals), name);
    }
    EXPECT_FALSE(litkit::parse_normals("Mean").has_value());
    EXPECT_FALSE(litkit::parse_normals("angel").has_value());
}

TEST(Crease, SixtyDegreesMakesEveryCubeCornerTakeItsFacesNormal) {
    // Neighbouring cube faces meet at 90°: n̂_f·n̂_g = 0, not above cos 60° =
    // 0.5, so each corner sums its own face only.
    const Mesh cube = litkit::make_cube(1.0f);
    for (const Normals weighting : weightings) {
        SCOPED_TRACE(std::string(litkit::to_string(weighting)));
        const std::vector<glm::vec3> normals = corner_normals(cube, weighting, 60.0f);
        ASSERT_EQ(normals.size(), cube.triangles.size() * 3);
        for (std::size_t t = 0; t < cube.triangles.size(); ++t) {
            const auto& c = cube.triangles[t];
            const glm::vec3 face = litkit::face_normal(cube.positions[c[0]], cube.positions[c[1]],
                                                       cube.positions[c[2]]);
            for (int k = 0; k < 3; ++k) EXPECT_EQ(normals[3 * t + k], face);
        }
    }
}

TEST(Crease, SplitsTheTwoTrianglesOnlyBelowTheirNinetyDegrees) {
    // Triangles A (normal +z) and B (normal +x) meet at 90°.
    const Mesh mesh = two_triangles();
    for (const HandValue& value : two_triangle_values()) {
        SCOPED_TRACE(std::string(litkit::to_string(value.weighting)));
        // 60°: A's corner at the origin (entry 0) keeps +z, B's (entry 3) +x.
        const std::vector<glm::vec3> split = corner_normals(mesh, value.weighting, 60.0f);
        expect_near(split[0], {0, 0, 1});
        expect_near(split[3], {1, 0, 0});
        // 100°: cos 100° < 0 = n̂_A·n̂_B, so both count: the vertex normal.
        const std::vector<glm::vec3> joined = corner_normals(mesh, value.weighting, 100.0f);
        expect_near(joined[0], value.normal);
        expect_near(joined[3], value.normal);
    }
}

TEST(Crease, LeavesASphereSmooth) {
    // A 32 × 16 sphere's neighbouring faces are about 11° apart: nothing
    // splits at 60°, so every corner has exactly its vertex normal.
    const Mesh sphere = litkit::make_sphere(1.0f, 32, 16);
    for (const Normals weighting : weightings) {
        SCOPED_TRACE(std::string(litkit::to_string(weighting)));
        const std::vector<glm::vec3> vertex = vertex_normals(sphere, weighting);
        const std::vector<glm::vec3> corner = corner_normals(sphere, weighting, 60.0f);
        for (std::size_t t = 0; t < sphere.triangles.size(); ++t)
            for (int k = 0; k < 3; ++k)
                ASSERT_EQ(corner[3 * t + k], vertex[sphere.triangles[t][k]]) << t << " " << k;
    }
}

TEST(Crease, AngleOutsideZeroToOneEightyIsRefused) {
    EXPECT_THROW(corner_normals(two_triangles(), Normals::Mean, 0.0f), litkit::ArgumentError);
    EXPECT_THROW(corner_normals(two_triangles(), Normals::Mean, 181.0f), litkit::ArgumentError);
    EXPECT_THROW(corner_normals(two_triangles(), Normals::File, 60.0f), litkit::ArgumentError);
}

litkit::SceneObject object_of(litkit::Shape shape) {
    litkit::SceneObject object;
    object.shape = std::move(shape);
    object.position = {0.5f, -1.0f, 2.0f};
    object.rotation_degrees = {10.0f, 40.0f, -25.0f};
    object.scale = 1.5f;
    return object;
}

void expect_same(const litkit::WorldMesh& a, const litkit::WorldMesh& b) {
    EXPECT_EQ(a.positions, b.positions);
    EXPECT_EQ(a.normals, b.normals);
    EXPECT_EQ(a.triangles, b.triangles);
}

TEST(WorldMeshNormals, DefaultsAndOneEightyDegreeCreaseChangeNothing) {
    const litkit::SceneObject cube = object_of(litkit::CubeShape{2.0f});
    const litkit::WorldMesh plain = litkit::world_mesh(cube);
    expect_same(litkit::world_mesh(cube, litkit::NormalOptions{}), plain);
    expect_same(litkit::world_mesh(cube, {Normals::Mean, 180.0f}), plain);
}

TEST(WorldMeshNormals, SphereUnderACreaseIsTheUnsplitSphere) {
    const litkit::SceneObject sphere = object_of(litkit::SphereShape{1.0f, 32, 16});
    expect_same(litkit::world_mesh(sphere, {Normals::Angle, 60.0f}),
                litkit::world_mesh(sphere, {Normals::Angle, std::nullopt}));
}

TEST(WorldMeshNormals, CreasedCubeGetsOneVertexPerFaceCorner) {
    // 6 faces × 4 corners: the built-in cube already has 24 positions, one
    // per face corner, and each takes its face's normal, rotated.
    const litkit::SceneObject cube = object_of(litkit::CubeShape{2.0f});
    const litkit::WorldMesh mesh = litkit::world_mesh(cube, {Normals::Area, 60.0f});
    EXPECT_EQ(mesh.positions.size(), 24u);
    for (const auto& t : mesh.triangles) {
        const glm::vec3 face =
            litkit::face_normal(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]);
        for (const std::uint32_t corner : t) expect_near(mesh.normals[corner], face, 1e-5f);
    }
}

// A UV sphere of radius 1 written as OBJ with its exact normals (vn = the
// position), in the test's temporary folder.
fs::path write_sphere_obj(const std::string& name, int segments, int rings, bool every_normal) {
    const fs::path path = fs::path(testing::TempDir()) / name;
    std::ofstream out(path);
    const Mesh sphere = litkit::make_sphere(1.0f, segments, rings);
    for (const glm::vec3& p : sphere.positions) {
        const glm::vec3 n = glm::normalize(p);
        out << "v " << p.x << ' ' << p.y << ' ' << p.z << "\n";
        out << "vn " << n.x << ' ' << n.y << ' ' << n.z << "\n";
    }
    for (std::size_t t = 0; t < sphere.triangles.size(); ++t) {
        const auto& c = sphere.triangles[t];
        out << "f";
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t index = c[k] + 1;
            // The last face's last corner lacks its normal when asked.
            if (!every_normal && t + 1 == sphere.triangles.size() && k == 2)
                out << ' ' << index;
            else
                out << ' ' << index << "//" << index;
        }
        out << "\n";
    }
    return path;
}

// The largest angle (radians) between a vertex normal and the direction
// from the sphere's centre to that vertex.
double largest_error_from_radial(const litkit::WorldMesh& mesh, const glm::vec3& centre) {
    double largest = 0.0;
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        const glm::dvec3 radial = glm::normalize(glm::dvec3(mesh.positions[i] - centre));
        const double cosine = glm::dot(radial, glm::dvec3(mesh.normals[i]));
        largest = std::max(largest, std::acos(std::min(1.0, cosine)));
    }
    return largest;
}

TEST(FileNormals, ExactSphereNormalsMatchTheAnalyticSphereBetterThanMean) {
    // A coarse 8 × 5 sphere: the mean of its faces' normals leans visibly off
    // radial at most vertices (no face is symmetric about the vertex's
    // latitude); the file's normals are radial to float precision, rotated
    // with the object (docs/spec.md §9.2).
    const litkit::SceneObject sphere =
        object_of(litkit::MeshFileShape{write_sphere_obj("sphere8x5.obj", 8, 5, true)});
    const double file_error = largest_error_from_radial(
        litkit::world_mesh(sphere, {Normals::File, std::nullopt}), sphere.position);
    const double mean_error = largest_error_from_radial(
        litkit::world_mesh(sphere, {Normals::Mean, std::nullopt}), sphere.position);
    EXPECT_LT(file_error, 1e-3);  // float rounding of written text and rotation
    EXPECT_GT(mean_error, 10.0 * file_error);
}

TEST(FileNormals, CreaseAngleIsIgnored) {
    const litkit::SceneObject sphere =
        object_of(litkit::MeshFileShape{write_sphere_obj("sphere6x4.obj", 6, 4, true)});
    expect_same(litkit::world_mesh(sphere, {Normals::File, 10.0f}),
                litkit::world_mesh(sphere, {Normals::File, std::nullopt}));
}

TEST(FileNormals, MissingNormalAtACornerIsLocatedAtTheFaceLine) {
    const fs::path path = write_sphere_obj("sphere-missing.obj", 6, 4, false);
    const litkit::SceneObject sphere = object_of(litkit::MeshFileShape{path});
    // Each position is written as a v and a vn line, then one f line per
    // triangle: the last face is on line 2·positions + triangles.
    const Mesh written = litkit::make_sphere(1.0f, 6, 4);
    const std::size_t last_line = 2 * written.positions.size() + written.triangles.size();
    try {
        litkit::world_mesh(sphere, {Normals::File, std::nullopt});
        FAIL() << "no error";
    } catch (const litkit::SceneError& error) {
        ASSERT_EQ(error.diagnostics().size(), 1u);
        EXPECT_EQ(error.diagnostics()[0].location.file, path.string());
        EXPECT_EQ(error.diagnostics()[0].location.line, last_line);
    }
    // Every other weighting ignores the file's normals.
    EXPECT_NO_THROW(litkit::world_mesh(sphere, {Normals::Mean, std::nullopt}));
}

TEST(NormalOptions, ObjectOverridesSceneAndSceneFileAppliesToMeshesOnly) {
    litkit::Scene scene;
    scene.normals = Normals::File;
    scene.crease_angle_degrees = 45.0f;
    litkit::SceneObject cube = object_of(litkit::CubeShape{});
    litkit::SceneObject mesh = object_of(litkit::MeshFileShape{"model.obj"});
    EXPECT_EQ(litkit::normal_options(scene, cube).normals, Normals::Mean);
    EXPECT_EQ(litkit::normal_options(scene, mesh).normals, Normals::File);
    EXPECT_EQ(litkit::normal_options(scene, cube).crease_angle_degrees, 45.0f);
    cube.normals = Normals::Max;
    cube.crease_angle_degrees = 180.0f;
    EXPECT_EQ(litkit::normal_options(scene, cube).normals, Normals::Max);
    EXPECT_EQ(litkit::normal_options(scene, cube).crease_angle_degrees, 180.0f);
}

TEST(SceneFile, ReadsNormalsAndCreaseAngleInLightingAndPerObject) {
    const litkit::Scene scene = litkit::parse_scene(R"([room]
width = 10
height = 10
depth = 10
[observer]
position = [0, 0, 4]
[lighting]
shading = "faceted"
normals = "angle"
crease_angle = 30.5
[[objects]]
type = "cube"
position = [-2, 0, 0]
[[objects]]
type = "sphere"
position = [2, 0, 0]
normals = "max"
crease_angle = 180
)",
                                                    "normals.toml");
    EXPECT_EQ(scene.shading, litkit::Shading::Faceted);
    EXPECT_EQ(scene.normals, Normals::Angle);
    EXPECT_EQ(scene.crease_angle_degrees, 30.5f);
    ASSERT_EQ(scene.objects.size(), 2u);
    EXPECT_FALSE(scene.objects[0].normals.has_value());
    EXPECT_FALSE(scene.objects[0].crease_angle_degrees.has_value());
    EXPECT_EQ(scene.objects[1].normals, Normals::Max);
    EXPECT_EQ(scene.objects[1].crease_angle_degrees, 180.0f);
    EXPECT_EQ(litkit::normal_options(scene, scene.objects[0]).normals, Normals::Angle);
    EXPECT_EQ(litkit::normal_options(scene, scene.objects[1]).crease_angle_degrees, 180.0f);
}

litkit::Scene cube_scene(litkit::Shading shading) {
    litkit::Scene scene;
    scene.output.width = 160;
    scene.output.height = 120;
    scene.observer.position = {0.0f, 1.5f, 4.0f};
    scene.reflection = litkit::Reflection::Phong;
    scene.shading = shading;
    litkit::SceneObject cube = object_of(litkit::CubeShape{1.5f});
    cube.position = {0.0f, 0.0f, 0.0f};
    scene.objects.push_back(cube);
    scene.lights.push_back({"key", litkit::Light{litkit::PointLight{{1.0f, 2.0f, 2.5f}}}});
    scene.lights.push_back({"fill", litkit::Light{litkit::AmbientLight{}}});
    return scene;
}

TEST(Crease, SixtyDegreeCubeUnderPhongShadingIsTheFacetedCube) {
    // With every corner normal its face's, Phong shading interpolates three
    // equal unit normals: the face normal, as faceted shading uses, at the
    // same points. Every pixel agrees within 1/255 (float rounding of the
    // interpolation), and the picture differs from the pillowed cube.
    litkit::Scene creased = cube_scene(litkit::Shading::Phong);
    creased.crease_angle_degrees = 60.0f;
    const litkit::Image phong = litkit::render(creased);
    const litkit::Image faceted = litkit::render(cube_scene(litkit::Shading::Faceted));
    ASSERT_EQ(phong.rgb.size(), faceted.rgb.size());
    std::size_t object_pixels = 0;
    for (std::size_t i = 0; i < phong.rgb.size(); ++i) {
        EXPECT_LE(std::abs(int(phong.rgb[i]) - int(faceted.rgb[i])), 1) << "byte " << i;
        object_pixels += phong.rgb[i] != 0;
    }
    EXPECT_GT(object_pixels, phong.rgb.size() / 10);
    EXPECT_NE(litkit::render(cube_scene(litkit::Shading::Phong)).rgb, phong.rgb);
}

}  // namespace

// The renderer lends its threads to mesh building (src/scene/world_mesh.hpp):
// the welding beside the triangles' weights, the normalising and the move
// to world space in pieces. Whatever runs the pieces, in whatever order,
// the mesh must be the very one, bit for bit.
namespace {

template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

// A mesh with everything welding and weighting must skip: a zero-area
// triangle, one whose corners weld (closer than the weld distance), a
// position no triangle uses, exact duplicates, a NaN position.
Mesh awkward_mesh() {
    Mesh mesh = litkit::make_sphere(1.0f, 24, 12);
    const auto base = static_cast<std::uint32_t>(mesh.positions.size());
    mesh.positions.push_back({2.0f, 0.0f, 0.0f});
    mesh.positions.push_back({2.0f, 1.0f, 0.0f});
    mesh.positions.push_back({2.0f, 2.0f, 0.0f});           // collinear: zero area
    mesh.positions.push_back({2.0f, 0.0f, 1e-9f});          // welds with base
    mesh.positions.push_back({5.0f, 5.0f, 5.0f});           // unused
    mesh.positions.push_back({2.0f, 1.0f, 0.0f});           // duplicate of base + 1
    mesh.positions.push_back({std::nanf(""), 0.0f, 0.0f});  // not finite
    mesh.triangles.push_back({base, base + 1, base + 2});
    mesh.triangles.push_back({base, base + 3, base + 1});
    mesh.triangles.push_back({base + 5, base, base + 6});
    mesh.triangles.push_back({base + 5, mesh.triangles[0][0], base + 3});
    return mesh;
}

}  // namespace

TEST(ParallelMeshBuilding, ThreadsGiveTheSameNormalsBitForBit) {
    litkit::ThreadPool pool(2);
    const litkit::ParallelFor threads = [&](std::size_t count, const litkit::ParallelJob& job) {
        pool.parallel_for(count, [&](std::size_t index, int) { job(index); });
    };
    const litkit::ParallelFor backwards = [](std::size_t count, const litkit::ParallelJob& job) {
        for (std::size_t index = count; index-- > 0;) job(index);
    };
    const std::vector<Mesh> meshes = {awkward_mesh(), litkit::make_sphere(1.5f, 512, 256),
                                      litkit::make_teapot(1.0f, 6), litkit::make_cube(2.0f)};
    for (const Mesh& mesh : meshes) {
        for (const Normals weighting : weightings) {
            const std::vector<glm::vec3> alone = vertex_normals(mesh, weighting);
            EXPECT_TRUE(same_bits(vertex_normals(mesh, weighting, threads), alone))
                << litkit::to_string(weighting) << ", " << mesh.triangles.size() << " triangles";
            EXPECT_TRUE(same_bits(vertex_normals(mesh, weighting, backwards), alone))
                << litkit::to_string(weighting) << ", " << mesh.triangles.size() << " triangles";
        }
    }
    // The checks come first, with or without threads.
    Mesh bad = litkit::make_cube(1.0f);
    bad.triangles.push_back({0, 1, 99});
    EXPECT_THROW(vertex_normals(bad, Normals::Mean, threads), litkit::ArgumentError);
    EXPECT_THROW(vertex_normals(bad, Normals::File, threads), litkit::ArgumentError);
}

TEST(ParallelMeshBuilding, ThreadsGiveTheSameWorldMeshBitForBit) {
    litkit::ThreadPool pool(2);
    const litkit::ParallelFor threads = [&](std::size_t count, const litkit::ParallelJob& job) {
        pool.parallel_for(count, [&](std::size_t index, int) { job(index); });
    };
    const std::vector<litkit::SceneObject> objects = {
        object_of(litkit::SphereShape{1.5f, 512, 256}),
        object_of(litkit::TorusShape{1.0f, 0.3f, 96, 48}), object_of(litkit::TeapotShape{1.0f, 6}),
        object_of(litkit::CubeShape{2.0f})};
    for (const litkit::SceneObject& object : objects) {
        for (const Normals weighting : weightings) {
            for (const std::optional<float> crease :
                 {std::optional<float>{}, std::optional<float>{60.0f}}) {
                const litkit::NormalOptions options{weighting, crease};
                const litkit::WorldMesh alone = litkit::world_mesh(object, options);
                const litkit::WorldMesh lent = litkit::world_mesh(object, options, threads);
                EXPECT_TRUE(same_bits(lent.positions, alone.positions));
                EXPECT_TRUE(same_bits(lent.normals, alone.normals)) << litkit::to_string(weighting);
                EXPECT_EQ(lent.triangles, alone.triangles);
            }
        }
    }
}

// A built-in shape is built once for load_scene's validation and the
// renderer of the same scene (Scene::built_meshes, scene/world_mesh.hpp).
namespace {

litkit::SceneObject sphere_object(int segments, int rings) {
    litkit::SceneObject object;
    object.shape = litkit::SphereShape{.radius = 1.5f, .segments = segments, .rings = rings};
    return object;
}

// A mesh no shape makes: where world_mesh uses it, it was taken.
litkit::Mesh marker_mesh() {
    litkit::Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.triangles = {{0, 1, 2}};
    return mesh;
}

litkit::WorldMesh world_mesh_from(const litkit::SceneObject& object, litkit::BuiltMeshes& built) {
    return litkit::world_mesh(object, litkit::NormalOptions{}, litkit::ParallelFor{}, &built);
}

}  // namespace

TEST(BuiltMeshes, WorldMeshTakesTheMeshKeptForItsShapeOnce) {
    litkit::BuiltMeshes built;
    built.keep(sphere_object(40, 20).shape, marker_mesh());
    // Another parameter: not that mesh.
    EXPECT_EQ(world_mesh_from(sphere_object(40, 21), built).triangles,
              litkit::make_sphere(1.5f, 40, 21).triangles);
    // Without the kept meshes: built.
    EXPECT_EQ(litkit::world_mesh(sphere_object(40, 20)).triangles,
              litkit::make_sphere(1.5f, 40, 20).triangles);
    // The same parameters: taken (the marker's one triangle) ...
    EXPECT_EQ(world_mesh_from(sphere_object(40, 20), built).triangles.size(), 1u);
    // ... once: the next is built.
    EXPECT_EQ(world_mesh_from(sphere_object(40, 20), built).triangles,
              litkit::make_sphere(1.5f, 40, 20).triangles);
}

TEST(BuiltMeshes, OnlyTheLastFourAreKept) {
    litkit::BuiltMeshes built;
    built.keep(sphere_object(30, 10).shape, marker_mesh());
    for (int rings = 11; rings <= 14; ++rings)
        built.keep(sphere_object(30, rings).shape, litkit::make_sphere(1.5f, 30, rings));
    EXPECT_EQ(world_mesh_from(sphere_object(30, 10), built).triangles,
              litkit::make_sphere(1.5f, 30, 10).triangles);
    EXPECT_EQ(world_mesh_from(sphere_object(30, 14), built).triangles,
              litkit::make_sphere(1.5f, 30, 14).triangles);
}

TEST(BuiltMeshes, MeshFilesAreNotKept) {
    const fs::path file = fs::temp_directory_path() / "litkit-kept-mesh-test.obj";
    {
        std::ofstream out(file);
        out << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\n";
    }
    litkit::SceneObject object;
    object.shape = litkit::MeshFileShape{.file = file};
    litkit::BuiltMeshes built;
    built.keep(object.shape, marker_mesh());
    EXPECT_EQ(world_mesh_from(object, built).triangles.size(), 2u);  // read from the file
    fs::remove(file);
}

TEST(BuiltMeshes, LoadingASceneKeepsItsShapesForTheRenderer) {
    // load_scene validates (building the sphere); the renderer takes that
    // mesh: the picture is the one of a scene built without keeping.
    const fs::path file = fs::path(LITKIT_SOURCE_DIR) / "examples" / "sphere.toml";
    litkit::Scene loaded = litkit::load_scene(std::span(&file, 1));
    loaded.output.width = 160;
    loaded.output.height = 120;
    const litkit::Image kept = litkit::render(loaded);
    const litkit::Image built = litkit::render(loaded);  // nothing kept any more
    EXPECT_EQ(kept.rgb, built.rgb);
}

TEST(BuiltMeshes, EachShapeIsBuiltOnceFromLoadingToRendering) {
    // The mesh that loading built is kept in the scene; put a marker in its
    // place to see who uses it.
    const fs::path file = fs::path(LITKIT_SOURCE_DIR) / "examples" / "sphere.toml";
    litkit::Scene loaded = litkit::load_scene(std::span(&file, 1));
    ASSERT_TRUE(loaded.built_meshes);
    ASSERT_EQ(loaded.objects.size(), 1u);
    const litkit::Shape& shape = loaded.objects[0].shape;
    const std::optional<litkit::Mesh> from_loading = loaded.built_meshes->take(shape);
    ASSERT_TRUE(from_loading);
    const auto& sphere = std::get<litkit::SphereShape>(shape);
    EXPECT_EQ(from_loading->triangles,
              litkit::make_sphere(sphere.radius, sphere.segments, sphere.rings).triangles);
    loaded.built_meshes->keep(shape, marker_mesh());
    // Validating again takes the kept mesh and keeps it back, building none.
    (void)litkit::validate_scene(loaded);
    // A copy of the scene shares the kept meshes: its renderer takes the marker ...
    const litkit::Scene copy = loaded;
    EXPECT_EQ(litkit::Renderer(copy).triangle_count(), 1u);
    // ... once: the next renderer builds the sphere.
    EXPECT_EQ(litkit::Renderer(loaded).triangle_count(), from_loading->triangles.size());
    // A scene built in code keeps nothing: its renderers build their meshes.
    litkit::Scene in_code;
    EXPECT_FALSE(in_code.built_meshes);
    EXPECT_FALSE(litkit::validate_scene(in_code).empty());  // warns: no lights, no objects
}
