// SPDX-License-Identifier: MIT
// What the commands that load a scene share: the scene's options (their
// definitions and the arguments they fill), and the scene loaded with them.
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "litkit/backend.hpp"
#include "litkit/error.hpp"
#include "litkit/scene.hpp"

namespace litkit_cli {

// The scene and what replaces parts of it, and the renderer that draws it.
struct SceneArguments {
    std::vector<std::string> scenes;
    std::optional<int> width;
    std::optional<int> height;
    std::optional<std::string> reflection;
    std::optional<std::string> shading;
    std::optional<std::string> normals;
    std::optional<float> crease_angle;
    std::optional<int> max_depth;  // docs/spec.md §10.2 item 9; replaces [lighting] max_depth
    std::optional<int> samples;    // docs/spec.md §11; replaces [output] samples
    std::optional<int> threads;    // CPU backend only; none: one per core
    std::string backend = "cpu";   // a name of litkit::backends(); backend_id() reads it
    std::uint64_t max_triangles = litkit::default_triangle_budget;  // docs/reliability.md

    // The backend --backend named (CLI11 lets through only names it has).
    litkit::Backend backend_id() const;
};

// docs/spec.md §9.2's options, shared by every command that loads a scene.
void add_normals_options(CLI::App* command, SceneArguments& arguments);

// The scene files and every option that replaces part of the scene;
// `rendering`: also the options that choose and tune a renderer.
void add_scene_options(CLI::App* command, SceneArguments& arguments, bool rendering = true);

void print_diagnostics(const std::vector<litkit::Diagnostic>& diagnostics);

// -q/--quiet (main.cpp sets it): a successful run says nothing, no "litkit:
// wrote", note, warning or progress bar; errors and what a command exists
// to print (explain, bench, --help) still show.
void set_quiet(bool quiet);
bool quiet();
// `stream` for a message of a successful run, or a stream that drops it under --quiet.
std::ostream& say(std::ostream& stream);

// The scene (or the built-in default) with the command line's replacements
// of [output] and [lighting]; its warnings shown.
litkit::Scene load(const SceneArguments& arguments);

// R11: when [lighting] leaves a model out, ask on a terminal; `--yes` answers
// for the user; without a terminal it is an error that says how to fix it.
void settle_missing_lighting(litkit::Scene& scene, bool yes);

}  // namespace litkit_cli
