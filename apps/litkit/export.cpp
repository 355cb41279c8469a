// SPDX-License-Identifier: MIT
// litkit export: the scene as GLSL shaders, or as a C++ program that draws it
// with OpenGL.
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "litkit/error.hpp"
#include "litkit/export.hpp"
#include "options.hpp"

namespace litkit_cli {

namespace {

namespace fs = std::filesystem;

struct ExportArguments {
    SceneArguments scene;
    std::string format;
    std::string directory;
    std::string name;
    bool yes = false;
    bool force = false;
    std::uint64_t max_source_numbers = litkit::default_max_source_numbers;
};

// "my scene.toml" → "my_scene"; the default scene → "default_scene".
std::string program_name_for(const std::vector<std::string>& scenes) {
    if (scenes.empty()) return "default_scene";
    std::string name = fs::path(scenes.front()).stem().string();
    for (char& c : name) {
        const bool keep =
            (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
        if (!keep) c = '_';
    }
    if (name.empty() || (name[0] >= '0' && name[0] <= '9')) name = "scene_" + name;
    return name;
}

int run_export(const ExportArguments& arguments) {
    litkit::Scene scene = load(arguments.scene);
    settle_missing_lighting(scene, arguments.yes);
    const litkit::ExportOptions options{
        .replace_existing = arguments.force,
        .inputs = {arguments.scene.scenes.begin(), arguments.scene.scenes.end()},
        .max_source_numbers = arguments.max_source_numbers};
    const fs::path directory = arguments.directory;
    std::vector<fs::path> written;
    std::string program;
    try {
        if (arguments.format == "glsl") {
            written = litkit::export_glsl(scene, directory, options);
        } else {
            program =
                arguments.name.empty() ? program_name_for(arguments.scene.scenes) : arguments.name;
            const std::string label = arguments.scene.scenes.empty()
                                          ? std::string("(litkit's default scene)")
                                          : arguments.scene.scenes.front();
            written = litkit::export_cpp(scene, directory, program, label, options);
        }
    } catch (const litkit::IoError& error) {
        if (error.reason() != "already exists") throw;
        throw UsageError{"'" + error.path() + "' already exists; pass --force to replace it"};
    } catch (const litkit::ArgumentError& error) {
        throw UsageError{error.what()};
    }
    for (const fs::path& file : written)
        say(std::cout) << "litkit: wrote " << file.string() << "\n";
    if (!program.empty()) {
        say(std::cout) << "build and run it with:\n  "
                       << litkit::export_cpp_instructions(directory, program) << "\n";
    }
    return exit_success;
}

}  // namespace

Command add_export(CLI::App& app, const DefinesOptions& defines) {
    auto arguments = std::make_shared<ExportArguments>();
    CLI::App* export_command = app.add_subcommand(
        "export", "Write the scene as GLSL shaders or as a C++ program that draws it with OpenGL");
    if (defines(*export_command)) {
        add_scene_options(export_command, arguments->scene, false);
        export_command
            ->add_option("--format", arguments->format,
                         "glsl: the vertex and fragment shaders; cpp: main.cpp and CMakeLists.txt")
            ->required()
            ->check(CLI::IsMember({"glsl", "cpp"}));
        export_command->add_option("-o,--output", arguments->directory, "Folder to write into")
            ->required();
        export_command->add_option("--name", arguments->name,
                                   "cpp: the program's name (default: the first scene's name)");
        export_command->add_flag(
            "-y,--yes", arguments->yes,
            "Use the default models (phong / phong) where [lighting] leaves one out");
        export_command->add_flag("-f,--force", arguments->force, "Replace files that exist");
        export_command
            ->add_option("--max-source-numbers", arguments->max_source_numbers,
                         "cpp: the most numbers of vertex data main.cpp may hold")
            ->check(CLI::PositiveNumber)
            ->capture_default_str();
    }
    return {.app = export_command, .run = [arguments] { return run_export(*arguments); }};
}

}  // namespace litkit_cli
