// `litkit view`: a live window on a scene (docs/viewer.md).
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "litkit/scene.hpp"

namespace litkit_cli {

struct ViewerOptions {
    std::vector<std::filesystem::path> files;  // empty: the built-in default scene
    std::string title;                         // the scene's name for the title bar
    bool gl_backend = false;
    int threads = 0;
    bool show_panel = true;
    // A measurement (docs/performance.md): orbit this many frames, 2° each,
    // as fast as they render and show, print the frame rate and close.
    int benchmark_frames = 0;
    // The command line's replacements, applied again after every reload.
    std::function<void(litkit::Scene&)> apply_options;
    // Reading the files as `render` does (validation, R11); throws like it.
    std::function<litkit::Scene()> load;
};

// Opens the window and runs until it is closed (Esc, Q, the window's close
// button, SIGINT or SIGTERM). Returns the exit status. `scene` is the scene
// as loaded and checked at start.
int run_viewer(const ViewerOptions& options, litkit::Scene scene);

}  // namespace litkit_cli
