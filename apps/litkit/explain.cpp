// SPDX-License-Identifier: MIT
// litkit explain: how a pixel got its value, step by step; or the equations
// at a point (--at).
#include <algorithm>
#include <cctype>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "commands.hpp"
#include "litkit/explain.hpp"
#include "litkit/render.hpp"
#include "options.hpp"

namespace litkit_cli {

namespace {

struct ExplainArguments {
    SceneArguments scene;
    std::vector<int> pixel;     // X,Y
    std::vector<float> at;      // X,Y,Z
    std::vector<float> normal;  // NX,NY,NZ
    std::string object;         // --at: whose material (name or index)
    bool json = false;
    bool yes = false;
};

int run_explain(const ExplainArguments& arguments) {
    litkit::Scene scene = load(arguments.scene);
    settle_missing_lighting(scene, arguments.yes);
    if (arguments.pixel.empty() == arguments.at.empty())
        throw UsageError{"explain needs either --pixel X,Y or --at X,Y,Z --normal NX,NY,NZ"};
    if (!arguments.pixel.empty()) {
        const int x = arguments.pixel[0], y = arguments.pixel[1];
        if (x < 0 || y < 0 || x >= scene.output.width || y >= scene.output.height) {
            throw UsageError{"pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                             ") is outside the " + std::to_string(scene.output.width) + "x" +
                             std::to_string(scene.output.height) + " image"};
        }
        litkit::RenderOptions options;
        options.threads = arguments.scene.threads.value_or(0);
        const litkit::PixelExplanation explanation = litkit::explain_pixel(scene, x, y, options);
        std::cout << (arguments.json ? litkit::explanation_json(explanation, scene) + "\n"
                                     : litkit::explanation_text(explanation, scene));
        return exit_success;
    }
    if (arguments.normal.empty()) throw UsageError{"--at needs --normal NX,NY,NZ"};
    const glm::vec3 normal{arguments.normal[0], arguments.normal[1], arguments.normal[2]};
    if (normal == glm::vec3(0.0f)) throw UsageError{"--normal must not be the zero vector"};
    // The material: the object named (or numbered) by --object, else the first.
    litkit::Material material;
    std::optional<litkit::Reflection> reflection;
    if (!scene.objects.empty()) {
        std::size_t index = 0;
        if (!arguments.object.empty()) {
            const auto named = std::find_if(
                scene.objects.begin(), scene.objects.end(),
                [&](const litkit::SceneObject& o) { return o.name == arguments.object; });
            if (named != scene.objects.end()) {
                index = static_cast<std::size_t>(named - scene.objects.begin());
            } else if (std::all_of(arguments.object.begin(), arguments.object.end(), ::isdigit) &&
                       std::stoul(arguments.object) < scene.objects.size()) {
                index = std::stoul(arguments.object);
            } else {
                throw UsageError{"no object '" + arguments.object + "' in the scene"};
            }
        }
        material = scene.objects[index].material;
        reflection = scene.objects[index].reflection;
    }
    const litkit::Reflection model =
        reflection.value_or(scene.reflection.value_or(litkit::default_reflection));
    const litkit::PointEvaluation point = litkit::explain_point(
        scene, model, material, {arguments.at[0], arguments.at[1], arguments.at[2]}, normal);
    std::cout << (arguments.json ? litkit::evaluation_json(point, scene, model) + "\n"
                                 : litkit::evaluation_text(point, scene, model, material));
    return exit_success;
}

}  // namespace

Command add_explain(CLI::App& app, const DefinesOptions& defines) {
    auto arguments = std::make_shared<ExplainArguments>();
    CLI::App* explain = app.add_subcommand(
        "explain", "How a pixel got its value, step by step; or the equations at a point (--at)");
    if (defines(*explain)) {
        add_scene_options(explain, arguments->scene);
        explain->add_option("--pixel", arguments->pixel, "The pixel X,Y (0,0: top left)")
            ->delimiter(',')
            ->expected(2);
        explain->add_option("--at", arguments->at, "A point X,Y,Z in the world")
            ->delimiter(',')
            ->expected(3);
        explain->add_option("--normal", arguments->normal, "With --at: the surface normal NX,NY,NZ")
            ->delimiter(',')
            ->expected(3);
        explain->add_option(
            "--object", arguments->object,
            "With --at: the object (name or index) whose material to use (default: the first)");
        explain->add_flag("--json", arguments->json, "One JSON object instead of text");
        explain->add_flag("-y,--yes", arguments->yes,
                          "Use the default models (phong / phong) where [lighting] leaves one out");
    }
    return {.app = explain, .run = [arguments] { return run_explain(*arguments); }};
}

}  // namespace litkit_cli
