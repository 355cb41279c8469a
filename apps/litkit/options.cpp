// SPDX-License-Identifier: MIT
#include "options.hpp"

#include <unistd.h>

#include <array>
#include <charconv>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include "backend_renderer.hpp"
#include "litkit/lighting.hpp"
#include "litkit/limits.hpp"
#include "litkit/mesh.hpp"
#include "litkit/render.hpp"
#include "litkit/validate.hpp"
#include "usage_error.hpp"

namespace litkit_cli {

namespace {

namespace fs = std::filesystem;

bool quiet_run = false;

// Loads the scene (or the built-in default) and shows its warnings.
litkit::Scene load(const std::vector<std::string>& files,
                   std::uint64_t max_triangles = litkit::default_triangle_budget) {
    if (files.empty()) return litkit::default_scene();
    std::vector<fs::path> paths(files.begin(), files.end());
    litkit::Scene scene = litkit::load_scene(paths, {.max_triangles = max_triangles});
    if (!quiet_run) print_diagnostics(scene.warnings);
    return scene;
}

// A library list of names (litkit::shading_names, ...) as CLI11 takes it.
template <std::size_t N>
std::vector<std::string> names_of(const std::array<std::string_view, N>& names) {
    return {names.begin(), names.end()};
}

}  // namespace

litkit::Backend SceneArguments::backend_id() const {
    return litkit::parse_backend(backend).value_or(litkit::default_backend);
}

void add_normals_options(CLI::App* command, SceneArguments& arguments) {
    command->add_option("--normals", arguments.normals, "How vertex normals weight faces")
        ->check(CLI::IsMember(names_of(litkit::normals_names)));
    command
        ->add_option("--crease-angle", arguments.crease_angle,
                     "Split normals between faces more than this many degrees apart")
        ->check(CLI::Validator(
            [](const std::string& text) -> std::string {
                // docs/spec.md §9.2: (0, 180]. Runs before CLI11 converts the text.
                char* end = nullptr;
                const float degrees = std::strtof(text.c_str(), &end);
                return end != text.c_str() && *end == '\0' && degrees > 0.0f && degrees <= 180.0f
                           ? std::string()
                           : "crease angle " + text + " is not in (0, 180] degrees";
            },
            "DEGREES in (0, 180]"));
}

void add_scene_options(CLI::App* command, SceneArguments& arguments, bool rendering) {
    command->add_option("SCENE", arguments.scenes,
                        "Scene files (TOML), merged in order; none: the built-in default scene");
    command->add_option("--width", arguments.width, "Image width in pixels")
        ->check(CLI::Range(1, litkit::max_image_side));
    command->add_option("--height", arguments.height, "Image height in pixels")
        ->check(CLI::Range(1, litkit::max_image_side));
    std::vector<std::string> reflections;
    for (const litkit::ReflectionModel& model : litkit::reflection_models())
        reflections.emplace_back(model.name);
    command->add_option("--reflection", arguments.reflection, "Reflection model")
        ->check(CLI::IsMember(reflections));
    command->add_option("--shading", arguments.shading, "Shading model")
        ->check(CLI::IsMember(names_of(litkit::shading_names)));
    add_normals_options(command, arguments);
    command
        ->add_option("--max-triangles", arguments.max_triangles,
                     "The scene-wide triangle budget (docs/reliability.md)")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    if (!rendering) return;
    command
        ->add_option("--max-depth", arguments.max_depth,
                     "Surface interactions along one ray path through glass, the first hit "
                     "included (docs/spec.md §10)")
        ->check(CLI::Range(litkit::min_max_depth, litkit::max_max_depth));
    command
        ->add_option("--samples", arguments.samples,
                     "Samples per pixel, 1, 4, 8 or 16: anti-aliasing (docs/spec.md §11)")
        ->check(CLI::Validator(
            [](std::string& text) {
                int samples = 0;
                const auto [end, error] =
                    std::from_chars(text.data(), text.data() + text.size(), samples);
                return error == std::errc() && end == text.data() + text.size() &&
                               litkit::valid_sample_count(samples)
                           ? std::string()
                           : "samples must be 1, 4, 8 or 16, found " + text;
            },
            "1|4|8|16"));
    command
        ->add_option("--threads", arguments.threads, "Threads of the CPU backend (0: one per core)")
        ->check(CLI::Range(0, litkit::max_render_threads));
    // litkit::backends(): every backend with what it is.
    std::vector<std::string> backends;
    std::string backend_help;
    for (const litkit::BackendInfo& backend : litkit::backends()) {
        backends.emplace_back(backend.name);
        backend_help += (backend_help.empty() ? "" : "; ") + std::string(backend.name) + ": " +
                        std::string(backend.summary);
    }
    command->add_option("--backend", arguments.backend, backend_help)
        ->check(CLI::IsMember(backends))
        ->capture_default_str();
}

void set_quiet(bool quiet) { quiet_run = quiet; }

bool quiet() { return quiet_run; }

std::ostream& say(std::ostream& stream) {
    static std::ostream nowhere(nullptr);  // no buffer: every write is dropped
    return quiet_run ? nowhere : stream;
}

void print_diagnostics(const std::vector<litkit::Diagnostic>& diagnostics) {
    for (const litkit::Diagnostic& diagnostic : diagnostics)
        std::cerr << diagnostic.to_string() << "\n";
}

litkit::Scene load(const SceneArguments& arguments) {
    if (arguments.threads) {
        const std::string not_applicable = threads_not_applicable(arguments.backend_id());
        if (!not_applicable.empty()) throw UsageError{not_applicable};
    }
    litkit::Scene scene = load(arguments.scenes, arguments.max_triangles);
    if (arguments.width) scene.output.width = *arguments.width;
    if (arguments.height) scene.output.height = *arguments.height;
    if (arguments.reflection) scene.reflection = litkit::parse_reflection(*arguments.reflection);
    if (arguments.shading) scene.shading = litkit::parse_shading(*arguments.shading);
    if (arguments.normals) scene.normals = litkit::parse_normals(*arguments.normals);
    if (arguments.crease_angle) scene.crease_angle_degrees = *arguments.crease_angle;
    if (arguments.max_depth) scene.max_depth = *arguments.max_depth;
    if (arguments.samples) scene.output.samples = *arguments.samples;
    if (scene.normals == litkit::Normals::File && arguments.normals) {
        // docs/spec.md §9.2: `--normals file` asks every mesh file for a
        // normal at each face corner; validating again reports one that
        // lacks it at its line, before any rendering (warnings were shown).
        // No other weighting, and no crease angle (its option checks the
        // range), changes what validation finds, and validating again
        // repeats every hull and overlap test: for the 261k-triangle sphere
        // 27 M instructions and their fresh memory (docs/performance.md).
        std::vector<litkit::Diagnostic> errors;
        for (litkit::Diagnostic& diagnostic :
             litkit::validate_scene(scene, arguments.max_triangles))
            if (diagnostic.severity == litkit::Severity::Error)
                errors.push_back(std::move(diagnostic));
        if (!errors.empty()) throw litkit::SceneError(std::move(errors));
    }
    return scene;
}

void settle_missing_lighting(litkit::Scene& scene, bool yes) {
    if (scene.reflection && scene.shading) return;
    std::string missing = !scene.reflection && !scene.shading ? "shading/reflection model"
                          : !scene.reflection                 ? "reflection model"
                                                              : "shading model";
    bool use_defaults = yes;
    if (!use_defaults && ::isatty(STDIN_FILENO)) {
        std::cerr << "Scene has no " << missing << ". Use the defaults (phong / phong)? [Y/n] "
                  << std::flush;
        std::string answer;
        if (std::getline(std::cin, answer)) {
            use_defaults = answer.empty() || answer == "y" || answer == "Y" || answer == "yes" ||
                           answer == "Yes";
        }
        if (!use_defaults) std::cerr << (std::cin ? "" : "\n");
    } else if (!use_defaults) {
        throw UsageError{"scene has no " + missing +
                         " and standard input is not a terminal to ask; add [lighting] with "
                         "reflection = \"phong\" and shading = \"phong\" to the scene, pass "
                         "--reflection/--shading, or pass --yes to use the defaults"};
    }
    if (!use_defaults) {
        throw UsageError{"stopped: scene has no " + missing +
                         "; add [lighting] to the scene or pass --yes"};
    }
    if (!scene.reflection) scene.reflection = litkit::default_reflection;
    if (!scene.shading) scene.shading = litkit::default_shading;
}

}  // namespace litkit_cli
