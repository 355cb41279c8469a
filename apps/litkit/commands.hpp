// SPDX-License-Identifier: MIT
// The commands of `litkit`, one file each: render.cpp, check.cpp, init.cpp,
// export.cpp, compare.cpp, view.cpp, explain.cpp, turntable.cpp and
// bench.cpp. Each defines its subcommand and runs it; main.cpp adds them,
// parses the command line, runs the one named and decides the exit status of
// what it throws.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>

#include "usage_error.hpp"

namespace litkit_cli {

// A command as main.cpp sees it.
struct Command {
    CLI::App* app = nullptr;   // its subcommand
    std::function<int()> run;  // runs it on the arguments parsed; returns the exit status
    // Out of memory while it ran: it was building meshes or rendering (true),
    // or reading or checking the scene (false).
    bool renders = false;
    // `litkit view` ends on SIGINT/SIGTERM through SDL, which installs its
    // own handlers only where none is set.
    bool leaves_signals_to_sdl = false;
};

// Whether a command gets its options now (main.cpp says why not always).
using DefinesOptions = std::function<bool(const CLI::App& command)>;

// Each adds its subcommand to `app` (with its options where `defines` says
// so) and returns how to run it.
Command add_render(CLI::App& app, const DefinesOptions& defines);
Command add_check(CLI::App& app, const DefinesOptions& defines);
Command add_init(CLI::App& app, const DefinesOptions& defines);
Command add_export(CLI::App& app, const DefinesOptions& defines);
Command add_compare(CLI::App& app, const DefinesOptions& defines);
Command add_view(CLI::App& app, const DefinesOptions& defines);
Command add_explain(CLI::App& app, const DefinesOptions& defines);
Command add_turntable(CLI::App& app, const DefinesOptions& defines);
Command add_bench(CLI::App& app, const DefinesOptions& defines);

}  // namespace litkit_cli
