// SPDX-License-Identifier: MIT
// Tests of `litkit view` (docs/viewer.md) as a user meets it: the real viewer
// in a real window on a virtual X display (Xvfb, started here), driven by
// real input events (xdotool) and read back with xwd. Every picture is
// compared with `litkit render` of the same settings.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "litkit/image.hpp"
#include "litkit/scene.hpp"
#include "run_command.hpp"

namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;
using litkit_test::run_command;

std::string quoted(const fs::path& path) { return "'" + path.string() + "'"; }

// One Xvfb for the whole suite, on a display number it picks itself.
class Display {
  public:
    Display() {
        int fds[2];
        if (pipe(fds) != 0) return;
        pid_ = fork();
        if (pid_ == 0) {
            close(fds[0]);
            const int devnull = open("/dev/null", O_WRONLY);
            dup2(devnull, 2);
            const std::string fd = std::to_string(fds[1]);
            // -noreset: by default the server resets when its last client
            // leaves, and a viewer started in that moment finds no display.
            execlp("Xvfb", "Xvfb", "-displayfd", fd.c_str(), "-screen", "0", "1280x1024x24",
                   "-nolisten", "tcp", "-noreset", static_cast<char*>(nullptr));
            _exit(127);
        }
        close(fds[1]);
        char buffer[32] = {};
        const ssize_t n = read(fds[0], buffer, sizeof buffer - 1);
        // Kept open: Xvfb writes the number again when it starts a new
        // server generation, and ends if it cannot.
        number_fd_ = fds[0];
        if (n > 0) {
            // Appended, not ":" + std::string(...): GCC 12 warns falsely
            // (-Wrestrict) on a literal added to a temporary string.
            name_ = ":";
            name_.append(buffer, static_cast<std::size_t>(n - (buffer[n - 1] == '\n')));
        }
    }
    ~Display() {
        if (number_fd_ >= 0) close(number_fd_);
        if (pid_ > 0) {
            kill(pid_, SIGTERM);
            waitpid(pid_, nullptr, 0);
        }
    }
    const std::string& name() const { return name_; }

  private:
    pid_t pid_ = -1;
    int number_fd_ = -1;
    std::string name_;
};

Display& display() {
    static Display instance;
    return instance;
}

// An 8-bit RGB picture from an X window dump (TrueColor, 32 bits a pixel).
litkit::Image read_xwd(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::vector<unsigned char> data((std::istreambuf_iterator<char>(in)), {});
    auto field = [&](int index) {
        const unsigned char* p = data.data() + 4 * index;
        return std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 | std::uint32_t(p[2]) << 8 |
               p[3];
    };
    litkit::Image image;
    if (data.size() < 100 || field(11) != 32) return image;
    const std::uint32_t header = field(0), width = field(4), height = field(5),
                        byte_order = field(7);
    const std::uint32_t bytes_per_line = field(12), masks[3] = {field(14), field(15), field(16)};
    const std::size_t offset = header + 12 * std::size_t(field(19));
    if (data.size() < offset + std::size_t(bytes_per_line) * height) return image;
    image = litkit::Image(int(width), int(height));
    for (std::uint32_t y = 0; y < height; ++y) {
        for (std::uint32_t x = 0; x < width; ++x) {
            const unsigned char* p = data.data() + offset + std::size_t(y) * bytes_per_line + 4 * x;
            const std::uint32_t v =
                byte_order == 0 ? (p[0] | p[1] << 8 | p[2] << 16 | std::uint32_t(p[3]) << 24)
                                : (std::uint32_t(p[0]) << 24 | p[1] << 16 | p[2] << 8 | p[3]);
            for (int c = 0; c < 3; ++c) {
                const std::uint32_t mask = masks[c];
                image.pixel(int(x), int(y))[c] =
                    static_cast<std::uint8_t>((v & mask) >> __builtin_ctz(mask));
            }
        }
    }
    return image;
}

int largest_difference(const litkit::Image& a, const litkit::Image& b) {
    if (a.width != b.width || a.height != b.height) return 256;
    int worst = 0;
    for (std::size_t i = 0; i < a.rgb.size(); ++i)
        worst = std::max(worst, std::abs(int(a.rgb[i]) - int(b.rgb[i])));
    return worst;
}

const char* const small_scene = R"toml(
[room]
width = 10
height = 10
depth = 10

[observer]
position = [0, 1, 4]
look_at = [0, 0, 0]

[lighting]
reflection = "phong"
shading = "phong"

[output]
width = 160
height = 120
background = [20, 30, 40]

[[lights]]
name = "key"
type = "point"
position = [2, 3, 3]
intensity = 12

[[objects]]
name = "ball"
type = "sphere"
radius = 1
segments = 24
rings = 12
material = { color = [200, 100, 60], shininess = 20 }
)toml";

class Viewer : public ::testing::Test {
  protected:
    void SetUp() override {
        ASSERT_FALSE(display().name().empty())
            << "Xvfb did not start (scripts/install-deps.sh installs it)";
        dir = fs::temp_directory_path() /
              ("litkit-viewer-" + std::to_string(getpid()) + "-" +
               ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
        write_scene(small_scene);
    }
    void TearDown() override {
        if (pid > 0) {
            kill(pid, SIGTERM);
            waitpid(pid, nullptr, 0);
        }
        fs::remove_all(dir);
    }

    void write_scene(const std::string& text, const fs::path& name = "scene.toml") const {
        std::ofstream(dir / name) << text;
    }

    // Starts the viewer; its window's id in `window`.
    void start(const std::string& arguments) {
        pid = fork();
        if (pid == 0) {
            if (chdir(dir.c_str()) != 0) _exit(127);
            setenv("DISPLAY", display().name().c_str(), 1);
            // Mesa and SDL keep a few allocations to the end of the process
            // (the GL suites say the same): no leak check for the window.
            setenv("ASAN_OPTIONS", "detect_leaks=0", 1);
            const int out = open("stdout.txt", O_WRONLY | O_CREAT | O_TRUNC, 0644);
            const int err = open("stderr.txt", O_WRONLY | O_CREAT | O_TRUNC, 0644);
            dup2(out, 1);
            dup2(err, 2);
            execl("/bin/sh", "sh", "-c",
                  (std::string("exec '" LITKIT_CLI "' view ") + arguments).c_str(),
                  static_cast<char*>(nullptr));
            _exit(127);
        }
        const auto deadline = std::chrono::steady_clock::now() + 15s;
        std::string searched;
        while (window.empty() && std::chrono::steady_clock::now() < deadline) {
            // The window's id: the first line that is a number (xdotool may
            // print warnings too).
            const auto found = xdo("search --pid " + std::to_string(pid) + " --name 'litkit view'");
            std::istringstream lines(found.output);
            for (std::string line; window.empty() && std::getline(lines, line);)
                if (!line.empty() && line.find_first_not_of("0123456789") == std::string::npos)
                    window = line;
            searched = found.output;
            if (window.empty()) std::this_thread::sleep_for(50ms);
        }
        ASSERT_FALSE(window.empty())
            << "no window on display [" << display().name() << "]; xdotool said:\n"
            << searched << "\nstderr:\n"
            << text_of("stderr.txt");
    }

    litkit_test::CommandRun xdo(const std::string& arguments) const {
        return run_command("DISPLAY=" + display().name() + " xdotool " + arguments);
    }
    // A key press through XTEST, as a keyboard makes it, to the viewer's
    // window given the focus.
    void key(const std::string& name) const { xdo("windowfocus " + window + " key " + name); }

    litkit::Image screenshot() const {
        const fs::path file = dir / "window.xwd";
        run_command("DISPLAY=" + display().name() + " xwd -silent -id " + window + " -out " +
                    quoted(file));
        return read_xwd(file);
    }

    // The picture `litkit render` draws of the scene with these options.
    litkit::Image rendered(const std::string& options,
                           const std::string& scene = "scene.toml") const {
        const auto made = run_command("cd " + quoted(dir) + " && '" LITKIT_CLI "' render " + scene +
                                      " " + options + " -o expected.png");
        EXPECT_EQ(made.status, 0) << made.output;
        return litkit::read_png(dir / "expected.png");
    }

    // Waits until the window shows `expected` (within 1/255); the largest
    // difference of the last look otherwise.
    int wait_for(const litkit::Image& expected, std::chrono::milliseconds limit = 5000ms) const {
        const auto deadline = std::chrono::steady_clock::now() + limit;
        int difference = 256;
        do {
            difference = largest_difference(screenshot(), expected);
            if (difference <= 1) return difference;
            std::this_thread::sleep_for(40ms);
        } while (std::chrono::steady_clock::now() < deadline);
        return difference;
    }

    std::string text_of(const std::string& name) const {
        std::ifstream in(dir / name);
        return std::string((std::istreambuf_iterator<char>(in)), {});
    }
    bool alive() const { return pid > 0 && waitpid(pid, nullptr, WNOHANG) == 0; }
    // The viewer's exit status; one that has not ended within 5 s is killed
    // (so that its window cannot cover the next test's) and counts as -1.
    int wait_exit() {
        int status = -1;
        pid_t done = 0;
        for (int i = 0; i < 100 && (done = waitpid(pid, &status, WNOHANG)) == 0; ++i)
            std::this_thread::sleep_for(50ms);
        if (done == 0) {
            kill(pid, SIGKILL);
            waitpid(pid, nullptr, 0);
            pid = -1;
            return -1;
        }
        pid = -1;
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    }

    fs::path dir;
    pid_t pid = -1;
    std::string window;
};

}  // namespace

TEST_F(Viewer, ShowsTheRenderPixelForPixelAndSwitchesModelsAtAKey) {
    ASSERT_NO_FATAL_FAILURE(start("scene.toml --no-ui"));
    EXPECT_LE(wait_for(rendered("")), 1) << "at start";
    const std::pair<const char*, const char*> keys[] = {
        {"1", "--reflection lambert"},
        {"2", "--reflection half-lambert"},
        {"3", "--reflection phong"},
        {"4", "--reflection blinn-phong"},
        {"f", "--reflection blinn-phong --shading flat"},
        {"g", "--reflection blinn-phong --shading gouraud"},
        {"p", "--reflection blinn-phong --shading phong"},
        {"7", "--reflection toon --shading phong"},
        {"0", ""},
    };
    for (const auto& [pressed, options] : keys) {
        key(pressed);
        EXPECT_LE(wait_for(rendered(options)), 1) << "after key " << pressed;
    }
    key("q");
    EXPECT_EQ(wait_exit(), 0);
}

// Anti-aliasing (docs/spec.md §11): A cycles 1, 4, 8, 16 samples; at rest
// the window is `litkit render --samples N`'s picture, and --samples starts
// it there.
TEST_F(Viewer, AKeyCyclesSamplesAndTheWindowEqualsRender) {
    ASSERT_NO_FATAL_FAILURE(start("scene.toml --no-ui --samples 4"));
    EXPECT_LE(wait_for(rendered("--samples 4")), 1) << "at start";
    EXPECT_GT(largest_difference(screenshot(), rendered("")), 1) << "4 samples are not 1";
    const std::pair<const char*, const char*> presses[] = {
        {"8", "--samples 8"}, {"16", "--samples 16"}, {"1", ""}, {"4", "--samples 4"}};
    for (const auto& [now, options] : presses) {
        key("a");
        EXPECT_LE(wait_for(rendered(options)), 1) << "A to " << now << " samples";
    }
    key("q");
    EXPECT_EQ(wait_exit(), 0);
}

TEST_F(Viewer, OrbitMovesTheCameraAndRPutsItBack) {
    ASSERT_NO_FATAL_FAILURE(start("scene.toml --no-ui"));
    const litkit::Image start_picture = rendered("");
    ASSERT_LE(wait_for(start_picture), 1);
    xdo("mousemove --window " + window + " 80 60 mousedown 1 mousemove --window " + window +
        " 120 70 mouseup 1");
    std::this_thread::sleep_for(300ms);
    EXPECT_GT(largest_difference(screenshot(), start_picture), 1) << "the drag turned nothing";
    key("r");
    EXPECT_LE(wait_for(start_picture), 1) << "R resets the camera";
    key("Escape");
    EXPECT_EQ(wait_exit(), 0);
}

TEST_F(Viewer, ReloadsOnSaveInPlaceAndByRenameAndSurvivesABadEdit) {
    ASSERT_NO_FATAL_FAILURE(start("scene.toml --no-ui"));
    const litkit::Image first = rendered("");
    ASSERT_LE(wait_for(first), 1);

    // Written in place: the ball turns green.
    std::string text = small_scene;
    text.replace(text.find("[200, 100, 60]"), 14, "[60, 200, 90]");
    write_scene(text);
    const litkit::Image green = rendered("");
    EXPECT_LE(wait_for(green), 1) << "after an in-place save";

    // Saved the way editors do: a new file renamed over the old one.
    std::string blue = small_scene;
    blue.replace(blue.find("[200, 100, 60]"), 14, "[60, 90, 220]");
    write_scene(blue, "scene.toml.new");
    fs::rename(dir / "scene.toml.new", dir / "scene.toml");
    const litkit::Image blue_picture = rendered("");
    EXPECT_LE(wait_for(blue_picture), 1) << "after a save by rename";

    // An invalid edit: the viewer lives on, keeps the picture, says where.
    std::string bad = blue;
    bad.replace(bad.find("intensity = 12"), 14, "intensity = -3");
    write_scene(bad);
    std::this_thread::sleep_for(600ms);
    EXPECT_TRUE(alive());
    EXPECT_LE(largest_difference(screenshot(), blue_picture), 1);
    EXPECT_NE(
        text_of("stderr.txt").find("scene.toml:24:13: error: lights[0] 'key': intensity must be"),
        std::string::npos)
        << text_of("stderr.txt");

    // A good save again: back to work.
    write_scene(text);
    EXPECT_LE(wait_for(green), 1) << "after the next valid save";
    key("q");
    EXPECT_EQ(wait_exit(), 0);
}

TEST_F(Viewer, ResizingRendersAtTheNewSize) {
    ASSERT_NO_FATAL_FAILURE(start("scene.toml --no-ui"));
    ASSERT_LE(wait_for(rendered("")), 1);
    xdo("windowsize " + window + " 200 150");
    EXPECT_LE(wait_for(rendered("--width 200 --height 150")), 1);
    key("q");
    EXPECT_EQ(wait_exit(), 0);
}

TEST_F(Viewer, SSavesThePictureBesideTheScene) {
    ASSERT_NO_FATAL_FAILURE(start("scene.toml --no-ui"));
    const litkit::Image first = rendered("");
    ASSERT_LE(wait_for(first), 1);
    key("s");
    const auto deadline = std::chrono::steady_clock::now() + 3s;
    while (!fs::exists(dir / "scene-1.png") && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(40ms);
    ASSERT_TRUE(fs::exists(dir / "scene-1.png"));
    EXPECT_EQ(litkit::read_png(dir / "scene-1.png").rgb, first.rgb);
    key("q");
    EXPECT_EQ(wait_exit(), 0);
    EXPECT_NE(text_of("stdout.txt").find("litkit: wrote scene-1.png"), std::string::npos);
}

TEST_F(Viewer, PanelEditsChangeThePictureAndSaveAsWritesAScene) {
    // The panel's layout for a scene of one object and one light: the gamma
    // and max_depth sliders' rows, the samples menu, then the object's and the light's, the
    // frame time, the file name and the Save button (Dear ImGui's default
    // style).
    ASSERT_NO_FATAL_FAILURE(start("scene.toml --width 480 --height 360"));
    std::this_thread::sleep_for(500ms);
    const litkit::Image before = screenshot();
    // Drag the gamma slider to its right end: gamma 4.
    // (Dear ImGui reads the button once a frame: hold it across frames.)
    xdo("mousemove --window " + window +
        " 60 90 sleep 0.1 mousedown 1 sleep 0.1 mousemove --window " + window +
        " 200 90 sleep 0.1 mousemove --window " + window + " 300 90 sleep 0.1 mouseup 1");
    std::this_thread::sleep_for(400ms);
    const litkit::Image after = screenshot();
    // The picture beside the panel changed (the ball's right side).
    EXPECT_GT(largest_difference(before, after), 8);

    // Type a file name and press Save as...
    xdo("mousemove --window " + window + " 100 214 sleep 0.1 click 1 sleep 0.1");
    xdo("type --delay 30 saved.toml");
    xdo("sleep 0.1 mousemove --window " + window + " 40 237 sleep 0.1 click 1");
    const auto deadline = std::chrono::steady_clock::now() + 3s;
    while (!fs::exists(dir / "saved.toml") && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(40ms);
    ASSERT_TRUE(fs::exists(dir / "saved.toml")) << text_of("stderr.txt");
    // The saved scene renders to the picture the window shows, panel aside:
    // compare the part right of the panel.
    key("h");
    std::this_thread::sleep_for(300ms);
    const litkit::Image shown = screenshot();
    const litkit::Image saved = rendered("", "saved.toml");
    EXPECT_LE(largest_difference(shown, saved), 1);
    key("q");
    EXPECT_EQ(wait_exit(), 0);
}

TEST_F(Viewer, GlassSlidersChangeThePicture) {
    // A small ball right of the panel (few glass pixels and triangles: the
    // rays are traced quickly).
    std::string scene = small_scene;
    const std::string ball = "radius = 1\nsegments = 24\nrings = 12";
    scene.replace(scene.find(ball), ball.size(),
                  "radius = 0.6\nsegments = 16\nrings = 8\nposition = [1.6, 0, 0]");
    write_scene(scene);
    ASSERT_NO_FATAL_FAILURE(start("scene.toml --width 640 --height 360"));
    std::this_thread::sleep_for(500ms);
    const litkit::Image opaque = screenshot();
    ASSERT_EQ(opaque.width, 640);
    // The ball's most orange pixel (red above blue) right of the panel.
    auto orange = [](const litkit::Image& image, int x, int y) {
        return int(image.pixel(x, y)[0]) - int(image.pixel(x, y)[2]);
    };
    int bx = 0, by = 0;
    for (int y = 0; y < 360; ++y)
        for (int x = 420; x < 640; ++x)
            if (orange(opaque, x, y) > orange(opaque, bx, by)) bx = x, by = y;
    ASSERT_GT(orange(opaque, bx, by), 60) << "no ball beside the panel";
    // The ball's own rows open below its name (the row after max_depth and
    // samples):
    // color, ka, kd, ks, shininess, then transmission. A click at the right
    // end of transmission's slider: t = 1 (clamped), the ball turns to glass.
    xdo("mousemove --window " + window + " 40 156 sleep 0.1 click 1 sleep 0.2");
    xdo("mousemove --window " + window + " 243 291 sleep 0.2 click 1");
    // Through clear glass the background (20, 30, 40) shows, and white
    // highlights: no longer orange.
    const auto deadline = std::chrono::steady_clock::now() + 10s;
    litkit::Image glass = screenshot();
    while (glass.width == 640 && orange(glass, bx, by) > 20 &&
           std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(100ms);
        glass = screenshot();
    }
    ASSERT_EQ(glass.width, 640);
    const std::uint8_t* before = opaque.pixel(bx, by);
    const std::uint8_t* after = glass.pixel(bx, by);
    EXPECT_LE(orange(glass, bx, by), 20)
        << "before " << int(before[0]) << " " << int(before[1]) << " " << int(before[2])
        << ", after " << int(after[0]) << " " << int(after[1]) << " " << int(after[2]);
    EXPECT_TRUE(alive()) << text_of("stderr.txt");
    // Dear ImGui lets the slider go only on a later frame: a click beside
    // the panel (no drag: the camera stays) gives it that, and then the
    // mouse and keys are the viewer's again.
    xdo("mousemove --window " + window +
        " 600 330 sleep 0.3 click 1 sleep 0.3 mousemove --window " + window + " 590 300 sleep 0.3");
    // While the view is dragged, glass is traced to max_depth 2 only: the
    // rays inside the ball end at its far side, which turns black. Once the
    // button is released the picture at rest is exact again. (Right of the
    // panel; the drag goes 30 pixels right and back, the camera with it.)
    auto beside_panel = [](const litkit::Image& a, const litkit::Image& b) {
        int worst = 0;
        for (int y = 0; y < 360; ++y)
            for (int x = 420; x < 640; ++x)
                for (int c = 0; c < 3; ++c)
                    worst =
                        std::max(worst, std::abs(int(a.pixel(x, y)[c]) - int(b.pixel(x, y)[c])));
        return worst;
    };
    const litkit::Image rest = screenshot();
    ASSERT_EQ(rest.width, 640);
    xdo("mousemove --window " + window +
        " 590 300 sleep 0.1 mousedown 1 sleep 0.2 mousemove --window " + window +
        " 620 300 sleep 0.3 mousemove --window " + window + " 590 300 sleep 0.3");
    auto until = [&](auto done) {
        litkit::Image now = screenshot();
        for (int i = 0; i < 50 && !(now.width == 640 && done(now)); ++i) {
            std::this_thread::sleep_for(100ms);
            now = screenshot();
        }
        return now;
    };
    const litkit::Image moving =
        until([&](const litkit::Image& now) { return beside_panel(rest, now) > 8; });
    EXPECT_GT(beside_panel(rest, moving), 8) << "the drag drew glass at full depth";
    xdo("mouseup 1");
    const litkit::Image after_drag =
        until([&](const litkit::Image& now) { return beside_panel(rest, now) <= 1; });
    EXPECT_LE(beside_panel(rest, after_drag), 1) << "the picture at rest is not the exact one";
    key("q");
    EXPECT_EQ(wait_exit(), 0);
}

TEST_F(Viewer, InvalidSceneIsRefusedLikeRender) {
    write_scene("[room]\nwidth = 0\n");
    const auto refused = run_command("cd " + quoted(dir) + " && DISPLAY=" + display().name() +
                                     " '" LITKIT_CLI "' view scene.toml");
    const auto render = run_command("cd " + quoted(dir) + " && '" LITKIT_CLI "' render scene.toml");
    EXPECT_EQ(refused.status, 2);
    EXPECT_EQ(refused.output, render.output);
}

TEST_F(Viewer, SigtermEndsItCleanly) {
    ASSERT_NO_FATAL_FAILURE(start("scene.toml --no-ui"));
    ASSERT_LE(wait_for(rendered("")), 1);
    kill(pid, SIGTERM);
    EXPECT_EQ(wait_exit(), 0);
}

// Glass through the OpenGL drawer (docs/spec.md §10): the window shows what
// `litkit render --backend gl` draws, a ball of glass before a wall.
TEST_F(Viewer, OpenGlBackendDrawsGlass) {
    std::string scene = small_scene;
    const std::string colour = "material = { color = [200, 100, 60], shininess = 20 }";
    scene.replace(scene.find(colour), colour.size(),
                  "material = { color = [200, 100, 60], shininess = 20, transmission = 1 }\n\n"
                  "[[objects]]\nname = \"wall\"\ntype = \"cube\"\nsize = 2\n"
                  "position = [0.4, 0, -2.5]\nrotation = [0, 30, 0]\n"
                  "material = { color = [60, 200, 90] }");
    write_scene(scene);
    ASSERT_NO_FATAL_FAILURE(start("scene.toml --no-ui --backend gl"));
    EXPECT_LE(wait_for(rendered("--backend gl")), 1) << "at start";
    key("q");
    EXPECT_EQ(wait_exit(), 0);
}

TEST_F(Viewer, OpenGlBackendDrawsInTheWindowsOwnContext) {
    ASSERT_NO_FATAL_FAILURE(start("scene.toml --no-ui --backend gl"));
    EXPECT_LE(wait_for(rendered("--backend gl")), 1) << "at start";
    key("2");
    EXPECT_LE(wait_for(rendered("--backend gl --reflection half-lambert")), 1) << "after key 2";
    xdo("mousemove --window " + window + " 80 60 mousedown 1 mousemove --window " + window +
        " 120 70 mouseup 1");
    std::this_thread::sleep_for(300ms);
    key("r");
    EXPECT_LE(wait_for(rendered("--backend gl --reflection half-lambert")), 1)
        << "after an orbit and R";
    key("a");  // 4 samples per pixel, drawn by the backend at rest (docs/spec.md §11)
    EXPECT_LE(wait_for(rendered("--backend gl --reflection half-lambert --samples 4")), 1)
        << "after A";
    key("q");
    EXPECT_EQ(wait_exit(), 0);
}
