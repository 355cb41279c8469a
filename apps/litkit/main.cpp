// litkit: the command-line tool. Thin by design: it parses arguments, calls
// the library and decides how results and errors are shown and which exit
// status they get (docs/spec.md §6: 0 success, 1 a file could not be read or written,
// 2 invalid input or usage).
#include <CLI/CLI.hpp>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <new>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "litkit/compare.hpp"
#include "litkit/error.hpp"
#include "litkit/explain.hpp"
#include "litkit/export.hpp"
#include "core/files.hpp"
#include "litkit/gl_renderer.hpp"
#include "litkit/image.hpp"
#include "litkit/render.hpp"
#include "litkit/scene.hpp"
#include "litkit/turntable.hpp"
#include "gl_module.hpp"
#include "heap.hpp"
#include "modules.hpp"
#include "usage.hpp"
#include "viewer/viewer.hpp"
#include "litkit/validate.hpp"

namespace {

namespace fs = std::filesystem;

constexpr int exit_success = 0;
constexpr int exit_io = 1;
constexpr int exit_invalid = 2;

// A catchable signal ends the run as it would have, but first removes the
// temporary files of a write in progress (docs/reliability.md). A file size
// limit (ulimit -f) makes write() fail with EFBIG instead of killing the
// process, so that the failed write is reported and cleaned up like a full disk.
extern "C" void remove_temporaries_and_end(int signal_number) {
    litkit::remove_registered_temporaries();
    ::raise(signal_number);  // SA_RESETHAND | SA_NODEFER: the default action, now
}

void install_signal_handlers() {
    struct sigaction action {};
    action.sa_handler = remove_temporaries_and_end;
    action.sa_flags = SA_RESETHAND | SA_NODEFER;
    sigemptyset(&action.sa_mask);
    for (int signal_number : {SIGINT, SIGTERM, SIGHUP, SIGQUIT}) {
        struct sigaction previous {};
        // A signal ignored by whoever started us (nohup) stays ignored.
        if (::sigaction(signal_number, nullptr, &previous) == 0 && previous.sa_handler == SIG_IGN)
            continue;
        ::sigaction(signal_number, &action, nullptr);
    }
    ::signal(SIGXFSZ, SIG_IGN);
}

// `-o -`: the picture goes to standard output, so every message goes to
// standard error.
// Also any name of this process's standard output (/dev/stdout,
// /proc/self/fd/1, a file that standard output is redirected to).
bool is_standard_output(const std::filesystem::path& output) {
    if (output == "-") return true;
    struct stat named {};
    struct stat standard {};
    return ::stat(output.c_str(), &named) == 0 && ::fstat(STDOUT_FILENO, &standard) == 0 &&
           named.st_dev == standard.st_dev && named.st_ino == standard.st_ino;
}

void write_png_output(const litkit::Image& image, const std::filesystem::path& output) {
    if (is_standard_output(output)) {
        litkit::write_all(STDOUT_FILENO, litkit::encode_png(image), "standard output");
    } else {
        litkit::write_png(image, output);
    }
}

// What `render` and `bench` share: the scene and what replaces parts of it.
struct SceneArguments {
    std::vector<std::string> scenes;
    std::optional<int> width;
    std::optional<int> height;
    std::optional<std::string> reflection;
    std::optional<std::string> shading;
    std::optional<std::string> normals;
    std::optional<float> crease_angle;
    std::optional<int> threads;  // CPU backend only; none: one per core
    std::string backend = "cpu";
    std::uint64_t max_triangles = litkit::default_triangle_budget;  // docs/reliability.md
};

struct RenderArguments {
    SceneArguments scene;
    std::string output;
    bool yes = false;
};

struct CompareArguments {
    SceneArguments scene;  // --width/--height: the size of one tile
    std::string output;
    std::string vary = "both";
    bool no_labels = false;
    bool yes = false;
};

struct ViewArguments {
    SceneArguments scene;
    int orbit_frames = 0;
    bool no_ui = false;
    bool yes = false;
};

struct ExplainArguments {
    SceneArguments scene;
    std::vector<int> pixel;     // X,Y
    std::vector<float> at;      // X,Y,Z
    std::vector<float> normal;  // NX,NY,NZ
    std::string object;         // --at: whose material (name or index)
    bool json = false;
    bool yes = false;
};

struct TurntableArguments {
    SceneArguments scene;
    std::string output;
    int frames = 72;
    int delay_ms = 40;
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
    std::vector<std::string> reflections;
    for (const litkit::ReflectionModel& model : litkit::reflection_models())
        reflections.emplace_back(model.name);
    command->add_option("--reflection", arguments.reflection, "Reflection model")
        ->check(CLI::IsMember(reflections));
    command->add_option("--shading", arguments.shading, "Shading model")
        ->check(CLI::IsMember({"flat", "gouraud", "phong", "faceted"}));
    add_normals_options(command, arguments);
    command->add_option("--max-triangles", arguments.max_triangles,
                        "The scene-wide triangle budget (docs/reliability.md)")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
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
        const litkit::RenderOptions options{.threads = arguments.threads.value_or(0)};
        if (arguments.backend == "gl") {
            litkit_cli::CaughtError error;
            gl_ = litkit_cli::open_module<litkit_cli::GlModule, litkit::RenderOptions>(
                      "litkit-gl.so", "litkit_gl_module", "--backend gl")
                      .create(scene, options, error);
            if (!gl_) litkit_cli::throw_again(error);
        } else {
            cpu_ = std::make_unique<litkit::Renderer>(scene, options);
        }
    }
    void render_into(litkit::Image& image) {
        litkit_cli::CaughtError error;
        if (!gl_)
            cpu_->render_into(image);
        else if (!gl_->render_into(image, error))
            litkit_cli::throw_again(error);
    }
    std::size_t triangle_count() const {
        return gl_ ? gl_->triangle_count() : cpu_->triangle_count();
    }
    std::string description() const {
        if (gl_) return "OpenGL backend: " + gl_->description();
        return "CPU backend: " + std::to_string(cpu_->thread_count()) + " threads, " +
               cpu_->kernel_set() + " kernels";
    }
    // Pixels shaded in the last frame, where the backend counts them.
    std::optional<std::size_t> shaded_pixel_count() const {
        if (cpu_) return cpu_->shaded_pixel_count();
        return std::nullopt;
    }

private:
    std::unique_ptr<litkit::Renderer> cpu_;
    std::unique_ptr<litkit_cli::GlBackend> gl_;  // from the module litkit-gl.so
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
litkit::Scene load(const std::vector<std::string>& files,
                   std::uint64_t max_triangles = litkit::default_triangle_budget) {
    if (files.empty()) return litkit::default_scene();
    std::vector<fs::path> paths(files.begin(), files.end());
    litkit::Scene scene = litkit::load_scene(paths, {.max_triangles = max_triangles});
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
    if (scenes.front() == "-") return "stdin.png";  // the scene came from standard input
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
    if (arguments.backend == "gl" && arguments.threads) {
        // OpenGL decides its own parallelism (a GPU's cores, or llvmpipe's
        // LP_NUM_THREADS): say so rather than ignore the option.
        throw UsageError{"--threads applies to the CPU backend; with --backend gl the driver "
                         "chooses (for Mesa's llvmpipe, set LP_NUM_THREADS)"};
    }
    litkit::Scene scene = load(arguments.scenes, arguments.max_triangles);
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
        for (litkit::Diagnostic& diagnostic : litkit::validate_scene(scene, arguments.max_triangles))
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
    write_png_output(image, output);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    (is_standard_output(output) ? std::cerr : std::cout) << "litkit: wrote " << output.string() << " (" << image.width << "x" << image.height
              << ", " << renderer.triangle_count() << " triangles, " << static_cast<int>(seconds * 1000.0 + 0.5)
              << " ms" << (arguments.scene.backend == "gl" ? "; " + renderer.description() : "")
              << ")\n";
    // Done: the picture is in its file and the message out. The process
    // ends here, without taking the renderer, its threads and its memory
    // apart (a one-shot run's last 0.3 ms; the system frees it all at once).
    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);
    _exit(exit_success);
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
    const litkit::ExportOptions options{
        .replace_existing = arguments.force,
        .inputs = {arguments.scene.scenes.begin(), arguments.scene.scenes.end()}};
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
    } catch (const litkit::ArgumentError& error) {
        throw UsageError{error.what()};
    }
    for (const fs::path& file : written) std::cout << "litkit: wrote " << file.string() << "\n";
    if (!program.empty()) {
        std::cout << "build and run it with:\n  "
                  << litkit::export_cpp_instructions(directory, program) << "\n";
    }
    return exit_success;
}

// The output must not be one of the inputs (docs/spec.md §6).
void refuse_to_overwrite_inputs(const litkit::Scene& scene, const std::vector<std::string>& files,
                                const fs::path& output) {
    for (const fs::path& input : inputs_of(scene, files)) {
        if (litkit::same_file(input, output)) {
            throw UsageError{"refusing to write over input file '" + input.string() +
                             "'; choose another name with -o"};
        }
    }
}

// A scene file's stem with a suffix: "scene.toml" → "scene-compare.png".
fs::path output_beside(const std::vector<std::string>& scenes, const std::string& suffix) {
    const std::string stem = scenes.empty() ? "default" : fs::path(scenes.front()).stem().string();
    return stem + suffix;
}

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
        std::cout << "litkit: note: " << names
                  << " set their own models; every tile draws them in the tile's models\n";
    }
    std::cout << "litkit: wrote " << output.string() << " (" << grid.image.width << "x"
              << grid.image.height << ", " << grid.rows.size() << " x " << grid.columns.size()
              << " tiles of " << grid.tile_width << "x" << grid.tile_height << ", "
              << static_cast<int>(seconds * 1000.0 + 0.5) << " ms)\n";
    return exit_success;
}

int run_view(const ViewArguments& arguments) {
    // SDL2 and Dear ImGui load only now, with the module (docs/design.md).
    const auto& viewer = litkit_cli::open_module<litkit_cli::ViewerModule, litkit_cli::ViewerOptions>(
        "litkit-view.so", "litkit_viewer_module", "litkit view");
    litkit::Scene scene = load(arguments.scene);
    settle_missing_lighting(scene, arguments.yes);
    litkit_cli::ViewerOptions options;
    options.files.assign(arguments.scene.scenes.begin(), arguments.scene.scenes.end());
    options.title = arguments.scene.scenes.empty() ? "default scene" : arguments.scene.scenes.front();
    options.gl_backend = arguments.scene.backend == "gl";
    options.threads = arguments.scene.threads.value_or(0);
    options.show_panel = !arguments.no_ui;
    options.benchmark_frames = arguments.orbit_frames;
    // A reload reads the files as at start; [lighting] left out now takes
    // the defaults (there is no terminal to ask in a window).
    options.load = [arguments](litkit::Scene& loaded, litkit_cli::CaughtError& error) noexcept {
        return litkit_cli::call_catching(
            [&] {
                loaded = load(arguments.scene);
                settle_missing_lighting(loaded, true);
            },
            error);
    };
    litkit_cli::CaughtError error;
    const int status = viewer.run(options, std::move(scene), error);
    if (error.kind != litkit_cli::CaughtError::Kind::None) litkit_cli::throw_again(error);
    return status;
}

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
            const auto named = std::find_if(scene.objects.begin(), scene.objects.end(),
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

// "[#####.....] 12/72 frames, 30.1 frames/s, 2 s left" on a terminal.
void show_progress(int done, int total, double seconds) {
    constexpr int bar = 30;
    const int filled = done * bar / total;
    const double rate = seconds > 0.0 ? done / seconds : 0.0;
    const double left = rate > 0.0 ? (total - done) / rate : 0.0;
    std::fprintf(stderr, "\r[%s%s] %d/%d frames, %.1f frames/s, %.0f s left ",
                 std::string(static_cast<std::size_t>(filled), '#').c_str(),
                 std::string(static_cast<std::size_t>(bar - filled), '.').c_str(), done, total, rate,
                 left);
    std::fflush(stderr);
}

int run_turntable(const TurntableArguments& arguments) {
    litkit::Scene scene = load(arguments.scene);
    settle_missing_lighting(scene, arguments.yes);
    const std::vector<std::string>& files = arguments.scene.scenes;
    const std::string target =
        arguments.output.empty() ? output_beside(files, ".gif").string() : arguments.output;
    // "DIR/" or an existing folder: numbered PNGs; anything else: one GIF.
    const bool to_folder = target.ends_with('/') || fs::is_directory(target);
    const fs::path output(target);
    if (!to_folder) refuse_to_overwrite_inputs(scene, files, output);

    const bool terminal = ::isatty(STDERR_FILENO) == 1;
    const auto start = std::chrono::steady_clock::now();
    const auto elapsed = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    const litkit::Observer own = scene.observer;
    std::vector<litkit::Image> frames;
    std::vector<fs::path> written;
    const int digits = std::max(3, static_cast<int>(std::to_string(arguments.frames - 1).size()));
    if (to_folder) fs::create_directories(output);
    for (int k = 0; k < arguments.frames; ++k) {
        scene.observer = litkit::orbit(own, 360.0 * k / arguments.frames);
        Backend renderer(scene, arguments.scene);
        litkit::Image image;
        renderer.render_into(image);
        if (to_folder) {
            std::string number = std::to_string(k);
            number.insert(0, static_cast<std::size_t>(digits) - number.size(), '0');
            const fs::path frame = output / ("frame-" + number + ".png");
            refuse_to_overwrite_inputs(scene, files, frame);
            litkit::write_png(image, frame);
            written.push_back(frame);
        } else {
            frames.push_back(std::move(image));
        }
        if (terminal) show_progress(k + 1, arguments.frames, elapsed());
    }
    if (!to_folder) litkit::write_gif(frames, output, arguments.delay_ms);
    if (terminal) std::fputs("\n", stderr);
    std::cout << "litkit: wrote " << (to_folder ? written.size() : 1) << " "
              << (to_folder ? "frames into " : "animated GIF ") << output.string() << " ("
              << arguments.frames << " frames, " << static_cast<int>(elapsed() * 1000.0 + 0.5)
              << " ms)\n";
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
    litkit_cli::use_large_pages_for_the_heap();
    CLI::App app{"litkit: renders a lit, shaded 3D scene from a scene file"};
    app.set_version_flag("--version", std::string("litkit ") + LITKIT_VERSION);
    app.require_subcommand(1);
    // Lets `--version` (and any option of the top level) follow a command:
    // `litkit render --version` works as docs/spec.md §8 asks.
    app.fallthrough();

    // Only the command at hand gets its options: CLI11 spends about 3 µs
    // on each option it adds (0.3 ms for all of them, a twentieth of
    // `litkit render`'s whole run). Every command is still listed, and
    // --help, --version or no command at all define everything.
    const std::string_view command_word = argc > 1 ? std::string_view(argv[1]) : std::string_view();
    const bool define_all = command_word.empty() || command_word.starts_with("-");
    const auto defines = [&](const CLI::App* command) {
        return define_all || command->get_name() == command_word;
    };

    RenderArguments render_arguments;
    CLI::App* render = app.add_subcommand("render", "Render a scene (or the default scene) to PNG");
    if (defines(render)) {
        add_scene_options(render, render_arguments.scene);
        render->add_option("-o,--output", render_arguments.output,
                           "Output PNG (default: the first scene's name with .png; -: standard output)");
        render->add_flag("-y,--yes", render_arguments.yes,
                         "Use the default models (phong / phong) where [lighting] leaves one out");
    }

    SceneArguments check_arguments;
    CLI::App* check = app.add_subcommand("check", "Validate scene files without rendering");
    if (defines(check)) {
        check->add_option("SCENE", check_arguments.scenes, "Scene files (TOML), merged in order")
            ->required();
        add_normals_options(check, check_arguments);
        check->add_option("--max-triangles", check_arguments.max_triangles,
                          "The scene-wide triangle budget (docs/reliability.md)")
            ->check(CLI::PositiveNumber)
            ->capture_default_str();
    }

    std::string init_file;
    bool init_force = false;
    CLI::App* init = app.add_subcommand("init", "Write the default scene as a starting file");
    if (defines(init)) {
        init->add_option("FILE", init_file, "File to write (default: scene.toml)");
        init->add_flag("-f,--force", init_force, "Replace the file if it exists");
    }

    ExportArguments export_arguments;
    CLI::App* export_command = app.add_subcommand(
        "export", "Write the scene as GLSL shaders or as a C++ program that draws it with OpenGL");
    if (defines(export_command)) {
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
    }

    CompareArguments compare_arguments;
    CLI::App* compare = app.add_subcommand(
        "compare", "One picture of the scene under every reflection x shading pair, labelled");
    if (defines(compare)) {
        add_scene_options(compare, compare_arguments.scene);
        compare->get_option("--width")->description("Width of one tile (default: the scene's halved)");
        compare->get_option("--height")->description("Height of one tile (default: the scene's halved)");
        compare->add_option("-o,--output", compare_arguments.output,
                            "Output PNG (default: the first scene's name with -compare.png)");
        compare->add_option("--vary", compare_arguments.vary,
                            "both: every pair; reflection: one column (the scene's shading); "
                            "shading: one row (the scene's reflection model)")
            ->check(CLI::IsMember({"both", "reflection", "shading"}))
            ->capture_default_str();
        compare->add_flag("--no-labels", compare_arguments.no_labels,
                          "Only the tiles, edge to edge (each equals litkit render of that pair)");
        compare->add_flag("-y,--yes", compare_arguments.yes,
                          "Use the default models (phong / phong) where [lighting] leaves one out");
    }

    ViewArguments view_arguments;
    CLI::App* view = app.add_subcommand(
        "view", "A live window on the scene: orbit, switch models at a key, edit, reload on save");
    if (defines(view)) {
        add_scene_options(view, view_arguments.scene);
        view->add_flag("--no-ui", view_arguments.no_ui, "Start with the panel hidden (H shows it)");
        view->add_option("--orbit-frames", view_arguments.orbit_frames,
                         "Measure: orbit N frames as fast as they show, print frames/s and close")
            ->check(CLI::Range(1, 100000));
        view->add_flag("-y,--yes", view_arguments.yes,
                       "Use the default models (phong / phong) where [lighting] leaves one out");
    }

    ExplainArguments explain_arguments;
    CLI::App* explain = app.add_subcommand(
        "explain", "How a pixel got its value, step by step; or the equations at a point (--at)");
    if (defines(explain)) {
        add_scene_options(explain, explain_arguments.scene);
        explain->add_option("--pixel", explain_arguments.pixel, "The pixel X,Y (0,0: top left)")
            ->delimiter(',')
            ->expected(2);
        explain->add_option("--at", explain_arguments.at, "A point X,Y,Z in the world")
            ->delimiter(',')
            ->expected(3);
        explain->add_option("--normal", explain_arguments.normal, "With --at: the surface normal NX,NY,NZ")
            ->delimiter(',')
            ->expected(3);
        explain->add_option("--object", explain_arguments.object,
                            "With --at: the object (name or index) whose material to use (default: the first)");
        explain->add_flag("--json", explain_arguments.json, "One JSON object instead of text");
        explain->add_flag("-y,--yes", explain_arguments.yes,
                          "Use the default models (phong / phong) where [lighting] leaves one out");
    }

    TurntableArguments turntable_arguments;
    CLI::App* turntable = app.add_subcommand(
        "turntable", "The observer circles look_at once: an animated GIF, or PNG frames in DIR/");
    if (defines(turntable)) {
        add_scene_options(turntable, turntable_arguments.scene);
        turntable->add_option("-o,--output", turntable_arguments.output,
                              "spin.gif, or DIR/ for numbered PNGs (default: the first scene's name "
                              "with .gif)");
        turntable->add_option("--frames", turntable_arguments.frames, "Frames in one turn")
            ->check(CLI::Range(1, 10000))
            ->capture_default_str();
        turntable->add_option("--delay", turntable_arguments.delay_ms, "GIF: milliseconds per frame")
            ->check(CLI::Range(10, 10000))
            ->capture_default_str();
        turntable->add_flag("-y,--yes", turntable_arguments.yes,
                            "Use the default models (phong / phong) where [lighting] leaves one out");
    }

    BenchArguments bench_arguments;
    CLI::App* bench = app.add_subcommand(
        "bench", "Render frames into memory and report the time per frame");
    if (defines(bench)) {
        add_scene_options(bench, bench_arguments.scene);
        bench->add_option("--frames", bench_arguments.frames, "Frames to time (after one warm-up)")
            ->check(CLI::Range(1, 100000));
    }

    if (const auto status = litkit_cli::check_command(app, argc, argv)) return *status;
    try {
        app.parse(argc, argv);
    } catch (const CLI::Success& success) {
        return app.exit(success);
    } catch (const CLI::ParseError& error) {
        app.exit(error);
        const std::string suggestion = litkit_cli::option_suggestion(app, argc, argv);
        if (!suggestion.empty()) std::cerr << "hint: " << suggestion << "\n";
        return exit_invalid;
    }

    // The viewer ends on SIGINT/SIGTERM through SDL, which installs its own
    // handlers only where none is set.
    if (!view->parsed()) install_signal_handlers();
    try {
        if (render->parsed()) return run_render(render_arguments);
        if (check->parsed()) return run_check(check_arguments);
        if (init->parsed()) return run_init(init_file, init_force);
        if (bench->parsed()) return run_bench(bench_arguments);
        if (export_command->parsed()) return run_export(export_arguments);
        if (compare->parsed()) return run_compare(compare_arguments);
        if (turntable->parsed()) return run_turntable(turntable_arguments);
        if (explain->parsed()) return run_explain(explain_arguments);
        if (view->parsed()) return run_view(view_arguments);
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
    } catch (const litkit_cli::ModuleError& error) {
        std::cerr << "error: " << error.message << "\n";
        return exit_io;
    } catch (const std::bad_alloc&) {
        // Never "std::bad_alloc": what ran out, and what to do about it.
        std::cerr << "error: out of memory while " << (render->parsed() || compare->parsed() ||
                                                           turntable->parsed() || bench->parsed()
                                                       ? "building the meshes or rendering"
                                                       : "reading or checking the scene")
                  << "; lower the objects' tessellation, the image size or --max-triangles "
                     "(docs/reliability.md)\n";
        return exit_io;
    } catch (const std::exception& error) {
        std::cerr << "error: " << error.what() << "\n";
        return exit_io;
    }
    return exit_invalid;
}
