// Finding and opening the viewer module for `litkit view`, so that every
// other command starts without SDL2, Dear ImGui and what they load
// (docs/design.md, "The viewer module").
#pragma once

#include <string>

#include "viewer/viewer.hpp"

namespace litkit_cli {

// Why the module cannot be used, worded for "error: " (exit status 1, like a
// file that cannot be read).
struct ViewerModuleError {
    std::string message;
};

// Opens litkit-view.so beside this executable (the build tree), else in the
// installed library folder (lib/litkit beside bin/), and checks that it is
// this litkit's. Throws ViewerModuleError when it is missing, cannot be
// loaded (a library it needs is missing) or is another build's. The module
// stays loaded to the end of the process.
const ViewerModule& open_viewer_module();

}  // namespace litkit_cli
