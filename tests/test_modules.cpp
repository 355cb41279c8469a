// SPDX-License-Identifier: MIT
// The CLI's modules (apps/litkit/modules.hpp, docs/design.md "Modules"):
// litkit-view.so for `litkit view` and litkit-gl.so for `--backend gl` are
// opened only by the runs that use them, so the executable itself loads
// none of their libraries; a missing, broken or foreign module is an error
// message, never a crash. Most tests run a copy of the CLI in a folder of
// its own, laid out as an install (bin/litkit, lib/litkit/), with or without
// a module there.
#include <dlfcn.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <new>
#include <sstream>
#include <stdexcept>
#include <string>

#include "crossing.hpp"
#include "litkit/gl_renderer.hpp"
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
        dir = fs::temp_directory_path() /
              ("litkit-modules-" + std::to_string(getpid()) + "-" +
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
        return run_command("cd " + quoted(dir) + " && ASAN_OPTIONS=detect_leaks=0 " +
                           quoted(cli()) + " " + arguments);
    }
    // A real shared library without a litkit entry point: libstdc++.
    static std::string some_other_library() {
        Dl_info library{};
        if (dladdr(reinterpret_cast<void*>(&std::terminate), &library) == 0 || !library.dli_fname)
            return {};
        return library.dli_fname;
    }

    fs::path dir;
};

}  // namespace

TEST(ModulesLinking, TheExecutableLoadsNoWindowOrOpenGlLibraries) {
    // What the dynamic loader loads for the executable (how ldd asks it).
    const auto loaded = run_command("LD_TRACE_LOADED_OBJECTS=1 '" LITKIT_CLI "'");
    ASSERT_EQ(loaded.status, 0) << loaded.output;
    ASSERT_NE(loaded.output.find("libc.so"), std::string::npos) << loaded.output;
    for (const char* library : {"libSDL2", "libimgui", "libX11", "libwayland", "libpulse",
                                "libasound", "libepoxy", "libEGL", "libGL"})
        EXPECT_EQ(loaded.output.find(library), std::string::npos) << library << " in\n"
                                                                  << loaded.output;
}

#if LITKIT_CLI_LINKED_STATICALLY
TEST(ModulesLinking, TheStaticallyLinkedExecutableLoadsOnlyTheCLibrary) {
    // docs/design.md "Start-up": libstdc++, libgcc, libpng, zlib, FreeType,
    // brotli and giflib are linked in; toml++ and tinyobjloader are compiled
    // into the library. What is loaded is the C library, libm, the dynamic
    // loader and the kernel's vDSO, one per line; and ISA-L, which Debian
    // ships only as a shared library, where the build deflates with it.
    const auto loaded = run_command("LD_TRACE_LOADED_OBJECTS=1 '" LITKIT_CLI "'");
    ASSERT_EQ(loaded.status, 0) << loaded.output;
    std::istringstream lines(loaded.output);
    int count = 0;
    for (std::string line; std::getline(lines, line);) {
        if (line.find_first_not_of(" \t") == std::string::npos) continue;
        ++count;
        const bool expected =
            line.find("linux-vdso.so") != std::string::npos ||
            line.find("libc.so.6") != std::string::npos ||
            line.find("libm.so.6") != std::string::npos ||
            line.find("ld-linux") != std::string::npos ||
            (LITKIT_CLI_LOADS_ISAL && line.find("libisal.so.2") != std::string::npos);
        EXPECT_TRUE(expected) << "unexpected: " << line;
    }
    EXPECT_EQ(count, LITKIT_CLI_LOADS_ISAL ? 5 : 4) << loaded.output;
}
#endif

// Nothing is thrown across a module's boundary (apps/litkit/crossing.hpp):
// what one side catches, the other throws again as the same error, with the
// members its handlers read.
namespace {

litkit_cli::CaughtError caught_from(const std::function<void()>& thrower) {
    litkit_cli::CaughtError error;
    EXPECT_FALSE(litkit_cli::call_catching(thrower, error));
    return error;
}

// A Diagnostic made member by member: GCC 12 at -O3 warns falsely
// (-Wmaybe-uninitialized, on the strings' clean-up) about the same three
// written as aggregate initialisers in the test below.
litkit::Diagnostic diagnostic(litkit::FileLoc location, litkit::Severity severity,
                              std::string message) {
    litkit::Diagnostic made;
    made.location = std::move(location);
    made.severity = severity;
    made.message = std::move(message);
    return made;
}

template <class E>
E thrown_again(const litkit_cli::CaughtError& error) {
    try {
        litkit_cli::throw_again(error);
    } catch (const E& again) {
        return again;
    } catch (const std::exception& other) {
        ADD_FAILURE() << "threw another type: " << other.what();
    }
    throw std::logic_error("not thrown as expected");
}

}  // namespace

TEST(ModulesCrossing, NothingThrownIsNoError) {
    litkit_cli::CaughtError error;
    EXPECT_TRUE(litkit_cli::call_catching([] {}, error));
    EXPECT_EQ(error.kind, litkit_cli::CaughtError::Kind::None);
}

TEST(ModulesCrossing, SceneErrorKeepsItsDiagnosticsAndWarnings) {
    const litkit::Diagnostic problem =
        diagnostic({"a.toml", 3, 7}, litkit::Severity::Error, "radius must be > 0");
    const litkit::Diagnostic other =
        diagnostic({"b.toml", 1, 1}, litkit::Severity::Error, "unknown key 'x'");
    const litkit::Diagnostic warning =
        diagnostic({"a.toml", 9, 2}, litkit::Severity::Warning, "no lights");
    const auto error = caught_from([&] { throw litkit::SceneError({problem, other}, {warning}); });
    EXPECT_EQ(error.kind, litkit_cli::CaughtError::Kind::Scene);
    const auto again = thrown_again<litkit::SceneError>(error);
    ASSERT_EQ(again.diagnostics().size(), 2u);
    EXPECT_EQ(again.diagnostics()[1].to_string(), "b.toml:1:1: error: unknown key 'x'");
    ASSERT_EQ(again.warnings().size(), 1u);
    EXPECT_EQ(again.warnings()[0].to_string(), "a.toml:9:2: warning: no lights");
    EXPECT_EQ(again.location().to_string(), "a.toml:3:7");
    EXPECT_STREQ(again.what(), litkit::SceneError({problem, other}).what());
}

TEST(ModulesCrossing, IoErrorKeepsPathReasonPlaceAndDirection) {
    const auto error = caught_from([] {
        throw litkit::IoError("out.png", "No space left on device", {"s.toml", 4, 0},
                              litkit::IoError::Access::Write);
    });
    EXPECT_EQ(error.kind, litkit_cli::CaughtError::Kind::Io);
    const auto again = thrown_again<litkit::IoError>(error);
    EXPECT_EQ(again.path(), "out.png");
    EXPECT_EQ(again.reason(), "No space left on device");
    EXPECT_EQ(again.access(), litkit::IoError::Access::Write);
    EXPECT_STREQ(again.what(), "s.toml:4: error: cannot write 'out.png': No space left on device");
}

TEST(ModulesCrossing, EveryOtherKindIsThrownAgainAsItsOwnType) {
    const auto gl =
        caught_from([] { throw litkit::GlError("OpenGL is not available: no display"); });
    EXPECT_STREQ(thrown_again<litkit::GlError>(gl).what(), "OpenGL is not available: no display");

    const auto argument = caught_from([] { throw litkit::ArgumentError("radius 0", {"f", 2, 3}); });
    const auto argument_again = thrown_again<litkit::ArgumentError>(argument);
    EXPECT_STREQ(argument_again.what(), "radius 0");
    EXPECT_EQ(argument_again.location().line, 2u);

    const auto plain = caught_from([] { throw litkit::Error("plain"); });
    EXPECT_EQ(plain.kind, litkit_cli::CaughtError::Kind::Litkit);
    EXPECT_STREQ(thrown_again<litkit::Error>(plain).what(), "plain");

    const auto memory = caught_from([] { throw std::bad_alloc(); });
    EXPECT_EQ(memory.kind, litkit_cli::CaughtError::Kind::OutOfMemory);
    thrown_again<std::bad_alloc>(memory);

    const auto other = caught_from([] { throw std::out_of_range("index 7"); });
    EXPECT_EQ(other.kind, litkit_cli::CaughtError::Kind::Other);
    EXPECT_STREQ(thrown_again<std::runtime_error>(other).what(), "index 7");

    const auto unknown = caught_from([] { throw 42; });
    EXPECT_EQ(unknown.kind, litkit_cli::CaughtError::Kind::Other);
    EXPECT_STREQ(thrown_again<std::runtime_error>(unknown).what(), "unknown error");
}

TEST_F(Modules, MissingViewerIsAClearErrorAndEveryOtherCommandWorks) {
    const auto view = run("view");
    EXPECT_EQ(view.status, 1) << view.output;
    EXPECT_EQ(view.output.rfind(
                  "error: litkit view needs its module litkit-view.so, which is not installed", 0),
              0u)
        << view.output;
    EXPECT_NE(view.output.find(installed("litkit-view.so").string()), std::string::npos)
        << view.output;

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
    EXPECT_EQ(render.output.rfind(
                  "error: --backend gl needs its module litkit-gl.so, which is not installed", 0),
              0u)
        << render.output;
    EXPECT_FALSE(fs::exists(dir / "picture.png"));
}

TEST_F(Modules, BrokenModuleIsAClearError) {
    std::ofstream(installed("litkit-view.so")) << "not a shared library\n";
    const auto view = run("view");
    EXPECT_EQ(view.status, 1) << view.output;
    EXPECT_EQ(view.output.rfind("error: litkit view cannot load its module " +
                                    installed("litkit-view.so").string() + ": ",
                                0),
              0u)
        << view.output;
}

TEST_F(Modules, ALibraryThatIsNotLitkitsModuleIsRefused) {
    const std::string library = some_other_library();
    ASSERT_FALSE(library.empty());
    fs::copy_file(library, installed("litkit-gl.so"));
    const auto render = run("render --backend gl --width 40 --height 30 -o picture.png");
    EXPECT_EQ(render.status, 1) << render.output;
    const std::string all = run("--version").output;  // "litkit 0.1.0\n\nSIMD kernels: ..."
    const std::string version = all.substr(0, all.find('\n') + 1);  // "litkit 0.1.0\n"
    EXPECT_EQ(render.output, "error: " + installed("litkit-gl.so").string() +
                                 " is not a module of " + version.substr(0, version.size() - 1) +
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
                                    "' && ASAN_OPTIONS=detect_leaks=0 "
                                    "__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent.json '" LITKIT_CLI
                                    "' render --backend gl -o /dev/null");
    EXPECT_EQ(render.status, 1) << render.output;
    EXPECT_EQ(render.output.rfind("error: OpenGL is not available: ", 0), 0u) << render.output;
    EXPECT_NE(render.output.find("\nhint: render without OpenGL with --backend cpu\n"),
              std::string::npos)
        << render.output;
}
