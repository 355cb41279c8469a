// SPDX-License-Identifier: MIT
// The viewer: an SDL2 window with an OpenGL context that shows litkit's
// picture pixel for pixel (a texture blitted 1:1), a Dear ImGui panel over
// it, the camera under the mouse, the models under the keys, and the scene's
// files watched for changes. Nothing is drawn while nothing changes.
#include "viewer/viewer.hpp"

#include <SDL2/SDL.h>
#include <backends/imgui_impl_opengl3.h>
#include <backends/imgui_impl_sdl.h>
#include <imgui.h>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <variant>

#include "core/files.hpp"
#include "core/scale_free.hpp"
#include "litkit/error.hpp"
#include "litkit/image.hpp"
#include "litkit/limits.hpp"
#include "viewer/drawer.hpp"
#include "viewer/panel.hpp"
#include "viewer/watch.hpp"

namespace litkit_cli {

namespace {

namespace fs = std::filesystem;
using clock_type = std::chrono::steady_clock;

// The files a scene is made of: its scene files and its mesh files.
std::vector<fs::path> files_of(const ViewerOptions& options, const litkit::Scene& scene) {
    std::vector<fs::path> files = options.files;
    for (const litkit::SceneObject& object : scene.objects)
        if (const auto* mesh = std::get_if<litkit::MeshFileShape>(&object.shape))
            files.push_back(mesh->file);
    return files;
}

// The user's camera: the observer as the mouse moved it.
struct Camera {
    litkit::Observer observer;

    // Turns the observer about `up` through look_at (yaw) and about the
    // horizontal axis (pitch), stopping 5° short of the poles.
    void orbit(float yaw_radians, float pitch_radians) {
        const glm::vec3 up = litkit::scale_free::unit(observer.up);
        glm::vec3 offset = observer.position - observer.look_at;
        offset = glm::vec3(glm::rotate(glm::mat4(1.0f), yaw_radians, up) * glm::vec4(offset, 0.0f));
        const glm::vec3 right = glm::cross(up, offset);
        if (right != glm::vec3(0.0f)) {
            const float angle =
                std::acos(std::clamp(glm::dot(litkit::scale_free::unit(offset), up), -1.0f, 1.0f));
            const float limit = glm::radians(5.0f);
            const float pitched =
                std::clamp(angle - pitch_radians, limit, glm::pi<float>() - limit);
            offset = glm::vec3(
                glm::rotate(glm::mat4(1.0f), angle - pitched, litkit::scale_free::unit(right)) *
                glm::vec4(offset, 0.0f));
        }
        observer.position = observer.look_at + offset;
    }
    void zoom(float notches) {  // ×1.1 closer per notch
        const glm::vec3 offset = observer.position - observer.look_at;
        observer.position = observer.look_at + offset * std::pow(1.1f, -notches);
    }
    void pan(float right_amount, float up_amount) {
        const glm::vec3 forward = litkit::scale_free::unit(observer.look_at - observer.position);
        const glm::vec3 right = litkit::scale_free::unit(glm::cross(forward, observer.up));
        const glm::vec3 up = glm::cross(right, forward);
        const glm::vec3 move = right * right_amount + up * up_amount;
        observer.position += move;
        observer.look_at += move;
    }
};

// "scene-1.png", "scene-2.png", …: the first name not taken.
fs::path next_screenshot_name(const std::string& stem) {
    for (int n = 1;; ++n) {
        fs::path name = stem + "-" + std::to_string(n) + ".png";
        if (!fs::exists(name)) return name;
    }
}

// The count of samples per pixel after `samples` among 1, 4, 8, 16, round.
int next_sample_count(int samples) {
    const auto& counts = litkit::sample_counts;
    const auto at = std::find(counts.begin(), counts.end(), samples);
    return at == counts.end() || at + 1 == counts.end() ? counts.front() : *(at + 1);
}

struct KeyModel {
    SDL_Keycode key;
    litkit::Shading shading;
};
// F/G/P/D: docs/spec.md §9.4.
constexpr KeyModel shading_keys[] = {
    {SDLK_f, litkit::Shading::Flat},
    {SDLK_g, litkit::Shading::Gouraud},
    {SDLK_p, litkit::Shading::Phong},
    {SDLK_d, litkit::Shading::Faceted},
};

}  // namespace

int run_viewer(const ViewerOptions& options, litkit::Scene scene) {
    SDL_SetHint(SDL_HINT_VIDEO_X11_NET_WM_BYPASS_COMPOSITOR, "0");
    if (SDL_Init(SDL_INIT_VIDEO) != 0) {
        std::cerr << "error: cannot open a window: " << SDL_GetError() << "\n";
        return 1;
    }
    // No display (SDL would fall back to a driver without one): say so at once.
    const char* driver = SDL_GetCurrentVideoDriver();
    if (!driver || std::string(driver) == "offscreen" || std::string(driver) == "dummy") {
        std::cerr << "error: cannot open a window: no display (is DISPLAY set?)\n";
        SDL_Quit();
        return 1;
    }
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_MAJOR_VERSION, 3);
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_MINOR_VERSION, 3);
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_PROFILE_MASK, SDL_GL_CONTEXT_PROFILE_CORE);
    SDL_GL_SetAttribute(SDL_GL_DOUBLEBUFFER, 1);

    litkit::Scene file_scene = scene;  // as the files say (with the command line's options)
    Camera camera{scene.observer};
    std::optional<litkit::Reflection> key_reflection;
    std::optional<litkit::Shading> key_shading;
    bool show_panel = options.show_panel;
    bool turntable = false;
    std::string diagnostics;  // the last reload's errors, shown until a good one

    SDL_Window* window = SDL_CreateWindow(
        "litkit view", SDL_WINDOWPOS_UNDEFINED, SDL_WINDOWPOS_UNDEFINED, scene.output.width,
        scene.output.height, SDL_WINDOW_OPENGL | SDL_WINDOW_RESIZABLE | SDL_WINDOW_ALLOW_HIGHDPI);
    if (!window) {
        std::cerr << "error: cannot open a window: " << SDL_GetError() << "\n";
        SDL_Quit();
        return 1;
    }
    SDL_GLContext context = SDL_GL_CreateContext(window);
    if (!context) {
        std::cerr << "error: cannot create an OpenGL 3.3 context for the window: " << SDL_GetError()
                  << "\n";
        SDL_DestroyWindow(window);
        SDL_Quit();
        return 1;
    }
    SDL_GL_MakeCurrent(window, context);
    SDL_GL_SetSwapInterval(0);

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini beside the user's files
    ImGui::StyleColorsDark();
    ImGui_ImplSDL2_InitForOpenGL(window, context);
    ImGui_ImplOpenGL3_Init("#version 330 core");

    int status = 0;
    {
        Screen screen;
        std::unique_ptr<Drawer> drawer;
        litkit::Image image;
        FileWatcher watcher(files_of(options, file_scene));
        // When to reload after a change (`never`: none waiting). A plain time,
        // not an optional: GCC 12 took the optional's value for uninitialised.
        constexpr clock_type::time_point never = clock_type::time_point::max();
        clock_type::time_point reload_at = never;
        double frame_ms = 0.0;
        int shown_width = 0, shown_height = 0;
        char save_path[512] = "";
        bool confirm_overwrite = false;
        std::string save_message;

        int drag_button = 0;
        bool dragged = false;  // the camera moved since the button went down
        // While the view moves (a drag, the turntable, --benchmark) glass is
        // traced to at most moving_depth interactions, so that orbiting stays
        // fluid; at rest, to the scene's max_depth: the picture is exact.
        constexpr int moving_depth = 2;
        auto depth_now = [&] {
            const bool glass = std::any_of(
                scene.objects.begin(), scene.objects.end(),
                [](const litkit::SceneObject& o) { return o.material.transmission > 0.0f; });
            const bool moving = dragged || turntable || options.benchmark_frames > 0;
            return glass && moving ? std::min(scene.max_depth, moving_depth) : scene.max_depth;
        };
        int drawn_depth = 0;  // max_depth of the picture shown
        // Anti-aliasing (docs/spec.md §11) likewise, on either backend: one
        // sample while the view moves, the scene's at rest (the window is
        // then `litkit render`'s picture).
        auto samples_now = [&] {
            const bool moving = dragged || turntable || options.benchmark_frames > 0;
            return moving ? 1 : scene.output.samples;
        };
        int drawn_samples = 0;  // samples of the picture shown
        // The scene the picture shows: the file's, the keys' models, the camera.
        auto shown_scene = [&] {
            litkit::Scene shown = scene;
            shown.max_depth = depth_now();
            shown.output.samples = samples_now();
            shown.observer = camera.observer;
            if (key_reflection) shown.reflection = key_reflection;
            if (key_shading) shown.shading = key_shading;
            int w = 0, h = 0;
            SDL_GL_GetDrawableSize(window, &w, &h);
            shown.output.width = std::clamp(w, 1, litkit::max_image_side);
            shown.output.height = std::clamp(h, 1, litkit::max_image_side);
            return shown;
        };
        auto set_title = [&] {
            const litkit::Scene shown = shown_scene();
            std::string title =
                "litkit view - " + options.title + " - " +
                std::string(
                    litkit::to_string(shown.reflection.value_or(litkit::default_reflection))) +
                " / " +
                std::string(litkit::to_string(shown.shading.value_or(litkit::default_shading)));
            if (scene.output.samples > 1)
                title += " - " + std::to_string(scene.output.samples) + " samples at rest";
            if (!diagnostics.empty()) title += " - invalid edit, showing the last good scene";
            SDL_SetWindowTitle(window, title.c_str());
        };

        bool dirty = true;   // the picture must be rendered again
        bool redraw = true;  // the window must be drawn again
        // Dear ImGui lays a window out over a frame or two (an auto-sized
        // window appears on its second): draw this many more after a change.
        int panel_frames = 0;
        bool running = true;
        auto last_turn = clock_type::now();
        int benchmark_done = -1;  // frames shown while measuring (-1: the first is not timed)
        clock_type::time_point benchmark_start;
        while (running) {
            // Wait for something to do: events, the next reload check, or the
            // next turntable step. Nothing is rendered in between.
            const int timeout = dirty || panel_frames > 0 || options.benchmark_frames > 0 ? 0
                                : turntable || drag_button                                ? 10
                                : reload_at != never                                      ? 20
                                                                                          : 100;
            SDL_Event event;
            bool have = SDL_WaitEventTimeout(&event, timeout) == 1;
            if (have && show_panel) redraw = true;  // the panel answers every event
            while (have) {
                const bool panel_wants =
                    show_panel && ImGui_ImplSDL2_ProcessEvent(&event) &&
                    (ImGui::GetIO().WantCaptureMouse || ImGui::GetIO().WantCaptureKeyboard);
                switch (event.type) {
                    case SDL_QUIT:
                        running = false;
                        break;
                    case SDL_WINDOWEVENT:
                        if (event.window.event == SDL_WINDOWEVENT_SIZE_CHANGED) dirty = true;
                        redraw = true;
                        break;
                    case SDL_KEYDOWN: {
                        if (show_panel && ImGui::GetIO().WantCaptureKeyboard) break;
                        const SDL_Keycode key = event.key.keysym.sym;
                        if (key == SDLK_ESCAPE || key == SDLK_q)
                            running = false;
                        else if (key == SDLK_h)
                            show_panel = !show_panel, redraw = true;
                        else if (key == SDLK_r)
                            camera.observer = scene.observer, dirty = true;
                        else if (key == SDLK_SPACE)
                            turntable = !turntable, last_turn = clock_type::now();
                        else if (key == SDLK_a)  // the next of 1, 4, 8, 16 samples
                            scene.output.samples = next_sample_count(scene.output.samples),
                            set_title(), dirty = true;
                        else if (key == SDLK_0)
                            key_reflection.reset(), key_shading.reset(), dirty = true;
                        else if (key >= SDLK_1 && key <= SDLK_9) {
                            const auto models = litkit::reflection_models();
                            const std::size_t index = static_cast<std::size_t>(key - SDLK_1);
                            if (index < models.size())
                                key_reflection = models[index].id, dirty = true;
                        } else if (key == SDLK_s) {
                            const fs::path name = next_screenshot_name(
                                options.files.empty() ? "default"
                                                      : options.files.front().stem().string());
                            try {
                                if (drawer) drawer->snapshot(image);
                                litkit::write_png(image, name);
                                std::cout << "litkit: wrote " << name.string() << "\n"
                                          << std::flush;
                            } catch (const litkit::Error& error) {
                                std::cerr << error.what() << "\n";
                            }
                        } else {
                            for (const KeyModel& model : shading_keys)
                                if (key == model.key) key_shading = model.shading, dirty = true;
                        }
                        break;
                    }
                    case SDL_MOUSEBUTTONDOWN:
                        if (!panel_wants && (event.button.button == SDL_BUTTON_LEFT ||
                                             event.button.button == SDL_BUTTON_RIGHT))
                            drag_button = event.button.button;
                        break;
                    case SDL_MOUSEBUTTONUP:
                        drag_button = 0;
                        dragged = false;
                        break;
                    case SDL_MOUSEMOTION: {
                        if (!drag_button) break;
                        const litkit::Observer before = camera.observer;
                        if (drag_button == SDL_BUTTON_LEFT) {
                            camera.orbit(-0.01f * static_cast<float>(event.motion.xrel),
                                         -0.01f * static_cast<float>(event.motion.yrel));
                        } else {
                            const float distance =
                                glm::length(camera.observer.position - camera.observer.look_at);
                            int w = 0, h = 0;
                            SDL_GL_GetDrawableSize(window, &w, &h);
                            const float per_pixel =
                                2.0f * distance *
                                std::tan(glm::radians(camera.observer.fov_degrees) / 2.0f) /
                                static_cast<float>(std::max(h, 1));
                            camera.pan(-per_pixel * static_cast<float>(event.motion.xrel),
                                       per_pixel * static_cast<float>(event.motion.yrel));
                        }
                        if (!inside_room(scene.room, camera.observer.position))
                            camera.observer = before;
                        dirty = true;
                        dragged = true;
                        break;
                    }
                    case SDL_MOUSEWHEEL: {
                        if (panel_wants) break;
                        const litkit::Observer before = camera.observer;
                        camera.zoom(static_cast<float>(event.wheel.y));
                        if (!inside_room(scene.room, camera.observer.position) ||
                            glm::length(camera.observer.position - camera.observer.look_at) < 1e-3f)
                            camera.observer = before;
                        dirty = true;
                        break;
                    }
                    default:
                        break;
                }
                have = SDL_PollEvent(&event) == 1;
            }
            if (!running) break;

            if (options.benchmark_frames > 0 && !dirty) {
                if (benchmark_done == 0) benchmark_start = clock_type::now();
                if (++benchmark_done > options.benchmark_frames) {
                    const double ms = std::chrono::duration<double, std::milli>(clock_type::now() -
                                                                                benchmark_start)
                                          .count();
                    std::printf("orbit: %d frames of %dx%d in %.1f ms: %.1f frames/s\n",
                                options.benchmark_frames, shown_width, shown_height, ms,
                                1000.0 * options.benchmark_frames / ms);
                    break;
                }
                camera.orbit(glm::radians(2.0f), 0.0f);
                dirty = true;
            } else if (turntable) {
                const auto now = clock_type::now();
                const float seconds = std::chrono::duration<float>(now - last_turn).count();
                last_turn = now;
                const litkit::Observer before = camera.observer;
                camera.orbit(seconds * glm::radians(20.0f), 0.0f);  // 20° a second
                if (!inside_room(scene.room, camera.observer.position)) camera.observer = before;
                dirty = true;
            }

            // Live reload: a change starts a short wait (an editor may write
            // in several steps); then read, check, and show or keep.
            if (watcher.changed()) reload_at = clock_type::now() + std::chrono::milliseconds(60);
            if (reload_at != never && clock_type::now() >= reload_at) {
                reload_at = never;
                try {
                    litkit::Scene loaded;
                    if (CaughtError failure; !options.load(loaded, failure)) throw_again(failure);
                    if (!(loaded.observer.position == file_scene.observer.position &&
                          loaded.observer.look_at == file_scene.observer.look_at &&
                          loaded.observer.up == file_scene.observer.up &&
                          loaded.observer.fov_degrees == file_scene.observer.fov_degrees))
                        camera.observer = loaded.observer;  // the file moved the camera
                    camera.observer.fov_degrees = loaded.observer.fov_degrees;
                    camera.observer.near = loaded.observer.near;
                    camera.observer.far = loaded.observer.far;
                    file_scene = loaded;
                    scene = loaded;
                    if (!diagnostics.empty()) std::cerr << "litkit: the scene is valid again\n";
                    diagnostics.clear();
                    watcher.watch(files_of(options, loaded));
                    dirty = true;
                } catch (const litkit::SceneError& error) {
                    diagnostics.clear();
                    for (const litkit::Diagnostic& d : error.diagnostics())
                        diagnostics += d.to_string() + "\n";
                    std::cerr << diagnostics << std::flush;
                } catch (const litkit::Error& error) {
                    diagnostics = std::string(error.what()) + "\n";
                    std::cerr << diagnostics << std::flush;
                }
                set_title();
                redraw = true;
            }

            if (drawer && (depth_now() != drawn_depth || samples_now() != drawn_samples))
                dirty = true;  // the view stopped
            if (dirty) {
                const auto start = clock_type::now();
                const litkit::Scene shown = shown_scene();
                drawn_depth = shown.max_depth;
                drawn_samples = shown.output.samples;
                try {
                    if (!drawer)
                        drawer = std::make_unique<Drawer>(options.backend, shown, options.threads);
                    else
                        drawer->update(shown);
                    drawer->render(image);
                    shown_width = shown.output.width;
                    shown_height = shown.output.height;
                } catch (const litkit::Error& error) {
                    diagnostics = std::string(error.what()) + "\n";
                    std::cerr << diagnostics << std::flush;
                }
                frame_ms =
                    std::chrono::duration<double, std::milli>(clock_type::now() - start).count();
                dirty = false;
                redraw = true;
                set_title();
            }
            if (panel_frames > 0) {
                --panel_frames;
                redraw = true;
            } else if (redraw && show_panel) {
                panel_frames = 2;
            }
            if (!redraw) continue;

            int w = 0, h = 0;
            SDL_GL_GetDrawableSize(window, &w, &h);
            if (drawer) drawer->present(screen, image, w, h);
            if (show_panel) {
                ImGui_ImplOpenGL3_NewFrame();
                ImGui_ImplSDL2_NewFrame();
                ImGui::NewFrame();
                ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
                ImGui::SetNextWindowBgAlpha(0.85f);
                ImGui::Begin("litkit", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
                bool edited = false;
                // The models: the keys' choice, or the scene's.
                {
                    const auto models = litkit::reflection_models();
                    int reflection = key_reflection ? static_cast<int>(*key_reflection) + 1 : 0;
                    std::vector<const char*> names{"(the scene's)"};
                    for (const auto& model : models) names.push_back(model.name.data());
                    if (ImGui::Combo("reflection", &reflection, names.data(),
                                     static_cast<int>(names.size()))) {
                        key_reflection =
                            reflection == 0
                                ? std::nullopt
                                : std::optional(static_cast<litkit::Reflection>(reflection - 1));
                        dirty = true;
                    }
                    int shading = key_shading ? static_cast<int>(*key_shading) + 1 : 0;
                    std::vector<const char*> shadings{"(the scene's)"};
                    for (int s = 0; s < litkit::shading_count; ++s)
                        shadings.push_back(
                            litkit::to_string(static_cast<litkit::Shading>(s)).data());
                    if (ImGui::Combo("shading", &shading, shadings.data(),
                                     static_cast<int>(shadings.size()))) {
                        key_shading =
                            shading == 0 ? std::nullopt
                                         : std::optional(static_cast<litkit::Shading>(shading - 1));
                        dirty = true;
                    }
                }
                edited |= ImGui::SliderFloat("gamma", &scene.output.gamma, 0.2f, 4.0f);
                edited |= ImGui::SliderInt("max_depth", &scene.max_depth, 1, 16, "%d",
                                           ImGuiSliderFlags_AlwaysClamp);
                const char* const sample_names[] = {"1", "4", "8", "16"};
                int sample_index =
                    static_cast<int>(std::find(litkit::sample_counts.begin(),
                                               litkit::sample_counts.end(), scene.output.samples) -
                                     litkit::sample_counts.begin());
                if (ImGui::Combo("samples", &sample_index, sample_names, 4)) {
                    scene.output.samples = litkit::sample_counts[static_cast<std::size_t>(
                        std::clamp(sample_index, 0, 3))];
                    set_title();
                    dirty = true;
                }
                for (std::size_t i = 0; i < scene.objects.size(); ++i) {
                    litkit::SceneObject& object = scene.objects[i];
                    const std::string label =
                        (object.name.empty() ? "objects[" + std::to_string(i) + "]" : object.name) +
                        "##object" + std::to_string(i);
                    if (!ImGui::TreeNode(label.c_str())) continue;
                    edited |= material_controls(object.material);
                    ImGui::TreePop();
                }
                for (std::size_t i = 0; i < scene.lights.size(); ++i) {
                    litkit::SceneLight& light = scene.lights[i];
                    const std::string label =
                        (light.name.empty() ? "lights[" + std::to_string(i) + "]" : light.name) +
                        "##light" + std::to_string(i);
                    if (!ImGui::TreeNode(label.c_str())) continue;
                    edited |= light_controls(light, scene.room);
                    ImGui::TreePop();
                }
                ImGui::Text("frame %.1f ms, %dx%d", frame_ms, shown_width, shown_height);
                ImGui::Separator();
                ImGui::InputText("file", save_path, sizeof save_path);
                if (ImGui::Button(confirm_overwrite ? "Overwrite" : "Save as...") &&
                    save_path[0] != '\0') {
                    const fs::path path(save_path);
                    if (fs::exists(path) && !confirm_overwrite) {
                        confirm_overwrite = true;
                        save_message = "exists: press Overwrite to replace it";
                    } else {
                        litkit::Scene saved = scene;
                        saved.observer = camera.observer;
                        if (key_reflection) saved.reflection = key_reflection;
                        if (key_shading) saved.shading = key_shading;
                        try {
                            litkit::write_file_atomically(path, litkit::scene_to_toml(saved, path));
                            save_message = "saved " + path.string();
                            std::cout << "litkit: wrote " << path.string() << "\n" << std::flush;
                        } catch (const litkit::Error& error) {
                            save_message = error.what();
                        }
                        confirm_overwrite = false;
                    }
                }
                if (!save_message.empty()) ImGui::TextUnformatted(save_message.c_str());
                if (!diagnostics.empty()) {
                    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
                    ImGui::TextUnformatted(diagnostics.c_str());
                    ImGui::PopStyleColor();
                }
                ImGui::End();
                ImGui::Render();
                ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
                if (edited) dirty = true;
            }
            SDL_GL_SwapWindow(window);
            redraw = false;
        }
    }
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplSDL2_Shutdown();
    ImGui::DestroyContext();
    SDL_GL_DeleteContext(context);
    SDL_DestroyWindow(window);
    SDL_Quit();
    return status;
}

}  // namespace litkit_cli

extern "C" __attribute__((visibility("default"))) const litkit_cli::ViewerModule*
litkit_viewer_module() {
    static constexpr litkit_cli::ViewerModule module{
        litkit_cli::module_stamp<litkit_cli::ViewerModule, litkit_cli::ViewerOptions>(),
        [](const litkit_cli::ViewerOptions& options, litkit::Scene scene,
           litkit_cli::CaughtError& error) noexcept {
            int status = 1;
            litkit_cli::call_catching(
                [&] { status = litkit_cli::run_viewer(options, std::move(scene)); }, error);
            return status;
        }};
    return &module;
}
