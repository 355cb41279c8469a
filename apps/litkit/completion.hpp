// SPDX-License-Identifier: MIT
// `litkit --bash-completion`: a bash completion script made from the CLI11
// definitions of every command and option, so that it never lists an option
// the program lacks. The build writes it (docs/CMakeLists.txt) and `cmake
// --install` puts it where bash-completion looks (share/bash-completion/completions).
#pragma once

#include <CLI/CLI.hpp>

#include <string>

namespace litkit_cli {

// The script for `app` with every command's options defined: completes the
// commands, each command's options, the values of options that take a name
// from a list (--reflection, --shading, ...), and file names elsewhere.
std::string bash_completion(const CLI::App& app);

}  // namespace litkit_cli
