// SPDX-License-Identifier: MIT
// PLY and STL mesh files (src/geometry/ply.cpp, stl.cpp): small files whose
// every number is known, the text ones written here or in tests/data, the
// binary ones built from explicit values; bad files with the message and
// place of their error. glTF has test_gltf.cpp.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "geometry/mesh_formats.hpp"  // internal (src/)
#include "litkit/error.hpp"
#include "litkit/mesh.hpp"
#include "litkit/render.hpp"
#include "litkit/scene.hpp"
#include "litkit/shapes.hpp"
#include "mesh_file_bytes.hpp"

namespace {

namespace fs = std::filesystem;
using litkit::Mesh;
using litkit_test::Bytes;
using litkit_test::cube_triangles;
using litkit_test::cube_vertices;
using litkit_test::expect_io_error;
using litkit_test::expect_positions;
using litkit_test::Triangle;
using litkit_test::write_file;

const fs::path data = fs::path(LITKIT_TEST_DATA);

// --- PLY ---------------------------------------------------------------------

TEST(Ply, AsciiCubeHasItsVerticesAndEachQuadAsAFan) {
    const Mesh mesh = litkit::load_ply(data / "ply/cube.ply");
    expect_positions(mesh, cube_vertices);
    EXPECT_EQ(mesh.triangles, cube_triangles);
    EXPECT_EQ(mesh.triangle_faces,
              (std::vector<std::uint32_t>{0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5}));
    EXPECT_TRUE(litkit::is_closed(mesh));
    EXPECT_NEAR(litkit::signed_volume(mesh), 1.0, 1e-12);
    // Without nx ny nz no corner has a file normal.
    for (const Triangle& corners : mesh.triangle_file_normals)
        EXPECT_EQ(corners, (Triangle{litkit::missing_file_normal, litkit::missing_file_normal,
                                     litkit::missing_file_normal}));
}

TEST(Ply, LineOfFaceIsTheLineOfItsList) {
    // 12 header lines, 8 vertex lines: face 0 on line 21.
    EXPECT_EQ(litkit::detail::ply_line_of_face(data / "ply/cube.ply", 0), 21u);
    EXPECT_EQ(litkit::detail::ply_line_of_face(data / "ply/cube.ply", 2), 23u);
    EXPECT_EQ(litkit::detail::ply_line_of_face(data / "ply/cube.ply", 6), 0u);
}

// A 2 × 3 rectangle in z = -7, its coordinates of three types, with
// properties and an element that are read past.
std::string binary_rectangle(bool big_endian) {
    Bytes bytes{{}, big_endian};
    bytes.text("ply\nformat ")
        .text(big_endian ? "binary_big_endian" : "binary_little_endian")
        .text(
            " 1.0\ncomment explicit values\nelement vertex 4\nproperty float x\n"
            "property double y\nproperty short z\nproperty uchar red\nelement face 1\n"
            "property list uchar ushort vertex_indices\nproperty int flags\nelement edge 1\n"
            "property list uchar int vertex_pair\nend_header\n");
    const float xs[] = {0, 2, 2, 0};
    const double ys[] = {0, 0, 3, 3};
    for (int v = 0; v < 4; ++v)
        bytes.put(xs[v]).put(ys[v]).put(std::int16_t{-7}).put(std::uint8_t{200});
    bytes.put(std::uint8_t{4});
    for (std::uint16_t index : {0, 1, 2, 3}) bytes.put(index);
    bytes.put(std::int32_t{99});
    bytes.put(std::uint8_t{2}).put(std::int32_t{0}).put(std::int32_t{2});
    return bytes.data;
}

TEST(Ply, BinaryOfEitherByteOrderReadsTheSameNumbers) {
    for (bool big_endian : {false, true}) {
        SCOPED_TRACE(big_endian ? "big endian" : "little endian");
        const Mesh mesh = litkit::load_ply(write_file(
            big_endian ? "rectangle-be.ply" : "rectangle-le.ply", binary_rectangle(big_endian)));
        expect_positions(mesh, {{0, 0, -7}, {2, 0, -7}, {2, 3, -7}, {0, 3, -7}});
        EXPECT_EQ(mesh.triangles, (std::vector<Triangle>{{0, 1, 2}, {0, 2, 3}}));
        EXPECT_EQ(mesh.triangle_faces, (std::vector<std::uint32_t>{0, 0}));
    }
}

TEST(Ply, NormalsAreKeptPerVertexForNormalsFile) {
    const Mesh mesh = litkit::load_ply(write_file("normals.ply",
                                                  "ply\nformat ascii 1.0\n"
                                                  "element vertex 3\nproperty float x\n"
                                                  "property float y\nproperty float z\n"
                                                  "property float nx\nproperty float ny\n"
                                                  "property float nz\nelement face 1\n"
                                                  "property list uchar uint vertex_index\n"
                                                  "end_header\n"
                                                  "0 0 0 0 0 1\n1 0 0 0.6 0 0.8\n0 1 0 0 -1 0\n"
                                                  "3 0 1 2\n"));
    expect_positions(mesh, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    ASSERT_EQ(mesh.file_normals.size(), 3u);
    EXPECT_EQ(mesh.file_normals[1], glm::vec3(0.6f, 0.0f, 0.8f));
    EXPECT_EQ(mesh.file_normals[2], glm::vec3(0.0f, -1.0f, 0.0f));
    EXPECT_EQ(mesh.triangle_file_normals, (std::vector<Triangle>{{0, 1, 2}}));
}

// Lines: 1 ply, 2 format, 3–6 vertex, 7–8 face, 9 end_header, 10–12
// vertices, 13 the face.
std::string small_ply(const std::string& vertices, const std::string& faces) {
    return "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
           "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
           "end_header\n" +
           vertices + faces;
}

TEST(Ply, BadTextFilesAreLocated) {
    const std::string vertices = "0 0 0\n1 0 0\n0 1 0\n";
    auto read = [](const std::string& name, const std::string& text) {
        return [=] { litkit::load_ply(write_file(name, text)); };
    };
    expect_io_error(read("nan.ply", small_ply("0 0 0\n1 nan 0\n0 1 0\n", "3 0 1 2\n")),
                    "vertex 2: y 'nan' is not a finite number", 11, 3);
    expect_io_error(read("comma.ply", small_ply("0 0 0\n1 0,5 0\n0 1 0\n", "3 0 1 2\n")),
                    "vertex 2: y '0,5' is not a number (write the decimal separator as a point", 11,
                    3);
    expect_io_error(read("index.ply", small_ply(vertices, "3 0 1 5\n")),
                    "face 1: vertex index 5 is beyond the file's 3 vertices (indices count "
                    "from 0) ('5')",
                    13, 7);
    expect_io_error(read("negative.ply", small_ply(vertices, "3 0 -1 2\n")),
                    "face 1: vertex index -1 is beyond", 13, 5);
    expect_io_error(read("two.ply", small_ply(vertices, "2 0 1\n")),
                    "face 1: a face needs 3 or more vertices, this one has 2", 13, 1);
    expect_io_error(read("short.ply", small_ply(vertices, "3 0 1\n")),
                    "the file ends in face 1 of 1, before its vertex_indices", 14, 1);
    expect_io_error(read("trailing.ply", small_ply(vertices, "3 0 1 2\n7\n")),
                    "'7' follows the last element the header declares", 14, 1);
    // Too few lines for the count: refused before they are read.
    expect_io_error(read("few.ply", small_ply("0 0 0\n1 0 0\n", "")),
                    "the header declares 3 vertices of at least 6 bytes each, but only 12 bytes "
                    "are left for them",
                    3, 9);
    expect_io_error(read("garbage.ply", "hello\n"),
                    "not a PLY file: it does not start with the line 'ply'", 1, 1);
    expect_io_error(read("format.ply", "ply\nformat binary 1.0\nend_header\n"),
                    "unknown format 'binary'", 2, 8);
    expect_io_error(read("type.ply",
                         "ply\nformat ascii 1.0\nelement vertex 1\n"
                         "property real x\nend_header\n"),
                    "unknown property type 'real'", 4, 10);
    expect_io_error(read("no-z.ply",
                         "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                         "property float y\nelement face 0\n"
                         "property list uchar int vertex_indices\nend_header\n"),
                    "the vertex element needs properties x, y and z", 3, 9);
    expect_io_error(read("no-end.ply", "ply\nformat ascii 1.0\nelement vertex 1\n"),
                    "the header has no 'end_header' line", 4, 1);
    expect_io_error(read("no-faces.ply",
                         "ply\nformat ascii 1.0\nelement vertex 0\n"
                         "property float x\nproperty float y\nproperty float z\n"
                         "element face 0\nproperty list uchar int vertex_indices\n"
                         "end_header\n"),
                    "the file has no faces");
}

TEST(Ply, BadBinaryFilesNameTheByte) {
    std::string bytes = binary_rectangle(false);
    const std::size_t header = bytes.find("end_header\n") + 11;
    // The edge's second index: 4 vertices of 15 bytes, a face of 13, the
    // edge's count, its first index.
    expect_io_error(
        [&] { litkit::load_ply(write_file("cut.ply", bytes.substr(0, bytes.size() - 1))); },
        "the file ends in edge 1 of 1, in its vertex_pair (byte " +
            std::to_string(header + 60 + 13 + 1 + 4) + ")");
    std::string nan = bytes;
    const float not_a_number = std::numeric_limits<float>::quiet_NaN();
    std::memcpy(nan.data() + header + 15, &not_a_number, 4);  // vertex 2's x
    expect_io_error(
        [&] { litkit::load_ply(write_file("nan-le.ply", nan)); },
        "vertex 2: coordinate x is not a finite number (byte " + std::to_string(header + 15) + ")");
    expect_io_error([&] { litkit::load_ply(write_file("extra.ply", bytes + "xy")); },
                    "2 bytes follow the last element the header declares (byte " +
                        std::to_string(bytes.size()) + ")");
    // A count of 4 GiB is refused before anything is set aside for it.
    std::string huge = bytes;
    huge.replace(huge.find("vertex 4"), 8, "vertex 4294967295");
    expect_io_error([&] { litkit::load_ply(write_file("huge.ply", huge)); },
                    "the header declares 4294967295 vertices of at least 15 bytes each, but "
                    "only 82 bytes are left for them",
                    4, 9);
}

// --- STL ---------------------------------------------------------------------

TEST(Stl, AsciiCubeHasThreeCornersOfItsOwnPerFacet) {
    const Mesh mesh = litkit::load_stl(data / "stl/cube.stl");
    ASSERT_EQ(mesh.triangles.size(), 12u);
    ASSERT_EQ(mesh.positions.size(), 36u);
    for (std::size_t t = 0; t < 12; ++t) {
        EXPECT_EQ(mesh.triangles[t], (Triangle{3 * std::uint32_t(t), 3 * std::uint32_t(t) + 1,
                                               3 * std::uint32_t(t) + 2}));
        for (int k = 0; k < 3; ++k)
            EXPECT_EQ(mesh.positions[3 * t + k], cube_vertices[cube_triangles[t][k]])
                << "facet " << t << " corner " << k;
        EXPECT_EQ(mesh.triangle_faces[t], t);
    }
    // Closed once equal coordinates count as one vertex (docs/spec.md §10.1).
    EXPECT_TRUE(litkit::is_closed(mesh));
    EXPECT_NEAR(litkit::signed_volume(mesh), 1.0, 1e-12);
    // Facets are seven lines each, after the solid's line.
    EXPECT_EQ(litkit::detail::stl_line_of_face(data / "stl/cube.stl", 3), 23u);
}

// Two triangles of the unit square in z = 0, binary, the free header
// starting with "solid" as some exporters write it.
std::string binary_square() {
    Bytes bytes;
    std::string header = "solid but binary";
    header.resize(80, ' ');
    bytes.text(header).put(std::uint32_t{2});
    const float corners[2][3][3] = {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
                                    {{1, 0, 0}, {1, 1, 0}, {0, 1, 0}}};
    for (const auto& triangle : corners) {
        bytes.put(0.0f).put(0.0f).put(1.0f);  // the normal, not read
        for (const auto& corner : triangle) bytes.put(corner[0]).put(corner[1]).put(corner[2]);
        bytes.put(std::uint16_t{0});
    }
    return bytes.data;
}

TEST(Stl, BinaryIsRecognisedByItsSizeEvenAfterSolid) {
    const std::string bytes = binary_square();
    ASSERT_EQ(bytes.size(), 184u);
    const Mesh mesh = litkit::load_stl(write_file("square.stl", bytes));
    expect_positions(mesh, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
    EXPECT_EQ(mesh.triangles, (std::vector<Triangle>{{0, 1, 2}, {3, 4, 5}}));
    EXPECT_EQ(litkit::detail::stl_line_of_face(write_file("square.stl", bytes), 0), 0u);
}

TEST(Stl, BadBinaryFilesNameTheByte) {
    std::string nan = binary_square();
    const float not_a_number = std::numeric_limits<float>::quiet_NaN();
    std::memcpy(nan.data() + 178, &not_a_number, 4);  // 84 + 50 + 12 (normal) + 24 + 8
    expect_io_error([&] { litkit::load_stl(write_file("nan.stl", nan)); },
                    "triangle 2, corner 3: the z coordinate is not a finite number (byte 178)");
    // Binary although it starts with "solid": the count has a zero byte.
    const std::string cut = binary_square().substr(0, 183);
    expect_io_error([&] { litkit::load_stl(write_file("cut.stl", cut)); },
                    "binary STL: the count at byte 80 says 2 triangles, which take 84 + 50 × 2 = "
                    "184 bytes, but the file has 183 (it is cut short)");
    std::string huge = binary_square().substr(0, 134);
    huge.replace(0, 5, "dense");
    huge.replace(80, 4, "\xff\xff\xff\xff");
    expect_io_error([&] { litkit::load_stl(write_file("huge.stl", huge)); },
                    "says 4294967295 triangles, which take 84 + 50 × 4294967295 = 214748364834 "
                    "bytes, but the file has 134");
    expect_io_error([&] { litkit::load_stl(write_file("garbage.stl", "hello")); },
                    "not an STL file");
    std::string empty = binary_square().substr(0, 84);
    empty.replace(80, 4, std::string(4, '\0'));
    expect_io_error([&] { litkit::load_stl(write_file("empty.stl", empty)); },
                    "the file has no faces");
}

// Lines: 1 solid, 2 facet, 3 outer loop, 4–6 vertices, 7 endloop, 8
// endfacet, 9 endsolid.
std::string small_stl(const std::string& vertices, const std::string& end = "endloop\n") {
    return "solid tri\nfacet normal 0 0 1\n outer loop\n" + vertices + " " + end +
           "endfacet\nendsolid tri\n";
}

TEST(Stl, BadTextFilesAreLocated) {
    auto read = [](const std::string& name, const std::string& text) {
        return [=] { litkit::load_stl(write_file(name, text)); };
    };
    const Mesh mesh =
        litkit::load_stl(write_file("tri.stl", small_stl("  vertex 0 0 0\n  vertex 1 0 0\n"
                                                         "  vertex 0 1 0\n")));
    expect_positions(mesh, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    expect_io_error(read("nan.stl", small_stl("  vertex 0 0 0\n  vertex 1 nan 0\n"
                                              "  vertex 0 1 0\n")),
                    "vertex y coordinate 'nan' is not a finite number", 5, 12);
    expect_io_error(read("two.stl", small_stl("  vertex 0 0 0\n  vertex 1 0\n  vertex 0 1 0\n")),
                    "vertex z coordinate 'vertex' is not a number", 6, 3);
    expect_io_error(read("four.stl", small_stl("  vertex 0 0 0\n  vertex 1 0 0\n"
                                               "  vertex 0 1 0\n  vertex 1 1 0\n")),
                    "expected 'endloop' after a facet's three vertices, found 'vertex'", 7, 3);
    expect_io_error(read("no-end.stl",
                         "solid a\nfacet normal 0 0 1\n outer loop\n"
                         "  vertex 0 0 0\n  vertex 1 0 0\n  vertex 0 1 0\n"
                         " endloop\nendfacet\n"),
                    "the file ends before 'endsolid'", 9, 1);
    expect_io_error(read("word.stl", "solid a\nfacets\n"),
                    "expected 'facet' or 'endsolid', found 'facets'", 2, 1);
    expect_io_error(read("none.stl", "solid a\nendsolid a\n"), "the file has no faces");
}

// --- the format key ------------------------------------------------------------

TEST(MeshFiles, AGivenFormatReadsAFileOfAnyName) {
    const fs::path renamed = write_file("cube-ply.txt", "");
    fs::copy_file(data / "ply/cube.ply", renamed, fs::copy_options::overwrite_existing);
    const Mesh mesh = litkit::load_mesh_file(renamed, litkit::MeshFileFormat::Ply);
    EXPECT_EQ(mesh.triangles, cube_triangles);
    // By its extension it is an OBJ file, which it is not.
    EXPECT_THROW(litkit::load_mesh_file(renamed), litkit::IoError);
}

TEST(MeshFiles, TheFormatKeyIsReadAndWritten) {
    const std::string text = R"([room]
width = 10
height = 10
depth = 10
[observer]
position = [0, 0, 4]
[[objects]]
type = "mesh"
file = "cube-ply.txt"
format = "ply"
[[objects]]
type = "mesh"
file = "cube.stl"
position = [2, 0, 0]
)";
    const fs::path folder = litkit_test::scratch_folder() / "keyed";
    fs::create_directories(folder);
    fs::copy_file(data / "ply/cube.ply", folder / "cube-ply.txt",
                  fs::copy_options::overwrite_existing);
    fs::copy_file(data / "stl/cube.stl", folder / "cube.stl", fs::copy_options::overwrite_existing);
    const litkit::Scene scene = litkit::parse_scene(text, folder / "scene.toml");
    const auto& given = std::get<litkit::MeshFileShape>(scene.objects[0].shape);
    EXPECT_EQ(given.format, litkit::MeshFileFormat::Ply);
    EXPECT_EQ(std::get<litkit::MeshFileShape>(scene.objects[1].shape).format, std::nullopt);
    const std::string written = litkit::scene_to_toml(scene, folder / "scene.toml");
    EXPECT_NE(written.find("file = \"cube-ply.txt\"\nformat = \"ply\"\n"), std::string::npos)
        << written;
    EXPECT_EQ(written.find("format = \"obj\""), std::string::npos) << "no key where none was given";
}

// The same cube as OBJ, PLY, STL and glTF (examples/meshes/cube.*) draws
// the same picture, byte for byte: the readers give the same positions and
// triangles (STL's corners weld to the same vertices, docs/spec.md §2).
TEST(MeshFiles, TheSameCubeInEachFormatDrawsTheSamePicture) {
    const fs::path meshes = fs::path(LITKIT_SOURCE_DIR) / "examples/meshes";
    auto picture = [&](const std::string& file) {
        const std::string text = R"([room]
width = 10
height = 10
depth = 10
[observer]
position = [1.5, 2, 3]
look_at = [0, 0, 0]
[output]
width = 160
height = 120
[lighting]
reflection = "phong"
shading = "phong"
[[lights]]
type = "point"
position = [2, 3, 2]
[[objects]]
type = "mesh"
rotation = [10, 20, 0]
file = ")" + file + "\"\n";
        return litkit::render(litkit::parse_scene(text, meshes / "scene.toml"));
    };
    const litkit::Image obj = picture("cube.obj");
    int covered = 0;
    for (std::size_t i = 0; i < obj.rgb.size(); i += 3)
        covered += obj.rgb[i] != 0 || obj.rgb[i + 1] != 0 || obj.rgb[i + 2] != 0;
    EXPECT_GT(covered, 1000) << "the cube is drawn";
    for (const char* file : {"cube.ply", "cube.stl", "cube.gltf"})
        EXPECT_EQ(picture(file).rgb, obj.rgb) << file;
}

}  // namespace
