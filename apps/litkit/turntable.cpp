// SPDX-License-Identifier: MIT
// litkit turntable: the observer circles look_at once; an animated GIF or
// PNG, or numbered PNG frames in a folder; all the frames or a range of them.
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "backend_renderer.hpp"
#include "commands.hpp"
#include "litkit/image.hpp"
#include "litkit/turntable.hpp"
#include "options.hpp"
#include "outputs.hpp"
#include "usage_error.hpp"

namespace litkit_cli {

namespace {

namespace fs = std::filesystem;

struct TurntableArguments {
    SceneArguments scene;
    std::string output;
    int frames = 72;
    std::string range;  // "A:B", frames A to B-1; empty: every frame
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

// --range A:B: frames [first, end) of the turn.
struct FrameRange {
    int first = 0;
    int end = 0;
};

// "A:B" with 0 <= A < B <= frames; a usage error naming the part at fault.
FrameRange parse_range(const std::string& text, int frames) {
    const auto fail = [&](const std::string& why) {
        throw UsageError{"--range " + text + ": " + why +
                         " (--range A:B renders frames A to B-1 of the --frames " +
                         std::to_string(frames) + ", counted from 0)"};
    };
    const std::size_t colon = text.find(':');
    if (colon == std::string::npos) fail("no ':' between the first frame and the end");
    const auto number = [&](std::string_view part, const char* which) {
        int value = 0;
        const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), value);
        if (part.empty() || error != std::errc{} || end != part.data() + part.size())
            fail(std::string(which) + " '" + std::string(part) + "' is not a frame number");
        return value;
    };
    const std::string_view whole(text);
    const FrameRange range{.first = number(whole.substr(0, colon), "the first frame"),
                           .end = number(whole.substr(colon + 1), "the end")};
    if (range.first < 0) fail("the first frame " + std::to_string(range.first) + " is below 0");
    if (range.end <= range.first)
        fail("the end " + std::to_string(range.end) + " is not after the first frame " +
             std::to_string(range.first));
    if (range.end > frames)
        fail("the end " + std::to_string(range.end) + " is beyond the turn's " +
             std::to_string(frames) + " frames");
    return range;
}

enum class Written { Folder, Gif, Png };

int run_turntable(const TurntableArguments& arguments) {
    const FrameRange range = arguments.range.empty()
                                 ? FrameRange{.first = 0, .end = arguments.frames}
                                 : parse_range(arguments.range, arguments.frames);
    litkit::Scene scene = load(arguments.scene);
    settle_missing_lighting(scene, arguments.yes);
    const std::vector<std::string>& files = arguments.scene.scenes;
    const std::string target =
        arguments.output.empty() ? output_beside(files, ".gif").string() : arguments.output;
    // "DIR/" or an existing folder: numbered PNGs; a .png name: an animated
    // PNG; a .gif name (or standard output): one GIF; any other name: refused.
    const fs::path output(target);
    Written writes = Written::Gif;
    if (target.ends_with('/') || fs::is_directory(target)) {
        writes = Written::Folder;
    } else {
        refuse_to_overwrite_inputs(scene, files, output);
        require_picture_name(output, {".gif", ".png"}, "turntable",
                             "an animated GIF or PNG, or PNG frames into a folder named DIR/");
        std::string extension = output.extension().string();
        for (char& c : extension)
            c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        if (extension == ".png" && !is_standard_output(output)) writes = Written::Png;
    }

    const bool terminal = ::isatty(STDERR_FILENO) == 1 && !quiet();
    const auto start = std::chrono::steady_clock::now();
    const auto elapsed = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    const litkit::Observer own = scene.observer;
    std::vector<litkit::Image> gif_frames;
    litkit::AnimatedPng animated(arguments.delay_ms);
    int written = 0;
    // Frames are numbered in the whole turn, so that slices (--range) join in one folder.
    const int digits = std::max(3, static_cast<int>(std::to_string(arguments.frames - 1).size()));
    if (writes == Written::Folder) fs::create_directories(output);
    const int count = range.end - range.first;
    for (int k = range.first; k < range.end; ++k) {
        scene.observer = litkit::orbit(own, 360.0 * k / arguments.frames);
        BackendRenderer renderer(arguments.scene.backend_id(), scene,
                                 {.threads = arguments.scene.threads.value_or(0)});
        litkit::Image image;
        renderer.render_into(image);
        if (writes == Written::Folder) {
            std::string number = std::to_string(k);
            number.insert(0, static_cast<std::size_t>(digits) - number.size(), '0');
            const fs::path frame = output / ("frame-" + number + ".png");
            refuse_to_overwrite_inputs(scene, files, frame);
            litkit::write_png(image, frame);
            ++written;
        } else if (writes == Written::Png) {
            animated.add(image);
        } else {
            gif_frames.push_back(std::move(image));
        }
        if (terminal) show_progress(k + 1 - range.first, count, elapsed());
    }
    if (writes == Written::Gif) litkit::write_gif(gif_frames, output, arguments.delay_ms);
    if (writes == Written::Png) animated.write(output);
    if (terminal) std::fputs("\n", stderr);
    auto& said = say(std::cout) << "litkit: wrote ";
    if (writes == Written::Folder) {
        said << written << " frames into ";
    } else {
        said << (writes == Written::Png ? "1 animated PNG " : "1 animated GIF ");
    }
    said << output.string() << " (" << count << " frames";
    if (!arguments.range.empty())
        said << ", " << range.first << " to " << range.end - 1 << " of " << arguments.frames;
    said << ", " << static_cast<int>(elapsed() * 1000.0 + 0.5) << " ms)\n";
    return exit_success;
}

}  // namespace

Command add_turntable(CLI::App& app, const DefinesOptions& defines) {
    auto arguments = std::make_shared<TurntableArguments>();
    CLI::App* turntable = app.add_subcommand(
        "turntable",
        "The observer circles look_at once: an animated GIF or PNG, or PNG frames in DIR/");
    if (defines(*turntable)) {
        add_scene_options(turntable, arguments->scene);
        turntable->add_option(
            "-o,--output", arguments->output,
            "spin.gif (256 colours a frame), spin.png (an animated PNG, full colour), or DIR/ "
            "for numbered PNGs (default: the first scene's name with .gif)");
        turntable->add_option("--frames", arguments->frames, "Frames in one turn")
            ->check(CLI::Range(1, 10000))
            ->capture_default_str();
        turntable
            ->add_option("--range", arguments->range,
                         "Render only frames A to B-1 (from 0, B excluded) of the turn, "
                         "to spread one turntable over machines; DIR/ joins the slices")
            ->type_name("A:B");
        turntable
            ->add_option("--delay", arguments->delay_ms,
                         "GIF and animated PNG: milliseconds per frame")
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
