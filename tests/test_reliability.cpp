// SPDX-License-Identifier: MIT
// docs/reliability.md: output written whole to what the user named and nothing else;
// input bounded, located and exact; scale. Real files, real device nodes and
// FIFOs made in a temporary folder (the tests run as root), real signals.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/inotify.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/files.hpp"
#include "litkit/error.hpp"
#include "litkit/image.hpp"
#include "litkit/mesh.hpp"
#include "litkit/shapes.hpp"
#include "run_command.hpp"

namespace fs = std::filesystem;

namespace {

using litkit_test::CommandRun;
using litkit_test::run_command;

const char* small_scene = R"(
[room]
width = 10
height = 10
depth = 10

[observer]
position = [0, 0, 4]

[lighting]
reflection = "phong"
shading = "phong"

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

class Reliability : public ::testing::Test {
  protected:
    void SetUp() override {
        dir = fs::temp_directory_path() /
              ("litkit-rel-" + std::to_string(::getpid()) + "-" +
               ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
        write("scene.toml", small_scene);
    }
    void TearDown() override { fs::remove_all(dir); }
    void write(const fs::path& name, const std::string& text) {
        std::ofstream(dir / name, std::ios::binary) << text;
    }
    std::string read(const fs::path& name) {
        std::ifstream in(dir / name, std::ios::binary);
        return {std::istreambuf_iterator<char>(in), {}};
    }
    CommandRun cli(const std::string& arguments) { return shell("'" LITKIT_CLI "' " + arguments); }
    CommandRun shell(const std::string& command) {
        // In a subshell, so that run_command's own redirections apply to all of it.
        return run_command("cd '" + dir.string() + "' && ( " + command + " )");
    }
    // The names in the folder other than those given.
    std::vector<std::string> others(std::vector<std::string> expected) {
        std::vector<std::string> found;
        for (const auto& entry : fs::directory_iterator(dir)) {
            const std::string name = entry.path().filename().string();
            if (std::find(expected.begin(), expected.end(), name) == expected.end())
                found.push_back(name);
        }
        return found;
    }
    fs::path dir;
};

bool is_png(const std::string& bytes) { return bytes.rfind("\x89PNG\r\n\x1a\n", 0) == 0; }

// ---- A1: special files are written through, links followed, modes kept ----

TEST_F(Reliability, RenderToANullDeviceWritesThroughAndKeepsTheDevice) {
    ASSERT_EQ(::mknod((dir / "null").c_str(), S_IFCHR | 0666, ::makedev(1, 3)), 0)
        << std::strerror(errno);
    CommandRun run = cli("render scene.toml -o null");
    EXPECT_EQ(run.status, 0) << run.output;
    struct stat status {};
    ASSERT_EQ(::lstat((dir / "null").c_str(), &status), 0);
    EXPECT_TRUE(S_ISCHR(status.st_mode));
    EXPECT_EQ(status.st_rdev, ::makedev(1, 3));
    EXPECT_EQ(others({"scene.toml", "null"}), std::vector<std::string>{});
}

TEST_F(Reliability, RenderThroughASymlinkToADeviceKeepsLinkAndDevice) {
    ASSERT_EQ(::mknod((dir / "null").c_str(), S_IFCHR | 0666, ::makedev(1, 3)), 0);
    fs::create_symlink("null", dir / "link");
    CommandRun run = cli("render scene.toml -o link");
    EXPECT_EQ(run.status, 0) << run.output;
    EXPECT_TRUE(fs::is_symlink(dir / "link"));
    EXPECT_TRUE(fs::is_character_file(dir / "null"));
}

TEST_F(Reliability, RenderToAFifoWritesThroughIt) {
    ASSERT_EQ(::mkfifo((dir / "pipe").c_str(), 0644), 0);
    CommandRun run = shell("{ cat pipe > received.png & } && '" LITKIT_CLI
                           "' render scene.toml -o pipe && wait");
    EXPECT_EQ(run.status, 0) << run.output;
    EXPECT_TRUE(fs::is_fifo(dir / "pipe"));
    EXPECT_EQ(litkit::read_png(dir / "received.png").width, 64);
}

TEST_F(Reliability, RenderThroughASymlinkReplacesItsTargetAndKeepsTheLink) {
    fs::create_directories(dir / "pictures");
    write("pictures/real.png", "old");
    fs::create_symlink("pictures/real.png", dir / "link.png");
    CommandRun run = cli("render scene.toml -o link.png");
    EXPECT_EQ(run.status, 0) << run.output;
    EXPECT_TRUE(fs::is_symlink(dir / "link.png"));
    EXPECT_EQ(litkit::read_png(dir / "pictures/real.png").height, 48);
    EXPECT_EQ(std::distance(fs::directory_iterator(dir / "pictures"), {}), 1);
}

TEST_F(Reliability, AReplacedFileKeepsItsMode) {
    write("out.png", "old");
    ASSERT_EQ(::chmod((dir / "out.png").c_str(), 0600), 0);
    CommandRun run = cli("render scene.toml -o out.png");
    EXPECT_EQ(run.status, 0) << run.output;
    struct stat status {};
    ASSERT_EQ(::stat((dir / "out.png").c_str(), &status), 0);
    EXPECT_EQ(status.st_mode & 07777, 0600u);
    EXPECT_TRUE(is_png(read("out.png")));
}

TEST_F(Reliability, DashWritesThePngToStandardOutputAndMessagesToStandardError) {
    CommandRun run = cli("render scene.toml -o - > stdout.png 2> stderr.txt");
    EXPECT_EQ(run.status, 0) << run.output;
    EXPECT_EQ(litkit::read_png(dir / "stdout.png").width, 64);
    EXPECT_NE(read("stderr.txt").find("litkit: wrote - (64x48"), std::string::npos)
        << read("stderr.txt");
    EXPECT_FALSE(fs::exists(dir / "-"));
}

// /proc/self/fd/1 rather than /dev/stdout: the code before this test would
// have replaced the machine's own /dev/stdout (tests touch no system device);
// under /proc it could only fail.
TEST_F(Reliability, StandardOutputByNameWritesThroughToAPipe) {
    CommandRun run = cli("render scene.toml -o /proc/self/fd/1 2> stderr.txt | cat > piped.png");
    EXPECT_EQ(run.status, 0) << run.output;
    EXPECT_EQ(litkit::read_png(dir / "piped.png").width, 64);
    EXPECT_EQ(read("piped.png").find("litkit: wrote"), std::string::npos);
    EXPECT_NE(read("stderr.txt").find("litkit: wrote /proc/self/fd/1 (64x48"), std::string::npos)
        << read("stderr.txt");
}

// ---- A2: names, folders, signals, size limits, full disks ----

TEST_F(Reliability, ANameOfNameMaxBytesWorks) {
    const std::string name = std::string(251, 'a') + ".png";  // 255 bytes: NAME_MAX
    CommandRun run = cli("render scene.toml -o " + name);
    EXPECT_EQ(run.status, 0) << run.output;
    EXPECT_TRUE(is_png(read(name)));
    EXPECT_EQ(others({"scene.toml", name}), std::vector<std::string>{});
}

TEST_F(Reliability, AFolderAsOutputGetsAClearMessage) {
    fs::create_directories(dir / "existing");
    CommandRun slash = cli("render scene.toml -o existing/");
    EXPECT_EQ(slash.status, 1);
    EXPECT_NE(
        slash.output.find("error: cannot write 'existing/': is a folder; name a file to write"),
        std::string::npos)
        << slash.output;
    CommandRun bare = cli("render scene.toml -o existing");
    EXPECT_EQ(bare.status, 1);
    EXPECT_NE(bare.output.find("error: cannot write 'existing': is a folder; name a file to write"),
              std::string::npos)
        << bare.output;
    CommandRun missing = cli("render scene.toml -o missing/");
    EXPECT_EQ(missing.status, 1);
    EXPECT_NE(
        missing.output.find(
            "error: cannot write 'missing/': names a folder (ends with '/'); name a file to write"),
        std::string::npos)
        << missing.output;
    EXPECT_EQ(others({"scene.toml", "existing"}), std::vector<std::string>{});
    EXPECT_TRUE(fs::is_empty(dir / "existing"));
}

TEST_F(Reliability, AFileSizeLimitLeavesNoTemporaryFile) {
    write("out.png", "old picture");
    // dash counts ulimit -f in 512-byte blocks: 1 block is less than the PNG.
    CommandRun run = shell("ulimit -f 1 && '" LITKIT_CLI "' render scene.toml -o out.png");
    EXPECT_EQ(run.status, 1) << run.output;
    EXPECT_NE(run.output.find("File too large"), std::string::npos) << run.output;
    EXPECT_EQ(read("out.png"), "old picture");
    EXPECT_EQ(others({"scene.toml", "out.png"}), std::vector<std::string>{});
}

// A full disk: a 64 KiB tmpfs mounted in the temporary folder (root only).
TEST_F(Reliability, AFullDiskLeavesNoTemporaryFileAndTheOldFile) {
    const fs::path small = dir / "small";
    fs::create_directories(small);
    ASSERT_EQ(::mount("tmpfs", small.c_str(), "tmpfs", 0, "size=64k"), 0) << std::strerror(errno);
    std::ofstream(small / "out.png") << "old picture";
    CommandRun run = cli("render scene.toml --width 1024 --height 1024 -o small/out.png");
    std::vector<std::string> left;
    for (const auto& entry : fs::directory_iterator(small))
        left.push_back(entry.path().filename().string());
    std::string old;
    {
        std::ifstream in(small / "out.png");
        old.assign(std::istreambuf_iterator<char>(in), {});
    }
    ::umount(small.c_str());
    EXPECT_EQ(run.status, 1) << run.output;
    EXPECT_NE(run.output.find("No space left on device"), std::string::npos) << run.output;
    EXPECT_EQ(left, std::vector<std::string>{"out.png"});
    EXPECT_EQ(old, "old picture");
}

// Starts litkit on a large picture, waits (inotify) for the temporary file
// to appear, stops the process, and sends `signal_number` only if the
// picture has not been renamed into place yet. True when the signal came
// during the write; then the process must have died of it, leaving nothing.
bool signal_during_write(const fs::path& dir, int signal_number, std::string& problem) {
    const int watch = ::inotify_init1(IN_CLOEXEC);
    if (watch < 0 || ::inotify_add_watch(watch, dir.c_str(), IN_CREATE) < 0) {
        problem = "inotify";
        return false;
    }
    const pid_t child = ::fork();
    if (child == 0) {
        if (::chdir(dir.c_str()) != 0) ::_exit(127);
        ::signal(signal_number, SIG_DFL);
        const int null = ::open("/dev/null", O_RDWR);
        ::dup2(null, 0);
        ::dup2(null, 1);
        ::dup2(null, 2);
        ::execl(LITKIT_CLI, LITKIT_CLI, "render", "scene.toml", "--width", "4096", "--height",
                "4096", "-o", "out.png", static_cast<char*>(nullptr));
        ::_exit(127);
    }
    bool stopped = false;
    alignas(inotify_event) char buffer[4096];
    while (!stopped) {
        const ssize_t n = ::read(watch, buffer, sizeof buffer);
        if (n <= 0) break;
        for (ssize_t at = 0; at < n;) {
            const auto* event = reinterpret_cast<const inotify_event*>(buffer + at);
            if (event->len && std::string(event->name).rfind(".litkit-", 0) == 0) {
                ::kill(child, SIGSTOP);
                stopped = true;
            }
            at += static_cast<ssize_t>(sizeof(inotify_event) + event->len);
        }
    }
    ::close(watch);
    int status = 0;
    if (!stopped) {
        ::waitpid(child, &status, 0);
        problem = "no temporary file seen";
        return false;
    }
    ::waitpid(child, &status, WUNTRACED);  // until it has stopped
    const bool renamed = fs::exists(dir / "out.png");
    ::kill(child, renamed ? SIGCONT : signal_number);
    if (!renamed) ::kill(child, SIGCONT);
    ::waitpid(child, &status, 0);
    if (renamed) {
        fs::remove(dir / "out.png");
        return false;
    }
    if (!WIFSIGNALED(status) || WTERMSIG(status) != signal_number)
        problem = "the process did not die of the signal (status " + std::to_string(status) + ")";
    return true;
}

void expect_signal_leaves_nothing(const fs::path& dir, int signal_number) {
    bool caught = false;
    for (int attempt = 0; attempt < 10 && !caught; ++attempt) {
        std::string problem;
        caught = signal_during_write(dir, signal_number, problem);
        if (caught) {
            EXPECT_EQ(problem, "");
        }
    }
    ASSERT_TRUE(caught) << "the signal never came before the rename in 10 runs";
    // The signal may have been held while the finished picture was renamed
    // into place (the write is short without fsync): then out.png is there,
    // whole. What must never be left is a temporary file or a partial picture.
    std::vector<std::string> left;
    for (const auto& entry : fs::directory_iterator(dir))
        left.push_back(entry.path().filename().string());
    std::sort(left.begin(), left.end());
    if (left.size() == 2 && left[0] == "out.png") {
        EXPECT_EQ(litkit::read_png(dir / "out.png").width, 4096);  // whole, or read_png throws
        left.erase(left.begin());
    }
    EXPECT_EQ(left, std::vector<std::string>{"scene.toml"});
}

TEST_F(Reliability, SigtermDuringTheWriteLeavesNoTemporaryFile) {
    expect_signal_leaves_nothing(dir, SIGTERM);
}

TEST_F(Reliability, SigintDuringTheWriteLeavesNoTemporaryFile) {
    expect_signal_leaves_nothing(dir, SIGINT);
}

// ---- A3: export never writes over its inputs, and writes its folder whole ----

TEST_F(Reliability, ExportRefusesToWriteOverTheSceneItExports) {
    fs::create_directories(dir / "e");
    write("e/main.cpp", small_scene);
    for (const std::string force : {"", " --force"}) {
        CommandRun run = cli("export --format cpp e/main.cpp -o e" + force);
        EXPECT_EQ(run.status, 2) << run.output;
        EXPECT_NE(run.output.find("error: refusing to write 'e/main.cpp' over input file "
                                  "'e/main.cpp'; choose another folder with -o"),
                  std::string::npos)
            << run.output;
        EXPECT_EQ(read("e/main.cpp"), small_scene);
        EXPECT_FALSE(fs::exists(dir / "e/CMakeLists.txt"));
    }
}

// Mounts a 64 KiB tmpfs at dir/small; the generated program is larger.
class SmallDisk : public Reliability {
  protected:
    void SetUp() override {
        Reliability::SetUp();
        small = dir / "small";
        fs::create_directories(small);
        mounted = ::mount("tmpfs", small.c_str(), "tmpfs", 0, "size=64k") == 0;
        ASSERT_TRUE(mounted) << std::strerror(errno);
    }
    void TearDown() override {
        if (mounted) ::umount(small.c_str());
        Reliability::TearDown();
    }
    std::vector<std::string> listing(const fs::path& folder) {
        std::vector<std::string> names;
        for (const auto& entry : fs::directory_iterator(folder))
            names.push_back(entry.path().filename().string());
        std::sort(names.begin(), names.end());
        return names;
    }
    fs::path small;
    bool mounted = false;
};

TEST_F(SmallDisk, ExportOnAFullDiskCreatesNoFolder) {
    CommandRun run = cli("export --format cpp scene.toml -o small/program");
    EXPECT_EQ(run.status, 1) << run.output;
    EXPECT_NE(run.output.find("No space left on device"), std::string::npos) << run.output;
    EXPECT_EQ(listing(small), std::vector<std::string>{});
}

TEST_F(SmallDisk, ExportWithForceOnAFullDiskKeepsBothOldFiles) {
    fs::create_directories(small / "program");
    std::ofstream(small / "program/main.cpp") << "old main";
    std::ofstream(small / "program/CMakeLists.txt") << "old cmake";
    CommandRun run = cli("export --format cpp scene.toml -o small/program --force");
    EXPECT_EQ(run.status, 1) << run.output;
    EXPECT_NE(run.output.find("No space left on device"), std::string::npos) << run.output;
    EXPECT_EQ(listing(small / "program"), (std::vector<std::string>{"CMakeLists.txt", "main.cpp"}));
    EXPECT_EQ(read("small/program/main.cpp"), "old main");
    EXPECT_EQ(read("small/program/CMakeLists.txt"), "old cmake");
}

TEST_F(Reliability, ExportIntoAnExistingFolderReplacesBothAndKeepsOtherFiles) {
    fs::create_directories(dir / "program");
    write("program/main.cpp", "old main");
    write("program/notes.txt", "mine");
    ASSERT_EQ(::chmod((dir / "program/main.cpp").c_str(), 0600), 0);
    CommandRun run = cli("export --format cpp scene.toml -o program --force");
    EXPECT_EQ(run.status, 0) << run.output;
    EXPECT_NE(read("program/main.cpp").find("int main("), std::string::npos);
    EXPECT_NE(read("program/CMakeLists.txt").find("add_executable(scene main.cpp)"),
              std::string::npos);
    EXPECT_EQ(read("program/notes.txt"), "mine");
    struct stat status {};
    ASSERT_EQ(::stat((dir / "program/main.cpp").c_str(), &status), 0);
    EXPECT_EQ(status.st_mode & 07777, 0600u);
    EXPECT_EQ(std::distance(fs::directory_iterator(dir / "program"), {}), 3);
}

// ---- B4: nesting is bounded before toml++ recurses ----

TEST_F(Reliability, ATableHeaderOf50000PartsIsRefusedWhereItGoesTooDeep) {
    std::string header = "[a";
    for (int i = 1; i < 50000; ++i) header += ".a";
    write("deep.toml", header + "]\n");
    CommandRun run = cli("check deep.toml");
    EXPECT_EQ(run.status, 1) << run.output;
    // '[' is one level and each dot one more: the 64th dot, at column 129, is level 65.
    EXPECT_EQ(run.output,
              "deep.toml:1:129: error: cannot read 'deep.toml': nested deeper than 64 "
              "levels (tables, arrays and dotted keys; docs/reliability.md)\n");
}

TEST_F(Reliability, DeepDottedKeysArraysAndInlineTablesAreRefused) {
    std::string key = "a";
    for (int i = 1; i < 50000; ++i) key += ".a";
    write("key.toml", key + " = 1\n");
    write("arrays.toml", "x = " + std::string(50000, '[') + std::string(50000, ']') + "\n");
    std::string tables = "x = ";
    for (int i = 0; i < 50000; ++i) tables += "{a = ";
    write("tables.toml", tables + "1" + std::string(50000, '}') + "\n");
    // The 65th level: the 65th dot of the key (column 130); the 65th '['
    // (column 4 + 65); the 65th '{' (column 4 + 64 * 5 + 1).
    const std::pair<const char*, const char*> cases[] = {{"key.toml", "key.toml:1:130:"},
                                                         {"arrays.toml", "arrays.toml:1:69:"},
                                                         {"tables.toml", "tables.toml:1:325:"}};
    for (const auto& [file, place] : cases) {
        CommandRun run = cli(std::string("check ") + file);
        EXPECT_EQ(run.status, 1) << run.output;
        EXPECT_EQ(run.output.rfind(std::string(place) + " error: cannot read '" + file +
                                       "': nested deeper than 64 levels",
                                   0),
                  0u)
            << run.output;
    }
}

TEST_F(Reliability, BracketsAndDotsInStringsAndCommentsAreNotNesting) {
    std::string scene = small_scene;
    scene +=
        "# " + std::string(200, '[') + " a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a\n";
    std::string name = "name = \"" + std::string(100, '[');
    for (int i = 0; i < 100; ++i) name += "a.";
    scene += name + "\"\n";
    scene += "[output.background]\n";  // not a scene key: a located SceneError, not a nesting one
    write("strings.toml", scene);
    CommandRun run = cli("check strings.toml");
    EXPECT_EQ(run.output.find("nested deeper"), std::string::npos) << run.output;
    EXPECT_EQ(run.status, 2) << run.output;
}

TEST_F(Reliability, NestingAtTheLimitIsReadByToml) {
    std::string header = "[a";
    for (int i = 1; i < 64; ++i) header += ".a";
    write("limit.toml", header + "]\nx = 1\n");
    CommandRun run = cli("check limit.toml");
    EXPECT_EQ(run.output.find("nested deeper"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("limit.toml:1:2: error:"), std::string::npos) << run.output;
}

// ---- B5: input files are bounded; pipes and standard input work ----

TEST_F(Reliability, AZeroDeviceAsTheSceneIsRefusedQuicklyWithItsName) {
    ASSERT_EQ(::mknod((dir / "zero").c_str(), S_IFCHR | 0666, ::makedev(1, 5)), 0);
    // The message is the proof that reading stopped at the limit (without it
    // the read goes on until memory runs out); no timing is asserted, as a
    // busy machine reads 256 MiB slowly.
    CommandRun run = cli("check zero");
    EXPECT_EQ(run.status, 1) << run.output;
    EXPECT_EQ(run.output,
              "error: cannot read 'zero': larger than the limit of 256 MiB for scene "
              "and mesh files (docs/reliability.md)\n");
}

TEST_F(Reliability, AZeroDeviceAsTheMeshIsRefusedWithItsName) {
    ASSERT_EQ(::mknod((dir / "zero").c_str(), S_IFCHR | 0666, ::makedev(1, 5)), 0);
    write("mesh.toml", std::string(small_scene) +
                           "[[objects]]\ntype = \"mesh\"\nfile = \"zero\"\nposition = [3, 0, 0]\n");
    CommandRun run = cli("check mesh.toml");
    EXPECT_EQ(run.status, 1) << run.output;
    // Located at the scene's `file` key (line 28), as a mesh file that cannot be opened.
    EXPECT_EQ(run.output,
              "mesh.toml:28:8: error: cannot read 'zero': larger than the limit of "
              "256 MiB for scene and mesh files (docs/reliability.md)\n");
}

TEST_F(Reliability, ARegularFileOverTheLimitIsRefusedWithoutReadingIt) {
    std::filesystem::resize_file((write("big.toml", ""), dir / "big.toml"), (256u << 20) + 1);
    CommandRun run = cli("check big.toml");
    EXPECT_EQ(run.status, 1) << run.output;
    EXPECT_NE(run.output.find("cannot read 'big.toml': larger than the limit of 256 MiB"),
              std::string::npos)
        << run.output;
}

TEST_F(Reliability, AFifoAndStandardInputStillWork) {
    ASSERT_EQ(::mkfifo((dir / "pipe").c_str(), 0644), 0);
    CommandRun fifo = shell("{ cat scene.toml > pipe & } && '" LITKIT_CLI "' check pipe && wait");
    EXPECT_EQ(fifo.status, 0) << fifo.output;
    EXPECT_EQ(fifo.output, "ok\n");
    CommandRun dash = shell("'" LITKIT_CLI "' check - < scene.toml");
    EXPECT_EQ(dash.status, 0) << dash.output;
    EXPECT_EQ(dash.output, "ok\n");
    CommandRun render = shell("'" LITKIT_CLI "' render - -o piped.png < scene.toml");
    EXPECT_EQ(render.status, 0) << render.output;
    EXPECT_EQ(litkit::read_png(dir / "piped.png").width, 64);
    CommandRun named = shell("'" LITKIT_CLI "' render - < scene.toml");
    EXPECT_EQ(named.status, 0) << named.output;
    EXPECT_EQ(litkit::read_png(dir / "stdin.png").width, 64);
}

// ---- B6: OBJ numbers are exact or a located error ----

TEST_F(Reliability, BadObjNumbersAreLocatedErrors) {
    write("mesh.toml",
          std::string(small_scene) +
              "[[objects]]\ntype = \"mesh\"\nfile = \"mesh.obj\"\nposition = [3, 0, 0]\n");
    const std::string after = " (objects[1].file at mesh.toml:28:8)\n";
    const std::pair<std::string, std::string> cases[] = {
        {"v nan 0 0", "mesh.obj:3:3: error: cannot read '" + std::string("mesh.obj") +
                          "': vertex x coordinate 'nan' is not a finite number"},
        {"v 0 inf 0", "mesh.obj:3:5: error: cannot read '" + std::string("mesh.obj") +
                          "': vertex y coordinate 'inf' is not a finite number"},
        {"v abc def ghi", "mesh.obj:3:3: error: cannot read '" + std::string("mesh.obj") +
                              "': vertex x coordinate 'abc' is not a number"},
        {"v 1", "mesh.obj:3:4: error: cannot read '" + std::string("mesh.obj") +
                    "': vertex needs 3 coordinates, found 1"},
        {"v 0,5 -0,5 0,5", "mesh.obj:3:3: error: cannot read '" + std::string("mesh.obj") +
                               "': vertex x coordinate '0,5' is not a number (write the decimal "
                               "separator as a point: '.')"},
        {"v 0 0 1e999",
         "mesh.obj:3:7: error: cannot read '" + std::string("mesh.obj") +
             "': vertex z coordinate '1e999' is beyond the range of numbers litkit reads"},
        // Skin weights (tinyobjloader's "vw"), whose joints it makes ints
        // unchecked: fuzz_obj found "vw 1 1e9990" (docs/reliability.md).
        {"vw 1 1e9990 0.5", "mesh.obj:3:6: error: cannot read '" + std::string("mesh.obj") +
                                "': vertex weight's joint '1e9990' is not a joint number (0 to "
                                "2147483520)"},
        {"vw 1 3e9 0.5", "mesh.obj:3:6: error: cannot read '" + std::string("mesh.obj") +
                             "': vertex weight's joint '3e9' is not a joint number (0 to "
                             "2147483520)"},
        {"vw 1.5 2 0.5", "mesh.obj:3:4: error: cannot read '" + std::string("mesh.obj") +
                             "': vertex weight's vertex '1.5' is not a vertex number (0 to "
                             "2147483647)"},
        // tinyobjloader's number reader overflows an int on an exponent of
        // 2147483648 or 2147483649 (fuzz_obj found "12e214748364838"), in
        // every line it reads reals from: weights and tags too.
        {"vw 1 2 12e2147483648", "mesh.obj:3:8: error: cannot read '" + std::string("mesh.obj") +
                                     "': vertex weight's weight '12e2147483648' is beyond the "
                                     "range of numbers litkit reads"},
        {"t name 0/1/0 -.E+0002147483649",
         "mesh.obj:3:14: error: cannot read '" + std::string("mesh.obj") +
             "': tag value '-.E+0002147483649' is beyond the range of numbers litkit reads"},
        // A zero with such an exponent is 0 for std::from_chars, not for
        // tinyobjloader; a joint that rounds to 2^31 as a float; a face
        // index whose negation overflows; a coordinate beyond a float.
        {"v 0e2147483648 0 0", "mesh.obj:3:3: error: cannot read '" + std::string("mesh.obj") +
                                   "': vertex x coordinate '0e2147483648' is beyond the range of "
                                   "numbers litkit reads"},
        {"vw 1 2147483600 0.5", "mesh.obj:3:6: error: cannot read '" + std::string("mesh.obj") +
                                    "': vertex weight's joint '2147483600' is not a joint number "
                                    "(0 to 2147483520)"},
        {"f -9223372036854775808 1 2",
         "mesh.obj:3:3: error: cannot read '" + std::string("mesh.obj") +
             "': face 1 refers to vertex -9223372036854775808, but the file defines 2 vertices "
             "before it"},
        {"v 1e39 0 0", "mesh.obj:3:3: error: cannot read '" + std::string("mesh.obj") +
                           "': vertex x coordinate '1e39' is beyond the range of numbers litkit "
                           "reads"},
        {"vw 1 2 -1e39", "mesh.obj:3:8: error: cannot read '" + std::string("mesh.obj") +
                             "': vertex weight's weight '-1e39' is beyond the range of numbers "
                             "litkit reads"},
        // tinyobjloader makes a zero mantissa with an exponent of 442 or
        // more 0 * 5^e = NaN, where std::from_chars reads 0: fuzz_obj found
        // the joint (a NaN made an int); a coordinate too.
        {"vw 0 1  in) 00e7066", "mesh.obj:3:13: error: cannot read '" + std::string("mesh.obj") +
                                    "': vertex weight's joint '00e7066' is not a joint number (0 "
                                    "to 2147483520)"},
        {"v 0 0e442 0", "mesh.obj:3:5: error: cannot read '" + std::string("mesh.obj") +
                            "': vertex y coordinate '0e442' is beyond the range of numbers litkit "
                            "reads"},
        {"vn 0 0 .0e999", "mesh.obj:3:8: error: cannot read '" + std::string("mesh.obj") +
                              "': normal z coordinate '.0e999' is beyond the range of numbers "
                              "litkit reads"},
        // A lone carriage return ends a line, for tinyobjloader and so for
        // litkit: the vertex is line 4.
        {"s 1\rv 0 0 12e214748364838",
         "mesh.obj:4:7: error: cannot read '" + std::string("mesh.obj") +
             "': vertex z coordinate '12e214748364838' is beyond the range of numbers litkit "
             "reads"},
    };
    for (const auto& [line, expected] : cases) {
        write("mesh.obj", "v 0 0 0\nv 1 0 0\n" + line + "\nf 1 2 3\n");
        CommandRun run = cli("check mesh.toml");
        EXPECT_EQ(run.status, 1) << line;
        // The mesh file's path is resolved against the scene's folder.
        EXPECT_EQ(run.output, expected + after) << line;
    }
    // The same lines one digit short of the overflow are read (there
    // tinyobjloader's weight or tag real is 0 · ∞, not a number, and litkit
    // uses neither), as are a tag's name and counts that would be beyond
    // the range as reals, and the largest joint.
    for (const char* line : {"vw 1 2 0e2147483647", "t name 0/1/0 -.E+0002147483647",
                             "t 1e2147483648 1e2147483648/0/0", "vw 1 2147483520 0.5",
                             "vw 1 2 0e500x", "t name 0/1/0 -0e600", "v 0 0e441 0"}) {
        write("mesh.obj", "v 0 0 0\nv 1 0 0\n" + std::string(line) + "\nv 0 1 0\nf 1 2 3\n");
        CommandRun run = cli("check mesh.toml");
        EXPECT_EQ(run.status, 0) << line << run.output;
    }
}

TEST_F(Reliability, ObjLinesEndWhereTinyobjloaderEndsThem) {
    write("mesh.toml",
          std::string(small_scene) +
              "[[objects]]\ntype = \"mesh\"\nfile = \"mesh.obj\"\nposition = [3, 0, 0]\n");
    // An old Mac file (lone carriage returns) is read line by line: before,
    // litkit's check saw one line and called its "f" a vertex coordinate.
    write("mesh.obj", "v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 3\r");
    CommandRun good = cli("check mesh.toml");
    EXPECT_EQ(good.status, 0) << good.output;
    const litkit::Mesh mesh = litkit::load_obj(dir / "mesh.obj");
    EXPECT_EQ(mesh.positions.size(), 3u);
    ASSERT_EQ(mesh.triangles.size(), 1u);
    EXPECT_EQ(mesh.triangles[0], (std::array<std::uint32_t, 3>{0, 1, 2}));
    // Errors count lines the same way, in litkit's check and in the face
    // lookup that places tinyobjloader's own complaints.
    write("mesh.obj", "v 0 0 0\r\nv 1 0 0\rv 0 1 0\n\rf 1 2 9\r");
    CommandRun bad = cli("check mesh.toml");
    EXPECT_EQ(bad.status, 1);
    EXPECT_EQ(bad.output,
              "mesh.obj:5:7: error: cannot read 'mesh.obj': face 1 refers to vertex 9, "
              "but the file defines 3 vertices (objects[1].file at mesh.toml:28:8)\n");
    write("mesh.obj", "v 0 0 0\rv 1 0 0\r\rv 0 1 0\rf 1 2 3\rf 1 2\rf 3 2 1\r");
    EXPECT_EQ(litkit::line_of_face(dir / "mesh.obj", 0), 5u);
    EXPECT_EQ(litkit::line_of_face(dir / "mesh.obj", 1), 7u);
    EXPECT_EQ(litkit::line_of_face(dir / "mesh.obj", 2), 0u);
}

TEST_F(Reliability, FaceIndicesOutOfRangeAreLocatedErrors) {
    write("mesh.toml",
          std::string(small_scene) +
              "[[objects]]\ntype = \"mesh\"\nfile = \"mesh.obj\"\nposition = [3, 0, 0]\n");
    const std::string path = "mesh.obj";
    const std::pair<std::string, std::string> cases[] = {
        {"f 1 2 -4",
         path + ":4:7: error: cannot read '" + path +
             "': face 1 refers to vertex -4, but the file defines 3 vertices before it"},
        {"f 1 2 3/1", path + ":4:9: error: cannot read '" + path +
                          "': face 1 refers to texture coordinate 1, but the file defines 0 "
                          "texture coordinates"},
        {"f 1 2 x", path + ":4:7: error: cannot read '" + path +
                        "': face corner 'x': 'x' is not a vertex number (1, 2, … or -1, -2, …)"},
    };
    for (const auto& [line, expected] : cases) {
        write("mesh.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n" + line + "\n");
        CommandRun run = cli("check mesh.toml");
        EXPECT_EQ(run.status, 1) << line;
        EXPECT_EQ(run.output, expected + " (objects[1].file at mesh.toml:28:8)\n") << line;
    }
    write("mesh.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -1\n");
    EXPECT_EQ(cli("check mesh.toml").status, 0);
}

// ---- B7: messages tell the truth, one problem per line ----

// small_scene with lines added at the end of [observer] (from line 10) and
// to the sphere (from line 26).
std::string scene_with(const std::string& observer_extra, const std::string& sphere_extra) {
    std::string scene = small_scene;
    scene.insert(scene.find("[lighting]"), observer_extra);
    return scene + sphere_extra;
}

TEST_F(Reliability, AScaleTooSmallForAFloatIsReportedAsWritten) {
    write("tiny.toml", scene_with("", "scale = 1e-50\n"));
    CommandRun run = cli("check tiny.toml");
    EXPECT_EQ(run.status, 2);
    EXPECT_EQ(run.output,
              "tiny.toml:26:9: error: objects[0]: scale 1e-50 is too small (closest to "
              "0 a scene holds: 1.401298464324817e-45; write 0 for zero)\n");
}

TEST_F(Reliability, FarAndNearAreComparedAsWritten) {
    write("same.toml", scene_with("near = 5\nfar = 5.0000001\n\n", ""));
    CommandRun same = cli("check same.toml");
    EXPECT_EQ(same.status, 2);
    EXPECT_EQ(same.output,
              "same.toml:11:7: error: observer: far (5.0000001) and near (5) are the "
              "same 32-bit float (5); make far greater than near by more than that "
              "precision\n");
    write("below.toml", scene_with("near = 5\nfar = 4.9999999\n\n", ""));
    CommandRun below = cli("check below.toml");
    EXPECT_EQ(below.status, 2);
    EXPECT_EQ(below.output,
              "below.toml:11:7: error: observer: far (4.9999999) must be greater than "
              "near (5)\n");
    write("apart.toml", scene_with("near = 5\nfar = 5.001\n\n", ""));
    CommandRun apart = cli("check apart.toml");
    EXPECT_EQ(apart.status, 0) << apart.output;
    EXPECT_EQ(apart.output.find("far"), std::string::npos) << apart.output;
}

TEST_F(Reliability, ControlCharactersInNamesAndPathsAreEscaped) {
    // A name that would otherwise print a second, forged diagnostic line.
    const std::string forged = "name = \"x\\nforged.toml:1:1: error: forged\\u0007\"\n";
    std::string scene = small_scene;
    scene.insert(scene.find("[[objects]]"), forged);  // the light
    write("names.toml", scene + forged);              // and the sphere: a duplicate
    CommandRun run = cli("check names.toml");
    EXPECT_EQ(run.status, 2);
    EXPECT_EQ(run.output,
              "names.toml:27:8: error: objects[0]: name 'x\\nforged.toml:1:1: error: "
              "forged\\x07' is already used by lights[0]\n");
    write("path.toml",
          std::string(small_scene) +
              "[[objects]]\ntype = \"mesh\"\nfile = \"no\\nsuch.obj\"\nposition = [3, 0, 0]\n");
    CommandRun path = cli("check path.toml");
    EXPECT_EQ(path.status, 1);
    EXPECT_EQ(path.output,
              "path.toml:28:8: error: cannot read 'no\\nsuch.obj': No such file or "
              "directory\n");
}

// ---- B8: directions and the view at any scale ----

std::string lights_with_direction(const std::string& length) {
    std::string scene = small_scene;
    scene.resize(scene.find("[[lights]]"));
    return scene + "[[lights]]\ntype = \"directional\"\ndirection = [" + length + ", -" + length +
           ", -" + length +
           "]\n[[lights]]\ntype = \"spot\"\nposition = [0, 3, 3]\ndirection = [0, -" + length +
           ", -" + length +
           "]\ncutoff = 40\nintensity = 5\n[[objects]]\ntype = "
           "\"sphere\"\nradius = 1\n";
}

TEST_F(Reliability, TinyAndHugeDirectionsDrawWhatUnitDirectionsDraw) {
    write("unit.toml", lights_with_direction("1"));
    write("tiny.toml", lights_with_direction("1e-30"));  // squared: 0 as a float
    write("huge.toml", lights_with_direction("1e30"));   // squared: infinite as a float
    for (const char* name : {"unit", "tiny", "huge"}) {
        const CommandRun run = cli(std::string("render ") + name + ".toml -o " + name + ".png");
        ASSERT_EQ(run.status, 0) << run.output;
    }
    const litkit::Image unit = litkit::read_png(dir / "unit.png");
    EXPECT_EQ(litkit::read_png(dir / "tiny.png").rgb, unit.rgb);
    EXPECT_EQ(litkit::read_png(dir / "huge.png").rgb, unit.rgb);
}

TEST_F(Reliability, AViewOfLength4e19IsNotCalledParallelToUp) {
    // small_scene scaled by 1e19: the view's squared length overflows a float.
    // (near and far scaled too: at their defaults the sphere, 3e19 away, is
    // beyond far = 1000, which check rightly warns of.)
    write("big.toml",
          "[room]\nwidth = 1e20\nheight = 1e20\ndepth = 1e20\n[observer]\n"
          "position = [0, 0, 4e19]\nnear = 5e17\nfar = 1e22\n[lighting]\nreflection = "
          "\"phong\"\nshading = "
          "\"phong\"\n[[lights]]\ntype = \"directional\"\ndirection = [1, -1, -1]\n"
          "[[objects]]\ntype = \"sphere\"\nradius = 1e19\n");
    const CommandRun run = cli("check big.toml");
    EXPECT_EQ(run.status, 0) << run.output;
    EXPECT_EQ(run.output, "ok\n");
    // And a truly parallel up is still refused at that scale.
    write("parallel.toml",
          "[room]\nwidth = 1e20\nheight = 1e20\ndepth = 1e20\n[observer]\n"
          "position = [0, 0, 4e19]\nup = [0, 0, 1e-30]\n[lighting]\nreflection = "
          "\"phong\"\nshading = \"phong\"\n[[lights]]\ntype = \"directional\"\n"
          "direction = [1, -1, -1]\n[[objects]]\ntype = \"sphere\"\nradius = 1e19\n");
    const CommandRun parallel = cli("check parallel.toml");
    EXPECT_EQ(parallel.status, 2);
    EXPECT_EQ(parallel.output,
              "parallel.toml:7:6: error: observer: up [0, 0, 1e-30] is parallel to "
              "the view direction [0, 0, -4e+19]\n");
}

// ---- C9: the hashed duplicate check and the broad phase find what the
// pairwise loops found (their speed is measured by bench/check-scale.sh) ----

TEST_F(Reliability, EveryLightAtAnEarlierLightsPlaceIsReported) {
    std::string scene = small_scene;
    for (int i = 0; i < 3; ++i)  // lights[1..3] at one place; -0 is the same place as 0
        scene += std::string("[[lights]]\ntype = \"point\"\nposition = [") + (i == 1 ? "-0" : "0") +
                 ", 3, -3]\nintensity = 1\n";
    write("lights.toml", scene);
    CommandRun run = cli("check lights.toml");
    EXPECT_EQ(run.status, 2);
    EXPECT_EQ(run.output,
              "lights.toml:32:12: error: lights[2]: position [0, 3, -3] is also the position of "
              "lights[1]\n"
              "lights.toml:36:12: error: lights[3]: position [0, 3, -3] is also the position of "
              "lights[1]\n"
              "lights.toml:36:12: error: lights[3]: position [0, 3, -3] is also the position of "
              "lights[2]\n");
}

TEST_F(Reliability, OverlapsAmongManyObjectsAreAllFoundInOrder) {
    std::string scene = small_scene;
    scene.replace(scene.find("width = 10"), 10, "width = 400");
    // 200 spheres in a row, 2 apart (touching none), and two that overlap
    // objects 50 and 120 (placed at x = -199 + 2i).
    for (int i = 0; i < 200; ++i)
        scene +=
            "[[objects]]\ntype = \"sphere\"\nradius = 0.5\nsegments = 8\nrings = 4\n"
            "position = [" +
            std::to_string(-199 + 2 * i) + ", 0, -2]\n";
    for (const int x : {-199 + 2 * 120, -199 + 2 * 50})
        scene += "[[objects]]\ntype = \"cube\"\nsize = 0.5\nposition = [" + std::to_string(x) +
                 ".25, 0, -2]\n";
    write("many.toml", scene);
    CommandRun run = cli("check many.toml");
    EXPECT_EQ(run.status, 2);
    // objects[201] (x = 41.25) overlaps objects[121] (x = 41); objects[202]
    // (x = -98.75) overlaps objects[51] (x = -99).
    EXPECT_NE(run.output.find("error: objects[201]: overlaps objects[121]\n"), std::string::npos)
        << run.output;
    EXPECT_NE(run.output.find("error: objects[202]: overlaps objects[51]\n"), std::string::npos)
        << run.output;
    std::size_t errors = 0;  // (most spheres are outside the view: warnings)
    for (std::size_t at = run.output.find("error:"); at != std::string::npos;
         at = run.output.find("error:", at + 1))
        ++errors;
    EXPECT_EQ(errors, 2u) << run.output;
    EXPECT_EQ(run.output.find("objects[0]: overlaps"), std::string::npos) << run.output;
}

// ---- C10: a scene-wide triangle budget, and no bad_alloc text ----

std::string eight_tori() {
    std::string scene = small_scene;
    scene.resize(scene.find("[[objects]]"));
    for (int i = 0; i < 8; ++i)
        scene += "[[objects]]\nname = \"ring" + std::to_string(i) +
                 "\"\ntype = \"torus\"\nmajor_radius = 0.3\nminor_radius = 0.05\nsegments = "
                 "4096\nsides = 4096\nposition = [" +
                 std::to_string(i - 4) + ".5, 0, -2]\n";
    return scene;
}

TEST_F(Reliability, EightToriAtTheMaximumTessellationAreRefusedBeforeAnythingIsBuilt) {
    write("tori.toml", eight_tori());
    // 8 × 2 × 4096 × 4096 = 268,435,456 triangles; located at the largest
    // (the first of equals), objects[0]'s table on line 23.
    const std::string expected =
        "tori.toml:23:1: error: objects[0] 'ring0': the objects need 268,435,456 triangles "
        "together, more than the budget of 64,000,000 (object 'ring0' 33,554,432, object 'ring1' "
        "33,554,432, object 'ring2' 33,554,432, object 'ring3' 33,554,432, object 'ring4' "
        "33,554,432 and 3 more); lower their tessellation, or raise the budget with "
        "--max-triangles (docs/reliability.md)\n";
    for (const char* command : {"check tori.toml", "render tori.toml -o tori.png"}) {
        // Memory limited to 1 GiB: building anything would fail. (Not under
        // ASan, which reserves more address space than that to start.)
#if defined(LITKIT_SANITIZED)
        const std::string limit;
#else
        const std::string limit = "ulimit -v 1048576 && ";
#endif
        CommandRun run = shell(limit + "'" LITKIT_CLI "' " + command);
        EXPECT_EQ(run.status, 2) << command;
        EXPECT_EQ(run.output, expected) << command;
    }
    EXPECT_FALSE(fs::exists(dir / "tori.png"));
}

TEST_F(Reliability, MaxTrianglesSetsTheBudget) {
    // The sphere of small_scene: 2 × 64 × 31 = 3,968 triangles.
    CommandRun low = cli("check scene.toml --max-triangles 3967");
    EXPECT_EQ(low.status, 2);
    EXPECT_NE(low.output.find("error: objects[0]: the objects need 3,968 triangles together, "
                              "more than the budget of 3,967 (objects[0] 3,968)"),
              std::string::npos)
        << low.output;
    EXPECT_EQ(cli("check scene.toml --max-triangles 3968").status, 0);
    CommandRun render = cli("render scene.toml --max-triangles 3967 -o out.png");
    EXPECT_EQ(render.status, 2) << render.output;
}

TEST_F(Reliability, RunningOutOfMemorySaysWhatWasBeingBuilt) {
#if defined(LITKIT_SANITIZED)
    GTEST_SKIP() << "ASan reserves more address space than ulimit -v allows";
#else
    write("tori.toml", eight_tori());
    CommandRun run = shell("ulimit -v 1048576 && '" LITKIT_CLI
                           "' render tori.toml --max-triangles 1000000000 -o tori.png");
    EXPECT_EQ(run.status, 1) << run.output;
    EXPECT_EQ(run.output,
              "error: out of memory while building the meshes or rendering; lower the "
              "objects' tessellation, the image size or --max-triangles "
              "(docs/reliability.md)\n");
    EXPECT_FALSE(fs::exists(dir / "tori.png"));
#endif
}

// ---- D11: the exported program fails fast without a display, and follows
// litkit's rules for its output ----

TEST_F(Reliability, TheExportedProgramRefusesToReplaceAndNeedsADisplayForAWindow) {
    ASSERT_EQ(cli("export --format cpp scene.toml -o program").status, 0);
    const CommandRun configure = shell("'" LITKIT_CMAKE "' -S program -B program/build");
    ASSERT_EQ(configure.status, 0) << configure.output;
    ASSERT_EQ(configure.output.find("SDL2 not found"), std::string::npos) << configure.output;
    const CommandRun build = shell("'" LITKIT_CMAKE "' --build program/build");
    ASSERT_EQ(build.status, 0) << build.output;

    const auto start = std::chrono::steady_clock::now();
    const CommandRun window =
        shell("env -u DISPLAY -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER program/build/scene --window");
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(window.status, 1) << window.output;
    EXPECT_EQ(window.output,
              "scene: error: no display to open a window on (DISPLAY and "
              "WAYLAND_DISPLAY are not set); run without --window to write a PNG\n");
    EXPECT_LT(seconds, 5.0);  // it used to wait forever

    write("scene.png", "old picture");
    const CommandRun refused = shell("program/build/scene");
    EXPECT_EQ(refused.status, 2) << refused.output;
    EXPECT_EQ(refused.output,
              "scene: error: 'scene.png' already exists; pass --force to replace it\n");
    EXPECT_EQ(read("scene.png"), "old picture");
    const CommandRun forced = shell("program/build/scene --force");
    EXPECT_EQ(forced.status, 0) << forced.output;
    EXPECT_EQ(litkit::read_png(dir / "scene.png").width, 64);
    EXPECT_FALSE(fs::exists(dir / "scene.png.tmp"));
}

TEST(TemporaryRegistry, RemovesFilesThenFolders) {
    const fs::path folder =
        fs::temp_directory_path() / ("litkit-registry-" + std::to_string(::getpid()));
    fs::create_directories(folder);
    std::ofstream(folder / "a") << "x";
    const int folder_slot = litkit::register_temporary(folder);
    const int file_slot = litkit::register_temporary(folder / "a");
    ASSERT_GE(folder_slot, 0);
    ASSERT_GE(file_slot, 0);
    litkit::remove_registered_temporaries();
    EXPECT_FALSE(fs::exists(folder));
    litkit::unregister_temporary(file_slot);
    litkit::unregister_temporary(folder_slot);
}

}  // namespace
