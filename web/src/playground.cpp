// SPDX-License-Identifier: MIT
// The playground page's way into litkit (docs/web.md): a few C functions that
// web/site/playground.js calls through emscripten's ccall. Each takes the
// scene text as the page has it and does what the command line does with a
// file: parse_scene (which validates), the model choices as --reflection and
// --shading, missing [lighting] models filled in as `--yes` does, then the
// CPU renderer. Results go back as JSON text plus an RGBA buffer in the
// module's memory.
//
// One thread: emscripten builds without pthreads here, so the renderer is
// asked for one thread and its pool starts no worker (thread_pool.cpp starts
// threads − 1 of them); hardware_concurrency() is 1 there as well.
#include <emscripten/emscripten.h>

#include <chrono>
#include <cstdint>
#include <exception>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "litkit/error.hpp"
#include "litkit/explain.hpp"
#include "litkit/render.hpp"
#include "litkit/scene.hpp"

#include "core/json.hpp"

namespace {

// The page's scene file: relative mesh paths resolve in its folder, where the
// page writes the examples' meshes and the OBJ files a user drops in.
constexpr const char* scene_path = "/scene/scene.toml";

struct State {
    std::optional<litkit::Scene> scene;  // the last one that parsed and validated
    std::unique_ptr<litkit::Renderer> renderer;
    litkit::Image image;
    std::vector<std::uint8_t> rgba;
    std::string reply;  // the last JSON answer, alive until the next call
};

State& state() {
    static State s;
    return s;
}

// JSON text from the library's one writer (src/core/json.hpp): shortest
// numbers, and null for a number that is not finite.
namespace json = litkit::json;

std::string json_diagnostic(const litkit::Diagnostic& d) {
    return "{\"line\":" + std::to_string(d.location.line) +
           ",\"column\":" + std::to_string(d.location.column) + ",\"severity\":" +
           json::string(d.severity == litkit::Severity::Error ? "error" : "warning") +
           ",\"message\":" + json::string(d.message) + ",\"text\":" + json::string(d.to_string()) +
           "}";
}

std::string json_diagnostics(const std::vector<litkit::Diagnostic>& list) {
    std::string out = "[";
    for (const litkit::Diagnostic& d : list) {
        if (out.size() > 1) out += ',';
        out += json_diagnostic(d);
    }
    return out + "]";
}

std::string json_vec3(const glm::vec3& v) {
    return "[" + json::number(v.x) + "," + json::number(v.y) + "," + json::number(v.z) + "]";
}

// Where each value the sliders change is written in the text (line, column
// of the value; absent: the key is not in the text).
std::string json_locations(const litkit::Scene& scene) {
    static const char* const paths[] = {"objects[0]",
                                        "objects[0].material",
                                        "objects[0].material.color",
                                        "objects[0].material.ka",
                                        "objects[0].material.kd",
                                        "objects[0].material.ks",
                                        "objects[0].material.shininess",
                                        "lights[0]",
                                        "lights[0].intensity",
                                        "lights[0].position",
                                        "lighting",
                                        "room"};
    std::string out = "{";
    for (const char* path : paths) {
        const auto found = scene.locations.find(path);
        if (found == scene.locations.end()) continue;
        if (out.size() > 1) out += ',';
        out += json::string(path) + ":[" + std::to_string(found->second.line) + "," +
               std::to_string(found->second.column) + "]";
    }
    return out + "}";
}

// The first object's material and the first light, for the sliders.
std::string json_values(const litkit::Scene& scene) {
    std::string out = "{\"room\":[" + json::number(scene.room.width) + "," +
                      json::number(scene.room.height) + "," + json::number(scene.room.depth) + "]";
    if (!scene.objects.empty()) {
        const litkit::Material& m = scene.objects[0].material;
        out += ",\"material\":{\"color\":" + json_vec3(m.color * 255.0f) +
               ",\"ka\":" + json::number(m.ka) + ",\"kd\":" + json::number(m.kd) +
               ",\"ks\":" + json::number(m.ks) + ",\"shininess\":" + json::number(m.shininess) +
               "}";
    }
    if (!scene.lights.empty()) {
        const litkit::Light& light = scene.lights[0].light;
        out += ",\"light\":{\"intensity\":" + json::number(light.intensity);
        if (const auto* point = std::get_if<litkit::PointLight>(&light.kind))
            out += ",\"position\":" + json_vec3(point->position);
        else if (const auto* spot = std::get_if<litkit::SpotLight>(&light.kind))
            out += ",\"position\":" + json_vec3(spot->position);
        out += "}";
    }
    return out + "}";
}

// The page's model choices, as --reflection/--shading ("" keeps the
// scene's), then R11's defaults where the scene still has none.
void choose_models(litkit::Scene& scene, std::string_view reflection, std::string_view shading) {
    if (!reflection.empty()) scene.reflection = litkit::parse_reflection(reflection);
    if (!shading.empty()) scene.shading = litkit::parse_shading(shading);
    if (!scene.reflection) scene.reflection = litkit::default_reflection;
    if (!scene.shading) scene.shading = litkit::default_shading;
}

// The last picture as RGBA for the canvas (alpha 255).
void to_rgba(const litkit::Image& image, std::vector<std::uint8_t>& rgba) {
    const std::size_t pixels = static_cast<std::size_t>(image.width) * image.height;
    rgba.resize(pixels * 4);
    for (std::size_t i = 0; i < pixels; ++i) {
        rgba[i * 4 + 0] = image.rgb[i * 3 + 0];
        rgba[i * 4 + 1] = image.rgb[i * 3 + 1];
        rgba[i * 4 + 2] = image.rgb[i * 3 + 2];
        rgba[i * 4 + 3] = 255;
    }
}

// Draws `scene` with the kept renderer (meshes are rebuilt only when an
// object's geometry changed) and answers with the picture's size and timing.
std::string draw(const litkit::Scene& scene) {
    State& s = state();
    const auto start = std::chrono::steady_clock::now();
    if (s.renderer)
        s.renderer->update(scene);
    else
        s.renderer = std::make_unique<litkit::Renderer>(scene, litkit::RenderOptions{.threads = 1});
    s.renderer->render_into(s.image);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    to_rgba(s.image, s.rgba);
    return "\"width\":" + std::to_string(s.image.width) +
           ",\"height\":" + std::to_string(s.image.height) + ",\"ms\":" + json::number(ms) +
           ",\"threads\":" + std::to_string(s.renderer->thread_count());
}

std::string failure(const std::exception& e) {
    std::vector<litkit::Diagnostic> errors;
    if (const auto* scene_error = dynamic_cast<const litkit::SceneError*>(&e)) {
        errors = scene_error->diagnostics();
    } else if (const auto* error = dynamic_cast<const litkit::Error*>(&e)) {
        errors.push_back({error->location(), litkit::Severity::Error, error->what()});
    } else {
        errors.push_back({{}, litkit::Severity::Error, e.what()});
    }
    // A failed load keeps its warnings, as the command line shows them too.
    std::vector<litkit::Diagnostic> warnings;
    if (const auto* scene_error = dynamic_cast<const litkit::SceneError*>(&e))
        warnings = scene_error->warnings();
    return "{\"ok\":false,\"errors\":" + json_diagnostics(errors) +
           ",\"warnings\":" + json_diagnostics(warnings) + "}";
}

const char* reply(std::string text) {
    state().reply = std::move(text);
    return state().reply.c_str();
}

}  // namespace

extern "C" {

// Parses, validates and draws `text` with the page's model choices ("" for
// the scene's own) and samples per pixel (0 for the scene's own). On success
// the picture replaces the last one; on failure the last good scene and
// picture stay, and the answer lists the errors.
EMSCRIPTEN_KEEPALIVE const char* litkit_render(const char* text, const char* reflection,
                                               const char* shading, int samples) {
    try {
        const auto start = std::chrono::steady_clock::now();
        litkit::Scene scene = litkit::parse_scene(text, scene_path);
        const double parse_ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count();
        const bool lighting_given = scene.reflection && scene.shading;
        choose_models(scene, reflection, shading);
        if (samples != 0) {  // as --samples (docs/spec.md §11)
            if (!litkit::valid_sample_count(samples))
                throw litkit::ArgumentError("samples must be 1, 4, 8 or 16, found " +
                                            std::to_string(samples));
            scene.output.samples = samples;
        }
        std::string answer =
            "{\"ok\":true," + draw(scene) + ",\"parse_ms\":" + json::number(parse_ms) +
            ",\"warnings\":" + json_diagnostics(scene.warnings) +
            ",\"lighting_given\":" + (lighting_given ? "true" : "false") +
            ",\"values\":" + json_values(scene) + ",\"locations\":" + json_locations(scene) + "}";
        state().scene = std::move(scene);
        return reply(std::move(answer));
    } catch (const std::exception& e) {
        return reply(failure(e));
    }
}

// One tile of the grid view (as `litkit compare`): the last good scene with
// these models for every object, at this size.
EMSCRIPTEN_KEEPALIVE const char* litkit_render_tile(const char* reflection, const char* shading,
                                                    int width, int height) {
    State& s = state();
    if (!s.scene) return reply("{\"ok\":false,\"errors\":[]}");
    try {
        litkit::Scene tile = *s.scene;
        tile.reflection = litkit::parse_reflection(reflection);
        tile.shading = litkit::parse_shading(shading);
        if (!tile.reflection || !tile.shading) throw litkit::ArgumentError("unknown model");
        tile.output.width = width;
        tile.output.height = height;
        for (litkit::SceneObject& object : tile.objects) {
            object.reflection.reset();
            object.shading.reset();
        }
        return reply("{\"ok\":true," + draw(tile) + "}");
    } catch (const std::exception& e) {
        return reply(failure(e));
    }
}

// The RGBA pixels of the last picture drawn (4 · width · height bytes).
EMSCRIPTEN_KEEPALIVE const std::uint8_t* litkit_pixels() { return state().rgba.data(); }

// `litkit explain --pixel x,y` of the last good scene with its model choices:
// the text the command prints and the pixel's value.
EMSCRIPTEN_KEEPALIVE const char* litkit_explain(int x, int y) {
    State& s = state();
    if (!s.scene) return reply("{\"ok\":false,\"errors\":[]}");
    try {
        const litkit::PixelExplanation e =
            litkit::explain_pixel(*s.scene, x, y, litkit::RenderOptions{.threads = 1});
        return reply("{\"ok\":true,\"x\":" + std::to_string(x) + ",\"y\":" + std::to_string(y) +
                     ",\"hit\":" + (e.hit ? "true" : "false") + ",\"rgb\":[" +
                     std::to_string(e.rgb[0]) + "," + std::to_string(e.rgb[1]) + "," +
                     std::to_string(e.rgb[2]) +
                     "],\"text\":" + json::string(litkit::explanation_text(e, *s.scene)) + "}");
    } catch (const std::exception& e) {
        return reply(failure(e));
    }
}

// A mesh file changed under the same name: build every mesh again.
EMSCRIPTEN_KEEPALIVE void litkit_forget_meshes() { state().renderer.reset(); }

// The models' scene-file names, for the page's menus and grid.
EMSCRIPTEN_KEEPALIVE const char* litkit_models() {
    std::string out = "{\"reflection\":[";
    bool first = true;
    for (const litkit::ReflectionModel& model : litkit::reflection_models()) {
        if (!first) out += ',';
        first = false;
        out += json::string(litkit::to_string(model.id));
    }
    out += "],\"shading\":[";
    for (std::string_view name : litkit::shading_names) {
        if (out.back() != '[') out += ',';
        out += json::string(name);
    }
    out += "],\"default_scene\":" + json::string(litkit::default_scene_toml()) + "}";
    return reply(std::move(out));
}

}  // extern "C"
