// SPDX-License-Identifier: MIT
// litkit compare: one picture of the scene under every reflection × shading
// pair, labelled.
#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "litkit/compare.hpp"
#include "litkit/image.hpp"
#include "options.hpp"
#include "outputs.hpp"

namespace litkit_cli {

namespace {

namespace fs = std::filesystem;

struct CompareArguments {
    SceneArguments scene;  // --width/--height: the size of one tile
    std::string output;
    std::string vary = "both";
    bool no_labels = false;
    bool yes = false;
};

int run_compare(const CompareArguments& arguments) {
    // --width/--height size the tiles here; --reflection/--shading set the
    // model that --vary keeps.
    SceneArguments scene_arguments = arguments.scene;
    scene_arguments.width.reset();
    scene_arguments.height.reset();
    litkit::Scene scene = load(scene_arguments);
    if (arguments.vary != "both") settle_missing_lighting(scene, arguments.yes);
    const std::vector<std::string>& files = arguments.scene.scenes;
    const fs::path output = arguments.output.empty() ? output_beside(files, "-compare.png")
                                                     : fs::path(arguments.output);
    refuse_to_overwrite_inputs(scene, files, output);
    require_picture_name(output, {".png"}, "compare", "a PNG picture");

    litkit::CompareOptions options;
    options.tile_width = arguments.scene.width.value_or(0);
    options.tile_height = arguments.scene.height.value_or(0);
    options.vary = arguments.vary == "reflection" ? litkit::CompareOptions::Vary::Reflection
                   : arguments.vary == "shading"  ? litkit::CompareOptions::Vary::Shading
                                                  : litkit::CompareOptions::Vary::Both;
    options.labels = !arguments.no_labels;
    options.threads = arguments.scene.threads.value_or(0);
    const auto start = std::chrono::steady_clock::now();
    const litkit::CompareGrid grid = litkit::compare_models(scene, options);
    litkit::write_png(grid.image, output);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!grid.overridden_objects.empty()) {
        std::string names;
        for (std::size_t index : grid.overridden_objects) {
            const std::string& name = scene.objects[index].name;
            names += (names.empty() ? "" : ", ") +
                     (name.empty() ? "objects[" + std::to_string(index) + "]" : "'" + name + "'");
        }
        say(std::cout) << "litkit: note: " << names
                       << " set their own models; every tile draws them in the tile's models\n";
    }
    say(std::cout) << "litkit: wrote " << output.string() << " (" << grid.image.width << "x"
                   << grid.image.height << ", " << grid.rows.size() << " x " << grid.columns.size()
                   << " tiles of " << grid.tile_width << "x" << grid.tile_height << ", "
                   << static_cast<int>(seconds * 1000.0 + 0.5) << " ms)\n";
    return exit_success;
}

}  // namespace

Command add_compare(CLI::App& app, const DefinesOptions& defines) {
    auto arguments = std::make_shared<CompareArguments>();
    CLI::App* compare = app.add_subcommand(
        "compare", "One picture of the scene under every reflection x shading pair, labelled");
    if (defines(*compare)) {
        add_scene_options(compare, arguments->scene);
        compare->get_option("--width")->description(
            "Width of one tile (default: the scene's halved)");
        compare->get_option("--height")
            ->description("Height of one tile (default: the scene's halved)");
        compare->add_option("-o,--output", arguments->output,
                            "Output PNG (default: the first scene's name with -compare.png)");
        compare
            ->add_option("--vary", arguments->vary,
                         "both: every pair; reflection: one column (the scene's shading); "
                         "shading: one row (the scene's reflection model)")
            ->check(CLI::IsMember({"both", "reflection", "shading"}))
            ->capture_default_str();
        compare->add_flag("--no-labels", arguments->no_labels,
                          "Only the tiles, edge to edge (each equals litkit render of that pair)");
        compare->add_flag("-y,--yes", arguments->yes,
                          "Use the default models (phong / phong) where [lighting] leaves one out");
    }
    return {
        .app = compare, .run = [arguments] { return run_compare(*arguments); }, .renders = true};
}

}  // namespace litkit_cli
