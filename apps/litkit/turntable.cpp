// SPDX-License-Identifier: MIT
// litkit turntable: the observer circles look_at once; an animated GIF, or
// numbered PNG frames in a folder.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "backend_renderer.hpp"
#include "commands.hpp"
#include "litkit/image.hpp"
#include "litkit/turntable.hpp"
#include "options.hpp"
#include "outputs.hpp"

namespace litkit_cli {

namespace {

namespace fs = std::filesystem;

struct TurntableArguments {
    SceneArguments scene;
    std::string output;
    int frames = 72;
    int delay_ms = 40;
    bool yes = false;
};

// "[#####.....] 12/72 frames, 30.1 frames/s, 2 s left" on a terminal.
void show_progress(int done, int total, double seconds) {
    constexpr int bar = 30;
    const int filled = done * bar / total;
    const double rate = seconds > 0.0 ? done / seconds : 0.0;
    const double left = rate > 0.0 ? (total - done) / rate : 0.0;
    std::fprintf(stderr, "\r[%s%s] %d/%d frames, %.1f frames/s, %.0f s left ",
                 std::string(static_cast<std::size_t>(filled), '#').c_str(),
                 std::string(static_cast<std::size_t>(bar - filled), '.').c_str(), done, total,
                 rate, left);
    std::fflush(stderr);
}

int run_turntable(const TurntableArguments& arguments) {
    litkit::Scene scene = load(arguments.scene);
    settle_missing_lighting(scene, arguments.yes);
    const std::vector<std::string>& files = arguments.scene.scenes;
    const std::string target =
        arguments.output.empty() ? output_beside(files, ".gif").string() : arguments.output;
    // "DIR/" or an existing folder: numbered PNGs; anything else: one GIF.
    const bool to_folder = target.ends_with('/') || fs::is_directory(target);
    const fs::path output(target);
    if (!to_folder) {
        refuse_to_overwrite_inputs(scene, files, output);
        require_picture_name(output, {".gif"}, "turntable",
                             "an animated GIF, or PNG frames into a folder named DIR/");
    }

    const bool terminal = ::isatty(STDERR_FILENO) == 1 && !quiet();
    const auto start = std::chrono::steady_clock::now();
    const auto elapsed = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    const litkit::Observer own = scene.observer;
    std::vector<litkit::Image> frames;
    std::vector<fs::path> written;
    const int digits = std::max(3, static_cast<int>(std::to_string(arguments.frames - 1).size()));
    if (to_folder) fs::create_directories(output);
    for (int k = 0; k < arguments.frames; ++k) {
        scene.observer = litkit::orbit(own, 360.0 * k / arguments.frames);
        BackendRenderer renderer(arguments.scene.backend_id(), scene,
                                 {.threads = arguments.scene.threads.value_or(0)});
        litkit::Image image;
        renderer.render_into(image);
        if (to_folder) {
            std::string number = std::to_string(k);
            number.insert(0, static_cast<std::size_t>(digits) - number.size(), '0');
            const fs::path frame = output / ("frame-" + number + ".png");
            refuse_to_overwrite_inputs(scene, files, frame);
            litkit::write_png(image, frame);
            written.push_back(frame);
        } else {
            frames.push_back(std::move(image));
        }
        if (terminal) show_progress(k + 1, arguments.frames, elapsed());
    }
    if (!to_folder) litkit::write_gif(frames, output, arguments.delay_ms);
    if (terminal) std::fputs("\n", stderr);
    say(std::cout) << "litkit: wrote " << (to_folder ? written.size() : 1) << " "
                   << (to_folder ? "frames into " : "animated GIF ") << output.string() << " ("
                   << arguments.frames << " frames, " << static_cast<int>(elapsed() * 1000.0 + 0.5)
                   << " ms)\n";
    return exit_success;
}

}  // namespace

Command add_turntable(CLI::App& app, const DefinesOptions& defines) {
    auto arguments = std::make_shared<TurntableArguments>();
    CLI::App* turntable = app.add_subcommand(
        "turntable", "The observer circles look_at once: an animated GIF, or PNG frames in DIR/");
    if (defines(*turntable)) {
        add_scene_options(turntable, arguments->scene);
        turntable->add_option(
            "-o,--output", arguments->output,
            "spin.gif, or DIR/ for numbered PNGs (default: the first scene's name "
            "with .gif)");
        turntable->add_option("--frames", arguments->frames, "Frames in one turn")
            ->check(CLI::Range(1, 10000))
            ->capture_default_str();
        turntable->add_option("--delay", arguments->delay_ms, "GIF: milliseconds per frame")
            ->check(CLI::Range(10, 10000))
            ->capture_default_str();
        turntable->add_flag(
            "-y,--yes", arguments->yes,
            "Use the default models (phong / phong) where [lighting] leaves one out");
    }
    return {.app = turntable,
            .run = [arguments] { return run_turntable(*arguments); },
            .renders = true};
}

}  // namespace litkit_cli
