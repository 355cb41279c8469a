// SPDX-License-Identifier: MIT
// `litkit view`: a live window on a scene (docs/viewer.md).
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "crossing.hpp"
#include "litkit/backend.hpp"
#include "litkit/scene.hpp"
#include "modules.hpp"

namespace litkit_cli {

struct ViewerOptions {
    std::vector<std::filesystem::path> files;  // empty: the built-in default scene
    std::string title;                         // the scene's name for the title bar
    litkit::Backend backend = litkit::default_backend;
    int threads = 0;
    bool show_panel = true;
    // A measurement (docs/performance.md): orbit this many frames, 2° each,
    // as fast as they render and show, print the frame rate and close.
    int benchmark_frames = 0;
    // Reading the files as `render` does (validation, R11): into `scene`, or
    // false with what it threw in `error` (crossing.hpp).
    std::function<bool(litkit::Scene& scene, CaughtError& error)> load;
};

// Opens the window and runs until it is closed (Esc, Q, the window's close
// button, SIGINT or SIGTERM). Returns the exit status. `scene` is the scene
// as loaded and checked at start.
int run_viewer(const ViewerOptions& options, litkit::Scene scene);

// The viewer is a module of its own, litkit-view.so, which only `litkit
// view` opens (modules.hpp). This is what its entry function returns.
struct ViewerModule {
    ModuleStamp stamp;  // module_stamp<ViewerModule, ViewerOptions>()
    // run_viewer; what it throws comes back in `error` (crossing.hpp).
    int (*run)(const ViewerOptions& options, litkit::Scene scene, CaughtError& error) noexcept;
};

}  // namespace litkit_cli

// The viewer module's entry, by a C name for dlsym.
extern "C" const litkit_cli::ViewerModule* litkit_viewer_module();
