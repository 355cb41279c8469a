// SPDX-License-Identifier: MIT
// The command-line tool as a user meets it: exit statuses, messages, files.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "litkit/backend.hpp"
#include "litkit/image.hpp"
#include "run_command.hpp"

namespace fs = std::filesystem;

namespace {

using CliRun = litkit_test::CommandRun;
using litkit_test::run_command;

// Runs the CLI with `arguments` in `directory`, standard input from /dev/null
// (not a terminal).
CliRun run_cli(const std::string& arguments, const fs::path& directory) {
    return run_command("cd '" + directory.string() + "' && '" LITKIT_CLI "' " + arguments);
}

// Runs a copy of the CLI placed in `directory` as the unprivileged user
// nobody, for checks that permission bits cannot make as root. The copy
// keeps the binary reachable for nobody wherever the build tree lives.
CliRun run_cli_as_nobody(const std::string& arguments, const fs::path& directory) {
    std::error_code error;
    fs::copy_file(LITKIT_CLI, directory / "litkit-copy", fs::copy_options::overwrite_existing,
                  error);
    if (error) return {};
    return run_command("cd '" + directory.string() +
                       "' && setpriv --reuid=65534 --regid=65534 --clear-groups ./litkit-copy " +
                       arguments);
}

class Cli : public ::testing::Test {
  protected:
    void SetUp() override {
        dir = fs::temp_directory_path() /
              ("litkit-cli-" + std::to_string(::getpid()) + "-" +
               ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override { fs::remove_all(dir); }
    void write(const fs::path& name, const std::string& text) { std::ofstream(dir / name) << text; }
    std::string read(const fs::path& name) {
        std::ifstream in(dir / name, std::ios::binary);
        return {std::istreambuf_iterator<char>(in), {}};
    }
    fs::path dir;
};

const char* scene_without_lighting = R"(
[room]
width = 10
height = 10
depth = 10

[observer]
position = [0, 0, 4]

[output]
width = 64
height = 48

[[lights]]
type = "point"
position = [0, 3, 3]
intensity = 10

[[objects]]
type = "sphere"
radius = 1
)";

}  // namespace

TEST_F(Cli, VersionPrintsTheVersionAndSucceeds) {
    CliRun run = run_cli("--version", dir);
    EXPECT_EQ(run.status, 0);
    EXPECT_NE(run.output.find("litkit "), std::string::npos) << run.output;
}

TEST_F(Cli, HelpListsTheCommands) {
    CliRun run = run_cli("--help", dir);
    EXPECT_EQ(run.status, 0);
    for (const char* command : {"render", "check", "init"})
        EXPECT_NE(run.output.find(command), std::string::npos) << command;
}

TEST_F(Cli, RenderHelpListsItsOptions) {
    CliRun run = run_cli("render --help", dir);
    EXPECT_EQ(run.status, 0);
    for (const char* option :
         {"--output", "--width", "--height", "--reflection", "--shading", "--threads", "--yes"})
        EXPECT_NE(run.output.find(option), std::string::npos) << option;
}

TEST_F(Cli, UnknownOptionIsAUsageError) {
    EXPECT_EQ(run_cli("render --colour red", dir).status, 2);
    EXPECT_EQ(run_cli("", dir).status, 2);
}

TEST_F(Cli, AloneItPrintsTheCommandsAndExits2) {
    CliRun run = run_cli("", dir);
    EXPECT_EQ(run.status, 2);
    EXPECT_NE(run.output.find("usage: litkit COMMAND"), std::string::npos) << run.output;
    for (const char* command :
         {"render", "check", "init", "export", "compare", "explain", "turntable", "bench"})
        EXPECT_NE(run.output.find("  " + std::string(command) + " "), std::string::npos) << command;
}

TEST_F(Cli, MisspeltCommandGetsASuggestion) {
    CliRun run = run_cli("rendr", dir);
    EXPECT_EQ(run.status, 2);
    EXPECT_NE(run.output.find("error: 'rendr' is not a litkit command; did you mean 'render'?"),
              std::string::npos)
        << run.output;
    CliRun far = run_cli("paint", dir);
    EXPECT_EQ(far.status, 2);
    EXPECT_EQ(far.output.find("did you mean"), std::string::npos) << far.output;
}

TEST_F(Cli, MisspeltOptionGetsASuggestion) {
    CliRun run = run_cli("render --widht 64", dir);
    EXPECT_EQ(run.status, 2);
    EXPECT_NE(run.output.find("unknown option '--widht'; did you mean '--width'?"),
              std::string::npos)
        << run.output;
    EXPECT_FALSE(fs::exists(dir / "default.png"));
    CliRun compare = run_cli("compare --no-label", dir);
    EXPECT_EQ(compare.status, 2);
    EXPECT_NE(compare.output.find("did you mean '--no-labels'?"), std::string::npos)
        << compare.output;
}

TEST_F(Cli, ThreadsWithTheOpenGlBackendIsRefusedNotIgnored) {
    CliRun run = run_cli("render --backend gl --threads 2", dir);
    EXPECT_EQ(run.status, 2);
    EXPECT_NE(run.output.find("--threads applies to the CPU backend"), std::string::npos)
        << run.output;
    EXPECT_FALSE(fs::exists(dir / "default.png"));
}

TEST(Backends, TheListIsInTheEnumerationsOrderAndEachNameParsesBackToItsBackend) {
    const auto backends = litkit::backends();
    ASSERT_FALSE(backends.empty());
    for (std::size_t i = 0; i < backends.size(); ++i) {
        EXPECT_EQ(static_cast<std::size_t>(backends[i].id), i) << backends[i].name;
        EXPECT_EQ(litkit::to_string(backends[i].id), backends[i].name);
        EXPECT_EQ(litkit::parse_backend(backends[i].name), backends[i].id);
        EXPECT_FALSE(backends[i].summary.empty()) << backends[i].name;
    }
    EXPECT_EQ(litkit::parse_backend("cpu"), litkit::Backend::Cpu);
    EXPECT_EQ(litkit::parse_backend("gl"), litkit::Backend::Gl);
    EXPECT_EQ(litkit::parse_backend("GL"), std::nullopt);
    EXPECT_EQ(litkit::parse_backend(""), std::nullopt);
    EXPECT_EQ(litkit::to_string(litkit::default_backend), "cpu");
}

TEST_F(Cli, BackendOptionOffersEveryBackendOfTheLibrarysList) {
    CliRun help = run_cli("render --help", dir);
    EXPECT_EQ(help.status, 0);
    for (const litkit::BackendInfo& backend : litkit::backends()) {
        const std::string described =
            std::string(backend.name) + ": " + std::string(backend.summary);
        EXPECT_NE(help.output.find(described), std::string::npos) << described << "\n"
                                                                  << help.output;
    }
    EXPECT_EQ(run_cli("render --backend vulkan", dir).status, 2);
    EXPECT_FALSE(fs::exists(dir / "default.png"));
}

TEST_F(Cli, BadOptionValuesAreUsageErrors) {
    EXPECT_EQ(run_cli("render --width 0", dir).status, 2);
    EXPECT_EQ(run_cli("render --width 20000", dir).status, 2);
    EXPECT_EQ(run_cli("render --reflection Phong", dir).status, 2);
    EXPECT_EQ(run_cli("render --shading smooth", dir).status, 2);
    EXPECT_FALSE(fs::exists(dir / "default.png"));
}

TEST_F(Cli, RenderWithoutSceneDrawsTheDefaultSceneAt800x600) {
    CliRun run = run_cli("render -o out.png", dir);
    ASSERT_EQ(run.status, 0) << run.output;
    const litkit::Image image = litkit::read_png(dir / "out.png");
    EXPECT_EQ(image.width, 800);
    EXPECT_EQ(image.height, 600);
    // The cube is lit: some pixel is far from the black background, and the
    // Phong highlight makes some pixel nearly white.
    int lit = 0, bright = 0;
    for (std::size_t i = 0; i < image.rgb.size(); i += 3) {
        const int sum = image.rgb[i] + image.rgb[i + 1] + image.rgb[i + 2];
        lit += sum > 60;
        bright += image.rgb[i] > 200 && image.rgb[i + 1] > 200 && image.rgb[i + 2] > 200;
    }
    EXPECT_GT(lit, 800 * 600 / 50) << "the default cube should cover a good part of the image";
    EXPECT_GT(bright, 10) << "the default cube should show a highlight";
}

TEST_F(Cli, RenderDefaultNameAndSizeOverrides) {
    CliRun run = run_cli("render --width 40 --height 30", dir);
    ASSERT_EQ(run.status, 0) << run.output;
    const litkit::Image image = litkit::read_png(dir / "default.png");
    EXPECT_EQ(image.width, 40);
    EXPECT_EQ(image.height, 30);
}

TEST_F(Cli, MissingLightingWithoutTerminalIsAnErrorNamingTheFixes) {
    write("scene.toml", scene_without_lighting);
    CliRun run = run_cli("render scene.toml -o out.png", dir);
    EXPECT_EQ(run.status, 2);
    EXPECT_NE(run.output.find("--yes"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("[lighting]"), std::string::npos) << run.output;
    EXPECT_FALSE(fs::exists(dir / "out.png"));
}

TEST_F(Cli, MissingLightingWithYesUsesTheDefaults) {
    write("scene.toml", scene_without_lighting);
    CliRun with_yes = run_cli("render scene.toml --yes -o yes.png", dir);
    ASSERT_EQ(with_yes.status, 0) << with_yes.output;
    CliRun explicit_models =
        run_cli("render scene.toml --reflection phong --shading phong -o explicit.png", dir);
    ASSERT_EQ(explicit_models.status, 0) << explicit_models.output;
    EXPECT_EQ(litkit::read_png(dir / "yes.png").rgb, litkit::read_png(dir / "explicit.png").rgb);
}

TEST_F(Cli, ReflectionOverrideChangesThePicture) {
    write("scene.toml", scene_without_lighting);
    ASSERT_EQ(run_cli("render scene.toml --yes --reflection lambert -o a.png", dir).status, 0);
    ASSERT_EQ(run_cli("render scene.toml --yes --reflection phong -o b.png", dir).status, 0);
    EXPECT_NE(litkit::read_png(dir / "a.png").rgb, litkit::read_png(dir / "b.png").rgb);
}

TEST_F(Cli, OutputNameDefaultsToTheSceneName) {
    write("ball.toml", scene_without_lighting);
    ASSERT_EQ(run_cli("render ball.toml --yes", dir).status, 0);
    EXPECT_TRUE(fs::exists(dir / "ball.png"));
}

TEST_F(Cli, MissingSceneFileCannotBeReadExit1) {
    CliRun run = run_cli("render lights.toml -o out.png", dir);
    EXPECT_EQ(run.status, 1);
    EXPECT_NE(run.output.find("error: cannot read 'lights.toml': No such file or directory"),
              std::string::npos)
        << run.output;
    EXPECT_FALSE(fs::exists(dir / "out.png"));
}

TEST_F(Cli, DirectoryAsSceneCannotBeReadExit1) {
    fs::create_directory(dir / "scenes.toml");
    CliRun run = run_cli("render scenes.toml --yes -o out.png", dir);
    EXPECT_EQ(run.status, 1);
    EXPECT_NE(run.output.find("error: cannot read 'scenes.toml': Is a directory"),
              std::string::npos)
        << run.output;
    EXPECT_FALSE(fs::exists(dir / "out.png"));
}

TEST_F(Cli, SceneWithoutReadPermissionCannotBeReadExit1) {
    write("locked.toml", scene_without_lighting);
    fs::permissions(dir / "locked.toml", fs::perms::none);
    CliRun run;
    if (::geteuid() != 0) {
        run = run_cli("check locked.toml", dir);
    } else {
        // Root reads whatever the permission bits say: ask as nobody.
        if (run_cli_as_nobody("--version", dir).status != 0)
            GTEST_SKIP() << "running as root, and cannot run the CLI as user nobody (setpriv): "
                            "permission bits do not stop root's reads";
        run = run_cli_as_nobody("check locked.toml", dir);
    }
    EXPECT_EQ(run.status, 1);
    EXPECT_NE(run.output.find("error: cannot read 'locked.toml': Permission denied"),
              std::string::npos)
        << run.output;
}

TEST_F(Cli, PathThroughAFileCannotBeReadExit1) {
    write("file.toml", scene_without_lighting);
    CliRun run = run_cli("check file.toml/x.toml", dir);
    EXPECT_EQ(run.status, 1);
    EXPECT_NE(run.output.find("error: cannot read 'file.toml/x.toml': Not a directory"),
              std::string::npos)
        << run.output;
}

TEST_F(Cli, SecondSceneFileMissingCannotBeReadExit1) {
    write("room.toml", scene_without_lighting);
    CliRun run = run_cli("render room.toml lights.toml --yes -o out.png", dir);
    EXPECT_EQ(run.status, 1);
    EXPECT_NE(run.output.find("error: cannot read 'lights.toml': No such file or directory"),
              std::string::npos)
        << run.output;
    EXPECT_FALSE(fs::exists(dir / "out.png"));
    EXPECT_EQ(run_cli("check room.toml lights.toml", dir).status, 1);
}

TEST_F(Cli, NonUtf8SceneCannotBeReadExit1WithItsPlace) {
    // "café" in Latin-1: the é is the single byte 0xE9.
    write("scene.toml", "[room]\nwidth = 10\n# caf\xe9\n");
    CliRun run = run_cli("check scene.toml", dir);
    EXPECT_EQ(run.status, 1);
    EXPECT_NE(run.output.find("scene.toml:3:"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("error: cannot read 'scene.toml': "), std::string::npos)
        << run.output;
}

TEST_F(Cli, TextThatIsNotTomlCannotBeReadExit1WithItsPlace) {
    write("notes.toml", "Dear litkit,\nplease draw me a teapot.\n");
    CliRun run = run_cli("check notes.toml", dir);
    EXPECT_EQ(run.status, 1);
    EXPECT_NE(run.output.find("notes.toml:1:"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("error: cannot read 'notes.toml': "), std::string::npos)
        << run.output;
}

TEST_F(Cli, PictureGivenAsSceneCannotBeReadExit1) {
    ASSERT_EQ(run_cli("render --width 8 --height 8 -o picture.png", dir).status, 0);
    CliRun run = run_cli("render picture.png --yes -o out.png", dir);
    EXPECT_EQ(run.status, 1);
    EXPECT_NE(run.output.find("picture.png:1:"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("error: cannot read 'picture.png': "), std::string::npos)
        << run.output;
    EXPECT_FALSE(fs::exists(dir / "out.png"));
}

TEST_F(Cli, UsageErrorsExit2WithAHint) {
    for (const char* arguments :
         {"", "frobnicate", "render --colour red", "render --width 0", "render --threads -1",
          "render --shading smooth", "check", "init a.toml b.toml"}) {
        CliRun run = run_cli(arguments, dir);
        EXPECT_EQ(run.status, 2) << arguments << "\n" << run.output;
        EXPECT_NE(run.output.find("Run with --help for more information."), std::string::npos)
            << arguments << "\n"
            << run.output;
    }
    EXPECT_FALSE(fs::exists(dir / "default.png"));
    EXPECT_FALSE(fs::exists(dir / "a.toml"));
}

TEST_F(Cli, RefusesToWriteOverAnInput) {
    write("scene.toml", scene_without_lighting);
    const std::string before = read("scene.toml");
    CliRun run = run_cli("render scene.toml --yes -o scene.toml", dir);
    EXPECT_EQ(run.status, 2);
    EXPECT_EQ(read("scene.toml"), before);
    // One wording for every command that writes a file of its own naming
    // (render, compare, turntable).
    EXPECT_NE(run.output.find("error: refusing to write over input file 'scene.toml'; choose "
                              "another name with -o"),
              std::string::npos)
        << run.output;
    CliRun compare = run_cli("compare scene.toml --yes --width 16 --height 16 -o scene.toml", dir);
    EXPECT_EQ(compare.status, 2);
    EXPECT_NE(compare.output.find("error: refusing to write over input file 'scene.toml'; choose "
                                  "another name with -o"),
              std::string::npos)
        << compare.output;
    EXPECT_EQ(read("scene.toml"), before);
}

TEST_F(Cli, FailedRenderLeavesThePreviousOutputUntouched) {
    write("old.png", "previous output");
    write("scene.toml", "this is = not [valid toml");
    CliRun run = run_cli("render scene.toml --yes -o old.png", dir);
    EXPECT_EQ(run.status, 1);
    EXPECT_EQ(read("old.png"), "previous output");
}

TEST_F(Cli, InvalidTomlReportsWhereParsingStopped) {
    write("scene.toml", "[room]\nwidth = = 3\n");
    CliRun run = run_cli("check scene.toml", dir);
    EXPECT_EQ(run.status, 1);
    EXPECT_NE(run.output.find("scene.toml:2:"), std::string::npos) << run.output;
}

TEST_F(Cli, TypeMismatchIsInvalidInputExit2WithLocation) {
    std::string text = scene_without_lighting;
    text.replace(text.find("radius = 1"), 10, "radius = \"big\"");
    write("scene.toml", text);
    CliRun run = run_cli("check scene.toml", dir);
    EXPECT_EQ(run.status, 2);
    EXPECT_NE(run.output.find("scene.toml:21:10: error:"), std::string::npos) << run.output;
}

TEST_F(Cli, InitWritesTheDefaultSceneWhichRendersLikeTheBuiltIn) {
    ASSERT_EQ(run_cli("init", dir).status, 0);
    ASSERT_TRUE(fs::exists(dir / "scene.toml"));
    ASSERT_EQ(run_cli("render scene.toml -o from-file.png --width 80 --height 60", dir).status, 0);
    ASSERT_EQ(run_cli("render -o built-in.png --width 80 --height 60", dir).status, 0);
    EXPECT_EQ(litkit::read_png(dir / "from-file.png").rgb,
              litkit::read_png(dir / "built-in.png").rgb);
}

TEST_F(Cli, InitRefusesToReplaceAFileUnlessForced) {
    write("mine.toml", "# my scene\n");
    EXPECT_EQ(run_cli("init mine.toml", dir).status, 2);
    EXPECT_EQ(read("mine.toml"), "# my scene\n");
    EXPECT_EQ(run_cli("init mine.toml --force", dir).status, 0);
    EXPECT_NE(read("mine.toml"), "# my scene\n");
}

TEST_F(Cli, CheckSaysOkForAValidScene) {
    ASSERT_EQ(run_cli("init", dir).status, 0);
    CliRun run = run_cli("check scene.toml", dir);
    EXPECT_EQ(run.status, 0) << run.output;
    EXPECT_NE(run.output.find("ok"), std::string::npos);
}

TEST_F(Cli, BenchPrintsFrameTimesWithAMachineReadableLastLine) {
    CliRun run = run_cli("bench --frames 3 --width 64 --height 48 --shading flat", dir);
    ASSERT_EQ(run.status, 0) << run.output;
    EXPECT_NE(run.output.find("image: 64x48, 12 triangles"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("pixels shaded: "), std::string::npos) << run.output;
    const std::size_t last_line = run.output.rfind("median_frame_ms=");
    ASSERT_NE(last_line, std::string::npos) << run.output;
    EXPECT_NE(run.output.find(" fps=", last_line), std::string::npos) << run.output;
    EXPECT_FALSE(fs::exists(dir / "default.png")) << "bench renders into memory only";
}

// docs/spec.md §9.2 on the command line.
const char* cube_and_mesh_scene = R"(
[room]
width = 10
height = 10
depth = 10

[observer]
position = [0, 1, 5]

[output]
width = 64
height = 48

[[lights]]
type = "point"
position = [0, 3, 3]
intensity = 10

[[objects]]
type = "cube"
position = [-1.2, 0, 0]
rotation = [20, 30, 0]

[[objects]]
type = "mesh"
file = "square.obj"
position = [1.2, 0, 0]
)";

// Line 7 is the face whose third corner has no normal.
const char* square_missing_a_normal =
    "v -0.5 -0.5 0\nv 0.5 -0.5 0\nv 0.5 0.5 0\nv -0.5 0.5 0\nvn 0 0 1\n"
    "f 1//1 2//1 3//1\nf 1//1 3//1 4\n";

TEST_F(Cli, CreaseAngleOptionChangesThePicture) {
    // A cube's pillowed normals become its faces' at 60° (its faces meet at 90°).
    write("scene.toml", cube_and_mesh_scene);
    write("square.obj", square_missing_a_normal);
    ASSERT_EQ(run_cli("render scene.toml --yes -o smooth.png", dir).status, 0);
    const CliRun creased = run_cli("render scene.toml --yes --crease-angle 60 -o sharp.png", dir);
    ASSERT_EQ(creased.status, 0) << creased.output;
    EXPECT_NE(litkit::read_png(dir / "smooth.png").rgb, litkit::read_png(dir / "sharp.png").rgb);
}

TEST_F(Cli, BadNormalsOptionValuesAreUsageErrors) {
    EXPECT_EQ(run_cli("render --normals angel", dir).status, 2);
    EXPECT_EQ(run_cli("render --crease-angle 0", dir).status, 2);
    EXPECT_EQ(run_cli("render --crease-angle 181", dir).status, 2);
    EXPECT_EQ(run_cli("render --crease-angle sixty", dir).status, 2);
    EXPECT_EQ(run_cli("bench --crease-angle -5", dir).status, 2);
    EXPECT_FALSE(fs::exists(dir / "default.png"));
}

TEST_F(Cli, FileNormalsOnAMeshWithoutThemIsInvalidInputAtTheMeshLine) {
    // From the command line, "file" applies to the mesh only (the cube uses
    // mean), and the mesh's face on line 7 lacks a normal.
    write("scene.toml", cube_and_mesh_scene);
    write("square.obj", square_missing_a_normal);
    for (const char* backend : {"cpu", "gl"}) {
        const CliRun run =
            run_cli(std::string("render scene.toml --yes --normals file --backend ") + backend +
                        " -o out.png",
                    dir);
        if (run.output.find("OpenGL is not available") != std::string::npos) continue;
        EXPECT_EQ(run.status, 2) << run.output;
        EXPECT_NE(run.output.find("square.obj:7: error: "), std::string::npos) << run.output;
        EXPECT_FALSE(fs::exists(dir / "out.png"));
    }
    // check finds it too, and the scene itself (mean normals) is fine.
    const CliRun checked = run_cli("check scene.toml --normals file", dir);
    EXPECT_EQ(checked.status, 2) << checked.output;
    EXPECT_NE(checked.output.find("square.obj:7: error: "), std::string::npos) << checked.output;
    EXPECT_EQ(run_cli("check scene.toml", dir).status, 0);
}

namespace {

// docs/spec.md §10: a glass cube (the closed cube of tests/data/obj), or
// with `cube_file` another mesh. The object is on line 16.
std::string glass_scene(const std::string& cube_file = "closed_cube.obj") {
    return R"([room]
width = 10
height = 10
depth = 10
[observer]
position = [0, 1, 4]
[lighting]
reflection = "phong"
shading = "phong"
[output]
width = 64
height = 48
[[lights]]
type = "point"
position = [0, 3, 3]
[[objects]]
name = "glass"
type = "mesh"
file = ")" +
           (fs::path(LITKIT_TEST_DATA) / "obj" / cube_file).string() +
           R"("
material = { transmission = 0.5, ior = 1.5 }
)";
}

}  // namespace

TEST_F(Cli, MaxDepthIsAnOptionOfEveryCommandThatRenders) {
    for (const char* command : {"render", "compare", "turntable", "explain", "view", "bench"}) {
        const CliRun help = run_cli(std::string(command) + " --help", dir);
        EXPECT_EQ(help.status, 0) << command;
        EXPECT_NE(help.output.find("--max-depth"), std::string::npos) << command;
    }
    // 1–16 (docs/spec.md §10.1), an integer.
    for (const char* value : {"0", "17", "2.5", "deep"}) {
        const CliRun run = run_cli(std::string("render --max-depth ") + value, dir);
        EXPECT_EQ(run.status, 2) << value << ": " << run.output;
    }
    EXPECT_EQ(run_cli("bench --max-depth 0", dir).status, 2);
    EXPECT_FALSE(fs::exists(dir / "default.png"));
    // The ends of the range; without glass the picture does not change.
    ASSERT_EQ(run_cli("render -o plain.png", dir).status, 0);
    ASSERT_EQ(run_cli("render --max-depth 1 -o one.png", dir).status, 0);
    ASSERT_EQ(run_cli("render --max-depth 16 -o sixteen.png", dir).status, 0);
    EXPECT_EQ(read("plain.png"), read("one.png"));
    EXPECT_EQ(read("plain.png"), read("sixteen.png"));
}

TEST_F(Cli, CheckReportsAnOpenMeshThatRefractsAtTheObject) {
    write("open.toml", glass_scene("open_cube.obj"));
    const CliRun open = run_cli("check open.toml", dir);
    EXPECT_EQ(open.status, 2) << open.output;
    EXPECT_NE(open.output.find("open.toml:16:1: error: objects[0] 'glass': transmission 0.5 needs "
                               "a closed mesh (docs/spec.md §10.1), and mesh file 'open_cube.obj' "
                               "is not closed: its edge from [0.5, 0.5, 0.5] to [-0.5, 0.5, "
                               "0.5] (face 1, line 13) belongs to one triangle only"),
              std::string::npos)
        << open.output;
    write("closed.toml", glass_scene());
    const CliRun closed = run_cli("check closed.toml", dir);
    EXPECT_EQ(closed.status, 0) << closed.output;
}

TEST_F(Cli, GlassIsDrawnByOpenGlAndTheExports) {
    write("glass.toml", glass_scene());
    const CliRun gl = run_cli("render glass.toml --backend gl --max-depth 3 -o gl.png", dir);
    if (gl.output.find("OpenGL is not available") == std::string::npos) {
        EXPECT_EQ(gl.status, 0) << gl.output;
        EXPECT_TRUE(fs::exists(dir / "gl.png"));
    }
    const CliRun glsl = run_cli("export glass.toml --format glsl -o shaders", dir);
    EXPECT_EQ(glsl.status, 0) << glsl.output;
    const CliRun cpp = run_cli("export glass.toml --format cpp -o program", dir);
    EXPECT_EQ(cpp.status, 0) << cpp.output;
    EXPECT_TRUE(fs::exists(dir / "program" / "main.cpp"));
    // The CPU backend takes it.
    const CliRun cpu = run_cli("render glass.toml --max-depth 3 -o cpu.png", dir);
    EXPECT_EQ(cpu.status, 0) << cpu.output;
    // The controls: the same keys with transmission 0 go everywhere.
    std::string opaque = glass_scene();
    opaque.replace(opaque.find("transmission = 0.5"), 18, "transmission = 0.0");
    write("opaque.toml", opaque);
    const CliRun opaque_gl = run_cli("render opaque.toml --backend gl -o opaque.png", dir);
    if (opaque_gl.output.find("OpenGL is not available") == std::string::npos) {
        EXPECT_EQ(opaque_gl.status, 0) << opaque_gl.output;
    }
    EXPECT_EQ(run_cli("export opaque.toml --format glsl -o opaque-shaders", dir).status, 0);
}
