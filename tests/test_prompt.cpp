// SPDX-License-Identifier: MIT
// R11 as a user at a terminal meets it: when [lighting] leaves a model out and
// standard input is a terminal, the CLI asks whether to use the defaults. The
// CLI runs on a real pseudo-terminal, and every read has a deadline, so a
// question that never comes or a CLI that never ends fails the test instead
// of hanging it.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>
#include <sys/ioctl.h>
#include <sys/wait.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "litkit/image.hpp"

namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;

// Generous: a sanitizer build on a busy machine is slow, and only a hang
// should ever reach it.
constexpr std::chrono::seconds deadline_after{60};

constexpr std::string_view question_end = "[Y/n] ";

// The CLI running on the slave side of a pseudo-terminal, as its session
// leader with the terminal as its controlling terminal. The test holds the
// master side: what it writes there is what the user types.
class TerminalSession {
  public:
    // Starts the CLI with `arguments` in `directory`. With `stdin_from_null`,
    // standard input is /dev/null while standard output and error stay on
    // the terminal (`litkit render scene.toml < /dev/null` typed in a shell).
    TerminalSession(const std::vector<std::string>& arguments, const fs::path& directory,
                    bool stdin_from_null = false) {
        master_ = ::posix_openpt(O_RDWR | O_NOCTTY | O_CLOEXEC);
        if (master_ < 0 || ::grantpt(master_) != 0 || ::unlockpt(master_) != 0) return;
        const char* slave_name = ::ptsname(master_);
        if (!slave_name) return;

        // Everything the child needs is prepared before fork: after it, the
        // child only makes async-signal-safe calls.
        const std::string slave_path = slave_name;
        const std::string folder = directory.string();
        std::vector<std::string> words{LITKIT_CLI};
        words.insert(words.end(), arguments.begin(), arguments.end());
        std::vector<char*> argv;
        for (std::string& word : words) argv.push_back(word.data());
        argv.push_back(nullptr);

        pid_ = ::fork();
        if (pid_ == 0) {
            // New session, then the first terminal it opens becomes its
            // controlling terminal; TIOCSCTTY says so explicitly.
            if (::setsid() < 0) ::_exit(126);
            const int slave = ::open(slave_path.c_str(), O_RDWR);
            if (slave < 0 || ::ioctl(slave, TIOCSCTTY, 0) != 0) ::_exit(126);
            int input = slave;
            if (stdin_from_null) input = ::open("/dev/null", O_RDONLY);
            if (input < 0 || ::dup2(input, STDIN_FILENO) < 0 || ::dup2(slave, STDOUT_FILENO) < 0 ||
                ::dup2(slave, STDERR_FILENO) < 0)
                ::_exit(126);
            if (slave > STDERR_FILENO) ::close(slave);
            if (input > STDERR_FILENO) ::close(input);
            if (::chdir(folder.c_str()) != 0) ::_exit(126);
            ::execv(argv[0], argv.data());
            ::_exit(127);
        }
        deadline_ = Clock::now() + deadline_after;
    }

    ~TerminalSession() {
        if (pid_ > 0 && !status_) {
            ::kill(pid_, SIGKILL);
            ::waitpid(pid_, nullptr, 0);
        }
        if (master_ >= 0) ::close(master_);
    }

    TerminalSession(const TerminalSession&) = delete;
    TerminalSession& operator=(const TerminalSession&) = delete;

    bool started() const { return master_ >= 0 && pid_ > 0; }

    // Reads what the CLI prints until `text` appears. False when the CLI
    // ended, or the deadline passed, without printing it.
    bool wait_for(std::string_view text) {
        while (output_.find(text) == std::string::npos) {
            if (!read_some()) return false;
        }
        return true;
    }

    // What the user types.
    void type(std::string_view keys) {
        while (!keys.empty()) {
            const ssize_t written = ::write(master_, keys.data(), keys.size());
            if (written < 0 && errno == EINTR) continue;
            if (written <= 0) return;
            keys.remove_prefix(static_cast<std::size_t>(written));
        }
    }

    // The end-of-file key, at the start of a line: the terminal's VEOF
    // character (^D unless the terminal was set up otherwise).
    void type_end_of_file() {
        termios settings{};
        char end_of_file = '\x04';
        if (::tcgetattr(master_, &settings) == 0)
            end_of_file = static_cast<char>(settings.c_cc[VEOF]);
        type(std::string_view(&end_of_file, 1));
    }

    // Reads until the CLI closes the terminal, then collects its exit
    // status. Nothing when it was killed or the deadline passed (the CLI is
    // then killed).
    std::optional<int> wait_for_exit() {
        while (read_some()) {
        }
        while (!status_) {
            int raw = 0;
            const pid_t done = ::waitpid(pid_, &raw, WNOHANG);
            if (done == pid_) {
                status_ = raw;
                break;
            }
            if (done < 0 || Clock::now() > deadline_) return std::nullopt;
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
        if (!WIFEXITED(*status_)) return std::nullopt;
        return WEXITSTATUS(*status_);
    }

    // Everything the CLI printed so far (standard output and error, with the
    // terminal's echo of what was typed, and \r\n line ends).
    const std::string& output() const { return output_; }

  private:
    // One read from the master side, waiting at most until the deadline.
    // False at the end: the CLI closed its side (EIO), or time ran out.
    bool read_some() {
        const auto left =
            std::chrono::duration_cast<std::chrono::milliseconds>(deadline_ - Clock::now());
        if (left.count() <= 0) return false;
        pollfd ready{master_, POLLIN, 0};
        const int polled = ::poll(&ready, 1, static_cast<int>(left.count()));
        if (polled < 0 && errno == EINTR) return true;
        if (polled <= 0) return false;
        char buffer[4096];
        const ssize_t count = ::read(master_, buffer, sizeof buffer);
        if (count < 0 && errno == EINTR) return true;
        if (count <= 0) return false;
        output_.append(buffer, static_cast<std::size_t>(count));
        return true;
    }

    int master_ = -1;
    pid_t pid_ = -1;
    Clock::time_point deadline_{};
    std::optional<int> status_;
    std::string output_;
};

class Prompt : public ::testing::Test {
  protected:
    void SetUp() override {
        dir = fs::temp_directory_path() /
              ("litkit-prompt-" + std::to_string(::getpid()) + "-" +
               ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override { fs::remove_all(dir); }
    void write(const fs::path& name, const std::string& text) { std::ofstream(dir / name) << text; }
    fs::path dir;
};

// A valid scene with no [lighting] table; `lighting` is put in its place.
std::string scene_with_lighting(const std::string& lighting) {
    return R"(
[room]
width = 10
height = 10
depth = 10

[observer]
position = [0, 0, 4]

[output]
width = 64
height = 48
)" + lighting +
           R"(
[[lights]]
type = "point"
position = [0, 3, 3]
intensity = 10

[[objects]]
type = "sphere"
radius = 1
)";
}

const std::string scene_without_lighting = scene_with_lighting("");

const std::string question =
    "Scene has no shading/reflection model. Use the defaults (phong / phong)? [Y/n] ";

}  // namespace

TEST_F(Prompt, AnsweringYesRendersWithTheDefaults) {
    write("scene.toml", scene_without_lighting);
    TerminalSession session({"render", "scene.toml", "-o", "out.png"}, dir);
    ASSERT_TRUE(session.started());
    ASSERT_TRUE(session.wait_for(question_end)) << session.output();
    EXPECT_NE(session.output().find(question), std::string::npos) << session.output();
    EXPECT_FALSE(fs::exists(dir / "out.png")) << "nothing is rendered before the answer";
    session.type("y\n");
    EXPECT_EQ(session.wait_for_exit(), 0) << session.output();
    ASSERT_TRUE(fs::exists(dir / "out.png")) << session.output();
    EXPECT_EQ(litkit::read_png(dir / "out.png").width, 64);
}

TEST_F(Prompt, PressingEnterAcceptsTheDefaults) {
    write("scene.toml", scene_without_lighting);
    TerminalSession session({"render", "scene.toml", "-o", "out.png"}, dir);
    ASSERT_TRUE(session.started());
    ASSERT_TRUE(session.wait_for(question_end)) << session.output();
    session.type("\n");
    EXPECT_EQ(session.wait_for_exit(), 0) << session.output();
    EXPECT_TRUE(fs::exists(dir / "out.png")) << session.output();
}

TEST_F(Prompt, TheAnswerIsTheSameAsYes) {
    write("scene.toml", scene_without_lighting);
    TerminalSession asked({"render", "scene.toml", "-o", "asked.png"}, dir);
    ASSERT_TRUE(asked.started());
    ASSERT_TRUE(asked.wait_for(question_end)) << asked.output();
    asked.type("Yes\n");
    ASSERT_EQ(asked.wait_for_exit(), 0) << asked.output();

    TerminalSession explicit_models({"render", "scene.toml", "--reflection", "phong", "--shading",
                                     "phong", "-o", "explicit.png"},
                                    dir);
    ASSERT_TRUE(explicit_models.started());
    ASSERT_EQ(explicit_models.wait_for_exit(), 0) << explicit_models.output();
    EXPECT_EQ(explicit_models.output().find(question_end), std::string::npos)
        << "both models given: nothing to ask\n"
        << explicit_models.output();
    EXPECT_EQ(litkit::read_png(dir / "asked.png").rgb, litkit::read_png(dir / "explicit.png").rgb);
}

TEST_F(Prompt, AnsweringNoStopsWithExit2AndNoImage) {
    write("scene.toml", scene_without_lighting);
    TerminalSession session({"render", "scene.toml", "-o", "out.png"}, dir);
    ASSERT_TRUE(session.started());
    ASSERT_TRUE(session.wait_for(question_end)) << session.output();
    session.type("n\n");
    EXPECT_EQ(session.wait_for_exit(), 2) << session.output();
    EXPECT_FALSE(fs::exists(dir / "out.png"));
    EXPECT_NE(session.output().find("error: "), std::string::npos) << session.output();
    EXPECT_NE(session.output().find("--yes"), std::string::npos)
        << "the message says how to go on\n"
        << session.output();
}

TEST_F(Prompt, EndOfFileStopsWithExit2AndNoImage) {
    write("scene.toml", scene_without_lighting);
    TerminalSession session({"render", "scene.toml", "-o", "out.png"}, dir);
    ASSERT_TRUE(session.started());
    ASSERT_TRUE(session.wait_for(question_end)) << session.output();
    session.type_end_of_file();
    EXPECT_EQ(session.wait_for_exit(), 2) << session.output();
    EXPECT_FALSE(fs::exists(dir / "out.png"));
    // The error starts on a line of its own, not after the question.
    EXPECT_NE(session.output().find("[Y/n] \r\nerror: "), std::string::npos) << session.output();
}

TEST_F(Prompt, TheQuestionNamesOnlyTheMissingModel) {
    struct Case {
        std::string lighting;
        std::string asked;
    };
    const std::vector<Case> cases{
        {"[lighting]\n", question},
        {"[lighting]\nreflection = \"lambert\"\n",
         "Scene has no shading model. Use the defaults (phong / phong)? [Y/n] "},
        {"[lighting]\nshading = \"flat\"\n",
         "Scene has no reflection model. Use the defaults (phong / phong)? [Y/n] "},
    };
    for (const Case& c : cases) {
        write("scene.toml", scene_with_lighting(c.lighting));
        fs::remove(dir / "out.png");
        TerminalSession session({"render", "scene.toml", "-o", "out.png"}, dir);
        ASSERT_TRUE(session.started());
        ASSERT_TRUE(session.wait_for(question_end)) << c.lighting << session.output();
        EXPECT_NE(session.output().find(c.asked), std::string::npos)
            << c.lighting << session.output();
        session.type("y\n");
        EXPECT_EQ(session.wait_for_exit(), 0) << c.lighting << session.output();
        EXPECT_TRUE(fs::exists(dir / "out.png")) << c.lighting;
    }
}

TEST_F(Prompt, ACommandLineModelCountsAsGiven) {
    write("scene.toml", scene_without_lighting);
    TerminalSession session({"render", "scene.toml", "--shading", "flat", "-o", "out.png"}, dir);
    ASSERT_TRUE(session.started());
    ASSERT_TRUE(session.wait_for(question_end)) << session.output();
    EXPECT_NE(session.output().find(
                  "Scene has no reflection model. Use the defaults (phong / phong)? [Y/n] "),
              std::string::npos)
        << session.output();
    session.type("n\n");
    EXPECT_EQ(session.wait_for_exit(), 2) << session.output();
}

TEST_F(Prompt, YesAnswersWithoutAsking) {
    write("scene.toml", scene_without_lighting);
    TerminalSession session({"render", "scene.toml", "--yes", "-o", "out.png"}, dir);
    ASSERT_TRUE(session.started());
    EXPECT_EQ(session.wait_for_exit(), 0) << session.output();
    EXPECT_EQ(session.output().find("[Y/n]"), std::string::npos) << session.output();
    EXPECT_TRUE(fs::exists(dir / "out.png")) << session.output();
}

TEST_F(Prompt, CompleteLightingIsNotQuestioned) {
    write("scene.toml",
          scene_with_lighting("[lighting]\nreflection = \"lambert\"\nshading = \"flat\"\n"));
    TerminalSession session({"render", "scene.toml", "-o", "out.png"}, dir);
    ASSERT_TRUE(session.started());
    EXPECT_EQ(session.wait_for_exit(), 0) << session.output();
    EXPECT_EQ(session.output().find("[Y/n]"), std::string::npos) << session.output();
}

TEST_F(Prompt, InputFromElsewhereIsNotATerminalEvenWithOutputOnOne) {
    // `litkit render scene.toml < /dev/null` typed at a terminal: nobody can
    // answer, so it is the no-terminal error, not a question.
    write("scene.toml", scene_without_lighting);
    TerminalSession session({"render", "scene.toml", "-o", "out.png"}, dir,
                            /*stdin_from_null=*/true);
    ASSERT_TRUE(session.started());
    EXPECT_EQ(session.wait_for_exit(), 2) << session.output();
    EXPECT_EQ(session.output().find("[Y/n]"), std::string::npos) << session.output();
    EXPECT_NE(session.output().find("not a terminal"), std::string::npos) << session.output();
    EXPECT_NE(session.output().find("--yes"), std::string::npos) << session.output();
    EXPECT_NE(session.output().find("[lighting]"), std::string::npos) << session.output();
    EXPECT_FALSE(fs::exists(dir / "out.png"));
}
