// SPDX-License-Identifier: MIT
// The scene keys of refraction (docs/spec.md §10.1) as scene files give them:
// read with their values and defaults, checked with the rules of §6 (range,
// type, "did you mean"), the closed-mesh rule, written back by scene_to_toml,
// and refused by the drawers that cannot trace rays yet. Each error is
// checked with its place; each has a valid control beside it.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "litkit/error.hpp"
#include "litkit/export.hpp"
#include "litkit/render.hpp"
#include "litkit/scene.hpp"
#include "litkit/validate.hpp"

namespace litkit {
namespace {

namespace fs = std::filesystem;

// The room and observer, six lines: text appended starts on line 7.
constexpr std::string_view required_tables = R"([room]
width = 10
height = 10
depth = 10
[observer]
position = [0, 0, 4]
)";

std::string with_required_tables(std::string_view extra) {
    return std::string(required_tables) + std::string(extra);
}

std::vector<Diagnostic> diagnostics_of(std::string_view text) {
    try {
        parse_scene(text, "scene.toml");
    } catch (const SceneError& error) {
        return error.diagnostics();
    }
    ADD_FAILURE() << "expected a SceneError for:\n" << text;
    return {};
}

// The 1-based column of `fragment` in line `line` of `text` (found there once).
std::uint32_t column_of(std::string_view text, std::uint32_t line, std::string_view fragment) {
    std::size_t begin = 0;
    for (std::uint32_t n = 1; n < line; ++n) begin = text.find('\n', begin) + 1;
    const std::string_view row = text.substr(begin, text.find('\n', begin) - begin);
    const std::size_t at = row.find(fragment);
    EXPECT_NE(at, std::string_view::npos) << fragment << " is not on line " << line;
    EXPECT_EQ(row.find(fragment, at + 1), std::string_view::npos) << fragment << " twice";
    return static_cast<std::uint32_t>(at + 1);
}

// Exactly one error, at line `line` where `fragment` starts, saying `message`.
void expect_single_error(std::string_view text, std::uint32_t line, std::string_view fragment,
                         std::string_view message) {
    const std::vector<Diagnostic> diagnostics = diagnostics_of(text);
    std::string all;
    for (const Diagnostic& d : diagnostics) all += d.to_string() + "\n";
    ASSERT_EQ(diagnostics.size(), 1u) << all;
    EXPECT_EQ(diagnostics[0].severity, Severity::Error);
    EXPECT_EQ(diagnostics[0].location.file, "scene.toml");
    EXPECT_EQ(diagnostics[0].location.line, line) << all;
    EXPECT_EQ(diagnostics[0].location.column, column_of(text, line, fragment)) << all;
    EXPECT_EQ(diagnostics[0].message, message);
}

// A cube whose material is `material` (an inline table's inside): the
// material is on line 9.
std::string cube_with_material(std::string_view material) {
    return with_required_tables("[[objects]]\ntype = \"cube\"\nmaterial = { " +
                                std::string(material) + " }\n");
}

// A room whose last key (line 5) is `key_and_value`, then the observer.
std::string room_with(std::string_view key_and_value) {
    return "[room]\nwidth = 10\nheight = 10\ndepth = 10\n" + std::string(key_and_value) +
           "\n[observer]\nposition = [0, 0, 4]\n";
}

// The errors validate_scene finds (a scene without lights also has a warning).
std::vector<std::string> errors_of(const Scene& scene) {
    std::vector<std::string> messages;
    for (const Diagnostic& d : validate_scene(scene))
        if (d.severity == Severity::Error) messages.push_back(d.message);
    return messages;
}

std::string lighting_with(std::string_view key_and_value) {
    return with_required_tables("[lighting]\n" + std::string(key_and_value) + "\n");
}

// ---------------------------------------------------------------------------
// Values and defaults

TEST(RefractionKeys, EveryKeyIsReadWithItsValue) {
    const std::string text = room_with("ior = 1.25") +
                             "[lighting]\nmax_depth = 3\n[[objects]]\ntype = \"sphere\"\n"
                             "material = { transmission = 0.75, ior = 1.33, absorption_color = "
                             "[51, 102, 255], absorption_distance = 2.5 }\n";
    const Scene scene = parse_scene(text, "scene.toml");
    EXPECT_EQ(scene.room.ior, 1.25f);
    EXPECT_EQ(scene.max_depth, 3);
    const Material& m = scene.objects.at(0).material;
    EXPECT_EQ(m.transmission, 0.75f);
    EXPECT_EQ(m.ior, 1.33f);
    // 51/255 = 0.2, 102/255 = 0.4, 255/255 = 1, as from_rgb8 divides.
    EXPECT_EQ(m.absorption_color, glm::vec3(51.0f / 255.0f, 102.0f / 255.0f, 1.0f));
    EXPECT_EQ(m.absorption_distance, 2.5f);
    // Each recorded where it was read, for later messages.
    EXPECT_EQ(scene.location_of("room.ior").line, 5u);
    // Lines 1-7 are the room and observer, 8 [lighting], 10 [[objects]].
    EXPECT_EQ(scene.location_of("lighting.max_depth").line, 9u);
    EXPECT_EQ(scene.location_of("objects[0].material.absorption_distance").line, 12u);
}

TEST(RefractionKeys, DefaultsAreTheSpecsWhereKeysAreMissing) {
    const Scene scene =
        parse_scene(with_required_tables("[[objects]]\ntype = \"cube\"\n"), "scene.toml");
    EXPECT_EQ(scene.room.ior, 1.0f);
    EXPECT_EQ(scene.max_depth, 8);
    EXPECT_EQ(default_max_depth, 8);
    EXPECT_EQ(min_max_depth, 1);
    EXPECT_EQ(max_max_depth, 16);
    const Material& m = scene.objects.at(0).material;
    EXPECT_EQ(m.transmission, 0.0f);
    EXPECT_EQ(m.ior, 1.5f);
    EXPECT_EQ(m.absorption_color, glm::vec3(1.0f));
    EXPECT_EQ(m.absorption_distance, 1.0f);
}

TEST(RefractionKeys, TheRangesEndsAreAccepted) {
    for (const char* material : {"transmission = 0", "transmission = 1", "ior = 1", "ior = 3",
                                 "absorption_color = [0, 0, 0]", "absorption_color = \"#ffffff\"",
                                 "absorption_distance = 1e-30", "absorption_distance = 1e30"})
        EXPECT_NO_THROW(parse_scene(cube_with_material(material), "scene.toml")) << material;
    for (const char* room : {"ior = 1", "ior = 3", "ior = 1.0003"})
        EXPECT_NO_THROW(parse_scene(room_with(room), "scene.toml")) << room;
    for (const char* lighting : {"max_depth = 1", "max_depth = 16"})
        EXPECT_NO_THROW(parse_scene(lighting_with(lighting), "scene.toml")) << lighting;
}

// ---------------------------------------------------------------------------
// Out of range, of the wrong type, misspelt

TEST(RefractionKeys, MaterialValuesOutOfRangeAreLocatedAtTheValue) {
    const struct {
        const char* material;
        const char* value;
        const char* message;
    } cases[] = {
        {"transmission = 1.5", "1.5",
         "objects[0]: material.transmission must be in [0, 1], found 1.5"},
        {"transmission = -0.25", "-0.25",
         "objects[0]: material.transmission must be in [0, 1], found -0.25"},
        {"ior = 0.5", "0.5", "objects[0]: material.ior must be in [1, 3], found 0.5"},
        {"ior = 3.5", "3.5", "objects[0]: material.ior must be in [1, 3], found 3.5"},
        {"absorption_distance = 0", "0",
         "objects[0]: material.absorption_distance must be > 0, found 0"},
        {"absorption_distance = -2", "-2",
         "objects[0]: material.absorption_distance must be > 0, found -2"},
        {"absorption_color = [256, 0, 0]", "256",
         "objects[0]: material.absorption_color[0] must be an integer 0-255, found integer 256"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.material);
        expect_single_error(cube_with_material(c.material), 9, c.value, c.message);
    }
}

TEST(RefractionKeys, MaterialValuesOfTheWrongTypeAreLocatedAtTheValue) {
    const struct {
        const char* material;
        const char* value;
        const char* message;
    } cases[] = {
        {"transmission = \"half\"", "\"half\"",
         "objects[0]: material.transmission must be a number, found string"},
        {"ior = [1.5]", "[1.5]",
         "objects[0]: material.ior must be a number, found array of 1 value"},
        {"absorption_color = 5", "5",
         "objects[0]: material.absorption_color must be [r, g, b] with integers 0-255 or a "
         "\"#rrggbb\" string, found integer 5"},
        {"absorption_color = [0.5, 0, 0]", "0.5",
         "objects[0]: material.absorption_color[0] must be an integer 0-255, found float 0.5"},
        {"absorption_distance = true", "true",
         "objects[0]: material.absorption_distance must be a number, found boolean true"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.material);
        expect_single_error(cube_with_material(c.material), 9, c.value, c.message);
    }
}

TEST(RefractionKeys, MisspeltMaterialKeysGetSuggestions) {
    const struct {
        const char* key;
        const char* meant;
    } cases[] = {
        {"IOR", "ior"},
        {"refraction_index", "ior"},
        {"index_of_refraction", "ior"},
        {"transmision", "transmission"},
        {"transparency", "transmission"},
        {"absorption_colour", "absorption_color"},
        {"absorption_distnce", "absorption_distance"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.key);
        expect_single_error(cube_with_material(std::string(c.key) + " = 1"), 9, c.key,
                            "objects[0]: unknown key 'material." + std::string(c.key) +
                                "'; did you mean 'material." + c.meant + "'?");
    }
}

TEST(RefractionKeys, RoomIorIsCheckedAsTheOtherKeys) {
    expect_single_error(room_with("ior = 0.9"), 5, "0.9", "room: ior must be in [1, 3], found 0.9");
    expect_single_error(room_with("ior = 3.01"), 5, "3.01",
                        "room: ior must be in [1, 3], found 3.01");
    expect_single_error(room_with("ior = \"1.33\""), 5, "\"1.33\"",
                        "room: ior must be a number, found string");
    expect_single_error(room_with("IOR = 1.33"), 5, "IOR",
                        "room: unknown key 'IOR'; did you mean 'ior'?");
    expect_single_error(room_with("refraction_index = 1.33"), 5, "refraction_index",
                        "room: unknown key 'refraction_index'; did you mean 'ior'?");
}

TEST(RefractionKeys, MaxDepthIsAnIntegerFrom1To16) {
    expect_single_error(lighting_with("max_depth = 0"), 8, "0",
                        "lighting: max_depth must be 1–16, found 0");
    expect_single_error(lighting_with("max_depth = 17"), 8, "17",
                        "lighting: max_depth must be 1–16, found 17");
    expect_single_error(lighting_with("max_depth = 4.0"), 8, "4.0",
                        "lighting: max_depth must be an integer, found float 4.0");
    expect_single_error(lighting_with("max_depth = \"8\""), 8, "\"8\"",
                        "lighting: max_depth must be an integer, found string");
    expect_single_error(lighting_with("max_dept = 8"), 8, "max_dept",
                        "lighting: unknown key 'max_dept'; did you mean 'max_depth'?");
    expect_single_error(lighting_with("max_bounces = 8"), 8, "max_bounces",
                        "lighting: unknown key 'max_bounces'; did you mean 'max_depth'?");
}

TEST(RefractionKeys, ScenesBuiltInCodeAreCheckedToo) {
    Scene scene = parse_scene(with_required_tables("[[objects]]\ntype = \"cube\"\n"), "s.toml");
    EXPECT_TRUE(errors_of(scene).empty());
    scene.objects[0].material.absorption_color = glm::vec3(51.0f, 1.0f, 1.0f);  // 0-255 by mistake
    scene.objects[0].material.absorption_distance = std::numeric_limits<float>::infinity();
    scene.max_depth = 20;
    scene.room.ior = 0.0f;
    EXPECT_EQ(errors_of(scene),
              (std::vector<std::string>{
                  "room: ior must be in [1, 3], found 0",
                  "lighting: max_depth must be 1–16, found 20",
                  "objects[0]: material.absorption_color must be 0–1 per channel "
                  "(litkit::from_rgb8 converts 0–255), found [51, 1, 1]",
                  "objects[0]: material.absorption_distance must be a finite number, "
                  "found inf",
              }));
    // check_renderable, every renderer's precondition, says the same.
    EXPECT_THROW(check_renderable(scene), SceneError);
}

// ---------------------------------------------------------------------------
// The closed-mesh rule

TEST(RefractionKeys, TransmissionOnTheTeapotIsLocatedAtTheObject) {
    const std::string text = with_required_tables(
        "[[objects]]\nname = \"pot\"\ntype = \"teapot\"\nmaterial = { transmission = 0.5 }\n");
    expect_single_error(text, 7, "[[objects]]",
                        "objects[0] 'pot': transmission 0.5 needs a closed mesh (docs/spec.md "
                        "§10.1), and the teapot is not closed; use a cube, sphere, torus or "
                        "closed mesh, or transmission 0");
    // The control: every key on the teapot, transmission 0, is ignored.
    EXPECT_NO_THROW(parse_scene(
        with_required_tables("[[objects]]\ntype = \"teapot\"\nmaterial = { transmission = 0, "
                             "ior = 2.42, absorption_color = \"#102030\", absorption_distance = "
                             "0.5 }\n"),
        "scene.toml"));
}

TEST(RefractionKeys, TheBuiltInClosedShapesMayRefract) {
    for (const char* shape : {"type = \"cube\"", "type = \"sphere\"\nsegments = 3\nrings = 2",
                              "type = \"torus\"\nsegments = 3\nsides = 3"})
        EXPECT_NO_THROW(parse_scene(with_required_tables("[[objects]]\n" + std::string(shape) +
                                                         "\nmaterial = { transmission = 1 }\n"),
                                    "scene.toml"))
            << shape;
}

std::string mesh_scene(const std::string& file, const char* transmission) {
    return with_required_tables("[[objects]]\nname = \"lens\"\ntype = \"mesh\"\nfile = \"" +
                                (fs::path(LITKIT_TEST_DATA) / "obj" / file).generic_string() +
                                "\"\nmaterial = { transmission = " + transmission + " }\n");
}

TEST(RefractionKeys, AnOpenMeshFileIsLocatedAtTheObjectNamingAnOpenEdge) {
    // tests/test_closed_mesh.cpp works the edge out: face 1 (line 13 of the
    // file), from (0.5, 0.5, 0.5) to (-0.5, 0.5, 0.5).
    expect_single_error(mesh_scene("open_cube.obj", "0.25"), 7, "[[objects]]",
                        "objects[0] 'lens': transmission 0.25 needs a closed mesh (docs/spec.md "
                        "§10.1), and mesh file 'open_cube.obj' is not closed: its edge from "
                        "[0.5, 0.5, 0.5] to [-0.5, 0.5, 0.5] (face 1, line 13) belongs to one "
                        "triangle only");
    // Controls: the open mesh that does not refract, and the closed one that does.
    EXPECT_NO_THROW(parse_scene(mesh_scene("open_cube.obj", "0"), "scene.toml"));
    EXPECT_NO_THROW(parse_scene(mesh_scene("closed_cube.obj", "1"), "scene.toml"));
}

TEST(RefractionKeys, AnOpenInMemoryMeshIsNamedByItsTriangle) {
    Scene scene = parse_scene(with_required_tables(""), "scene.toml");
    Mesh mesh;  // the tetrahedron of tests/test_closed_mesh.cpp without its face (1,2,3)
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}};
    SceneObject object;
    object.shape = MeshDataShape(mesh);
    object.material.transmission = 0.5f;
    scene.objects.push_back(object);
    EXPECT_EQ(errors_of(scene),
              std::vector<std::string>{
                  "objects[0]: transmission 0.5 needs a closed mesh (docs/spec.md §10.1), and the "
                  "in-memory mesh is not closed: its edge from [0, 1, 0] to [1, 0, 0] (triangle 0) "
                  "belongs to one triangle only"});
    // Closed with its fourth face; open again without transmission.
    mesh.triangles.push_back({1, 2, 3});
    scene.objects[0].shape = MeshDataShape(mesh);
    EXPECT_TRUE(errors_of(scene).empty());
    mesh.triangles.pop_back();
    scene.objects[0].shape = MeshDataShape(mesh);
    scene.objects[0].material.transmission = 0.0f;
    EXPECT_TRUE(errors_of(scene).empty());
}

// ---------------------------------------------------------------------------
// Written back

TEST(RefractionKeys, SceneToTomlWritesThemAndReadsBackTheSameScene) {
    const std::string text = room_with("ior = 1.25") +
                             "[lighting]\nmax_depth = 3\n[[objects]]\ntype = \"sphere\"\n"
                             "material = { transmission = 0.75, ior = 1.33, absorption_color = "
                             "[51, 102, 254], absorption_distance = 2.5 }\n";
    const Scene scene = parse_scene(text, "scene.toml");
    const std::string written = scene_to_toml(scene);
    for (const char* key :
         {"\nior = 1.25\n", "\nmax_depth = 3\n", "transmission = 0.75", "ior = 1.33",
          "absorption_color = [51, 102, 254]", "absorption_distance = 2.5"})
        EXPECT_NE(written.find(key), std::string::npos) << key << " not in\n" << written;
    const Scene again = parse_scene(written, "again.toml");
    EXPECT_EQ(again.room.ior, scene.room.ior);
    EXPECT_EQ(again.max_depth, scene.max_depth);
    const Material& a = again.objects.at(0).material;
    const Material& b = scene.objects.at(0).material;
    EXPECT_EQ(a.transmission, b.transmission);
    EXPECT_EQ(a.ior, b.ior);
    EXPECT_EQ(a.absorption_color, b.absorption_color);
    EXPECT_EQ(a.absorption_distance, b.absorption_distance);
    EXPECT_EQ(scene_to_toml(again), written);
    // The defaults are written too, and read back as the defaults.
    const Scene plain = parse_scene(with_required_tables("[[objects]]\ntype = \"cube\"\n"), "p");
    const Scene plain_again = parse_scene(scene_to_toml(plain), "p2");
    EXPECT_EQ(plain_again.max_depth, 8);
    EXPECT_EQ(plain_again.room.ior, 1.0f);
    EXPECT_EQ(plain_again.objects.at(0).material.ior, 1.5f);
    EXPECT_EQ(plain_again.objects.at(0).material.absorption_color, glm::vec3(1.0f));
    EXPECT_FALSE(plain_again.reflection.has_value()) << "[lighting] is written for max_depth alone";
}

// ---------------------------------------------------------------------------
// The exports draw glass with programs of their own (docs/spec.md §10)

TEST(RefractionKeys, TheExportsWriteGlassPrograms) {
    Scene scene = parse_scene(mesh_scene("closed_cube.obj", "0.5"), "scene.toml");
    const fs::path folder = fs::temp_directory_path() / "litkit-refraction-export";
    fs::remove_all(folder);
    std::vector<std::string> names;
    for (const fs::path& file : export_glsl(scene, folder)) names.push_back(file.filename());
    std::sort(names.begin(), names.end());
    const std::string stem = std::string(to_string(default_reflection)) + "-" +
                             std::string(to_string(default_shading)) + "-glass";
    EXPECT_EQ(names, (std::vector<std::string>{stem + ".frag", stem + ".vert"}));
    fs::remove_all(folder);
    // The control: every key present, transmission 0: the plain program.
    scene.objects[0].material.transmission = 0.0f;
    scene.objects[0].material.ior = 2.0f;
    for (const fs::path& file : export_glsl(scene, folder))
        EXPECT_EQ(file.filename().string().find("-glass"), std::string::npos) << file;
    fs::remove_all(folder);
}

}  // namespace
}  // namespace litkit
