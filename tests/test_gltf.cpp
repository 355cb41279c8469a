// SPDX-License-Identifier: MIT
// glTF 2.0 mesh files (src/geometry/gltf.cpp): small files whose every
// number is known, their buffers built here from explicit values; node
// transforms against matrices worked out by hand; bad files with the place
// of their error in the file.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "litkit/error.hpp"
#include "litkit/mesh.hpp"
#include "litkit/shapes.hpp"
#include "mesh_file_bytes.hpp"

namespace {

namespace fs = std::filesystem;
using litkit::Mesh;
using litkit_test::Bytes;
using litkit_test::expect_io_error;
using litkit_test::expect_positions;
using litkit_test::Triangle;
using litkit_test::write_file;

const fs::path data = fs::path(LITKIT_TEST_DATA);

// Writes `name`.bin (the one buffer) and `name`.gltf: the asset, the
// buffer, and `members` (JSON members, comma-separated).
fs::path write_gltf(const std::string& name, const std::string& bin, const std::string& members) {
    write_file(name + ".bin", bin);
    return write_file(name + ".gltf", R"({"asset": {"version": "2.0"}, "buffers": [{"uri": ")" +
                                          fs::path(name).filename().string() +
                                          R"(.bin", "byteLength": )" + std::to_string(bin.size()) +
                                          "}], " + members + "}");
}

// The corners (1, 0, 0), (0, 1, 0), (0, 0, 1) as floats: 36 bytes.
std::string corner_triangle() {
    Bytes bytes;
    for (float v : {1.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 1.0f}) bytes.put(v);
    return bytes.data;
}

// One node, `node` (its members), whose mesh is the corner triangle.
std::string triangle_members(const std::string& node) {
    return R"("scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0)" + node +
           R"(}], "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
           "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}],
           "bufferViews": [{"buffer": 0, "byteLength": 36}])";
}

void expect_near(const glm::vec3& actual, const glm::vec3& expected, float tolerance = 1e-6f) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}

TEST(Gltf, CubeWithItsBufferInADataUri) {
    const Mesh mesh = litkit::load_gltf(data / "gltf/cube.gltf");
    expect_positions(mesh, litkit_test::cube_vertices);
    EXPECT_EQ(mesh.triangles, litkit_test::cube_triangles);
    EXPECT_TRUE(litkit::is_closed(mesh));
    EXPECT_NEAR(litkit::signed_volume(mesh), 1.0, 1e-12);
}

// A parent turned 90° about z and moved 10 along x, a child scaled 2:
// p ↦ T·R·S·p, worked by hand: (1,0,0) → (2,0,0) → (0,2,0) → (10,2,0);
// (0,1,0) → (0,2,0) → (-2,0,0) → (8,0,0); (0,0,1) → (0,0,2) → (10,0,2).
TEST(Gltf, NodesPlaceTheirMeshesByTheirTransformsChained) {
    const std::string chain = R"("scenes": [{"nodes": [0]}],
        "nodes": [{"translation": [10, 0, 0], "rotation": [0, 0, 0.7071067811865476, 0.7071067811865476],
                   "children": [1]},
                  {"scale": [2, 2, 2], "mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}],
        "bufferViews": [{"buffer": 0, "byteLength": 36}])";
    const Mesh chained = litkit::load_gltf(write_gltf("chain", corner_triangle(), chain));
    ASSERT_EQ(chained.positions.size(), 3u);
    expect_near(chained.positions[0], {10, 2, 0});
    expect_near(chained.positions[1], {8, 0, 0});
    expect_near(chained.positions[2], {10, 0, 2});
    EXPECT_EQ(chained.triangles, (std::vector<Triangle>{{0, 1, 2}}));
    // The same placement as one matrix, column by column: R·S's columns
    // (0,2,0), (-2,0,0), (0,0,2), then the translation.
    const Mesh matrix = litkit::load_gltf(write_gltf(
        "matrix", corner_triangle(),
        triangle_members(R"(, "matrix": [0, 2, 0, 0, -2, 0, 0, 0, 0, 0, 2, 0, 10, 0, 0, 1])")));
    expect_positions(matrix, {{10, 2, 0}, {8, 0, 0}, {10, 0, 2}});
}

TEST(Gltf, AMirroringNodeKeepsTheFacesCounterClockwise) {
    const Mesh mesh = litkit::load_gltf(
        write_gltf("mirror", corner_triangle(), triangle_members(R"(, "scale": [-1, 1, 1])")));
    expect_positions(mesh, {{-1, 0, 0}, {0, 1, 0}, {0, 0, 1}});
    EXPECT_EQ(mesh.triangles, (std::vector<Triangle>{{0, 2, 1}}));
}

// Four corners of the unit square: a strip makes (0 1 2) and, turned to
// keep the winding, (1 3 2); a fan around the first makes (0 1 2), (0 2 3).
TEST(Gltf, StripsAndFansWithoutIndices) {
    Bytes square;
    for (float v : {0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 1.0f, 1.0f, 0.0f})
        square.put(v);
    const Mesh mesh = litkit::load_gltf(write_gltf("strips", square.data, R"(
        "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "mode": 5},
                                   {"attributes": {"POSITION": 0}, "mode": 6},
                                   {"attributes": {"POSITION": 0}, "mode": 1}]}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3"}],
        "bufferViews": [{"buffer": 0, "byteLength": 48}])"));
    EXPECT_EQ(mesh.positions.size(), 8u);
    EXPECT_EQ(mesh.triangles, (std::vector<Triangle>{{0, 1, 2}, {1, 3, 2}, {4, 5, 6}, {4, 6, 7}}));
    EXPECT_EQ(mesh.triangle_faces, (std::vector<std::uint32_t>{0, 1, 2, 3}));
}

// Normalised integers (KHR_mesh_quantization) map to [-1, 1]: c / 32767 for
// shorts, c / 127 for bytes, -32768 and -128 to -1.
TEST(Gltf, NormalizedAccessorsAreMappedToUnitRange) {
    Bytes bytes;
    for (std::int16_t v : {32767, 0, 0, 0, -32768, 0, 0, 0, 16384}) bytes.put(v);
    bytes.put(std::uint16_t{0});  // to a multiple of 4
    for (std::int8_t v : {127, 0, 0, 0, -128, 0, 0, 0, 64}) bytes.put(v);
    const Mesh mesh = litkit::load_gltf(write_gltf("quantized", bytes.data, R"(
        "extensionsUsed": ["KHR_mesh_quantization"],
        "extensionsRequired": ["KHR_mesh_quantization"],
        "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}},
                                   {"attributes": {"POSITION": 1}}]}],
        "accessors": [{"bufferView": 0, "componentType": 5122, "normalized": true, "count": 3, "type": "VEC3"},
                      {"bufferView": 1, "componentType": 5120, "normalized": true, "count": 3, "type": "VEC3"}],
        "bufferViews": [{"buffer": 0, "byteLength": 18}, {"buffer": 0, "byteOffset": 20, "byteLength": 9}])"));
    expect_positions(mesh, {{1, 0, 0},
                            {0, -1, 0},
                            {0, 0, static_cast<float>(16384.0 / 32767.0)},
                            {1, 0, 0},
                            {0, -1, 0},
                            {0, 0, static_cast<float>(64.0 / 127.0)}});
}

// No buffer view: three zero vectors, of which the sparse part replaces
// elements 0 and 2.
TEST(Gltf, SparseAccessorsReplaceTheirElements) {
    Bytes bytes;
    bytes.put(std::uint8_t{0}).put(std::uint8_t{2}).put(std::uint16_t{0});
    for (float v : {1.0f, 2.0f, 3.0f, 4.0f, 5.0f, 6.0f}) bytes.put(v);
    const Mesh mesh = litkit::load_gltf(write_gltf("sparse", bytes.data, R"(
        "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
        "accessors": [{"componentType": 5126, "count": 3, "type": "VEC3",
                       "sparse": {"count": 2, "indices": {"bufferView": 0, "componentType": 5121},
                                  "values": {"bufferView": 1}}}],
        "bufferViews": [{"buffer": 0, "byteLength": 2}, {"buffer": 0, "byteOffset": 4, "byteLength": 24}])"));
    expect_positions(mesh, {{1, 2, 3}, {0, 0, 0}, {4, 5, 6}});
}

// Normals go by the inverse transpose: scale (2, 1, 1) turns (0.6, 0.8, 0)
// into (0.3, 0.8, 0), of length √0.73, renormalised.
TEST(Gltf, NormalsArePlacedByTheInverseTransposeForNormalsFile) {
    std::string bin = corner_triangle();
    Bytes normals;
    for (int corner = 0; corner < 3; ++corner) normals.put(0.6f).put(0.8f).put(0.0f);
    bin += normals.data;
    const Mesh mesh = litkit::load_gltf(write_gltf("normals", bin, R"(
        "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0, "scale": [2, 1, 1]}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}}]}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                      {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC3"}],
        "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 36}])"));
    expect_positions(mesh, {{2, 0, 0}, {0, 1, 0}, {0, 0, 1}});
    ASSERT_EQ(mesh.file_normals.size(), 3u);
    const double length = std::sqrt(0.73);
    for (const glm::vec3& normal : mesh.file_normals)
        expect_near(normal,
                    {static_cast<float>(0.3 / length), static_cast<float>(0.8 / length), 0});
    EXPECT_EQ(mesh.triangle_file_normals, (std::vector<Triangle>{{0, 1, 2}}));
}

TEST(Gltf, TheDefaultSceneIsDrawnAndOnlyIt) {
    const Mesh mesh = litkit::load_gltf(write_gltf("scenes", corner_triangle(), R"(
        "scene": 1, "scenes": [{"nodes": [0]}, {"nodes": [1]}],
        "nodes": [{"mesh": 0}, {"mesh": 0, "translation": [0, 0, 5]}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}],
        "bufferViews": [{"buffer": 0, "byteLength": 36}])"));
    expect_positions(mesh, {{1, 0, 5}, {0, 1, 5}, {0, 0, 6}});
}

// GLB: a 12-byte header, then a JSON chunk and a BIN chunk, each padded to 4.
std::string glb_triangle() {
    std::string json = R"({"asset": {"version": "2.0"}, "buffers": [{"byteLength": 36}], )" +
                       triangle_members("") + "}";
    json.resize((json.size() + 3) / 4 * 4, ' ');
    const std::string bin = corner_triangle();
    Bytes bytes;
    bytes.text("glTF")
        .put(std::uint32_t{2})
        .put(std::uint32_t(12 + 8 + json.size() + 8 + bin.size()));
    bytes.put(std::uint32_t(json.size())).put(std::uint32_t{0x4E4F534A}).text(json);
    bytes.put(std::uint32_t(bin.size())).put(std::uint32_t{0x004E4942}).text(bin);
    return bytes.data;
}

TEST(Gltf, BinaryGlbWithItsBufferInside) {
    const Mesh mesh = litkit::load_gltf(write_file("triangle.glb", glb_triangle()));
    expect_positions(mesh, {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}});
    const std::string glb = glb_triangle();
    expect_io_error(
        [&] { litkit::load_gltf(write_file("cut.glb", glb.substr(0, glb.size() - 10))); },
        "not a valid GLB file");
}

TEST(Gltf, BuffersAreReadFromTheFilesFolderAndBelowOnly) {
    write_file("inner/parts/tri.bin", corner_triangle());
    const std::string members = triangle_members("");
    const std::string inside = R"({"asset": {"version": "2.0"},
        "buffers": [{"uri": "parts/tri.bin", "byteLength": 36}], )" +
                               members + "}";
    expect_positions(litkit::load_gltf(write_file("inner/inside.gltf", inside)),
                     {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}});
    write_file("outside.bin", corner_triangle());
    const std::string outside = R"({"asset": {"version": "2.0"},
        "buffers": [{"uri": "../outside.bin", "byteLength": 36}], )" +
                                members + "}";
    expect_io_error([&] { litkit::load_gltf(write_file("inner/outside.gltf", outside)); },
                    "buffer file '../outside.bin' is outside the glTF file's folder");
    const std::string escaped = R"({"asset": {"version": "2.0"},
        "buffers": [{"uri": "parts/..%2F..%2Foutside.bin", "byteLength": 36}], )" +
                                members + "}";
    expect_io_error([&] { litkit::load_gltf(write_file("inner/escaped.gltf", escaped)); },
                    "buffer file '../outside.bin' is outside the glTF file's folder");
}

// Each error names its place in the file.
TEST(Gltf, BadFilesNameThePlaceOfTheirError) {
    const std::string accessor =
        R"("accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}],
        "bufferViews": [{"buffer": 0, "byteLength": 36}])";
    auto read = [](const std::string& name, const std::string& bin, const std::string& members) {
        return [=] { litkit::load_gltf(write_gltf(name, bin, members)); };
    };
    std::string indexed = corner_triangle();
    for (std::uint8_t index : {0, 1, 7}) indexed += static_cast<char>(index);
    expect_io_error(read("index", indexed, R"(
        "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                      {"bufferView": 1, "componentType": 5121, "count": 3, "type": "SCALAR"}],
        "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 3}])"),
                    "meshes[0].primitives[0].indices: index 7 (element 2) is beyond the 3 "
                    "vertices of its POSITION");
    std::string too_many = triangle_members("");
    too_many.replace(too_many.find(R"("count": 3)"), 10, R"("count": 4)");
    expect_io_error(read("count", corner_triangle(), too_many),
                    "meshes[0].primitives[0].attributes.POSITION (accessors[0]): 4 elements of 12 "
                    "bytes from byte 0 do not fit in bufferViews[0] (36 bytes)");
    std::string nan = corner_triangle();
    const float not_a_number = std::numeric_limits<float>::quiet_NaN();
    std::memcpy(nan.data() + 16, &not_a_number, 4);  // element 1's y
    expect_io_error(read("nan", nan, triangle_members("")),
                    "meshes[0].primitives[0].attributes.POSITION (accessors[0]): element 1 has a "
                    "coordinate that is not a finite number");
    expect_io_error(read("cycle", corner_triangle(),
                         R"(
        "scenes": [{"nodes": [0]}], "nodes": [{"children": [1]}, {"children": [0], "mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}], )" +
                             accessor),
                    "nodes[1].children[0]: nodes[0] is met a second time");
    expect_io_error(read("no-node", corner_triangle(),
                         R"(
        "scenes": [{"nodes": [5]}], "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}], )" +
                             accessor),
                    "scenes[0].nodes[0]: node 5 does not exist (the file has 1)");
    expect_io_error(read("no-position", corner_triangle(),
                         R"(
        "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"NORMAL": 0}}]}], )" +
                             accessor),
                    "meshes[0].primitives[0].attributes: has no POSITION");
    expect_io_error(read("points", corner_triangle(),
                         R"(
        "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "mode": 0}]}], )" +
                             accessor),
                    "scenes[0]: the scene has no triangles (only points or lines");
    // Counts of 4 G elements without data behind them: the triangles they
    // would make are refused before anything is read; a normal's count
    // beyond the read limit is refused too.
    expect_io_error(read("huge-count", corner_triangle(), R"(
        "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
        "accessors": [{"componentType": 5126, "count": 4294967295, "type": "VEC3"}])"),
                    "meshes[0].primitives[0]: the file's meshes, placed by its nodes, make more "
                    "than 64000000 triangles");
    expect_io_error(read("huge-normals", corner_triangle(), R"(
        "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}}]}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                      {"componentType": 5126, "count": 4294967295, "type": "VEC3"}],
        "bufferViews": [{"buffer": 0, "byteLength": 36}])"),
                    "meshes[0].primitives[0].attributes.NORMAL (accessors[1]): its count "
                    "4294967295 is beyond what litkit reads");
    // A buffer that claims 4 GiB.
    const fs::path claimed = write_gltf("claimed", corner_triangle(), triangle_members(""));
    std::string text;
    {
        std::ifstream in(claimed);
        text.assign(std::istreambuf_iterator<char>(in), {});
    }
    text.replace(text.find(R"("byteLength": 36})"), 17, R"("byteLength": 4294967296})");
    expect_io_error([&] { litkit::load_gltf(write_file("claimed.gltf", text)); },
                    "File size mismatch");
    // Nesting is bounded before tinygltf, which reads extras recursively, sees it.
    const std::string prefix = R"({"asset": {"version": "2.0"}, "extras": )";
    expect_io_error(
        [&] {
            litkit::load_gltf(write_file(
                "deep.gltf", prefix + std::string(100000, '[') + std::string(100000, ']') + "}"));
        },
        "the JSON nests deeper than 64 levels (byte " + std::to_string(prefix.size() + 63) + ")");
    expect_io_error(
        read("draco", corner_triangle(),
             R"("extensionsRequired": ["KHR_draco_mesh_compression"], )" + triangle_members("")),
        "extensionsRequired: 'KHR_draco_mesh_compression' compresses the meshes");
    expect_io_error([&] { litkit::load_gltf(write_file("garbage.gltf", "hello")); },
                    "not a valid glTF file");
    expect_io_error(
        [&] { litkit::load_gltf(write_file("no-scene.gltf", R"({"asset": {"version": "2.0"}})")); },
        "scenes: the file has no scene");
}

}  // namespace
