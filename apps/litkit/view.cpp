// SPDX-License-Identifier: MIT
// litkit view: a live window on the scene (docs/viewer.md), from the module
// litkit-view.so.
#include <memory>
#include <utility>

#include "commands.hpp"
#include "crossing.hpp"
#include "modules.hpp"
#include "options.hpp"
#include "viewer/viewer.hpp"

namespace litkit_cli {

namespace {

struct ViewArguments {
    SceneArguments scene;
    int orbit_frames = 0;
    bool no_ui = false;
    bool yes = false;
};

int run_view(const ViewArguments& arguments) {
    // SDL2 and Dear ImGui load only now, with the module (docs/design.md).
    const auto& viewer = open_module<ViewerModule, ViewerOptions>(
        "litkit-view.so", "litkit_viewer_module", "litkit view");
    litkit::Scene scene = load(arguments.scene);
    settle_missing_lighting(scene, arguments.yes);
    ViewerOptions options;
    options.files.assign(arguments.scene.scenes.begin(), arguments.scene.scenes.end());
    options.title =
        arguments.scene.scenes.empty() ? "default scene" : arguments.scene.scenes.front();
    options.backend = arguments.scene.backend_id();
    options.threads = arguments.scene.threads.value_or(0);
    options.show_panel = !arguments.no_ui;
    options.benchmark_frames = arguments.orbit_frames;
    // A reload reads the files as at start; [lighting] left out now takes
    // the defaults (there is no terminal to ask in a window).
    options.load = [arguments](litkit::Scene& loaded, CaughtError& error) noexcept {
        return call_catching(
            [&] {
                loaded = load(arguments.scene);
                settle_missing_lighting(loaded, true);
            },
            error);
    };
    CaughtError error;
    const int status = viewer.run(options, std::move(scene), error);
    if (error.kind != CaughtError::Kind::None) throw_again(error);
    return status;
}

}  // namespace

Command add_view(CLI::App& app, const DefinesOptions& defines) {
    auto arguments = std::make_shared<ViewArguments>();
    CLI::App* view = app.add_subcommand(
        "view", "A live window on the scene: orbit, switch models at a key, edit, reload on save");
    if (defines(*view)) {
        add_scene_options(view, arguments->scene);
        view->add_flag("--no-ui", arguments->no_ui, "Start with the panel hidden (H shows it)");
        view->add_option("--orbit-frames", arguments->orbit_frames,
                         "Measure: orbit N frames as fast as they show, print frames/s and close")
            ->check(CLI::Range(1, 100000));
        view->add_flag("-y,--yes", arguments->yes,
                       "Use the default models (phong / phong) where [lighting] leaves one out");
    }
    return {.app = view,
            .run = [arguments] { return run_view(*arguments); },
            .leaves_signals_to_sdl = true};
}

}  // namespace litkit_cli
