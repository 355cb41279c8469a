// The CLI's modules (apps/litkit/modules.hpp, docs/design.md "Modules"):
// litkit-view.so for `litkit view` and litkit-gl.so for `--backend gl` are
// opened only by the runs that use them, so the executable itself loads
// none of their libraries; a missing, broken or foreign module is an error
// message, never a crash. Most tests run a copy of the CLI in a folder of
// its own, laid out as an install (bin/litkit, lib/litkit/), with or without
// a module there.
#include <gtest/gtest.h>
#include <dlfcn.h>
#include <unistd.h>

#include <exception>
#include <filesystem>
#include <fstream>
#include <string>

#include "run_command.hpp"

namespace {

namespace fs = std::filesystem;
using litkit_test::run_command;

// Built by appending: GCC 12's -Wrestrict misfires on "'" + std::string
// once inlined (GCC bug 105329).
std::string quoted(const fs::path& path) {
    std::string text = "'";
    text += path.string();
    text += "'";
    return text;
}

class Modules : public ::testing::Test {
protected:
    void SetUp() override {
        dir = fs::temp_directory_path() / ("litkit-modules-" + std::to_string(getpid()) + "-" +
                                           ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir);
        fs::create_directories(dir / "bin");
        fs::create_directories(dir / "lib" / "litkit");
        fs::copy_file(LITKIT_CLI, cli());
        fs::permissions(cli(), fs::perms::owner_all);
    }
    void TearDown() override { fs::remove_all(dir); }

    fs::path cli() const { return dir / "bin" / "litkit"; }
    fs::path installed(const std::string& module) const { return dir / "lib" / "litkit" / module; }
    // Mesa keeps a few allocations to the end of the process (the GL suites
    // say the same, tests/CMakeLists.txt): no leak check for the copy that
    // may draw with OpenGL under ASan.
    litkit_test::CommandRun run(const std::string& arguments) const {
        return run_command("cd " + quoted(dir) + " && ASAN_OPTIONS=detect_leaks=0 " + quoted(cli()) + " " +
                           arguments);
    }
    // A real shared library without a litkit entry point: libstdc++.
    static std::string some_other_library() {
        Dl_info library{};
        if (dladdr(reinterpret_cast<void*>(&std::terminate), &library) == 0 || !library.dli_fname) return {};
        return library.dli_fname;
    }

    fs::path dir;
};

}  // namespace

TEST(ModulesLinking, TheExecutableLoadsNoWindowOrOpenGlLibraries) {
    // What the dynamic loader loads for the executable (how ldd asks it).
    const auto loaded = run_command("LD_TRACE_LOADED_OBJECTS=1 '" LITKIT_CLI "'");
    ASSERT_EQ(loaded.status, 0) << loaded.output;
    ASSERT_NE(loaded.output.find("libstdc++"), std::string::npos) << loaded.output;
    for (const char* library :
         {"libSDL2", "libimgui", "libX11", "libwayland", "libpulse", "libasound", "libepoxy", "libEGL", "libGL"})
        EXPECT_EQ(loaded.output.find(library), std::string::npos) << library << " in\n" << loaded.output;
}

TEST_F(Modules, MissingViewerIsAClearErrorAndEveryOtherCommandWorks) {
    const auto view = run("view");
    EXPECT_EQ(view.status, 1) << view.output;
    EXPECT_EQ(view.output.rfind("error: litkit view needs its module litkit-view.so, which is not installed", 0), 0u)
        << view.output;
    EXPECT_NE(view.output.find(installed("litkit-view.so").string()), std::string::npos) << view.output;

    const auto render = run("render --width 40 --height 30 -o picture.png");
    EXPECT_EQ(render.status, 0) << render.output;
    EXPECT_TRUE(fs::exists(dir / "picture.png"));
    // The help documents `view` without the module (the man page is made from it).
    const auto help = run("view --help");
    EXPECT_EQ(help.status, 0) << help.output;
    EXPECT_NE(help.output.find("--orbit-frames"), std::string::npos) << help.output;
}

TEST_F(Modules, MissingOpenGlModuleIsAClearError) {
    const auto render = run("render --backend gl --width 40 --height 30 -o picture.png");
    EXPECT_EQ(render.status, 1) << render.output;
    EXPECT_EQ(render.output.rfind("error: --backend gl needs its module litkit-gl.so, which is not installed", 0), 0u)
        << render.output;
    EXPECT_FALSE(fs::exists(dir / "picture.png"));
}

TEST_F(Modules, BrokenModuleIsAClearError) {
    std::ofstream(installed("litkit-view.so")) << "not a shared library\n";
    const auto view = run("view");
    EXPECT_EQ(view.status, 1) << view.output;
    EXPECT_EQ(view.output.rfind("error: litkit view cannot load its module " +
                                    installed("litkit-view.so").string() + ": ", 0),
              0u)
        << view.output;
}

TEST_F(Modules, ALibraryThatIsNotLitkitsModuleIsRefused) {
    const std::string library = some_other_library();
    ASSERT_FALSE(library.empty());
    fs::copy_file(library, installed("litkit-gl.so"));
    const auto render = run("render --backend gl --width 40 --height 30 -o picture.png");
    EXPECT_EQ(render.status, 1) << render.output;
    const std::string version = run("--version").output;  // "litkit 0.1.0\n"
    EXPECT_EQ(render.output, "error: " + installed("litkit-gl.so").string() + " is not a module of " +
                                 version.substr(0, version.size() - 1) +
                                 " (another build's?); install litkit again\n");
}

TEST_F(Modules, InstalledModulesAreFoundInLibLitkit) {
    // The build tree's modules, where `cmake --install` puts them.
    const fs::path built = fs::path(LITKIT_CLI).parent_path();
    fs::copy_file(built / "litkit-gl.so", installed("litkit-gl.so"));
    const auto render = run("render --backend gl --width 40 --height 30 -o picture.png");
    EXPECT_EQ(render.status, 0) << render.output;
    EXPECT_NE(render.output.find("OpenGL backend: "), std::string::npos) << render.output;
}

TEST(ModulesErrors, AnOpenGlErrorInTheModuleIsReportedAsWithoutIt) {
    // No EGL vendor for libglvnd: the module's GlRenderer throws GlError,
    // which the CLI reports with its hint, as when it drew in-process.
    const auto render = run_command("cd '" + fs::temp_directory_path().string() +
                                    "' && ASAN_OPTIONS=detect_leaks=0 __EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent.json '" LITKIT_CLI
                                    "' render --backend gl -o /dev/null");
    EXPECT_EQ(render.status, 1) << render.output;
    EXPECT_EQ(render.output.rfind("error: OpenGL is not available: ", 0), 0u) << render.output;
    EXPECT_NE(render.output.find("\nhint: render without OpenGL with --backend cpu\n"), std::string::npos)
        << render.output;
}
