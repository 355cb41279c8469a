// SPDX-License-Identifier: MIT
// Scene files (docs/spec.md §5, §6): parsing, defaults, merging, located diagnostics,
// and the object transform of docs/spec.md §2.
#include "litkit/scene.hpp"
#include "litkit/shapes.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

namespace litkit {
namespace {

namespace fs = std::filesystem;

// A room and an observer: the two required tables. Six lines, so text
// appended to it starts on line 7.
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

// The diagnostics parse_scene reports for `text`, read as "scene.toml".
std::vector<Diagnostic> diagnostics_of(std::string_view text) {
    try {
        parse_scene(text, "scene.toml");
    } catch (const SceneError& error) {
        return error.diagnostics();
    }
    ADD_FAILURE() << "expected a SceneError for:\n" << text;
    return {};
}

// Checks that `text` gives exactly one diagnostic, at `line`:`column`, whose
// message is `message`.
void expect_single_diagnostic(std::string_view text, std::uint32_t line, std::uint32_t column,
                              std::string_view message) {
    std::vector<Diagnostic> diagnostics = diagnostics_of(text);
    std::string all;
    for (const Diagnostic& d : diagnostics) all += d.to_string() + "\n";
    ASSERT_EQ(diagnostics.size(), 1u) << all;
    const Diagnostic& diagnostic = diagnostics[0];
    EXPECT_EQ(diagnostic.location.file, "scene.toml");
    EXPECT_EQ(diagnostic.location.line, line) << diagnostic.to_string();
    EXPECT_EQ(diagnostic.location.column, column) << diagnostic.to_string();
    EXPECT_EQ(diagnostic.severity, Severity::Error);
    EXPECT_EQ(diagnostic.message, message);
}

void expect_vec3(const glm::vec3& actual, const glm::vec3& expected) {
    EXPECT_FLOAT_EQ(actual.x, expected.x);
    EXPECT_FLOAT_EQ(actual.y, expected.y);
    EXPECT_FLOAT_EQ(actual.z, expected.z);
}

void expect_near_vec3(const glm::vec3& actual, const glm::vec3& expected) {
    EXPECT_NEAR(actual.x, expected.x, 1e-5f);
    EXPECT_NEAR(actual.y, expected.y, 1e-5f);
    EXPECT_NEAR(actual.z, expected.z, 1e-5f);
}

// A fresh folder under the system's temporary folder, removed afterwards.
class SceneFiles : public ::testing::Test {
  protected:
    void SetUp() override {
        std::random_device random;
        folder_ = fs::temp_directory_path() /
                  ("litkit_test_scene_" + std::to_string(random()) + std::to_string(random()));
        fs::create_directories(folder_);
    }
    void TearDown() override {
        std::error_code ignored;
        fs::remove_all(folder_, ignored);
    }
    fs::path write(const fs::path& relative, std::string_view bytes) {
        fs::path path = folder_ / relative;
        fs::create_directories(path.parent_path());
        std::ofstream out(path, std::ios::binary);
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        return path;
    }
    fs::path folder_;
};

// ---------------------------------------------------------------------------
// Values and defaults

TEST(SceneParse, EveryKeyParsesWithItsValue) {
    // Absolute, so that it does not depend on the source name. The scene is
    // a valid one: the validator runs on it too.
    const std::string mesh_file = LITKIT_TEST_DATA "/obj/quad.obj";
    const Scene scene = parse_scene(R"(
[room]
width = 12
height = 8.5
depth = 20

[observer]
position = [1, 2, 3]
look_at = [0, -1, 0.5]
up = [0, 0, 1]
fov = 60
near = 0.1
far = 500

[lighting]
reflection = "blinn-phong"
shading = "gouraud"

[output]
width = 640
height = 480
background = [10, 20, 30]
gamma = 2.2

[[lights]]
name = "fill"
type = "ambient"
color = [255, 0, 51]
intensity = 0.5

[[lights]]
name = "sun"
type = "directional"
direction = [1, -2, 0]

[[lights]]
name = "bulb"
type = "point"
position = [1, 1, 1]
attenuation = [1, 0.5, 0.25]
intensity = 9

[[lights]]
name = "torch"
type = "spot"
position = [0, 3, 0]
attenuation = [0, 1, 0]
direction = [0, -1, 0]
cutoff = 20
exponent = 4

[[objects]]
name = "box"
type = "cube"
size = 2
position = [0, -1, -5]
rotation = [10, 30, 45]
scale = 1.5
material = { color = [200, 80, 60], ka = 0.2, kd = 0.6, ks = 0.3, shininess = 16 }
reflection = "lambert"
shading = "flat"

[[objects]]
type = "sphere"
position = [4, 0, 0]
radius = 0.5
segments = 12
rings = 6

[[objects]]
type = "torus"
position = [-3, 2, 2]
major_radius = 2
minor_radius = 0.5
segments = 10
sides = 8

[[objects]]
type = "teapot"
position = [2.5, 0, 6.5]
size = 3
subdivisions = 4

[[objects]]
type = "mesh"
position = [4, 1, -6]
file = ")" + mesh_file + R"("
)",
                                    "scene.toml");

    EXPECT_FLOAT_EQ(scene.room.width, 12.0f);
    EXPECT_FLOAT_EQ(scene.room.height, 8.5f);
    EXPECT_FLOAT_EQ(scene.room.depth, 20.0f);

    expect_vec3(scene.observer.position, {1, 2, 3});
    expect_vec3(scene.observer.look_at, {0, -1, 0.5f});
    expect_vec3(scene.observer.up, {0, 0, 1});
    EXPECT_FLOAT_EQ(scene.observer.fov_degrees, 60.0f);
    EXPECT_FLOAT_EQ(scene.observer.near, 0.1f);
    EXPECT_FLOAT_EQ(scene.observer.far, 500.0f);

    EXPECT_EQ(scene.reflection, Reflection::BlinnPhong);
    EXPECT_EQ(scene.shading, Shading::Gouraud);

    EXPECT_EQ(scene.output.width, 640);
    EXPECT_EQ(scene.output.height, 480);
    EXPECT_EQ(litkit::to_rgb8(scene.output.background), (Rgb8{10, 20, 30}));
    EXPECT_FLOAT_EQ(scene.output.gamma, 2.2f);

    ASSERT_EQ(scene.lights.size(), 4u);
    EXPECT_EQ(scene.lights[0].name, "fill");
    ASSERT_TRUE(std::holds_alternative<AmbientLight>(scene.lights[0].light.kind));
    expect_vec3(scene.lights[0].light.color, {1.0f, 0.0f, 0.2f});
    EXPECT_FLOAT_EQ(scene.lights[0].light.intensity, 0.5f);

    EXPECT_EQ(scene.lights[1].name, "sun");
    const auto* sun = std::get_if<DirectionalLight>(&scene.lights[1].light.kind);
    ASSERT_NE(sun, nullptr);
    expect_vec3(sun->direction, {1, -2, 0});

    EXPECT_EQ(scene.lights[2].name, "bulb");
    const auto* bulb = std::get_if<PointLight>(&scene.lights[2].light.kind);
    ASSERT_NE(bulb, nullptr);
    expect_vec3(bulb->position, {1, 1, 1});
    expect_vec3(bulb->attenuation, {1, 0.5f, 0.25f});
    EXPECT_FLOAT_EQ(scene.lights[2].light.intensity, 9.0f);

    EXPECT_EQ(scene.lights[3].name, "torch");
    const auto* torch = std::get_if<SpotLight>(&scene.lights[3].light.kind);
    ASSERT_NE(torch, nullptr);
    expect_vec3(torch->position, {0, 3, 0});
    expect_vec3(torch->attenuation, {0, 1, 0});
    expect_vec3(torch->direction, {0, -1, 0});
    EXPECT_FLOAT_EQ(torch->cutoff_degrees, 20.0f);
    EXPECT_FLOAT_EQ(torch->exponent, 4.0f);

    ASSERT_EQ(scene.objects.size(), 5u);
    const SceneObject& box = scene.objects[0];
    EXPECT_EQ(box.name, "box");
    const auto* cube = std::get_if<CubeShape>(&box.shape);
    ASSERT_NE(cube, nullptr);
    EXPECT_FLOAT_EQ(cube->size, 2.0f);
    expect_vec3(box.position, {0, -1, -5});
    expect_vec3(box.rotation_degrees, {10, 30, 45});
    EXPECT_FLOAT_EQ(box.scale, 1.5f);
    expect_vec3(box.material.color, {200 / 255.0f, 80 / 255.0f, 60 / 255.0f});
    EXPECT_FLOAT_EQ(box.material.ka, 0.2f);
    EXPECT_FLOAT_EQ(box.material.kd, 0.6f);
    EXPECT_FLOAT_EQ(box.material.ks, 0.3f);
    EXPECT_FLOAT_EQ(box.material.shininess, 16.0f);
    EXPECT_EQ(box.reflection, Reflection::Lambert);
    EXPECT_EQ(box.shading, Shading::Flat);

    const auto* sphere = std::get_if<SphereShape>(&scene.objects[1].shape);
    ASSERT_NE(sphere, nullptr);
    EXPECT_FLOAT_EQ(sphere->radius, 0.5f);
    EXPECT_EQ(sphere->segments, 12);
    EXPECT_EQ(sphere->rings, 6);

    const auto* torus = std::get_if<TorusShape>(&scene.objects[2].shape);
    ASSERT_NE(torus, nullptr);
    EXPECT_FLOAT_EQ(torus->major_radius, 2.0f);
    EXPECT_FLOAT_EQ(torus->minor_radius, 0.5f);
    EXPECT_EQ(torus->segments, 10);
    EXPECT_EQ(torus->sides, 8);

    const auto* teapot = std::get_if<TeapotShape>(&scene.objects[3].shape);
    ASSERT_NE(teapot, nullptr);
    EXPECT_FLOAT_EQ(teapot->size, 3.0f);
    EXPECT_EQ(teapot->subdivisions, 4);

    const auto* mesh = std::get_if<MeshFileShape>(&scene.objects[4].shape);
    ASSERT_NE(mesh, nullptr);
    EXPECT_EQ(mesh->file, fs::path(mesh_file));
}

TEST(SceneParse, DefaultsApplyWhereKeysAreMissing) {
    const Scene scene = parse_scene(with_required_tables(R"(
[[lights]]
type = "point"
position = [1, 1, 1]
[[lights]]
type = "spot"
position = [0, 3, 0]
direction = [0, -1, 0]
[[lights]]
type = "directional"
direction = [0, -1, 0]
[[objects]]
type = "cube"
[[objects]]
type = "sphere"
position = [3, 0, 0]
[[objects]]
type = "torus"
position = [-3, 0, 0]
[[objects]]
type = "teapot"
position = [0, 0, -3]
)"),
                                    "scene.toml");

    // [observer]: only position was given (docs/spec.md §1).
    expect_vec3(scene.observer.look_at, {0, 0, 0});
    expect_vec3(scene.observer.up, {0, 1, 0});
    EXPECT_FLOAT_EQ(scene.observer.fov_degrees, 45.0f);
    EXPECT_FLOAT_EQ(scene.observer.near, 0.05f);
    EXPECT_FLOAT_EQ(scene.observer.far, 1000.0f);

    // No [lighting]: not given, the caller decides (R11). No [output]: docs/spec.md §5.
    EXPECT_FALSE(scene.reflection.has_value());
    EXPECT_FALSE(scene.shading.has_value());
    EXPECT_EQ(scene.output.width, 800);
    EXPECT_EQ(scene.output.height, 600);
    EXPECT_EQ(scene.output.background, glm::vec3(0.0f));
    EXPECT_FLOAT_EQ(scene.output.gamma, 1.0f);

    ASSERT_EQ(scene.lights.size(), 3u);
    EXPECT_EQ(scene.lights[0].name, "");
    expect_vec3(scene.lights[0].light.color, {1, 1, 1});
    EXPECT_FLOAT_EQ(scene.lights[0].light.intensity, 1.0f);
    const auto* point = std::get_if<PointLight>(&scene.lights[0].light.kind);
    ASSERT_NE(point, nullptr);
    expect_vec3(point->attenuation, {0, 0, 1});
    const auto* spot = std::get_if<SpotLight>(&scene.lights[1].light.kind);
    ASSERT_NE(spot, nullptr);
    expect_vec3(spot->attenuation, {0, 0, 1});
    EXPECT_FLOAT_EQ(spot->cutoff_degrees, 30.0f);
    EXPECT_FLOAT_EQ(spot->exponent, 0.0f);
    EXPECT_TRUE(std::holds_alternative<DirectionalLight>(scene.lights[2].light.kind));

    ASSERT_EQ(scene.objects.size(), 4u);
    const SceneObject& cube_object = scene.objects[0];
    expect_vec3(cube_object.position, {0, 0, 0});
    expect_vec3(cube_object.rotation_degrees, {0, 0, 0});
    EXPECT_FLOAT_EQ(cube_object.scale, 1.0f);
    expect_vec3(cube_object.material.color, {1, 1, 1});
    EXPECT_FLOAT_EQ(cube_object.material.ka, 0.1f);
    EXPECT_FLOAT_EQ(cube_object.material.kd, 0.7f);
    EXPECT_FLOAT_EQ(cube_object.material.ks, 0.5f);
    EXPECT_FLOAT_EQ(cube_object.material.shininess, 32.0f);
    EXPECT_FALSE(cube_object.reflection.has_value());
    EXPECT_FALSE(cube_object.shading.has_value());

    const auto* cube = std::get_if<CubeShape>(&scene.objects[0].shape);
    ASSERT_NE(cube, nullptr);
    EXPECT_FLOAT_EQ(cube->size, 1.0f);
    const auto* sphere = std::get_if<SphereShape>(&scene.objects[1].shape);
    ASSERT_NE(sphere, nullptr);
    EXPECT_FLOAT_EQ(sphere->radius, 1.0f);
    EXPECT_EQ(sphere->segments, 64);
    EXPECT_EQ(sphere->rings, 32);
    const auto* torus = std::get_if<TorusShape>(&scene.objects[2].shape);
    ASSERT_NE(torus, nullptr);
    EXPECT_FLOAT_EQ(torus->major_radius, 1.0f);
    EXPECT_FLOAT_EQ(torus->minor_radius, 0.25f);
    EXPECT_EQ(torus->segments, 64);
    EXPECT_EQ(torus->sides, 32);
    const auto* teapot = std::get_if<TeapotShape>(&scene.objects[3].shape);
    ASSERT_NE(teapot, nullptr);
    EXPECT_FLOAT_EQ(teapot->size, 1.0f);
    EXPECT_EQ(teapot->subdivisions, 10);
}

TEST(SceneParse, IntegersAreAcceptedWhereNumbersBelong) {
    const Scene scene = parse_scene(with_required_tables(R"(
[[objects]]
type = "cube"
size = 3
material = { shininess = 8, ka = 0 }
)"),
                                    "scene.toml");
    ASSERT_EQ(scene.objects.size(), 1u);
    EXPECT_FLOAT_EQ(std::get<CubeShape>(scene.objects[0].shape).size, 3.0f);
    EXPECT_FLOAT_EQ(scene.objects[0].material.shininess, 8.0f);
    EXPECT_FLOAT_EQ(scene.objects[0].material.ka, 0.0f);
}

TEST(SceneParse, HexColoursAreReadPerChannel) {
    const Scene scene = parse_scene(with_required_tables(R"(
[output]
background = "#0a141E"
[[lights]]
type = "ambient"
color = "#ff8000"
[[objects]]
type = "cube"
material = { color = "#336699" }
)"),
                                    "scene.toml");
    EXPECT_EQ(litkit::to_rgb8(scene.output.background), (Rgb8{10, 20, 30}));
    expect_vec3(scene.lights[0].light.color, {1.0f, 128 / 255.0f, 0.0f});
    expect_vec3(scene.objects[0].material.color, {0.2f, 0.4f, 0.6f});
}

TEST(SceneParse, RecordsTheLocationOfEveryValueRead) {
    // Line 7 is the first line after the required tables.
    const Scene scene = parse_scene(with_required_tables(R"([[lights]]
type = "point"
position = [0, 3, 0]
[[objects]]
type = "cube"
[[objects]]
type = "sphere"
position = [-3, 0, 0]
material = { color = [1, 2, 3], kd = 0.5 }
)"),
                                    "scene.toml");
    auto expect_at = [&](std::string_view path, std::uint32_t line, std::uint32_t column) {
        FileLoc location = scene.location_of(path);
        EXPECT_EQ(location.file, "scene.toml") << path;
        EXPECT_EQ(location.line, line) << path;
        EXPECT_EQ(location.column, column) << path;
    };
    expect_at("room", 1, 1);
    expect_at("room.depth", 4, 9);
    expect_at("observer", 5, 1);
    expect_at("observer.position", 6, 12);
    expect_at("lights[0]", 7, 1);
    expect_at("lights[0].type", 8, 8);
    expect_at("lights[0].position", 9, 12);
    expect_at("objects[1]", 12, 1);
    expect_at("objects[1].position", 14, 12);
    expect_at("objects[1].material", 15, 12);
    expect_at("objects[1].material.kd", 15, 38);

    // Defaults have no place in the file.
    EXPECT_EQ(scene.location_of("observer.look_at").line, 0u);
    EXPECT_TRUE(scene.location_of("nothing.here").file.empty());
}

TEST(SceneParse, ShapeTypeNamesAreTheSceneFileSpellings) {
    EXPECT_EQ(shape_type_name(CubeShape{}), "cube");
    EXPECT_EQ(shape_type_name(SphereShape{}), "sphere");
    EXPECT_EQ(shape_type_name(TorusShape{}), "torus");
    EXPECT_EQ(shape_type_name(TeapotShape{}), "teapot");
    EXPECT_EQ(shape_type_name(MeshFileShape{}), "mesh");
}

TEST(SceneParse, RelativeMeshPathResolvesAgainstTheSourceFolder) {
    const Scene scene = parse_scene(with_required_tables(R"(
[[objects]]
type = "mesh"
file = "obj/quad.obj"
)"),
                                    LITKIT_TEST_DATA "/scene.toml");
    EXPECT_EQ(std::get<MeshFileShape>(scene.objects[0].shape).file,
              fs::path(LITKIT_TEST_DATA) / "obj" / "quad.obj");
}

// ---------------------------------------------------------------------------
// Diagnostics: one line each, located at the offending value (docs/spec.md §6)

TEST(SceneDiagnostics, StringWhereAnArrayBelongsIsLocatedAtTheValue) {
    expect_single_diagnostic(with_required_tables(R"([[lights]]
name = "key"
type = "point"
position = "0, 0, 0"
)"),
                             10, 12,
                             "lights[0] 'key': position must be an array of 3 numbers, found "
                             "string");
}

TEST(SceneDiagnostics, StringWhereANumberBelongs) {
    expect_single_diagnostic(with_required_tables(R"([[objects]]
type = "cube"
size = "big"
)"),
                             9, 8, "objects[0]: size must be a number, found string");
}

TEST(SceneDiagnostics, WrongElementOfAVectorIsLocatedAtTheElement) {
    expect_single_diagnostic(with_required_tables(R"([[objects]]
type = "cube"
position = [0, true, 0]
)"),
                             9, 16, "objects[0]: position[1] must be a number, found boolean true");
}

TEST(SceneDiagnostics, VectorOfTheWrongLength) {
    expect_single_diagnostic(
        "[room]\nwidth = 10\nheight = 10\ndepth = 10\n"
        "[observer]\nposition = [0, 4]\n",
        6, 12,
        "observer: position must be an array of 3 numbers, found array of 2 "
        "values");
}

TEST(SceneDiagnostics, FloatWhereAnIntegerBelongs) {
    expect_single_diagnostic(with_required_tables(R"([[objects]]
type = "sphere"
segments = 3.5
)"),
                             9, 12, "objects[0]: segments must be an integer, found float 3.5");
}

TEST(SceneDiagnostics, IntegerThatDoesNotFitAnIntIsAnError) {
    expect_single_diagnostic(with_required_tables(R"([output]
width = 3000000000
)"),
                             8, 9, "output: width 3000000000 is too large for an integer here");
}

TEST(SceneDiagnostics, NumberTooLargeForAFloatIsAnError) {
    expect_single_diagnostic(with_required_tables(R"([[objects]]
type = "cube"
size = 1e300
)"),
                             9, 8, "objects[0]: size 1e+300 is too large");
}

TEST(SceneDiagnostics, NanAndInfinityAreErrors) {
    std::vector<Diagnostic> diagnostics = diagnostics_of(with_required_tables(R"([output]
gamma = nan
[[lights]]
type = "ambient"
intensity = -inf
)"));
    ASSERT_EQ(diagnostics.size(), 2u);
    EXPECT_EQ(diagnostics[0].location.line, 8u);
    EXPECT_EQ(diagnostics[0].location.column, 9u);
    EXPECT_EQ(diagnostics[0].message, "output: gamma must be a finite number, found nan");
    EXPECT_EQ(diagnostics[1].location.line, 11u);
    EXPECT_EQ(diagnostics[1].location.column, 13u);
    EXPECT_EQ(diagnostics[1].message, "lights[0]: intensity must be a finite number, found -inf");
}

TEST(SceneDiagnostics, MissingRequiredKeyIsLocatedAtItsTable) {
    expect_single_diagnostic(with_required_tables(R"([[lights]]
name = "key"
type = "point"
)"),
                             7, 1, "lights[0] 'key': missing required key 'position'");
}

TEST(SceneDiagnostics, MissingRoomSizeIsLocatedAtTheRoom) {
    std::vector<Diagnostic> diagnostics =
        diagnostics_of("[observer]\nposition = [0, 0, 4]\n\n[room]\nwidth = 10\ndepth = 10\n");
    ASSERT_EQ(diagnostics.size(), 1u);
    EXPECT_EQ(diagnostics[0].location.line, 4u);
    EXPECT_EQ(diagnostics[0].location.column, 1u);
    EXPECT_EQ(diagnostics[0].message, "room: missing required key 'height'");
}

TEST(SceneDiagnostics, MissingRoomAndObserverAreErrors) {
    std::vector<Diagnostic> diagnostics = diagnostics_of("[output]\nwidth = 100\n");
    ASSERT_EQ(diagnostics.size(), 2u);
    EXPECT_EQ(diagnostics[0].location.file, "scene.toml");
    EXPECT_EQ(diagnostics[0].message, "missing required table [room]");
    EXPECT_EQ(diagnostics[1].message, "missing required table [observer]");
}

TEST(SceneDiagnostics, MissingTypeIsAnError) {
    expect_single_diagnostic(with_required_tables(R"([[objects]]
size = 1
)"),
                             7, 1,
                             "objects[0]: missing required key 'type' (one of cube, sphere, torus, "
                             "teapot, mesh)");
}

TEST(SceneDiagnostics, UnknownTypeGetsASuggestion) {
    expect_single_diagnostic(with_required_tables(R"([[lights]]
type = "Spot"
position = [0, 1, 0]
direction = [0, -1, 0]
)"),
                             8, 8,
                             "lights[0]: type \"Spot\" is not a light type (one of ambient, "
                             "directional, point, spot); did you mean 'spot'?");
}

TEST(SceneDiagnostics, UnknownKeyIsLocatedAtTheKeyWithASuggestion) {
    expect_single_diagnostic(with_required_tables(R"([[objects]]
type = "cube"
sise = 2
)"),
                             9, 1, "objects[0]: unknown key 'sise'; did you mean 'size'?");
}

TEST(SceneDiagnostics, UnknownKeyWithoutACloseMatchHasNoSuggestion) {
    expect_single_diagnostic(with_required_tables(R"([observer.extra]
)"),
                             7, 11, "observer: unknown key 'extra'");
}

TEST(SceneDiagnostics, UnknownTopLevelTableGetsASuggestion) {
    expect_single_diagnostic(with_required_tables(R"([ligthing]
reflection = "phong"
)"),
                             7, 2, "unknown top-level key 'ligthing'; did you mean 'lighting'?");
}

TEST(SceneDiagnostics, UnknownMaterialKeyIsNamedWithItsTable) {
    expect_single_diagnostic(with_required_tables(R"([[objects]]
name = "box"
type = "cube"
material = { kdd = 0.5 }
)"),
                             10, 14,
                             "objects[0] 'box': unknown key 'material.kdd'; did you mean "
                             "'material.kd'?");
}

TEST(SceneDiagnostics, KeyOfAnotherLightTypeIsAnError) {
    expect_single_diagnostic(
        with_required_tables(R"([[lights]]
type = "point"
position = [0, 1, 0]
cutoff = 20
)"),
        10, 1, "lights[0]: key 'cutoff' does not belong to a point light (only to: spot)");
}

TEST(SceneDiagnostics, KeyOfAnotherObjectTypeIsAnError) {
    expect_single_diagnostic(with_required_tables(R"([[objects]]
type = "cube"
radius = 2
)"),
                             9, 1,
                             "objects[0]: key 'radius' does not belong to a cube object (only to: "
                             "sphere)");
}

TEST(SceneDiagnostics, MisspeltEnumValuesGetSuggestions) {
    std::vector<Diagnostic> diagnostics = diagnostics_of(with_required_tables(R"([lighting]
reflection = "Phong"
shading = "gourad"
[[objects]]
type = "cube"
reflection = "blinn"
)"));
    ASSERT_EQ(diagnostics.size(), 3u);
    EXPECT_EQ(diagnostics[0].location.line, 8u);
    EXPECT_EQ(diagnostics[0].location.column, 14u);
    EXPECT_EQ(diagnostics[0].message,
              "lighting: reflection \"Phong\" is not a reflection model (one of lambert, "
              "half-lambert, phong, blinn-phong, oren-nayar, cook-torrance, toon, minnaert, "
              "gooch); did you mean 'phong'?");
    EXPECT_EQ(diagnostics[1].location.line, 9u);
    EXPECT_EQ(diagnostics[1].location.column, 11u);
    EXPECT_EQ(diagnostics[1].message,
              "lighting: shading \"gourad\" is not a shading model (one of flat, gouraud, "
              "phong, faceted); did you mean 'gouraud'?");
    EXPECT_EQ(diagnostics[2].location.line, 12u);
    EXPECT_EQ(diagnostics[2].location.column, 14u);
    EXPECT_NE(diagnostics[2].message.find("did you mean 'blinn-phong'?"), std::string::npos)
        << diagnostics[2].message;
}

TEST(SceneDiagnostics, BadColoursAreErrors) {
    std::vector<Diagnostic> diagnostics = diagnostics_of(with_required_tables(R"([output]
background = "#12345"
[[lights]]
type = "ambient"
color = [300, 0, 0.5]
)"));
    ASSERT_EQ(diagnostics.size(), 3u);
    EXPECT_EQ(diagnostics[0].location.line, 8u);
    EXPECT_EQ(diagnostics[0].location.column, 14u);
    EXPECT_EQ(diagnostics[0].message,
              "output: background must be [r, g, b] with integers 0-255 or a \"#rrggbb\" string, "
              "found \"#12345\"");
    EXPECT_EQ(diagnostics[1].location.column, 10u);
    EXPECT_EQ(diagnostics[1].message,
              "lights[0]: color[0] must be an integer 0-255, found integer 300");
    EXPECT_EQ(diagnostics[2].location.column, 18u);
    EXPECT_EQ(diagnostics[2].message,
              "lights[0]: color[2] must be an integer 0-255, found float 0.5");
}

TEST(SceneDiagnostics, LightsThatAreNotAnArrayOfTablesAreAnError) {
    expect_single_diagnostic(with_required_tables(R"([lights]
type = "point"
)"),
                             7, 1, "lights must be an array of tables ([[lights]]), found table");
}

TEST(SceneDiagnostics, AllProblemsAreReportedTogetherInFileOrder) {
    const std::string text = with_required_tables(R"([output]
width = "wide"
[[lights]]
type = "point"
[[objects]]
type = "cube"
size = 1
radius = 3
colour = [1, 2, 3]
)");
    std::vector<Diagnostic> diagnostics = diagnostics_of(text);
    ASSERT_EQ(diagnostics.size(), 4u);
    EXPECT_EQ(diagnostics[0].to_string(),
              "scene.toml:8:9: error: output: width must be an integer, found string");
    EXPECT_EQ(diagnostics[1].to_string(),
              "scene.toml:9:1: error: lights[0]: missing required key 'position'");
    EXPECT_EQ(diagnostics[2].to_string(),
              "scene.toml:14:1: error: objects[0]: key 'radius' does not belong to a cube object "
              "(only to: sphere)");
    EXPECT_EQ(diagnostics[3].to_string(),
              "scene.toml:15:1: error: objects[0]: unknown key 'colour'");

    // The exception's text lists them all, one per line.
    try {
        parse_scene(text, "scene.toml");
    } catch (const SceneError& error) {
        const std::string what = error.what();
        EXPECT_EQ(std::count(what.begin(), what.end(), '\n'), 3);
    }
}

// ---------------------------------------------------------------------------
// Files: reading, merging (docs/spec.md §5) and unreadable files (R9)

TEST_F(SceneFiles, TwoFilesMergeLightsAndObjectsInOrder) {
    const fs::path first = write("a.toml", R"([room]
width = 10
height = 10
depth = 10
[[lights]]
name = "a1"
type = "ambient"
[[objects]]
name = "first"
type = "cube"
)");
    const fs::path second = write("b.toml", R"([observer]
position = [0, 0, 4]
[[lights]]
name = "b1"
type = "point"
position = [1, 1, 1]
[[lights]]
name = "b2"
type = "directional"
direction = [0, -1, 0]
[[objects]]
name = "second"
type = "sphere"
position = [3, 0, 0]
)");
    const std::vector<fs::path> files{first, second};
    const Scene scene = load_scene(files);

    ASSERT_EQ(scene.lights.size(), 3u);
    EXPECT_EQ(scene.lights[0].name, "a1");
    EXPECT_EQ(scene.lights[1].name, "b1");
    EXPECT_EQ(scene.lights[2].name, "b2");
    ASSERT_EQ(scene.objects.size(), 2u);
    EXPECT_EQ(scene.objects[0].name, "first");
    EXPECT_EQ(scene.objects[1].name, "second");
    expect_vec3(scene.observer.position, {0, 0, 4});

    // Numbering runs on across files; locations name the file.
    const FileLoc b1 = scene.location_of("lights[1]");
    EXPECT_EQ(b1.file, second.string());
    EXPECT_EQ(b1.line, 3u);
    EXPECT_EQ(b1.column, 1u);
    EXPECT_EQ(scene.location_of("room").file, first.string());
}

TEST_F(SceneFiles, TableInTwoFilesIsAnErrorNamingBoth) {
    const fs::path first = write("c.toml", R"([room]
width = 10
height = 10
depth = 10
[observer]
position = [0, 0, 4]
)");
    const fs::path second = write("d.toml", R"(# a second room
[room]
width = 5
height = 5
depth = 5
)");
    const std::vector<fs::path> files{first, second};
    try {
        load_scene(files);
        FAIL() << "expected a SceneError";
    } catch (const SceneError& error) {
        ASSERT_EQ(error.diagnostics().size(), 1u);
        const Diagnostic& diagnostic = error.diagnostics()[0];
        EXPECT_EQ(diagnostic.location.file, second.string());
        EXPECT_EQ(diagnostic.location.line, 2u);
        EXPECT_EQ(diagnostic.location.column, 1u);
        EXPECT_EQ(diagnostic.message,
                  "[room] is defined twice: here and at " + first.string() + ":1:1");
    }
}

TEST_F(SceneFiles, RelativeMeshPathResolvesAgainstTheSceneFilesFolder) {
    // A tetrahedron: the validator reads mesh files.
    constexpr std::string_view tetrahedron =
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
        "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
    write("sub/models/thing.obj", tetrahedron);
    const fs::path absolute = write("elsewhere/other.obj", tetrahedron);
    const fs::path scene_file = write("sub/scene.toml", with_required_tables(R"(
[[objects]]
type = "mesh"
file = "models/thing.obj"
[[objects]]
type = "mesh"
position = [-3, 0, 0]
file = ")" + absolute.string() + R"("
)"));
    const std::vector<fs::path> files{scene_file};
    const Scene scene = load_scene(files);
    ASSERT_EQ(scene.objects.size(), 2u);
    EXPECT_EQ(std::get<MeshFileShape>(scene.objects[0].shape).file,
              folder_ / "sub" / "models" / "thing.obj");
    EXPECT_EQ(std::get<MeshFileShape>(scene.objects[1].shape).file, absolute);
}

TEST_F(SceneFiles, MissingFileIsAnIoError) {
    const fs::path missing = folder_ / "lights.toml";
    const std::vector<fs::path> files{missing};
    try {
        load_scene(files);
        FAIL() << "expected an IoError";
    } catch (const IoError& error) {
        EXPECT_EQ(error.path(), missing.string());
        EXPECT_EQ(error.reason(), "No such file or directory");
        EXPECT_EQ(std::string(error.what()),
                  "error: cannot read '" + missing.string() + "': No such file or directory");
    }
}

TEST_F(SceneFiles, DirectoryIsAnIoError) {
    const std::vector<fs::path> files{folder_};
    try {
        load_scene(files);
        FAIL() << "expected an IoError";
    } catch (const IoError& error) {
        EXPECT_EQ(error.path(), folder_.string());
        EXPECT_EQ(error.reason(), "Is a directory");
    }
}

TEST_F(SceneFiles, InvalidTomlIsAnIoErrorWithItsPlace) {
    const fs::path path = write("broken.toml", "[room]\nwidth = 10\nheight = = 3\n");
    const std::vector<fs::path> files{path};
    try {
        load_scene(files);
        FAIL() << "expected an IoError";
    } catch (const IoError& error) {
        EXPECT_EQ(error.path(), path.string());
        EXPECT_EQ(error.location().file, path.string());
        EXPECT_EQ(error.location().line, 3u);
        EXPECT_EQ(error.location().column, 10u);
        EXPECT_FALSE(error.reason().empty());
    }
}

TEST_F(SceneFiles, InvalidUtf8IsAnIoError) {
    const fs::path path = write("latin1.toml", "[room]\nwidth = 10\n# caf\xe9\n");
    const std::vector<fs::path> files{path};
    try {
        load_scene(files);
        FAIL() << "expected an IoError";
    } catch (const IoError& error) {
        EXPECT_EQ(error.location().line, 3u);
        EXPECT_NE(error.reason().find("utf-8"), std::string::npos) << error.reason();
    }
}

TEST(SceneParse, InvalidTomlTextIsAnIoError) {
    EXPECT_THROW(parse_scene("[room\n", "text.toml"), IoError);
}

// Found by fuzz/fuzz_scene.cpp: toml++ 3.3.0 reaches undefined behaviour
// (an "unreachable" point in is_non_ascii_horizontal_whitespace) when it
// meets most non-ASCII characters outside strings, down to the two bytes of
// "é" (upstream marzer/tomlplusplus#190, #295). Debian's build of it rejects
// them; these pin that such text stays a located IoError, as a typo like
// "fov = 45°" must.
TEST(SceneParse, NonAsciiOutsideStringsIsAnIoErrorWithItsPlace) {
    struct Case {
        std::string text;
        std::uint32_t line;
        std::uint32_t column;
    };
    const std::vector<Case> cases{
        {"\xc3\xa9", 1, 1},                                        // é
        {"caf\xc3\xa9 = 1\n", 1, 4},                               // a key café
        {with_required_tables("fov = 45\xc2\xb0\n"), 7, 9},        // 45°
        {with_required_tables("fov = 45 \xe3\x80\x80\n"), 7, 10},  // ideographic space
    };
    for (const Case& c : cases) {
        try {
            parse_scene(c.text, "scene.toml");
            ADD_FAILURE() << "expected an IoError for: " << c.text;
        } catch (const IoError& error) {
            EXPECT_EQ(error.location().line, c.line) << error.what();
            EXPECT_EQ(error.location().column, c.column) << error.what();
        }
    }
}

// The same toml++ path, in valid TOML: after a line-ending backslash in a
// multi-line string, the next line may start with any character (§ here).
TEST(SceneParse, NonAsciiAfterALineEndingBackslashStaysInTheString) {
    const Scene scene =
        parse_scene(with_required_tables(
                        "[[lights]]\ntype = \"ambient\"\nname = \"\"\"\\\n  \xc2\xa7 1\"\"\"\n"),
                    "scene.toml");
    ASSERT_EQ(scene.lights.size(), 1u);
    EXPECT_EQ(scene.lights[0].name, "\xc2\xa7 1");
}

// ---------------------------------------------------------------------------
// Placement (docs/spec.md §2)

glm::vec3 transform_point(const SceneObject& object, const glm::vec3& point) {
    glm::vec4 result = object_to_world(object) * glm::vec4(point, 1.0f);
    return {result.x, result.y, result.z};
}

TEST(ObjectToWorld, RotationAboutYMapsXToMinusZ) {
    SceneObject object;
    object.rotation_degrees = {0, 90, 0};
    expect_near_vec3(transform_point(object, {1, 0, 0}), {0, 0, -1});
}

TEST(ObjectToWorld, RotatesAboutXFirstThenY) {
    // Rx(90) takes +y to +z, then Ry(90) takes +z to +x. (The other order
    // would give +z.)
    SceneObject object;
    object.rotation_degrees = {90, 90, 0};
    expect_near_vec3(transform_point(object, {0, 1, 0}), {1, 0, 0});
}

TEST(ObjectToWorld, RotatesAboutYBeforeZ) {
    // Ry(90) takes +x to −z, which Rz leaves alone. (Rz first would give +y.)
    SceneObject object;
    object.rotation_degrees = {0, 90, 90};
    expect_near_vec3(transform_point(object, {1, 0, 0}), {0, 0, -1});
}

TEST(ObjectToWorld, ScalesThenRotatesThenTranslates) {
    SceneObject object;
    object.position = {1, 2, 3};
    object.rotation_degrees = {0, 0, 90};
    object.scale = 2.0f;
    // S: (2, 0, 0); Rz(90): (0, 2, 0); T: (1, 4, 3).
    expect_near_vec3(transform_point(object, {1, 0, 0}), {1, 4, 3});
    expect_near_vec3(transform_point(object, {0, 0, 0}), {1, 2, 3});
}

// Right angles turn axes onto axes exactly, and whole turns come off
// exactly (the sines and cosines are of degrees, core/portable_math.hpp):
// the same bits in every build, whatever its C library's sinf.
TEST(ObjectToWorld, RightAnglesAreExactAndWholeTurnsComeOff) {
    SceneObject object;
    object.rotation_degrees = {90, 90, 0};
    EXPECT_EQ(transform_point(object, {0, 1, 0}), glm::vec3(1, 0, 0));
    object.rotation_degrees = {0, 180, 270};
    EXPECT_EQ(transform_point(object, {1, 0, 0}), glm::vec3(0, 1, 0));
    SceneObject turned, reduced;
    turned.rotation_degrees = {10000, -1234.5f, 1e6f};  // 280, 205.5, 280 after whole turns
    reduced.rotation_degrees = {280, 205.5f, 280};
    EXPECT_EQ(object_to_world(turned), object_to_world(reduced));
}

// ---------------------------------------------------------------------------
// The default scene (docs/spec.md §7, R12)

TEST(DefaultScene, HasOneCubeOnePointLightAtTheCentreAndPhong) {
    const Scene scene = default_scene();
    ASSERT_EQ(scene.objects.size(), 1u);
    const auto* cube = std::get_if<CubeShape>(&scene.objects[0].shape);
    ASSERT_NE(cube, nullptr);
    ASSERT_EQ(scene.lights.size(), 1u);
    const auto* light = std::get_if<PointLight>(&scene.lights[0].light.kind);
    ASSERT_NE(light, nullptr);
    expect_vec3(light->position, {0, 0, 0});
    EXPECT_EQ(scene.reflection, Reflection::Phong);
    EXPECT_EQ(scene.shading, Shading::Phong);
    // A starting file draws something: no "outside the view" or similar.
    EXPECT_TRUE(scene.warnings.empty());

    // The light must not be inside the cube: it is farther from the cube's
    // centre than the cube's corners are.
    const SceneObject& object = scene.objects[0];
    const float half_diagonal = 0.5f * cube->size * object.scale * std::sqrt(3.0f);
    EXPECT_GT(glm::length(object.position - light->position), half_diagonal);

    // The file is commented for a student, and the locations name it.
    EXPECT_NE(default_scene_toml().find('#'), std::string_view::npos);
    EXPECT_EQ(scene.location_of("lights[0].position").file, "default.toml");
}

}  // namespace
}  // namespace litkit

// One catch for every error the library throws: litkit::Error,
// with the place of the first problem.
TEST(Errors, EveryLibraryErrorIsALitkitErrorWithItsPlace) {
    static_assert(std::is_base_of_v<litkit::Error, litkit::SceneError>);
    static_assert(std::is_base_of_v<litkit::Error, litkit::IoError>);
    static_assert(std::is_base_of_v<litkit::Error, litkit::ArgumentError>);
    try {
        litkit::parse_scene(
            "[room]\nwidth = 10\nheight = 10\ndepth = 10\n[observer]\nposition = [0, 0, 99]\n",
            "bad.toml");
        FAIL() << "no error";
    } catch (const litkit::Error& error) {
        EXPECT_EQ(error.location().to_string(), "bad.toml:6:12");
        EXPECT_EQ(std::string(error.what()).rfind("bad.toml:6:12: error: ", 0), 0u) << error.what();
    }
    try {
        litkit::parse_scene("[room\n", "text.toml");
        FAIL() << "no error";
    } catch (const litkit::Error& error) {
        EXPECT_EQ(error.location().file, "text.toml");
        EXPECT_EQ(error.location().line, 1u);
    }
    EXPECT_THROW(litkit::make_sphere(0.0f, 8, 4), litkit::Error);
}
