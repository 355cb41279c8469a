// litkit: the command-line tool. Thin by design: it parses arguments, calls
// the library and decides how results and errors are shown and which exit
// status they get (docs/spec.md §6: 0 success, 1 a file could not be read or written,
// 2 invalid input or usage).
#include <CLI/CLI.hpp>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "litkit/error.hpp"
#include "litkit/export.hpp"
#include "litkit/files.hpp"
#include "litkit/gl_renderer.hpp"
#include "litkit/image.hpp"
#include "litkit/render.hpp"
#include "litkit/scene.hpp"
#include "litkit/validate.hpp"

namespace {

namespace fs = std::filesystem;

constexpr int exit_success = 0;
constexpr int exit_io = 1;
constexpr int exit_invalid = 2;

// What `render` and `bench` share: the scene and what replaces parts of it.
struct SceneArguments {
    std::vector<std::string> scenes;
    std::optional<int> width;
    std::optional<int> height;
    std::optional<std::string> reflection;
    std::optional<std::string> shading;
    std::optional<std::string> normals;
    std::optional<float> crease_angle;
    int threads = 0;
    std::string backend = "cpu";
};

struct RenderArguments {
    SceneArguments scene;
    std::string output;
    bool yes = false;
};

struct ExportArguments {
    SceneArguments scene;
    std::string format;
    std::string directory;
    std::string name;
    bool yes = false;
    bool force = false;
};

struct BenchArguments {
    SceneArguments scene;
    int frames = 20;
};

// docs/spec.md §9.2's options, shared by every command that loads a scene.
void add_normals_options(CLI::App* command, SceneArguments& arguments) {
    command->add_option("--normals", arguments.normals, "How vertex normals weight faces")
        ->check(CLI::IsMember({"mean", "area", "angle", "max", "file"}));
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

// `rendering`: also the options that choose and tune a renderer.
void add_scene_options(CLI::App* command, SceneArguments& arguments, bool rendering = true) {
    command->add_option("SCENE", arguments.scenes,
                        "Scene files (TOML), merged in order; none: the built-in default scene");
    command->add_option("--width", arguments.width, "Image width in pixels")
        ->check(CLI::Range(1, 16384));
    command->add_option("--height", arguments.height, "Image height in pixels")
        ->check(CLI::Range(1, 16384));
    command->add_option("--reflection", arguments.reflection, "Reflection model")
        ->check(CLI::IsMember({"lambert", "half-lambert", "phong", "blinn-phong"}));
    command->add_option("--shading", arguments.shading, "Shading model")
        ->check(CLI::IsMember({"flat", "gouraud", "phong", "faceted"}));
    add_normals_options(command, arguments);
    if (!rendering) return;
    command->add_option("--threads", arguments.threads, "Threads of the CPU backend (0: one per core)")
        ->check(CLI::Range(0, 1024));
    command->add_option("--backend", arguments.backend,
                        "cpu: litkit's own renderer; gl: OpenGL 3.3 on a headless EGL context")
        ->check(CLI::IsMember({"cpu", "gl"}))
        ->capture_default_str();
}

// The renderer chosen with --backend; both draw the picture of docs/spec.md §1-§4.
class Backend {
public:
    Backend(const litkit::Scene& scene, const SceneArguments& arguments) {
        const litkit::RenderOptions options{.threads = arguments.threads};
        if (arguments.backend == "gl")
            gl_ = std::make_unique<litkit::GlRenderer>(scene, options);
        else
            cpu_ = std::make_unique<litkit::Renderer>(scene, options);
    }
    void render_into(litkit::Image& image) {
        if (gl_)
            gl_->render_into(image);
        else
            cpu_->render_into(image);
    }
    std::size_t triangle_count() const {
        return gl_ ? gl_->triangle_count() : cpu_->triangle_count();
    }
    std::string description() const {
        if (gl_) return "OpenGL backend: " + gl_->description();
        return "CPU backend: " + std::to_string(cpu_->thread_count()) + " threads";
    }
    // Pixels shaded in the last frame, where the backend counts them.
    std::optional<std::size_t> shaded_pixel_count() const {
        if (cpu_) return cpu_->shaded_pixel_count();
        return std::nullopt;
    }

private:
    std::unique_ptr<litkit::Renderer> cpu_;
    std::unique_ptr<litkit::GlRenderer> gl_;
};

// A usage problem found after CLI11's own parsing (exit status 2).
struct UsageError {
    std::string message;
};

void print_diagnostics(const std::vector<litkit::Diagnostic>& diagnostics) {
    for (const litkit::Diagnostic& diagnostic : diagnostics)
        std::cerr << diagnostic.to_string() << "\n";
}

// Loads the scene (or the built-in default) and shows its warnings.
litkit::Scene load(const std::vector<std::string>& files) {
    if (files.empty()) return litkit::default_scene();
    std::vector<fs::path> paths(files.begin(), files.end());
    litkit::Scene scene = litkit::load_scene(paths);
    print_diagnostics(scene.warnings);
    return scene;
}

// R11: when [lighting] leaves a model out, ask on a terminal; `--yes` answers
// for the user; without a terminal it is an error that says how to fix it.
void settle_missing_lighting(litkit::Scene& scene, bool yes) {
    if (scene.reflection && scene.shading) return;
    std::string missing = !scene.reflection && !scene.shading ? "shading/reflection model"
                          : !scene.reflection                ? "reflection model"
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

fs::path default_output(const std::vector<std::string>& scenes) {
    if (scenes.empty()) return "default.png";
    return fs::path(scenes.front()).filename().replace_extension(".png");
}

// Every file the run reads: the scene files and the mesh files they name.
std::vector<fs::path> inputs_of(const litkit::Scene& scene, const std::vector<std::string>& files) {
    std::vector<fs::path> inputs(files.begin(), files.end());
    for (const litkit::SceneObject& object : scene.objects) {
        if (const auto* mesh = std::get_if<litkit::MeshFileShape>(&object.shape))
            inputs.push_back(mesh->file);
    }
    return inputs;
}

// The scene with the command line's replacements of [output] and [lighting].
litkit::Scene load(const SceneArguments& arguments) {
    litkit::Scene scene = load(arguments.scenes);
    if (arguments.width) scene.output.width = *arguments.width;
    if (arguments.height) scene.output.height = *arguments.height;
    if (arguments.reflection) scene.reflection = litkit::parse_reflection(*arguments.reflection);
    if (arguments.shading) scene.shading = litkit::parse_shading(*arguments.shading);
    if (arguments.normals) scene.normals = litkit::parse_normals(*arguments.normals);
    if (arguments.crease_angle) scene.crease_angle_degrees = *arguments.crease_angle;
    if (arguments.normals || arguments.crease_angle) {
        // docs/spec.md §9.2: `--normals file` asks every mesh file for a
        // normal at each face corner; validating again reports one that
        // lacks it at its line, before any rendering (warnings were shown).
        std::vector<litkit::Diagnostic> errors;
        for (litkit::Diagnostic& diagnostic : litkit::validate_scene(scene))
            if (diagnostic.severity == litkit::Severity::Error) errors.push_back(std::move(diagnostic));
        if (!errors.empty()) throw litkit::SceneError(std::move(errors));
    }
    return scene;
}

int run_render(const RenderArguments& arguments) {
    litkit::Scene scene = load(arguments.scene);
    settle_missing_lighting(scene, arguments.yes);

    const std::vector<std::string>& files = arguments.scene.scenes;
    const fs::path output =
        arguments.output.empty() ? default_output(files) : fs::path(arguments.output);
    for (const fs::path& input : inputs_of(scene, files)) {
        if (litkit::same_file(input, output)) {
            throw UsageError{"refusing to write the image over input file '" + input.string() +
                             "'; choose another name with -o"};
        }
    }

    const auto start = std::chrono::steady_clock::now();
    Backend renderer(scene, arguments.scene);
    litkit::Image image;
    renderer.render_into(image);
    litkit::write_png(image, output);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << "litkit: wrote " << output.string() << " (" << image.width << "x" << image.height
              << ", " << renderer.triangle_count() << " triangles, " << static_cast<int>(seconds * 1000.0 + 0.5)
              << " ms" << (arguments.scene.backend == "gl" ? "; " + renderer.description() : "")
              << ")\n";
    return exit_success;
}

int run_check(const SceneArguments& arguments) {
    load(arguments);
    std::cout << "ok\n";
    return exit_success;
}

// Renders frames into memory and reports their times. One warm-up frame
// first; median and minimum of the rest (timing, not a test: nothing here
// passes or fails on speed).
int run_bench(const BenchArguments& arguments) {
    litkit::Scene scene = load(arguments.scene);
    settle_missing_lighting(scene, true);

    using clock = std::chrono::steady_clock;
    const auto setup_start = clock::now();
    Backend renderer(scene, arguments.scene);
    const double setup_ms =
        std::chrono::duration<double, std::milli>(clock::now() - setup_start).count();
    litkit::Image image;
    renderer.render_into(image);  // warm-up
    std::vector<double> frame_ms;
    for (int frame = 0; frame < arguments.frames; ++frame) {
        const auto start = clock::now();
        renderer.render_into(image);
        frame_ms.push_back(std::chrono::duration<double, std::milli>(clock::now() - start).count());
    }
    std::sort(frame_ms.begin(), frame_ms.end());
    const std::size_t n = frame_ms.size();
    const double median = n % 2 ? frame_ms[n / 2] : 0.5 * (frame_ms[n / 2 - 1] + frame_ms[n / 2]);
    const std::vector<std::string>& files = arguments.scene.scenes;
    std::printf("scene: %s\n", files.empty() ? "(default)" : files.front().c_str());
    std::printf("renderer: %s\n", renderer.description().c_str());
    std::printf("image: %dx%d, %zu triangles\n", image.width, image.height,
                renderer.triangle_count());
    std::printf("setup: %.3f ms (meshes, normals, world space%s)\n", setup_ms,
                arguments.scene.backend == "gl" ? ", context, shaders, upload" : "");
    if (const auto shaded = renderer.shaded_pixel_count()) {
        std::printf("pixels shaded: %zu per frame (%.1f%% of the image)\n", *shaded,
                    100.0 * static_cast<double>(*shaded) /
                        (static_cast<double>(image.width) * image.height));
    }
    std::printf("frames: %d, median %.3f ms, min %.3f ms\n", arguments.frames, median,
                frame_ms.front());
    std::printf("median_frame_ms=%.3f fps=%.1f\n", median, 1000.0 / median);
    return exit_success;
}

// "my scene.toml" → "my_scene"; the default scene → "default_scene".
std::string program_name_for(const std::vector<std::string>& scenes) {
    if (scenes.empty()) return "default_scene";
    std::string name = fs::path(scenes.front()).stem().string();
    for (char& c : name) {
        const bool keep = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
        if (!keep) c = '_';
    }
    if (name.empty() || (name[0] >= '0' && name[0] <= '9')) name = "scene_" + name;
    return name;
}

int run_export(const ExportArguments& arguments) {
    litkit::Scene scene = load(arguments.scene);
    settle_missing_lighting(scene, arguments.yes);
    const litkit::ExportOptions options{.replace_existing = arguments.force};
    const fs::path directory = arguments.directory;
    std::vector<fs::path> written;
    std::string program;
    try {
        if (arguments.format == "glsl") {
            written = litkit::export_glsl(scene, directory, options);
        } else {
            program = arguments.name.empty() ? program_name_for(arguments.scene.scenes) : arguments.name;
            const std::string label = arguments.scene.scenes.empty()
                                          ? std::string("(litkit's default scene)")
                                          : arguments.scene.scenes.front();
            written = litkit::export_cpp(scene, directory, program, label, options);
        }
    } catch (const litkit::IoError& error) {
        if (error.reason() != "already exists") throw;
        throw UsageError{"'" + error.path() + "' already exists; pass --force to replace it"};
    } catch (const std::invalid_argument& error) {
        throw UsageError{error.what()};
    }
    for (const fs::path& file : written) std::cout << "litkit: wrote " << file.string() << "\n";
    if (!program.empty()) {
        std::cout << "build and run it with:\n  "
                  << litkit::export_cpp_instructions(directory, program) << "\n";
    }
    return exit_success;
}

int run_init(const std::string& file, bool force) {
    const fs::path path = file.empty() ? fs::path("scene.toml") : fs::path(file);
    std::error_code error;
    if (!force && fs::exists(path, error)) {
        throw UsageError{"'" + path.string() + "' already exists; pass --force to replace it"};
    }
    litkit::write_file_atomically(path, litkit::default_scene_toml());
    std::cout << "litkit: wrote " << path.string() << "; render it with: litkit render "
              << path.string() << "\n";
    return exit_success;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"litkit: renders a lit, shaded 3D scene from a scene file"};
    app.set_version_flag("--version", std::string("litkit ") + LITKIT_VERSION);
    app.require_subcommand(1);
    // Lets `--version` (and any option of the top level) follow a command:
    // `litkit render --version` works as docs/spec.md §8 asks.
    app.fallthrough();

    RenderArguments render_arguments;
    CLI::App* render = app.add_subcommand("render", "Render a scene (or the default scene) to PNG");
    add_scene_options(render, render_arguments.scene);
    render->add_option("-o,--output", render_arguments.output,
                       "Output PNG (default: the first scene's name with .png)");
    render->add_flag("-y,--yes", render_arguments.yes,
                     "Use the default models (phong / phong) where [lighting] leaves one out");

    SceneArguments check_arguments;
    CLI::App* check = app.add_subcommand("check", "Validate scene files without rendering");
    check->add_option("SCENE", check_arguments.scenes, "Scene files (TOML), merged in order")
        ->required();
    add_normals_options(check, check_arguments);

    std::string init_file;
    bool init_force = false;
    CLI::App* init = app.add_subcommand("init", "Write the default scene as a starting file");
    init->add_option("FILE", init_file, "File to write (default: scene.toml)");
    init->add_flag("-f,--force", init_force, "Replace the file if it exists");

    ExportArguments export_arguments;
    CLI::App* export_command = app.add_subcommand(
        "export", "Write the scene as GLSL shaders or as a C++ program that draws it with OpenGL");
    add_scene_options(export_command, export_arguments.scene, false);
    export_command
        ->add_option("--format", export_arguments.format,
                     "glsl: the vertex and fragment shaders; cpp: main.cpp and CMakeLists.txt")
        ->required()
        ->check(CLI::IsMember({"glsl", "cpp"}));
    export_command->add_option("-o,--output", export_arguments.directory, "Folder to write into")
        ->required();
    export_command->add_option("--name", export_arguments.name,
                               "cpp: the program's name (default: the first scene's name)");
    export_command->add_flag("-y,--yes", export_arguments.yes,
                             "Use the default models (phong / phong) where [lighting] leaves one out");
    export_command->add_flag("-f,--force", export_arguments.force, "Replace files that exist");

    BenchArguments bench_arguments;
    CLI::App* bench = app.add_subcommand(
        "bench", "Render frames into memory and report the time per frame");
    add_scene_options(bench, bench_arguments.scene);
    bench->add_option("--frames", bench_arguments.frames, "Frames to time (after one warm-up)")
        ->check(CLI::Range(1, 100000));

    try {
        app.parse(argc, argv);
    } catch (const CLI::Success& success) {
        return app.exit(success);
    } catch (const CLI::ParseError& error) {
        app.exit(error);
        return exit_invalid;
    }

    try {
        if (render->parsed()) return run_render(render_arguments);
        if (check->parsed()) return run_check(check_arguments);
        if (init->parsed()) return run_init(init_file, init_force);
        if (bench->parsed()) return run_bench(bench_arguments);
        if (export_command->parsed()) return run_export(export_arguments);
    } catch (const litkit::SceneError& error) {
        print_diagnostics(error.diagnostics());
        print_diagnostics(error.warnings());
        return exit_invalid;
    } catch (const litkit::IoError& error) {
        std::cerr << error.what() << "\n";
        return exit_io;
    } catch (const litkit::GlError& error) {
        std::cerr << "error: " << error.what() << "\n"
                  << "hint: render without OpenGL with --backend cpu\n";
        return exit_io;
    } catch (const UsageError& error) {
        std::cerr << "error: " << error.message << "\n";
        return exit_invalid;
    } catch (const std::exception& error) {
        std::cerr << "error: " << error.what() << "\n";
        return exit_io;
    }
    return exit_invalid;
}
