// SPDX-License-Identifier: MIT
// `litkit export` and `litkit render --backend gl` through the command line:
// the exported GLSL compiles, the exported C++ program builds with
// the system's compiler and draws the picture `litkit render` draws, and the
// OpenGL backend's errors are clear.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include "litkit/error.hpp"
#include "litkit/export.hpp"
#include "litkit/image.hpp"
#include "litkit/scene.hpp"
#include "picture_agreement.hpp"
#include "run_command.hpp"

namespace fs = std::filesystem;

namespace {

using Outcome = litkit_test::CommandRun;

Outcome run(const std::string& command) { return litkit_test::run_command(command); }

std::string quoted(const fs::path& path) {
    std::string text = "'";
    text += path.string();
    text += "'";
    return text;
}

std::string read_text(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// Four objects, four different reflection × shading pairs (flat and faceted
// included; the faceted one with angle-weighted normals, docs/spec.md §9.2),
// every light kind, gamma 2.2 and a coloured background.
constexpr const char* mixed_scene = R"toml(
[room]
width = 10
height = 8
depth = 16

[observer]
position = [0, 1, 7]
fov = 45

[lighting]
reflection = "blinn-phong"
shading = "phong"

[output]
width = 320
height = 240
background = [30, 40, 60]
gamma = 2.2

[[lights]]
type = "ambient"
intensity = 0.25

[[lights]]
type = "directional"
direction = [-1, -1, -0.5]
color = [255, 230, 200]

[[lights]]
name = "{{OBJECTS}} is only a name"   # never read as the exporter's own markers
type = "point"
position = [2, 2, 2]
attenuation = [1, 0, 0.05]

[[lights]]
type = "spot"
position = [0, 3, 1]
direction = [0, -1, -0.3]
cutoff = 25
exponent = 4

[[objects]]
name = "ball"
type = "sphere"
position = [-1.3, 0, 0]
segments = 32
rings = 16
material = { color = [200, 80, 60], ka = 0.2, kd = 0.7, ks = 0.6, shininess = 40 }

[[objects]]
name = "box"
type = "cube"
size = 1.2
position = [1.3, 0, 0]
rotation = [20, 35, 0]
reflection = "half-lambert"
shading = "flat"
material = { color = [80, 160, 220] }

[[objects]]
name = "ring"
type = "torus"
position = [0, -2, 0]
rotation = [70, 0, 0]
major_radius = 0.7
minor_radius = 0.2
reflection = "phong"
shading = "gouraud"
material = { color = [230, 200, 90], ks = 0.8, shininess = 16 }

[[objects]]
name = "gem"
type = "sphere"
position = [2.4, -1.2, 0]
radius = 0.5
segments = 10
rings = 6
reflection = "phong"
shading = "faceted"
normals = "angle"
material = { color = [120, 220, 140], ks = 0.7, shininess = 24 }
)toml";

// The models of docs/spec.md §9.1, one object each under every shading, and a
// spot with a soft edge (§9.3) crossing them; 16 samples per pixel (§11) at
// gamma 2.2.
constexpr const char* family_scene = R"toml(
[room]
width = 12
height = 8
depth = 16

[observer]
position = [0, 1, 8]

[lighting]
reflection = "oren-nayar"
shading = "phong"

[output]
width = 320
height = 240
background = [30, 40, 60]
gamma = 2.2
samples = 16

[[lights]]
type = "ambient"
intensity = 0.2

[[lights]]
type = "directional"
direction = [-1, -1, -0.5]

[[lights]]
type = "spot"
position = [0, 3, 2]
direction = [0.2, -1, -0.6]
cutoff = 35
penumbra = 0.7

[[objects]]
type = "sphere"
position = [-3, 1, 0]
segments = 32
rings = 16
material = { color = [200, 150, 110], sigma = 40 }

[[objects]]
type = "sphere"
position = [0, 1, 0]
segments = 32
rings = 16
reflection = "cook-torrance"
shading = "gouraud"
material = { color = [190, 160, 60], ks = 1, roughness = 0.3, f0 = 0.5 }

[[objects]]
type = "sphere"
position = [3, 1, 0]
segments = 32
rings = 16
reflection = "toon"
material = { color = [80, 160, 220], bands = 4 }

[[objects]]
type = "torus"
position = [-1.6, -1.6, 0]
rotation = [60, 0, 0]
reflection = "minnaert"
shading = "flat"
material = { color = [200, 200, 210], minnaert_k = 0.6 }

[[objects]]
type = "teapot"
size = 1.5
position = [1.6, -2, 0]
reflection = "gooch"
material = { color = [220, 90, 70], ka = 0 }
)toml";

// Glass (docs/spec.md §10): a lens, an absorbing faceted cube and a
// gouraud-lit glass torus (not convex) before opaque objects of two models,
// with gamma 2.2 and 4 samples per pixel, for the glass programs of the exports.
constexpr const char* glass_scene = R"toml(
[room]
width = 20
height = 20
depth = 20

[observer]
position = [0.3, 0.4, 9]
look_at = [0, 0, 0]

[lighting]
reflection = "phong"
shading = "phong"
max_depth = 6

[output]
width = 320
height = 240
background = [30, 40, 60]
gamma = 2.2
samples = 4

[[lights]]
type = "ambient"
intensity = 0.3

[[lights]]
type = "directional"
direction = [-0.3, -0.4, -1]

[[objects]]
type = "cube"
size = 6
position = [0, 0, -5]
rotation = [10, 20, 0]
shading = "faceted"
material = { color = [200, 80, 60] }

[[objects]]
type = "sphere"
position = [2.6, -1.2, -1.5]
reflection = "gooch"
material = { color = [90, 160, 220] }

[[objects]]
type = "sphere"
position = [-1.5, 0.5, 1]
segments = 24
rings = 12
material = { ks = 0.5, transmission = 1, ior = 1.5 }

[[objects]]
type = "cube"
size = 1.6
position = [1.5, 1.2, 1]
rotation = [20, 30, 0]
shading = "faceted"
material = { transmission = 1, ior = 1.8, absorption_color = [230, 130, 50], absorption_distance = 0.5 }

[[objects]]
type = "torus"
position = [0.3, -1.5, 1.5]
rotation = [60, 0, 0]
shading = "gouraud"
material = { color = [230, 200, 90], transmission = 0.6, ior = 1.4 }
)toml";

class Export : public ::testing::Test {
  protected:
    void SetUp() override {
        dir = fs::temp_directory_path() /
              ("litkit-export-" + std::to_string(::getpid()) + "-" +
               ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
        std::ofstream(dir / "mixed.toml") << mixed_scene;
        std::ofstream(dir / "family.toml") << family_scene;
        std::ofstream(dir / "glass.toml") << glass_scene;
    }
    void TearDown() override { fs::remove_all(dir); }

    Outcome cli(const std::string& arguments) const {
        return run("cd " + quoted(dir) + " && '" LITKIT_CLI "' " + arguments);
    }

    // Exports `<name>.toml` as a C++ program, builds it (no warnings under
    // -Wall -Wextra -Wpedantic), runs it, and compares its picture with
    // `litkit render --backend gl` (the same OpenGL code on the same driver:
    // equal) and with the CPU backend (docs/spec.md's picture: within the
    // cross-backend tolerance away from edges, and with several samples per
    // pixel on the silhouettes too).
    void expect_program_draws_what_litkit_draws(const std::string& name,
                                                std::string& configure_output) const {
        const Outcome exported = cli("export --format cpp " + name + ".toml -o program");
        ASSERT_EQ(exported.status, 0) << exported.output;
        EXPECT_NE(exported.output.find("cmake -S program -B program/build"), std::string::npos)
            << exported.output;
        const Outcome configure = run("'" LITKIT_CMAKE "' -S " + quoted(dir / "program") + " -B " +
                                      quoted(dir / "program" / "build") +
                                      " '-DCMAKE_CXX_FLAGS=-Wall -Wextra -Wpedantic'");
        ASSERT_EQ(configure.status, 0) << configure.output;
        configure_output = configure.output;
        const Outcome build =
            run("'" LITKIT_CMAKE "' --build " + quoted(dir / "program" / "build"));
        ASSERT_EQ(build.status, 0) << build.output;
        EXPECT_EQ(build.output.find("warning"), std::string::npos) << build.output;

        const Outcome drawn =
            run("cd " + quoted(dir) + " && program/build/" + name + " -o exported.png");
        ASSERT_EQ(drawn.status, 0) << drawn.output;
        ASSERT_EQ(cli("render " + name + ".toml --backend gl -o gl.png").status, 0);
        ASSERT_EQ(cli("render " + name + ".toml -o cpu.png").status, 0);

        const litkit::Image exported_png = litkit::read_png(dir / "exported.png");
        ASSERT_EQ(exported_png.width, 320);
        ASSERT_EQ(exported_png.height, 240);
        EXPECT_EQ(exported_png.rgb, litkit::read_png(dir / "gl.png").rgb);
        const fs::path scene_file = dir / (name + ".toml");
        const litkit::Scene scene = litkit::load_scene(std::span(&scene_file, 1));
        const litkit::Image cpu_png = litkit::read_png(dir / "cpu.png");
        litkit::Scene one_sample = scene;
        one_sample.output.samples = 1;
        const litkit_test::Agreement a =
            litkit_test::agreement(exported_png, cpu_png, litkit_test::labels(one_sample));
        EXPECT_GT(a.counted, 320u * 240u / 10);
        EXPECT_GE(a.fraction(), litkit_test::required_fraction) << "worst " << a.worst << "/255";
        if (scene.output.samples > 1) {
            const litkit_test::EdgeAgreement e =
                litkit_test::edge_agreement(exported_png, cpu_png, litkit_test::labels(scene));
            EXPECT_GT(e.edges, 500u);
            EXPECT_GE(e.fraction(), 0.98) << e.within << " of " << e.edges;
            std::cout << scene.output.samples << " samples: " << e.within << " of " << e.edges
                      << " edge pixels within 2/255\n";
        }
    }

    fs::path dir;
};

}  // namespace

TEST_F(Export, GlslWritesOneProgramPerModelPairAndEachCompiles) {
    const std::string validator = LITKIT_GLSLANG_VALIDATOR;
    ASSERT_FALSE(validator.empty())
        << "glslangValidator not found: run scripts/install-deps.sh (glslang-tools)";
    const Outcome exported = cli("export --format glsl mixed.toml -o shaders");
    ASSERT_EQ(exported.status, 0) << exported.output;
    const std::vector<std::string> stems = {"blinn-phong-phong", "half-lambert-flat",
                                            "phong-gouraud", "phong-faceted"};
    std::size_t files = 0;
    for (const auto& entry : fs::directory_iterator(dir / "shaders"))
        files += entry.is_regular_file();
    EXPECT_EQ(files, 2 * stems.size());
    for (const std::string& stem : stems) {
        const fs::path vert = dir / "shaders" / (stem + ".vert");
        const fs::path frag = dir / "shaders" / (stem + ".frag");
        ASSERT_TRUE(fs::exists(vert)) << vert;
        ASSERT_TRUE(fs::exists(frag)) << frag;
        // Sized for the scene's four lights (in the stage that lights: the
        // vertex shader for flat and Gouraud, the fragment shader for Phong).
        const std::string text = read_text(vert) + read_text(frag);
        EXPECT_NE(text.find("MAX_LIGHTS = 4"), std::string::npos) << stem;
        EXPECT_NE(text.find("u_lights"), std::string::npos) << stem;
        for (const fs::path& shader : {vert, frag}) {
            const Outcome check = run("'" + validator + "' " + quoted(shader));
            EXPECT_EQ(check.status, 0) << shader << "\n" << check.output;
        }
        const Outcome link = run("'" + validator + "' -l " + quoted(vert) + " " + quoted(frag));
        EXPECT_EQ(link.status, 0) << stem << "\n" << link.output;
    }
}

TEST_F(Export, GlslTheValidatorRejectsABrokenShader) {
    // The check above can fail: a shader with an error does not pass.
    const std::string validator = LITKIT_GLSLANG_VALIDATOR;
    ASSERT_FALSE(validator.empty());
    ASSERT_EQ(cli("export --format glsl mixed.toml -o shaders").status, 0);
    const fs::path frag = dir / "shaders" / "phong-gouraud.frag";
    std::string text = read_text(frag);
    const std::size_t main_at = text.find("void main()");
    ASSERT_NE(main_at, std::string::npos);
    text.insert(main_at, "float broken = undefined_name;\n");
    std::ofstream(frag) << text;
    EXPECT_NE(run("'" + validator + "' " + quoted(frag)).status, 0);
}

TEST_F(Export, CppProgramOfTheNewModelsDrawsWhatLitkitDraws) {
    std::string configure_output;
    ASSERT_NO_FATAL_FAILURE(expect_program_draws_what_litkit_draws("family", configure_output));
}

// The glass programs and the glass scene's buffers travel with the program.
TEST_F(Export, CppProgramOfGlassDrawsWhatLitkitDraws) {
    std::string configure_output;
    ASSERT_NO_FATAL_FAILURE(expect_program_draws_what_litkit_draws("glass", configure_output));
    EXPECT_NE(read_text(dir / "program" / "main.cpp").find("const GlassScene glass_scene"),
              std::string::npos);
}

// Glass objects get programs of their own, with the ray tree; they compile.
TEST_F(Export, GlslWritesTheGlassProgramsAndEachCompiles) {
    const std::string validator = LITKIT_GLSLANG_VALIDATOR;
    ASSERT_FALSE(validator.empty());
    const Outcome exported = cli("export --format glsl glass.toml -o shaders");
    ASSERT_EQ(exported.status, 0) << exported.output;
    for (const std::string stem : {"phong-phong-glass", "phong-faceted-glass",
                                   "phong-gouraud-glass", "phong-faceted", "gooch-phong"}) {
        const fs::path vert = dir / "shaders" / (stem + ".vert");
        const fs::path frag = dir / "shaders" / (stem + ".frag");
        ASSERT_TRUE(fs::exists(frag)) << frag;
        const bool glass = stem.ends_with("-glass");
        EXPECT_EQ(read_text(frag).find("vec3 trace_bracket(") != std::string::npos, glass) << stem;
        const Outcome link = run("'" + validator + "' -l " + quoted(vert) + " " + quoted(frag));
        EXPECT_EQ(link.status, 0) << stem << "\n" << link.output;
    }
}

TEST_F(Export, CppProgramBuildsRunsAndDrawsWhatLitkitDraws) {
    std::string configure_output;
    ASSERT_NO_FATAL_FAILURE(expect_program_draws_what_litkit_draws("mixed", configure_output));
    EXPECT_TRUE(fs::exists(dir / "program" / "main.cpp"));
    EXPECT_TRUE(fs::exists(dir / "program" / "CMakeLists.txt"));

    // Usage errors get exit status 2.
    EXPECT_EQ(run(quoted(dir / "program" / "build" / "mixed") + " --bogus").status, 2);

    // --window: built with SDL2 (installed by scripts/install-deps.sh), shown
    // on a virtual X display for two seconds, then closed the way a window
    // manager would end it (SIGTERM, which SDL turns into a quit event).
    EXPECT_EQ(configure_output.find("SDL2 not found"), std::string::npos) << configure_output;
    const Outcome window = run("xvfb-run -a -s '-screen 0 640x480x24' sh -c '" +
                               (dir / "program" / "build" / "mixed").string() +
                               " --window & pid=$!; sleep 2; kill -TERM $pid; wait $pid'");
    EXPECT_EQ(window.status, 0) << window.output;
    EXPECT_NE(window.output.find("mixed: showing the scene"), std::string::npos) << window.output;
}

TEST_F(Export, RefusesToReplaceFilesWithoutForce) {
    fs::create_directories(dir / "program");
    std::ofstream(dir / "program" / "main.cpp") << "// the user's own\n";
    const Outcome refused = cli("export --format cpp mixed.toml -o program");
    EXPECT_EQ(refused.status, 2) << refused.output;
    EXPECT_NE(refused.output.find("already exists; pass --force"), std::string::npos)
        << refused.output;
    EXPECT_EQ(read_text(dir / "program" / "main.cpp"), "// the user's own\n");
    EXPECT_FALSE(fs::exists(dir / "program" / "CMakeLists.txt"));  // nothing half-written

    const Outcome forced = cli("export --format cpp mixed.toml -o program --force");
    EXPECT_EQ(forced.status, 0) << forced.output;
    EXPECT_NE(read_text(dir / "program" / "main.cpp").find("int main("), std::string::npos);
}

TEST_F(Export, RejectsAProgramNameThatIsNotAnIdentifier) {
    const Outcome bad = cli("export --format cpp mixed.toml -o program --name 'two words'");
    EXPECT_EQ(bad.status, 2) << bad.output;
    EXPECT_NE(bad.output.find("not a C identifier"), std::string::npos) << bad.output;
    EXPECT_FALSE(fs::exists(dir / "program"));
}

TEST_F(Export, RejectsAProgramNameCMakeKeepsForItself) {
    const Outcome bad = cli("export --format cpp mixed.toml -o program --name all");
    EXPECT_EQ(bad.status, 2) << bad.output;
    EXPECT_NE(bad.output.find("CMake keeps"), std::string::npos) << bad.output;
}

TEST_F(Export, PrintsBuildCommandsThatSurviveSpacesInPaths) {
    const Outcome exported = cli("export --format cpp mixed.toml -o 'my program'");
    ASSERT_EQ(exported.status, 0) << exported.output;
    EXPECT_NE(exported.output.find("cmake -S 'my program' -B 'my program/build'"),
              std::string::npos)
        << exported.output;
}

TEST_F(Export, GlslOfASceneWithoutObjectsIsTheScenesOwnPair) {
    std::ofstream(dir / "empty.toml")
        << "[room]\nwidth = 4\nheight = 4\ndepth = 4\n"
           "[observer]\nposition = [0, 0, 1]\n"
           "[lighting]\nreflection = \"lambert\"\nshading = \"gouraud\"\n";
    const Outcome exported = cli("export --format glsl empty.toml -o shaders");
    ASSERT_EQ(exported.status, 0) << exported.output;
    EXPECT_TRUE(fs::exists(dir / "shaders" / "lambert-gouraud.vert")) << exported.output;
    EXPECT_TRUE(fs::exists(dir / "shaders" / "lambert-gouraud.frag"));
}

TEST_F(Export, NeedsAFormatAndAFolder) {
    EXPECT_EQ(cli("export mixed.toml -o out").status, 2);
    EXPECT_EQ(cli("export --format cpp mixed.toml").status, 2);
    EXPECT_EQ(cli("export --format pdf mixed.toml -o out").status, 2);
}

TEST_F(Export, ReportsSceneErrorsLikeRender) {
    std::ofstream(dir / "bad.toml") << "[room]\nwidth = -1\n";
    const Outcome bad = cli("export --format glsl bad.toml -o out");
    EXPECT_EQ(bad.status, 2) << bad.output;
    EXPECT_NE(bad.output.find("bad.toml:2:"), std::string::npos) << bad.output;
    EXPECT_FALSE(fs::exists(dir / "out"));
}

// The limit on the numbers of vertex data in main.cpp (docs/reliability.md),
// at sizes counted by hand: a cube drawn flat is 12 triangles of 3 corners,
// each corner a position, a normal and a centroid, 12 · 27 = 324 numbers; a
// square of 4 vertices and 2 triangles drawn smooth is 4 · 6 (position and
// normal) + 2 · 3 (indices) = 30.
constexpr const char* flat_cube_scene = R"toml([room]
width = 10
height = 10
depth = 10
[observer]
position = [0, 1, 4]
[lighting]
reflection = "phong"
shading = "flat"
[[lights]]
type = "point"
position = [0, 3, 0]

[[objects]]
name = "box"
type = "cube"
)toml";

TEST_F(Export, CppRefusesMoreVertexDataThanItsLimitAtTheObject) {
    std::ofstream(dir / "cube.toml") << flat_cube_scene;
    const Outcome refused = cli("export --format cpp cube.toml -o out --max-source-numbers 323");
    EXPECT_EQ(refused.status, 2) << refused.output;
    EXPECT_NE(refused.output.find("cube.toml:14:1: error: objects[0] 'box': the C++ export would "
                                  "write at least 324 numbers of vertex data into main.cpp (this "
                                  "object: 12 triangles), more than its limit of 323"),
              std::string::npos)
        << refused.output;
    EXPECT_FALSE(fs::exists(dir / "out"));
    const Outcome written = cli("export --format cpp cube.toml -o out --max-source-numbers 324");
    EXPECT_EQ(written.status, 0) << written.output;
    EXPECT_TRUE(fs::exists(dir / "out" / "main.cpp"));
}

TEST_F(Export, CppCountsAMeshFilesVertexDataOnceRead) {
    // A mesh file's size is known once it is read: the exact count, 30.
    std::ofstream(dir / "square.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n";
    std::string text = flat_cube_scene;
    text.replace(text.find("flat"), 4, "phong");
    text.replace(text.find("type = \"cube\""), 13, "type = \"mesh\"\nfile = \"square.obj\"");
    std::ofstream(dir / "square.toml") << text;
    const fs::path scene_file = dir / "square.toml";
    const litkit::Scene scene = litkit::load_scene(std::span(&scene_file, 1));
    litkit::ExportOptions options;
    options.max_source_numbers = 29;
    try {
        litkit::export_cpp(scene, dir / "out", "square", "square.toml", options);
        ADD_FAILURE() << "exported past the limit";
    } catch (const litkit::SceneError& error) {
        ASSERT_EQ(error.diagnostics().size(), 1u);
        EXPECT_EQ(error.diagnostics()[0].location.line, 14u);
        EXPECT_NE(error.diagnostics()[0].message.find(
                      "would write 30 numbers of vertex data into main.cpp (this object: 2 "
                      "triangles), more than its limit of 29"),
                  std::string::npos)
            << error.diagnostics()[0].message;
    }
    EXPECT_FALSE(fs::exists(dir / "out"));
    options.max_source_numbers = 30;
    EXPECT_EQ(litkit::export_cpp(scene, dir / "out", "square", "square.toml", options).size(), 2u);
}

TEST_F(Export, GlBackendRendersThroughTheCli) {
    const Outcome rendered = cli("render --backend gl -o default.png");
    ASSERT_EQ(rendered.status, 0) << rendered.output;
    const litkit::Image image = litkit::read_png(dir / "default.png");
    EXPECT_EQ(image.width, 800);
    const Outcome bench = cli("bench --backend gl --frames 2");
    EXPECT_EQ(bench.status, 0) << bench.output;
    EXPECT_NE(bench.output.find("OpenGL backend"), std::string::npos) << bench.output;
}

TEST_F(Export, GlBackendWithoutOpenGlSaysWhyAndSuggestsTheCpu) {
    // glvnd told to use no EGL vendor at all: as on a machine without a driver.
    const Outcome failed = run("cd " + quoted(dir) +
                               " && __EGL_VENDOR_LIBRARY_FILENAMES=/dev/null '" LITKIT_CLI
                               "' render --backend gl -o none.png");
    EXPECT_EQ(failed.status, 1) << failed.output;
    EXPECT_NE(failed.output.find("OpenGL is not available"), std::string::npos) << failed.output;
    EXPECT_NE(failed.output.find("--backend cpu"), std::string::npos) << failed.output;
    EXPECT_FALSE(fs::exists(dir / "none.png"));
}

TEST_F(Export, ShadersInTheDocsAreCurrent) {
    // docs/shaders shows students the GLSL of the default scene; it must be
    // what litkit writes today. After changing the generator, refresh it with
    //   ./build/litkit export --format glsl -o docs/shaders --force
    const Outcome exported = cli("export --format glsl -o shaders");
    ASSERT_EQ(exported.status, 0) << exported.output;
    const fs::path docs = fs::path(LITKIT_SOURCE_DIR) / "docs" / "shaders";
    for (const char* name : {"phong-phong.vert", "phong-phong.frag"}) {
        ASSERT_TRUE(fs::exists(docs / name)) << docs / name;
        EXPECT_EQ(read_text(docs / name), read_text(dir / "shaders" / name))
            << name
            << " is out of date: ./build/litkit export --format glsl -o docs/shaders --force";
    }
}
