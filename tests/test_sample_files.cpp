// SPDX-License-Identifier: MIT
// Mesh files litkit did not write: public test models of the Open Asset
// Import Library, copied into tests/data/samples/ (README.md there names
// each file's origin and licence). Each is read by litkit's reader and
// checked against what the file itself says, counted here another way: a
// PLY header's element counts, an STL's facets or its binary count, a glTF
// accessor's count, min and max; bounding boxes from the coordinates read
// here directly; areas by hand. Files a reader cannot use give an IoError
// naming the file and the place, never a crash.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <iterator>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "litkit/error.hpp"
#include "litkit/mesh.hpp"
#include "litkit/shapes.hpp"

namespace {

namespace fs = std::filesystem;
using litkit::Mesh;

const fs::path samples = fs::path(LITKIT_TEST_DATA) / "samples";

std::string bytes_of(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

struct Box {
    glm::dvec3 min{std::numeric_limits<double>::infinity()};
    glm::dvec3 max{-std::numeric_limits<double>::infinity()};
    void add(const glm::dvec3& p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
};

void expect_bounds(const Mesh& mesh, const Box& expected) {
    const litkit::Bounds got = litkit::bounds(mesh);
    for (int axis = 0; axis < 3; ++axis) {
        EXPECT_EQ(static_cast<double>(got.min[axis]), expected.min[axis]) << "axis " << axis;
        EXPECT_EQ(static_cast<double>(got.max[axis]), expected.max[axis]) << "axis " << axis;
    }
}

double area(const Mesh& mesh) {
    double total = 0.0;
    for (const auto& t : mesh.triangles) {
        const glm::dvec3 a(mesh.positions[t[0]]), b(mesh.positions[t[1]]), c(mesh.positions[t[2]]);
        total += 0.5 * glm::length(glm::cross(b - a, c - a));
    }
    return total;
}

// The message of the IoError reading `path` throws; "" (and a failure) if none.
std::string error_of(const fs::path& path) {
    try {
        litkit::load_mesh_file(path);
    } catch (const litkit::IoError& error) {
        return error.what();
    }
    ADD_FAILURE() << path << " was read";
    return "";
}

// --- PLY ---------------------------------------------------------------------

TEST(SampleFiles, PlyAsciiCube) {
    // "element vertex 8", "element face 6" of quads: 12 triangles; the unit cube.
    const Mesh mesh = litkit::load_mesh_file(samples / "ply/cube.ply");
    EXPECT_EQ(mesh.positions.size(), 8u);
    EXPECT_EQ(mesh.triangles.size(), 12u);
    expect_bounds(mesh, Box{{0, 0, 0}, {1, 1, 1}});
    EXPECT_TRUE(litkit::is_closed(mesh));
    EXPECT_NEAR(std::abs(litkit::signed_volume(mesh)), 1.0, 1e-12);
    EXPECT_NEAR(area(mesh), 6.0, 1e-12);
}

TEST(SampleFiles, PlyBinaryLittleEndianCube) {
    // The header's counts, and the 8 vertices' floats read here after it.
    const std::string file = bytes_of(samples / "ply/cube_binary.ply");
    ASSERT_NE(file.find("element vertex 8\n"), std::string::npos);
    ASSERT_NE(file.find("element face 12\n"), std::string::npos);
    ASSERT_NE(file.find("property float x\nproperty float y\nproperty float z\n"),
              std::string::npos);
    const std::size_t body = file.find("end_header\n") + 11;
    Box box;
    for (int v = 0; v < 8; ++v) {
        float xyz[3];
        std::memcpy(xyz, file.data() + body + 12 * v, 12);  // little endian, as this machine
        box.add({xyz[0], xyz[1], xyz[2]});
    }
    // 12 faces of "uchar count, 3 int indices" make the rest of the file.
    EXPECT_EQ(file.size(), body + 8 * 12 + 12 * (1 + 3 * 4));
    const Mesh mesh = litkit::load_mesh_file(samples / "ply/cube_binary.ply");
    EXPECT_EQ(mesh.positions.size(), 8u);
    EXPECT_EQ(mesh.triangles.size(), 12u);
    expect_bounds(mesh, box);
    EXPECT_TRUE(litkit::is_closed(mesh));
}

TEST(SampleFiles, PlyWithoutFacesIsALocatedError) {
    const std::string message = error_of(samples / "ply/points.ply");
    EXPECT_NE(message.find("points.ply"), std::string::npos) << message;
    EXPECT_NE(message.find("face"), std::string::npos) << message;
}

// --- STL ---------------------------------------------------------------------

TEST(SampleFiles, StlAscii) {
    // Triangles: the facets counted in the text; the box: every vertex line.
    std::istringstream text(bytes_of(samples / "stl/sphereWithHole.stl"));
    std::size_t facets = 0;
    Box box;
    for (std::string word; text >> word;) {
        if (word == "facet") ++facets;
        if (word == "vertex") {
            double x, y, z;
            text >> x >> y >> z;
            box.add({static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)});
        }
    }
    ASSERT_GT(facets, 100u);
    const Mesh mesh = litkit::load_mesh_file(samples / "stl/sphereWithHole.stl");
    EXPECT_EQ(mesh.triangles.size(), facets);
    EXPECT_EQ(mesh.positions.size(), 3 * facets);  // corners of their own
    expect_bounds(mesh, box);
}

TEST(SampleFiles, StlBinary) {
    // 80 bytes of header, the count, then 50 bytes a facet: normal, 3 corners, 2 bytes.
    const std::string file = bytes_of(samples / "stl/Spider_binary.stl");
    std::uint32_t count = 0;
    std::memcpy(&count, file.data() + 80, 4);
    ASSERT_EQ(file.size(), 84 + 50 * std::size_t{count});
    Box box;
    for (std::uint32_t f = 0; f < count; ++f) {
        for (int corner = 0; corner < 3; ++corner) {
            float xyz[3];
            std::memcpy(xyz, file.data() + 84 + 50 * std::size_t{f} + 12 + 12 * corner, 12);
            box.add({xyz[0], xyz[1], xyz[2]});
        }
    }
    const Mesh mesh = litkit::load_mesh_file(samples / "stl/Spider_binary.stl");
    EXPECT_EQ(mesh.triangles.size(), count);
    expect_bounds(mesh, box);
}

TEST(SampleFiles, StlWithTwoSolids) {
    // Two solids of one triangle each, written out in the file: both read.
    const Mesh mesh = litkit::load_mesh_file(samples / "stl/triangle_with_two_solids.stl");
    EXPECT_EQ(mesh.triangles.size(), 2u);
    expect_bounds(mesh, Box{{-1, -1, 0}, {3, 3, 0}});
}

// --- glTF --------------------------------------------------------------------

// The POSITION accessor's min and max, as the file's JSON states them.
Box accessor_box(const fs::path& gltf) {
    const nlohmann::json json = nlohmann::json::parse(bytes_of(gltf));
    const nlohmann::json& accessor = json["accessors"][0];
    Box box;
    box.add({accessor["min"][0].get<double>(), accessor["min"][1].get<double>(),
             accessor["min"][2].get<double>()});
    box.add({accessor["max"][0].get<double>(), accessor["max"][1].get<double>(),
             accessor["max"][2].get<double>()});
    return box;
}

TEST(SampleFiles, GltfPrimitiveModesMakeOneUnitSquare) {
    // The glTF Asset Generator's square of side 1 in z = 0 (README.md of
    // Mesh_PrimitiveMode): as a strip (04), a fan (05), triangles (06), and
    // indexed triangles with 32-bit (13) and 8-bit (14) indices: two
    // triangles, area 1, the accessor's box, each time.
    for (const char* number : {"04", "05", "06", "13", "14"}) {
        const fs::path path =
            samples / "gltf" / ("Mesh_PrimitiveMode_" + std::string(number) + ".gltf");
        const Mesh mesh = litkit::load_mesh_file(path);
        EXPECT_EQ(mesh.triangles.size(), 2u) << number;
        EXPECT_NEAR(area(mesh), 1.0, 1e-12) << number;
        expect_bounds(mesh, accessor_box(path));
        // Both triangles face the same way (+z or -z): one flat square.
        const glm::vec3 n0 = litkit::face_normal(mesh.positions[mesh.triangles[0][0]],
                                                 mesh.positions[mesh.triangles[0][1]],
                                                 mesh.positions[mesh.triangles[0][2]]);
        const glm::vec3 n1 = litkit::face_normal(mesh.positions[mesh.triangles[1][0]],
                                                 mesh.positions[mesh.triangles[1][1]],
                                                 mesh.positions[mesh.triangles[1][2]]);
        EXPECT_EQ(n0, n1) << number;
        EXPECT_EQ(std::abs(n0.z), 1.0f) << number;
    }
}

TEST(SampleFiles, GltfPointsAreALocatedError) {
    const std::string message = error_of(samples / "gltf/Mesh_PrimitiveMode_00.gltf");
    EXPECT_NE(message.find("Mesh_PrimitiveMode_00.gltf"), std::string::npos) << message;
    EXPECT_NE(message.find("triangles"), std::string::npos) << message;
}

TEST(SampleFiles, GlbBox) {
    // assimp's box of side 1 about the origin, 24 vertices and 36 indices
    // (12 triangles), under a node matrix that turns y into -z and z into y:
    // the same box.
    const Mesh mesh = litkit::load_mesh_file(samples / "gltf/BoxBadNormals.glb");
    EXPECT_EQ(mesh.positions.size(), 24u);
    EXPECT_EQ(mesh.triangles.size(), 12u);
    expect_bounds(mesh, Box{{-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5}});
    EXPECT_NEAR(area(mesh), 6.0, 1e-6);
}

TEST(SampleFiles, GlbWithInfinitePositionsIsALocatedError) {
    const std::string message = error_of(samples / "gltf/BoxWithInfinites.glb");
    EXPECT_NE(message.find("BoxWithInfinites.glb"), std::string::npos) << message;
    EXPECT_NE(message.find("meshes[0].primitives[0]"), std::string::npos) << message;
}

}  // namespace
