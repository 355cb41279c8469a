// SPDX-License-Identifier: MIT
// The C++ API as a program calls it: the renderers' preconditions
// (check_renderable), meshes given in memory (MeshDataShape), and the
// inside-out warning for closed meshes whose faces wind clockwise.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include "litkit/gl_renderer.hpp"
#include "litkit/litkit.hpp"
#include "run_command.hpp"

namespace fs = std::filesystem;

namespace {

const fs::path octahedron_file = fs::path(LITKIT_SOURCE_DIR) / "examples/meshes/octahedron.obj";
const fs::path inside_out_file = fs::path(LITKIT_TEST_DATA) / "obj/inside_out.obj";

// The octahedron of examples/meshes/octahedron.obj, typed in again: corners
// at distance 1 on each axis, faces counter-clockwise seen from outside.
litkit::Mesh octahedron() {
    litkit::Mesh mesh;
    mesh.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    mesh.triangles = {{4, 0, 2}, {0, 5, 2}, {5, 1, 2}, {1, 4, 2},
                      {0, 4, 3}, {5, 0, 3}, {1, 5, 3}, {4, 1, 3}};
    return mesh;
}

litkit::Scene scene_with(litkit::Shape shape) {
    litkit::Scene scene = litkit::default_scene();
    scene.output.width = 160;
    scene.output.height = 120;
    scene.objects.at(0).shape = std::move(shape);
    scene.objects.at(0).rotation_degrees = {-20.0f, 60.0f, 15.0f};
    return scene;
}

// Renders, expecting SceneError, and returns its message.
std::string render_error(const litkit::Scene& scene) {
    try {
        litkit::render(scene);
    } catch (const litkit::SceneError& error) {
        return error.what();
    }
    ADD_FAILURE() << "render() accepted the scene";
    return {};
}

bool has_warning(const litkit::Scene& scene, const std::string& text) {
    for (const litkit::Diagnostic& warning : scene.warnings)
        if (warning.message.find(text) != std::string::npos) return true;
    return false;
}

}  // namespace

// --- preconditions ----------------------------------------------------------

TEST(Preconditions, ShapeParametersBuiltInCodeAreRefusedWithTheValue) {
    litkit::Scene scene = scene_with(litkit::SphereShape{.radius = -1.0f});
    const std::string message = render_error(scene);
    EXPECT_NE(message.find("objects[0]"), std::string::npos) << message;
    EXPECT_NE(message.find("radius must be > 0, found -1"), std::string::npos) << message;
}

TEST(Preconditions, NanOrInfiniteCameraIsRefused) {
    litkit::Scene scene = litkit::default_scene();
    scene.observer.position.y = std::numeric_limits<float>::quiet_NaN();
    EXPECT_NE(render_error(scene).find("observer: position must be finite"), std::string::npos);
    scene = litkit::default_scene();
    scene.observer.look_at.x = std::numeric_limits<float>::infinity();
    EXPECT_NE(render_error(scene).find("observer: look_at must be finite"), std::string::npos);
    scene = litkit::default_scene();
    scene.observer.fov_degrees = std::numeric_limits<float>::quiet_NaN();
    EXPECT_NE(render_error(scene).find("fov must be in [0.01, 180)"), std::string::npos);
}

TEST(Preconditions, ImageSizeOutOfRangeIsRefused) {
    litkit::Scene scene = litkit::default_scene();
    scene.output.width = 0;
    EXPECT_NE(render_error(scene).find("width must be 1–16384, found 0"), std::string::npos);
    scene = litkit::default_scene();
    scene.output.height = 100000;
    EXPECT_NE(render_error(scene).find("height must be 1–16384, found 100000"), std::string::npos);
}

TEST(Preconditions, EveryProblemIsListedAndEachIsALitkitError) {
    litkit::Scene scene = litkit::default_scene();
    scene.output.width = -5;
    scene.objects.at(0).material.kd = 2.0f;
    scene.lights.at(0).light.intensity = std::numeric_limits<float>::infinity();
    try {
        litkit::Renderer renderer(scene);
        FAIL() << "the renderer accepted the scene";
    } catch (const litkit::Error& error) {
        const auto* scene_error = dynamic_cast<const litkit::SceneError*>(&error);
        ASSERT_NE(scene_error, nullptr);
        EXPECT_EQ(scene_error->diagnostics().size(), 3u) << error.what();
    }
}

TEST(Preconditions, ThreadCountOutOfRangeIsAnArgumentError) {
    litkit::RenderOptions options;
    options.threads = -1;
    EXPECT_THROW(litkit::Renderer(litkit::default_scene(), options), litkit::ArgumentError);
    options.threads = litkit::max_render_threads + 1;
    EXPECT_THROW(litkit::render(litkit::default_scene(), options), litkit::ArgumentError);
}

TEST(Preconditions, AFailedUpdateKeepsTheSceneTheRendererHad) {
    litkit::Scene scene = scene_with(litkit::CubeShape{});
    litkit::Renderer renderer(scene);
    const litkit::Image before = renderer.render();
    litkit::Scene bad = scene;
    bad.observer.up = {0.0f, 0.0f, 0.0f};
    EXPECT_THROW(renderer.update(bad), litkit::SceneError);
    EXPECT_EQ(renderer.render().rgb, before.rgb);
}

TEST(Preconditions, TheOpenGlBackendChecksThemBeforeAnyOpenGl) {
    litkit::Scene scene = litkit::default_scene();
    scene.output.height = 0;
    // SceneError, not GlError: the check comes before a context is made, so
    // this holds on a machine without OpenGL too.
    EXPECT_THROW(litkit::GlRenderer renderer(scene), litkit::SceneError);
}

TEST(Preconditions, RelationsBetweenEntitiesAreValidateScenesNotTheRenderers) {
    // Two cubes in one place break spec §6 (validate_scene says so) but are
    // drawable: render() does not repeat the overlap checks.
    litkit::Scene scene = scene_with(litkit::CubeShape{});
    scene.objects.push_back(scene.objects.front());
    bool overlap_reported = false;
    for (const litkit::Diagnostic& d : litkit::validate_scene(scene))
        overlap_reported |= d.message.find("overlaps") != std::string::npos;
    EXPECT_TRUE(overlap_reported);
    EXPECT_NO_THROW(litkit::render(scene));
}

TEST(Preconditions, ValuesSetInCodeAreValidatedToo) {
    // validate_scene now finds non-finite values a file cannot hold.
    litkit::Scene scene = litkit::default_scene();
    scene.objects.at(0).position.z = std::numeric_limits<float>::quiet_NaN();
    bool found = false;
    for (const litkit::Diagnostic& d : litkit::validate_scene(scene))
        found |= d.message.find("position must be finite") != std::string::npos;
    EXPECT_TRUE(found);
}

// --- meshes in memory -------------------------------------------------------

TEST(MeshData, DrawsExactlyAsTheSameMeshReadFromAFile) {
    const litkit::Scene from_memory = scene_with(litkit::MeshDataShape(octahedron()));
    const litkit::Scene from_file = scene_with(litkit::MeshFileShape{octahedron_file});
    const litkit::Image expected = litkit::render(from_file);
    const litkit::Image image = litkit::render(from_memory);
    EXPECT_EQ(image.rgb, expected.rgb);
    int covered = 0;
    for (std::size_t i = 0; i < image.rgb.size(); i += 3)
        covered += image.rgb[i] != litkit::to_rgb8(from_file.output.background)[0];
    EXPECT_GT(covered, 500) << "the octahedron is drawn";
}

TEST(MeshData, OpenGlDrawsItAsItDrawsTheFile) {
    const litkit::Scene from_memory = scene_with(litkit::MeshDataShape(octahedron()));
    const litkit::Scene from_file = scene_with(litkit::MeshFileShape{octahedron_file});
    try {
        litkit::GlRenderer memory(from_memory);
        litkit::GlRenderer file(from_file);
        EXPECT_EQ(memory.triangle_count(), 8u);
        EXPECT_EQ(memory.render().rgb, file.render().rgb);
    } catch (const litkit::GlError& error) {
        GTEST_SKIP() << "no OpenGL here: " << error.what();
    }
}

TEST(MeshData, ExportedProgramEmbedsTheSameVerticesAsForTheFile) {
    const fs::path root = fs::temp_directory_path() / ("litkit-api-" + std::to_string(::getpid()));
    fs::remove_all(root);
    litkit::export_cpp(scene_with(litkit::MeshDataShape(octahedron())), root / "memory", "demo",
                       "s");
    litkit::export_cpp(scene_with(litkit::MeshFileShape{octahedron_file}), root / "file", "demo",
                       "s");
    auto text = [](const fs::path& path) {
        std::ifstream in(path);
        return std::string(std::istreambuf_iterator<char>(in), {});
    };
    std::string memory = text(root / "memory/main.cpp");
    // The one difference: the comment naming each object's shape type.
    const std::size_t type = memory.find("\"cube\": mesh data, 8 triangles");
    ASSERT_NE(type, std::string::npos);
    memory.replace(type, std::string("\"cube\": mesh data").size(), "\"cube\": mesh");
    const bool same = memory == text(root / "file/main.cpp");  // not printed: 40 kB
    EXPECT_TRUE(same);
    EXPECT_FALSE(litkit::export_glsl(scene_with(litkit::MeshDataShape(octahedron())), root / "glsl")
                     .empty());
    fs::remove_all(root);
}

TEST(MeshData, IsValidatedAsAMeshFileIs) {
    struct Case {
        litkit::Mesh mesh;
        std::string message;
    };
    std::vector<Case> cases;
    cases.push_back({litkit::Mesh{}, "the mesh has no triangles"});
    litkit::Mesh nan = octahedron();
    nan.positions[3].y = std::numeric_limits<float>::quiet_NaN();
    cases.push_back({nan, "position 3 is not finite"});
    litkit::Mesh beyond = octahedron();
    beyond.triangles[5][1] = 6;
    cases.push_back({beyond, "triangle 5 refers to position 6, but the mesh has 6 positions"});
    for (const Case& c : cases) {
        const litkit::Scene scene = scene_with(litkit::MeshDataShape(c.mesh));
        EXPECT_EQ(litkit::check_mesh_data(c.mesh).rfind(c.message, 0), 0u)
            << litkit::check_mesh_data(c.mesh);
        bool validated = false;
        for (const litkit::Diagnostic& d : litkit::validate_scene(scene))
            validated |= d.severity == litkit::Severity::Error &&
                         d.message.find("in-memory mesh: " + c.message) != std::string::npos;
        EXPECT_TRUE(validated) << c.message;
        EXPECT_NE(render_error(scene).find(c.message), std::string::npos) << c.message;
        EXPECT_THROW(litkit::object_mesh(scene.objects[0]), litkit::ArgumentError);
    }
    EXPECT_NE(render_error(scene_with(litkit::MeshDataShape{})).find("holds no mesh"),
              std::string::npos);
}

TEST(MeshData, UpdateKeepsItsMeshWhenOnlyTheCameraMoves) {
    litkit::Scene scene = scene_with(litkit::MeshDataShape(octahedron()));
    litkit::Renderer renderer(scene);
    scene.observer.position = {1.0f, 2.0f, 4.0f};
    renderer.update(scene);  // the same shared mesh
    EXPECT_EQ(renderer.mesh_builds(), 1u);
    litkit::Scene copy = scene_with(litkit::MeshDataShape(octahedron()));  // equal, not shared
    copy.observer = scene.observer;
    renderer.update(copy);
    EXPECT_EQ(renderer.mesh_builds(), 1u);
    // And the picture is the one a fresh renderer draws from there.
    EXPECT_EQ(renderer.render().rgb, litkit::render(copy).rgb);
    litkit::Mesh moved = octahedron();
    moved.positions[0].x = 1.5f;
    renderer.update(scene_with(litkit::MeshDataShape(moved)));
    EXPECT_EQ(renderer.mesh_builds(), 2u);
}

TEST(MeshData, SameGeometryComparesSharedOrEqualMeshes) {
    const litkit::Scene a = scene_with(litkit::MeshDataShape(octahedron()));
    litkit::Scene b = a;  // shares the mesh
    EXPECT_TRUE(litkit::same_geometry(a.objects[0], b.objects[0]));
    b = scene_with(litkit::MeshDataShape(octahedron()));
    EXPECT_TRUE(litkit::same_geometry(a.objects[0], b.objects[0]));
    litkit::Mesh other = octahedron();
    std::swap(other.triangles[0][0], other.triangles[0][1]);
    b = scene_with(litkit::MeshDataShape(other));
    EXPECT_FALSE(litkit::same_geometry(a.objects[0], b.objects[0]));
    b = scene_with(litkit::MeshFileShape{octahedron_file});
    EXPECT_FALSE(litkit::same_geometry(a.objects[0], b.objects[0]));
}

TEST(MeshData, SceneFilesRefuseItAndMeshToObjWritesIt) {
    litkit::Scene scene = scene_with(litkit::MeshDataShape(octahedron()));
    scene.objects[0].name = "gem";
    try {
        litkit::scene_to_toml(scene);
        FAIL() << "scene_to_toml wrote an in-memory mesh";
    } catch (const litkit::ArgumentError& error) {
        EXPECT_NE(std::string(error.what()).find("object 'gem' has an in-memory mesh"),
                  std::string::npos);
    }
    // The way out the message names: the mesh as an OBJ file, read back.
    const fs::path path =
        fs::temp_directory_path() / ("litkit-api-" + std::to_string(::getpid()) + ".obj");
    std::ofstream(path) << litkit::mesh_to_obj(octahedron());
    const litkit::Mesh back = litkit::load_obj(path);
    fs::remove(path);
    EXPECT_EQ(back.positions, octahedron().positions);
    EXPECT_EQ(back.triangles, octahedron().triangles);
    EXPECT_EQ(litkit::shape_type_name(scene.objects[0].shape), "mesh data");
}

// --- inside-out meshes ------------------------------------------------------

TEST(InsideOut, SignedVolumeAndClosedness) {
    // The octahedron is 8 tetrahedra of volume 1/6 each.
    EXPECT_NEAR(litkit::signed_volume(octahedron()), 4.0 / 3.0, 1e-12);
    const litkit::Mesh inside_out = litkit::load_obj(inside_out_file);
    EXPECT_NEAR(litkit::signed_volume(inside_out), -4.0 / 3.0, 1e-12);
    EXPECT_TRUE(litkit::is_closed(octahedron()));
    EXPECT_TRUE(litkit::is_closed(inside_out));
    EXPECT_TRUE(litkit::is_closed(litkit::make_cube(1.0f))) << "corners repeated per face weld";
    litkit::Mesh open = octahedron();
    open.triangles.pop_back();
    EXPECT_FALSE(litkit::is_closed(open));
    litkit::Mesh mixed = octahedron();  // one face flipped: not consistently wound
    std::swap(mixed.triangles[0][0], mixed.triangles[0][1]);
    EXPECT_FALSE(litkit::is_closed(mixed));
}

TEST(InsideOut, AnInsideOutObjFileLoadsWithAWarningThatSaysHowToFixIt) {
    const std::string scene_text =
        "[room]\nwidth = 10\nheight = 10\ndepth = 10\n"
        "[observer]\nposition = [0, 0, 4]\n"
        "[lighting]\nreflection = \"phong\"\nshading = \"phong\"\n"
        "[[lights]]\ntype = \"point\"\nposition = [2, 2, 3]\n"
        "[[objects]]\ntype = \"mesh\"\nfile = \"";
    const fs::path data = fs::path(LITKIT_TEST_DATA) / "obj";
    const litkit::Scene bad =
        litkit::parse_scene(scene_text + "inside_out.obj\"\n", data / "s.toml");
    ASSERT_TRUE(has_warning(bad, "inside out")) << "no warning";
    for (const litkit::Diagnostic& w : bad.warnings) {
        if (w.message.find("inside out") == std::string::npos) continue;
        EXPECT_NE(w.message.find("'inside_out.obj'"), std::string::npos) << w.message;
        EXPECT_NE(w.message.find("reverse the order of every face's vertices"), std::string::npos);
        EXPECT_EQ(w.location.line, 15u) << "at the file key";
    }
    EXPECT_NO_THROW(litkit::render(bad)) << "a warning, not an error";
    const std::string good_text = scene_text + octahedron_file.string() + "\"\n";
    EXPECT_FALSE(has_warning(litkit::parse_scene(good_text, data / "s.toml"), "inside out"));
}

TEST(InsideOut, TheCommandLineRendersItAndPrintsTheWarning) {
    const fs::path folder =
        fs::temp_directory_path() / ("litkit-inside-" + std::to_string(::getpid()));
    fs::create_directories(folder);
    std::ofstream(folder / "s.toml")
        << "[room]\nwidth = 10\nheight = 10\ndepth = 10\n[observer]\nposition = [0, 0, 4]\n"
           "[lighting]\nreflection = \"phong\"\nshading = \"phong\"\n"
           "[[lights]]\ntype = \"point\"\nposition = [2, 2, 3]\n"
           "[[objects]]\ntype = \"mesh\"\nfile = \""
        << inside_out_file.string() << "\"\n";
    const auto run = litkit_test::run_command(
        std::string(LITKIT_CLI) + " render " + (folder / "s.toml").string() + " -o " +
        (folder / "s.png").string() + " --width 40 --height 30");
    EXPECT_EQ(run.status, 0) << run.output;
    EXPECT_NE(run.output.find(
                  "s.toml:15:8: warning: objects[0]: mesh file 'inside_out.obj' is inside out"),
              std::string::npos)
        << run.output;
    EXPECT_TRUE(fs::exists(folder / "s.png"));
    fs::remove_all(folder);
}

TEST(InsideOut, AnInsideOutMeshInMemoryIsWarnedAbout) {
    litkit::Mesh mesh = octahedron();
    for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
    bool warned = false;
    for (const litkit::Diagnostic& d :
         litkit::validate_scene(scene_with(litkit::MeshDataShape(mesh))))
        warned |= d.severity == litkit::Severity::Warning &&
                  d.message.find("in-memory mesh is inside out") != std::string::npos;
    EXPECT_TRUE(warned);
}

// --- one colour convention --------------------------------------------------

namespace {

litkit::Rgb8 byte_triple(int b) {
    return {static_cast<std::uint8_t>(b), static_cast<std::uint8_t>(255 - b),
            static_cast<std::uint8_t>((b * 7) % 256)};
}

std::string toml_triple(const litkit::Rgb8& c) {
    return "[" + std::to_string(c[0]) + ", " + std::to_string(c[1]) + ", " + std::to_string(c[2]) +
           "]";
}

}  // namespace

TEST(Colours, EveryByteSurvivesTheRoundTripThrough0To1) {
    for (int b = 0; b < 256; ++b) {
        const litkit::Rgb8 bytes = byte_triple(b);
        const glm::vec3 unit = litkit::from_rgb8(bytes);
        EXPECT_EQ(unit.x, static_cast<float>(b) / 255.0f);
        EXPECT_EQ(litkit::to_rgb8(unit), bytes) << b;
    }
    EXPECT_EQ(litkit::to_rgb8({-0.5f, 2.0f, std::numeric_limits<float>::quiet_NaN()}),
              (litkit::Rgb8{0, 255, 0}));
    EXPECT_EQ(litkit::to_rgb8({0.5f / 255.0f, 1.5f / 255.0f, 0.49f / 255.0f}),
              (litkit::Rgb8{1, 2, 0}))
        << "halves round up";
}

TEST(Colours, EveryBackgroundByteIsDrawnAndWrittenBackAsGiven) {
    litkit::Scene base = litkit::default_scene();
    base.objects.clear();
    std::string text = litkit::scene_to_toml(base);
    const std::string key = "background = ";
    const std::size_t at = text.find(key) + key.size();
    for (int b = 0; b < 256; ++b) {
        const litkit::Rgb8 bytes = byte_triple(b);
        text.replace(at, text.find('\n', at) - at, toml_triple(bytes));
        litkit::Scene scene = litkit::parse_scene(text, "colour.toml");
        scene.output.width = 4;
        scene.output.height = 3;
        const litkit::Image image = litkit::render(scene);
        for (std::size_t i = 0; i < image.rgb.size(); i += 3)
            ASSERT_TRUE(image.rgb[i] == bytes[0] && image.rgb[i + 1] == bytes[1] &&
                        image.rgb[i + 2] == bytes[2])
                << "background " << toml_triple(bytes);
        EXPECT_NE(litkit::scene_to_toml(scene).find(key + toml_triple(bytes) + "\n"),
                  std::string::npos);
    }
}

TEST(Colours, OpenGlDrawsEveryBackgroundByteAsTheCpuDoes) {
    litkit::Scene scene = litkit::default_scene();
    scene.objects.clear();  // every pixel is background
    scene.output.width = 2;
    scene.output.height = 2;
    try {
        litkit::GlRenderer gl(scene);
        for (int b = 0; b < 256; ++b) {
            const litkit::Rgb8 bytes = byte_triple(b);
            scene.output.background = litkit::from_rgb8(bytes);
            gl.update(scene);
            const litkit::Image image = gl.render();
            const std::uint8_t* corner = image.pixel(0, 0);
            ASSERT_TRUE(corner[0] == bytes[0] && corner[1] == bytes[1] && corner[2] == bytes[2])
                << toml_triple(bytes) << " came out " << int(corner[0]) << " " << int(corner[1])
                << " " << int(corner[2]);
        }
    } catch (const litkit::GlError& error) {
        GTEST_SKIP() << "no OpenGL here: " << error.what();
    }
}

TEST(Colours, ABackgroundOutside0To1IsRefused) {
    litkit::Scene scene = litkit::default_scene();
    scene.output.background = {0.2f, 1.5f, 0.0f};
    EXPECT_NE(render_error(scene).find("background must be 0–1 per channel"), std::string::npos);
    scene.output.background = {std::numeric_limits<float>::quiet_NaN(), 0.0f, 0.0f};
    EXPECT_NE(render_error(scene).find("background must be 0–1 per channel"), std::string::npos);
}

TEST(Colours, TheExportedProgramClearsToTheSameBytes) {
    litkit::Scene scene = litkit::default_scene();
    scene.output.background = litkit::from_rgb8({1, 128, 255});
    const fs::path root =
        fs::temp_directory_path() / ("litkit-colour-" + std::to_string(::getpid()));
    fs::remove_all(root);
    litkit::export_cpp(scene, root, "demo", "s");
    std::ifstream in(root / "main.cpp");
    const std::string text((std::istreambuf_iterator<char>(in)), {});
    fs::remove_all(root);
    EXPECT_NE(text.find("glm::vec3(1, 128, 255) / 255.0f"), std::string::npos);
}

// --- no crash on any value --------------------------------------------------

TEST(Preconditions, AnyExtremeValueRendersOrThrowsALitkitErrorNeverCrashes) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    const std::vector<float> values = {nan, inf, -inf, -1.0f, 0.0f, 1e-30f, 1e30f, 3.0f};
    using Setter = void (*)(litkit::Scene&, float);
    const std::vector<std::pair<const char*, Setter>> fields = {
        {"room.width", [](litkit::Scene& s, float v) { s.room.width = v; }},
        {"observer.position.x", [](litkit::Scene& s, float v) { s.observer.position.x = v; }},
        {"observer.look_at.y", [](litkit::Scene& s, float v) { s.observer.look_at.y = v; }},
        {"observer.up.z",
         [](litkit::Scene& s, float v) {
             s.observer.up = {0.0f, v, 0.0f};
         }},
        {"observer.fov", [](litkit::Scene& s, float v) { s.observer.fov_degrees = v; }},
        {"observer.near", [](litkit::Scene& s, float v) { s.observer.near = v; }},
        {"observer.far", [](litkit::Scene& s, float v) { s.observer.far = v; }},
        {"output.gamma", [](litkit::Scene& s, float v) { s.output.gamma = v; }},
        {"output.background", [](litkit::Scene& s, float v) { s.output.background.y = v; }},
        {"light.intensity", [](litkit::Scene& s, float v) { s.lights[0].light.intensity = v; }},
        {"light.color", [](litkit::Scene& s, float v) { s.lights[0].light.color.x = v; }},
        {"light.position",
         [](litkit::Scene& s, float v) {
             s.lights[0].light.kind = litkit::PointLight{.position = {v, 0.0f, 0.0f}};
         }},
        {"light.attenuation",
         [](litkit::Scene& s, float v) {
             s.lights[0].light.kind = litkit::PointLight{.attenuation = {0.0f, 0.0f, v}};
         }},
        {"spot.cutoff",
         [](litkit::Scene& s, float v) {
             s.lights[0].light.kind = litkit::SpotLight{.cutoff_degrees = v};
         }},
        {"directional",
         [](litkit::Scene& s, float v) {
             s.lights[0].light.kind = litkit::DirectionalLight{{v, v, v}};
         }},
        {"object.scale", [](litkit::Scene& s, float v) { s.objects[0].scale = v; }},
        {"object.position", [](litkit::Scene& s, float v) { s.objects[0].position.z = v; }},
        {"object.rotation", [](litkit::Scene& s, float v) { s.objects[0].rotation_degrees.y = v; }},
        {"material.color", [](litkit::Scene& s, float v) { s.objects[0].material.color.z = v; }},
        {"material.shininess",
         [](litkit::Scene& s, float v) { s.objects[0].material.shininess = v; }},
        {"material.sigma", [](litkit::Scene& s, float v) { s.objects[0].material.sigma = v; }},
        {"cube.size", [](litkit::Scene& s, float v) { s.objects[0].shape = litkit::CubeShape{v}; }},
        {"sphere.radius",
         [](litkit::Scene& s, float v) {
             s.objects[0].shape = litkit::SphereShape{.radius = v, .segments = 8, .rings = 4};
         }},
        {"crease", [](litkit::Scene& s, float v) { s.objects[0].crease_angle_degrees = v; }},
        {"mesh data",
         [](litkit::Scene& s, float v) {
             litkit::Mesh mesh = octahedron();
             mesh.positions[1].x = v;
             s.objects[0].shape = litkit::MeshDataShape(std::move(mesh));
         }},
    };
    int refused = 0, drawn = 0;
    for (const auto& [name, set] : fields) {
        for (const float value : values) {
            litkit::Scene scene = litkit::default_scene();
            scene.output.width = 16;
            scene.output.height = 12;
            set(scene, value);
            try {
                const litkit::Image image = litkit::render(scene);
                EXPECT_EQ(image.rgb.size(), 16u * 12u * 3u) << name << " = " << value;
                ++drawn;
            } catch (const litkit::Error& error) {
                EXPECT_FALSE(std::string(error.what()).empty());
                ++refused;
            }
        }
    }
    // NaN and infinity are refused for every field, so at least 2 per field.
    EXPECT_GE(refused, 2 * static_cast<int>(fields.size()));
    EXPECT_GT(drawn, 0);
}
