// SPDX-License-Identifier: MIT
// litkit render: the scene (or the default scene) to PNG.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

#include "backend_renderer.hpp"
#include "commands.hpp"
#include "litkit/image.hpp"
#include "options.hpp"
#include "outputs.hpp"

namespace litkit_cli {

namespace {

namespace fs = std::filesystem;

struct RenderArguments {
    SceneArguments scene;
    std::string output;
    bool yes = false;
};

int run_render(const RenderArguments& arguments) {
    litkit::Scene scene = load(arguments.scene);
    settle_missing_lighting(scene, arguments.yes);

    const std::vector<std::string>& files = arguments.scene.scenes;
    const fs::path output =
        arguments.output.empty() ? default_output(files) : fs::path(arguments.output);
    refuse_to_overwrite_inputs(scene, files, output);
    require_picture_name(output, {".png"}, "render", "a PNG picture");

    const auto start = std::chrono::steady_clock::now();
    const litkit::Backend backend = arguments.scene.backend_id();
    BackendRenderer renderer(backend, scene, {.threads = arguments.scene.threads.value_or(0)});
    litkit::Image image;
    renderer.render_into(image);
    write_png_output(image, output);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // The message names the backend unless it is the default one.
    say(is_standard_output(output) ? std::cerr : std::cout)
        << "litkit: wrote " << output.string() << " (" << image.width << "x" << image.height << ", "
        << renderer.triangle_count() << " triangles, " << static_cast<int>(seconds * 1000.0 + 0.5)
        << " ms" << (backend != litkit::default_backend ? "; " + renderer.description() : "")
        << ")\n";
    // Done: the picture is in its file and the message out. The process
    // ends here, without taking the renderer, its threads and its memory
    // apart (a one-shot run's last 0.3 ms; the system frees it all at once).
    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);
    _exit(exit_success);
}

}  // namespace

Command add_render(CLI::App& app, const DefinesOptions& defines) {
    auto arguments = std::make_shared<RenderArguments>();
    CLI::App* render = app.add_subcommand("render", "Render a scene (or the default scene) to PNG");
    if (defines(*render)) {
        add_scene_options(render, arguments->scene);
        render->add_option(
            "-o,--output", arguments->output,
            "Output PNG (default: the first scene's name with .png; -: standard output)");
        render->add_flag("-y,--yes", arguments->yes,
                         "Use the default models (phong / phong) where [lighting] leaves one out");
    }
    return {.app = render, .run = [arguments] { return run_render(*arguments); }, .renders = true};
}

}  // namespace litkit_cli
