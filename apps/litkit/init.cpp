// SPDX-License-Identifier: MIT
// litkit init: the default scene as a starting file.
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <system_error>

#include "commands.hpp"
#include "core/files.hpp"
#include "litkit/scene.hpp"
#include "options.hpp"

namespace litkit_cli {

namespace {

namespace fs = std::filesystem;

struct InitArguments {
    std::string file;
    bool force = false;
};

int run_init(const std::string& file, bool force) {
    const fs::path path = file.empty() ? fs::path("scene.toml") : fs::path(file);
    std::error_code error;
    if (!force && fs::exists(path, error)) {
        throw UsageError{"'" + path.string() + "' already exists; pass --force to replace it"};
    }
    litkit::write_file_atomically(path, litkit::default_scene_toml());
    say(std::cout) << "litkit: wrote " << path.string() << "; render it with: litkit render "
                   << path.string() << "\n";
    return exit_success;
}

}  // namespace

Command add_init(CLI::App& app, const DefinesOptions& defines) {
    auto arguments = std::make_shared<InitArguments>();
    CLI::App* init = app.add_subcommand("init", "Write the default scene as a starting file");
    if (defines(*init)) {
        init->add_option("FILE", arguments->file, "File to write (default: scene.toml)");
        init->add_flag("-f,--force", arguments->force, "Replace the file if it exists");
    }
    return {.app = init,
            .run = [arguments] { return run_init(arguments->file, arguments->force); }};
}

}  // namespace litkit_cli
