// SPDX-License-Identifier: MIT
// Anti-aliasing (docs/spec.md §11): the key `[output] samples` as scene files
// give it (read, checked with its place, suggested, written back), pictures
// whose pixels are computed by hand, the command line's --samples, and what
// the exports write. The pictures against an independent reference, in
// every model: tests/test_render_reference.cpp (SupersampledMatchesReference).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <string_view>
#include <vector>

#include "litkit/error.hpp"
#include "litkit/explain.hpp"
#include "litkit/export.hpp"
#include "litkit/render.hpp"
#include "litkit/scene.hpp"
#include "litkit/validate.hpp"
#include "run_command.hpp"

namespace litkit {
namespace {

namespace fs = std::filesystem;

// The room and observer, six lines; then [output] on line 7, its key on 8.
std::string output_with(std::string_view key_and_value) {
    return "[room]\nwidth = 10\nheight = 10\ndepth = 10\n[observer]\nposition = [0, 0, 4]\n"
           "[output]\n" +
           std::string(key_and_value) + "\n";
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

// Exactly one error, on line 8 at column `column`, saying `message`.
void expect_error_on_line_8(std::string_view text, std::uint32_t column, std::string_view message) {
    const std::vector<Diagnostic> diagnostics = diagnostics_of(text);
    ASSERT_EQ(diagnostics.size(), 1u) << text;
    EXPECT_EQ(diagnostics[0].severity, Severity::Error);
    EXPECT_EQ(diagnostics[0].location.file, "scene.toml");
    EXPECT_EQ(diagnostics[0].location.line, 8u);
    EXPECT_EQ(diagnostics[0].location.column, column);
    EXPECT_EQ(diagnostics[0].message, message);
}

TEST(SamplesKey, IsReadWithItsValueAndDefaultsToOne) {
    EXPECT_EQ(parse_scene(output_with("gamma = 1"), "scene.toml").output.samples, 1);
    EXPECT_EQ(Scene{}.output.samples, default_samples);
    EXPECT_EQ(default_samples, 1);
    for (int samples : {1, 4, 8, 16}) {
        const Scene scene =
            parse_scene(output_with("samples = " + std::to_string(samples)), "scene.toml");
        EXPECT_EQ(scene.output.samples, samples);
        EXPECT_EQ(scene.location_of("output.samples").line, 8u);
    }
}

TEST(SamplesKey, OtherCountsAreLocatedErrors) {
    for (int samples : {0, 2, 3, 5, 32, -4}) {
        const std::string value = std::to_string(samples);
        expect_error_on_line_8(output_with("samples = " + value), 11,
                               "output: samples must be 1, 4, 8 or 16, found " + value);
    }
    expect_error_on_line_8(output_with("samples = 4.0"), 11,
                           "output: samples must be an integer, found float 4.0");
    expect_error_on_line_8(output_with("samples = \"4\""), 11,
                           "output: samples must be an integer, found string");
}

TEST(SamplesKey, OtherNamesGetSuggestions) {
    for (std::string_view name : {"antialias", "msaa", "spp", "sample"}) {
        SCOPED_TRACE(name);
        expect_error_on_line_8(
            output_with(std::string(name) + " = 4"), 1,
            "output: unknown key '" + std::string(name) + "'; did you mean 'samples'?");
    }
}

TEST(SamplesKey, IsWrittenBackWhenNotOne) {
    Scene scene = parse_scene(output_with("samples = 16"), "scene.toml");
    const std::string text = scene_to_toml(scene);
    EXPECT_NE(text.find("samples = 16\n"), std::string::npos) << text;
    EXPECT_EQ(parse_scene(text, "again.toml").output.samples, 16);
    scene.output.samples = 1;
    EXPECT_EQ(scene_to_toml(scene).find("samples"), std::string::npos);
}

TEST(SamplesKey, ScenesBuiltInCodeAreChecked) {
    Scene scene = default_scene();
    scene.output.samples = 3;
    bool found = false;
    for (const Diagnostic& d : validate_scene(scene))
        found |= d.severity == Severity::Error &&
                 d.message == "output: samples must be 1, 4, 8 or 16, found 3";
    EXPECT_TRUE(found);
    EXPECT_THROW(render(scene), SceneError);
}

// A vertical edge through the centre of pixel (10, 5) of a 21 × 11 picture:
// a cube without light (black) covers x ≤ 0 in front of the eye, whose
// centre column is x = 0, and the background is white. The samples left of
// the pixel's centre see the cube, the others the background: at 4 samples
// x = 0.375, 0.125 against 0.875, 0.625; at 8 and 16, half of them as well
// (the table of §11). So the pixel is round(255 · (1/2)^(1/γ)): 128 at
// γ = 1 (127.5 rounds up) and round(255 · 0.5^(1/2.2)) = round(186.08) =
// 186 at γ = 2.2, while its neighbours stay black and white.
Scene half_covered_pixel_scene(int samples, float gamma) {
    Scene scene;
    scene.room = {10.0f, 10.0f, 10.0f};
    scene.observer.position = {0.0f, 0.0f, 4.0f};
    scene.observer.look_at = {0.0f, 0.0f, 0.0f};
    scene.observer.fov_degrees = 40.0f;
    scene.output.width = 21;
    scene.output.height = 11;
    scene.output.background = {1.0f, 1.0f, 1.0f};
    scene.output.gamma = gamma;
    scene.output.samples = samples;
    scene.reflection = Reflection::Lambert;
    scene.shading = Shading::Flat;
    SceneObject cube;
    cube.shape = CubeShape{2.0f};
    cube.position = {-1.0f, 0.0f, 0.0f};  // x from -2 to 0, its front face at z = 1
    scene.objects.push_back(cube);
    return scene;
}

TEST(Supersampling, HalfCoveredPixelIsComputedByHand) {
    for (int samples : {4, 8, 16}) {
        for (const auto& [gamma, expected] : {std::pair{1.0f, 128}, std::pair{2.2f, 186}}) {
            SCOPED_TRACE(std::to_string(samples) + " samples, gamma " + std::to_string(gamma));
            const Image image = render(half_covered_pixel_scene(samples, gamma));
            for (int c = 0; c < 3; ++c) {
                EXPECT_EQ(image.pixel(10, 5)[c], expected);
                EXPECT_EQ(image.pixel(9, 5)[c], 0);
                EXPECT_EQ(image.pixel(11, 5)[c], 255);
            }
        }
    }
    // The control: one sample, at the centre, exactly on the edge; the
    // top-left rule leaves it to the background (the edge is the cube's
    // right edge), so it is white.
    const Image one = render(half_covered_pixel_scene(1, 1.0f));
    EXPECT_EQ(one.pixel(10, 5)[0], 255);
    EXPECT_EQ(one.pixel(9, 5)[0], 0);
    EXPECT_EQ(one.pixel(11, 5)[0], 255);
}

// explain lists the half-covered pixel's samples by hand: the two left of
// its centre (x = 0.375 and 0.125, samples 0 and 2 of the table) see the
// cube, black; the others the white background, L = 1^γ = 1; the mean is
// 0.5 and the pixel 128.
TEST(Supersampling, ExplainListsEverySample) {
    const Scene scene = half_covered_pixel_scene(4, 1.0f);
    const PixelExplanation e = explain_pixel(scene, 10, 5);
    ASSERT_EQ(e.samples.size(), 4u);
    const bool sees_cube[] = {true, false, true, false};
    const float xs[] = {0.375f, 0.875f, 0.125f, 0.625f};
    for (std::size_t k = 0; k < 4; ++k) {
        EXPECT_EQ(e.samples[k].position.x, xs[k]);
        EXPECT_EQ(e.samples[k].hit, sees_cube[k]) << k;
        EXPECT_EQ(e.samples[k].light, glm::vec3(sees_cube[k] ? 0.0f : 1.0f)) << k;
    }
    EXPECT_EQ(e.rgb, (Rgb8{128, 128, 128}));
    const std::string text = explanation_text(e, scene);
    EXPECT_NE(text.find("sample 1 at (0.875, 0.375): background, L = (1, 1, 1)"), std::string::npos)
        << text;
    EXPECT_NE(text.find("mean = (0.5, 0.5, 0.5)\nrgb = round(255 * that) = (128, 128, 128)"),
              std::string::npos)
        << text;
    const std::string json = explanation_json(e, scene);
    EXPECT_NE(json.find("\"mean\": [0.5, 0.5, 0.5]"), std::string::npos) << json;
    // With one sample there is no list.
    EXPECT_TRUE(explain_pixel(half_covered_pixel_scene(1, 1.0f), 10, 5).samples.empty());
}

// Renderer::probe's pixel is the rendered one, samples or not, on every
// pixel of a row across the cube's edges.
TEST(Supersampling, ProbeGivesTheRenderedPixel) {
    Scene scene = default_scene();
    scene.output.width = 80;
    scene.output.height = 60;
    for (int samples : {1, 8}) {
        scene.output.samples = samples;
        Renderer renderer(scene);
        const Image image = renderer.render();
        for (int x = 0; x < 80; ++x) {
            const PixelProbe probe = renderer.probe(x, 30);
            const std::uint8_t* want = image.pixel(x, 30);
            EXPECT_EQ(probe.rgb, (Rgb8{want[0], want[1], want[2]})) << x << ", " << samples;
            EXPECT_EQ(probe.samples.size(), samples > 1 ? 8u : 0u);
        }
        // The renderer still draws its samples after probing.
        EXPECT_EQ(renderer.render().rgb, image.rgb);
    }
}

// Probes in a row reuse the frame's vertex and setup stages; an update in
// between (a moved object, another light, other samples) must not find them
// stale: each probe equals a fresh renderer's render of the scene as it is.
TEST(Supersampling, ProbesAfterAnUpdateSeeTheNewScene) {
    Scene scene = default_scene();
    scene.output.width = 80;
    scene.output.height = 60;
    Renderer renderer(scene);
    const auto expect_probes_are_the_render = [&](const Scene& now, const char* what) {
        const Image image = Renderer(now).render();
        int differing = 0;
        for (int x = 0; x < 80; x += 3) {
            const std::uint8_t* want = image.pixel(x, 30);
            const PixelProbe probe = renderer.probe(x, 30);
            differing += probe.rgb != Rgb8{want[0], want[1], want[2]};
        }
        EXPECT_EQ(differing, 0) << what;
    };
    expect_probes_are_the_render(scene, "as built");
    scene.objects[0].position.x += 0.4f;  // the meshes are built again
    renderer.update(scene);
    expect_probes_are_the_render(scene, "object moved");
    scene.objects[0].rotation_degrees.y += 25.0f;
    scene.lights[0].light.intensity *= 0.5f;  // and the surfaces
    renderer.update(scene);
    expect_probes_are_the_render(scene, "object turned, light dimmed");
    scene.observer.position.x -= 0.7f;  // only the view: the meshes are kept
    renderer.update(scene);
    EXPECT_EQ(renderer.mesh_builds(), 3u);
    expect_probes_are_the_render(scene, "observer moved");
    scene.output.samples = 4;
    renderer.update(scene);
    expect_probes_are_the_render(scene, "four samples");
}

// A pixel whose samples all see one flat-shaded face is that face's colour,
// as with one sample: the mean of equal values.
TEST(Supersampling, PixelsInsideOneFlatFaceKeepTheirColour) {
    Scene scene = half_covered_pixel_scene(1, 2.2f);
    scene.objects[0].material.color = {0.8f, 0.4f, 0.2f};
    scene.lights.push_back({"sun", {AmbientLight{}, {1.0f, 1.0f, 1.0f}, 1.0f}});
    const Image one = render(scene);
    for (int samples : {4, 8, 16}) {
        scene.output.samples = samples;
        const Image many = render(scene);
        for (int y = 0; y < 11; ++y) {
            for (int x = 0; x < 10; ++x) {
                if (one.pixel(x, y)[0] != 255 && x > 0 && y > 0 && y < 10 &&
                    one.pixel(x - 1, y - 1)[0] != 255 && one.pixel(x, y + 1)[0] != 255) {
                    for (int c = 0; c < 3; ++c)
                        EXPECT_EQ(many.pixel(x, y)[c], one.pixel(x, y)[c]) << x << ", " << y;
                }
            }
        }
    }
}

// The exports write the scene's samples (the pictures: tests/test_export.cpp
// and tests/test_gl_samples.cpp). GLSL: the programs write a sample's light
// and the fragment shader says what the host does, offsets listed; C++: the
// pattern is the program's data. One sample: the pixel programs, no pattern
// but the centre.
TEST(Supersampling, ExportsWriteTheSamples) {
    Scene scene = default_scene();
    scene.output.samples = 4;
    const fs::path folder = fs::temp_directory_path() / "litkit_samples_exported";
    fs::remove_all(folder);
    auto text_of = [](const fs::path& file) {
        std::ifstream in(file);
        return std::string(std::istreambuf_iterator<char>(in), {});
    };
    for (const fs::path& file : export_glsl(scene, folder / "glsl")) {
        const std::string text = text_of(file);
        EXPECT_EQ(text.find("to_pixel("), std::string::npos) << file;
        if (file.extension() != ".frag") continue;
        EXPECT_NE(text.find("frag_color = vec4(sample_light("), std::string::npos) << file;
        for (const char* line :
             {"//     k = 0: (0.375, 0.125)\n", "//     k = 1: (0.875, 0.375)\n",
              "//     k = 2: (0.125, 0.625)\n", "//     k = 3: (0.625, 0.875)\n",
              "//     round(255 * ((S + n * B^gamma) / 4)^(1/gamma)), halves up,"})
            EXPECT_NE(text.find(line), std::string::npos) << line << "\n" << text;
    }
    export_cpp(scene, folder / "cpp", "program", "scene");
    const std::string program = text_of(folder / "cpp" / "main.cpp");
    EXPECT_NE(program.find("sample_pattern = {\n    {0.375f, 0.125f},\n    {0.875f, 0.375f},\n    "
                           "{0.125f, 0.625f},\n    {0.625f, 0.875f},\n};"),
              std::string::npos);
    EXPECT_NE(program.find("frag_color = vec4(sample_light("), std::string::npos);
    EXPECT_EQ(program.find("to_pixel("), std::string::npos);

    scene.output.samples = 1;  // the control
    for (const fs::path& file : export_glsl(scene, folder / "glsl1")) {
        const std::string text = text_of(file);
        EXPECT_EQ(text.find("Anti-aliasing"), std::string::npos) << file;
        EXPECT_EQ(text.find("sample_light"), std::string::npos) << file;
        if (file.extension() == ".frag") {
            EXPECT_NE(text.find("frag_color = vec4(to_pixel("), std::string::npos) << file;
        }
    }
    export_cpp(scene, folder / "cpp1", "program", "scene");
    const std::string one = text_of(folder / "cpp1" / "main.cpp");
    EXPECT_NE(one.find("sample_pattern = {\n    {0.5f, 0.5f},\n};"), std::string::npos);
    EXPECT_EQ(one.find("sample_light("), std::string::npos);
    fs::remove_all(folder);
}

TEST(SamplesOption, RenderTakesItAndRefusesOtherCounts) {
    const fs::path folder = fs::temp_directory_path() / "litkit_samples_cli";
    fs::remove_all(folder);
    fs::create_directories(folder);
    const std::string litkit = LITKIT_CLI;
    const std::string one = (folder / "one.png").string();
    const std::string four = (folder / "four.png").string();
    const std::string scene_four = (folder / "four_from_scene.png").string();
    EXPECT_EQ(litkit_test::run_command(litkit + " render --width 64 --height 48 -o " + one).status,
              0);
    EXPECT_EQ(
        litkit_test::run_command(litkit + " render --width 64 --height 48 --samples 4 -o " + four)
            .status,
        0);
    // The option replaces the key, as the other options do.
    const fs::path scene_file = folder / "scene.toml";
    {
        Scene scene = default_scene();
        scene.output.width = 64;
        scene.output.height = 48;
        scene.output.samples = 16;
        std::ofstream(scene_file) << scene_to_toml(scene);
    }
    EXPECT_EQ(litkit_test::run_command(litkit + " render " + scene_file.string() +
                                       " --samples 4 -o " + scene_four)
                  .status,
              0);
    const Image a = read_png(one), b = read_png(four), c = read_png(scene_four);
    EXPECT_NE(a.rgb, b.rgb) << "4 samples smooth the cube's edges";
    EXPECT_EQ(b.rgb, c.rgb) << "--samples 4 replaces the scene's 16";
    for (const char* bad : {"3", "0", "x", "32"}) {
        const litkit_test::CommandRun run =
            litkit_test::run_command(litkit + " render --samples " + std::string(bad) + " -o " +
                                     (folder / "bad.png").string());
        EXPECT_NE(run.status, 0) << bad;
        EXPECT_NE(run.output.find("samples must be 1, 4, 8 or 16, found " + std::string(bad)),
                  std::string::npos)
            << run.output;
        EXPECT_FALSE(fs::exists(folder / "bad.png"));
    }
    fs::remove_all(folder);
}

}  // namespace
}  // namespace litkit
