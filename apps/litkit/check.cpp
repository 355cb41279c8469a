// SPDX-License-Identifier: MIT
// litkit check: validates scene files without rendering.
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "options.hpp"

namespace litkit_cli {

namespace {

int run_check(const SceneArguments& arguments) {
    load(arguments);
    say(std::cout) << "ok\n";
    return exit_success;
}

}  // namespace

Command add_check(CLI::App& app, const DefinesOptions& defines) {
    auto arguments = std::make_shared<SceneArguments>();
    CLI::App* check = app.add_subcommand("check", "Validate scene files without rendering");
    if (defines(*check)) {
        check->add_option("SCENE", arguments->scenes, "Scene files (TOML), merged in order")
            ->required();
        add_normals_options(check, *arguments);
        check
            ->add_option("--max-triangles", arguments->max_triangles,
                         "The scene-wide triangle budget (docs/reliability.md)")
            ->check(CLI::PositiveNumber)
            ->capture_default_str();
    }
    return {.app = check, .run = [arguments] { return run_check(*arguments); }};
}

}  // namespace litkit_cli
