// SPDX-License-Identifier: MIT
// The command line's conventions: an output's name says what it holds (-o
// picture.jpg is refused, not filled with PNG bytes), -q/--quiet, and
// --version listing what the build was made with.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "litkit/image.hpp"
#include "litkit/scene.hpp"
#include "run_command.hpp"

namespace fs = std::filesystem;

namespace {

using litkit_test::CommandRun;

class Conventions : public ::testing::Test {
  protected:
    void SetUp() override {
        dir = fs::temp_directory_path() /
              ("litkit-conventions-" + std::to_string(::getpid()) + "-" +
               ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
        std::ofstream(dir / "scene.toml") << litkit::default_scene_toml();
    }
    void TearDown() override { fs::remove_all(dir); }
    CommandRun cli(const std::string& arguments) {
        return litkit_test::run_command("cd '" + dir.string() + "' && '" LITKIT_CLI "' " +
                                        arguments);
    }
    // Every file in the folder but the scene.
    std::vector<std::string> written() {
        std::vector<std::string> names;
        for (const fs::directory_entry& entry : fs::directory_iterator(dir))
            if (entry.path().filename() != "scene.toml") names.push_back(entry.path().filename());
        return names;
    }
    fs::path dir;
};

const std::string small = " --width 16 --height 12 ";

TEST_F(Conventions, RenderRefusesAnOutputNameThatIsNotPng) {
    for (const std::string name : {"picture.jpg", "picture.gif", "picture", "picture.png.txt"}) {
        const CommandRun run = cli("render scene.toml" + small + "-o " + name);
        EXPECT_EQ(run.status, 2) << name << ": " << run.output;
        EXPECT_EQ(run.output, "error: -o " + name +
                                  ": litkit render writes a PNG picture; name the output with "
                                  ".png (or - for standard output); nothing was written\n");
        EXPECT_EQ(written(), std::vector<std::string>{}) << name;
    }
}

TEST_F(Conventions, ThePngSuffixMayBeInCapitals) {
    const CommandRun run = cli("render scene.toml" + small + "-o Picture.PNG");
    EXPECT_EQ(run.status, 0) << run.output;
    EXPECT_EQ(litkit::read_png(dir / "Picture.PNG").width, 16);
}

TEST_F(Conventions, CompareRefusesAnOutputNameThatIsNotPng) {
    const CommandRun run = cli("compare scene.toml" + small + "-o grid.webp");
    EXPECT_EQ(run.status, 2) << run.output;
    EXPECT_NE(run.output.find("error: -o grid.webp: litkit compare writes a PNG picture; name "
                              "the output with .png"),
              std::string::npos)
        << run.output;
    EXPECT_EQ(written(), std::vector<std::string>{});
}

TEST_F(Conventions, TurntableRefusesAFileNameThatIsNotAnAnimation) {
    const CommandRun run = cli("turntable scene.toml --frames 2" + small + "-o spin.mp4");
    EXPECT_EQ(run.status, 2) << run.output;
    EXPECT_NE(run.output.find("error: -o spin.mp4: litkit turntable writes an animated GIF or "
                              "PNG, or PNG frames into a folder named DIR/; name the output "
                              "with .gif or .png"),
              std::string::npos)
        << run.output;
    EXPECT_EQ(written(), std::vector<std::string>{});
    // A folder, named with its slash or existing, takes the frames whatever its name.
    EXPECT_EQ(cli("turntable scene.toml --frames 2" + small + "-o frames.gif/").status, 0);
    EXPECT_TRUE(fs::exists(dir / "frames.gif" / "frame-000.png"));
    EXPECT_EQ(cli("turntable scene.toml --frames 2" + small + "-o spin.GIF").status, 0);
    EXPECT_TRUE(fs::is_regular_file(dir / "spin.GIF"));
}

TEST_F(Conventions, WhatIsNoPictureFileKeepsItsName) {
    // A device and standard output under any name; the name is not a file's.
    EXPECT_EQ(cli("render scene.toml" + small + "-o /dev/null").status, 0);
    const CommandRun piped = cli("render scene.toml" + small + "-o /dev/stdout > out.bin");
    EXPECT_EQ(piped.status, 0) << piped.output;
    EXPECT_EQ(litkit::read_png(dir / "out.bin").width, 16);
}

TEST_F(Conventions, QuietSaysNothingOnSuccessButStillShowsErrors) {
    for (const std::string quiet : {"-q render", "--quiet render", "render -q"}) {
        const CommandRun run = cli(quiet + " scene.toml" + small + "-o a.png");
        EXPECT_EQ(run.status, 0) << quiet;
        EXPECT_EQ(run.output, "") << quiet;
        EXPECT_EQ(litkit::read_png(dir / "a.png").height, 12) << quiet;
    }
    EXPECT_NE(cli("render scene.toml" + small + "-o a.png").output.find("litkit: wrote a.png"),
              std::string::npos);
    EXPECT_EQ(cli("check -q scene.toml").output, "");
    EXPECT_EQ(cli("-q turntable scene.toml --frames 2" + small + "-o t.gif").output, "");
    EXPECT_EQ(cli("-q compare scene.toml" + small + "-o c.png").output, "");
    // A warning (a scene without lights) is left out; an error is not.
    std::ofstream(dir / "dark.toml")
        << "[room]\nwidth = 10\nheight = 10\ndepth = 10\n[observer]\nposition = [0, 0, "
           "5]\n[lighting]\nreflection = \"phong\"\n"
           "shading = \"phong\"\n[[objects]]\ntype = \"cube\"\n";
    const CommandRun loud = cli("render dark.toml" + small + "-o d.png");
    ASSERT_EQ(loud.status, 0) << loud.output;
    ASSERT_NE(loud.output.find("warning"), std::string::npos) << loud.output;
    EXPECT_EQ(cli("-q render dark.toml" + small + "-o d.png").output, "");
    const CommandRun missing = cli("-q render missing.toml");
    EXPECT_EQ(missing.status, 1);
    EXPECT_NE(missing.output.find("missing.toml"), std::string::npos) << missing.output;
}

TEST_F(Conventions, VersionListsTheBuildsFeatures) {
    const CommandRun run = cli("--version");
    EXPECT_EQ(run.status, 0);
    EXPECT_EQ(run.output.rfind("litkit " LITKIT_VERSION_FOR_TESTS "\n\n", 0), 0u) << run.output;
    for (const char* line :
         {"\nSIMD kernels: avx512, avx2, portable (this CPU runs ",
          "\nOpenGL backend: module litkit-gl.so", "\nviewer: module litkit-view.so",
          "\nPython module: ", "\nPNG deflater: "})
        EXPECT_NE(run.output.find(line), std::string::npos) << line << "\n" << run.output;
    // After a command too (docs/spec.md §8).
    EXPECT_EQ(cli("render --version").output, run.output);
}

}  // namespace
