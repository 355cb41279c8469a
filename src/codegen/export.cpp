// SPDX-License-Identifier: MIT
#include "litkit/export.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iterator>
#include <stdexcept>
#include <string_view>
#include <system_error>
#include <utility>

#include "codegen/embedded_text.hpp"
#include "codegen/export_samples.hpp"
#include "codegen/gl_glass.hpp"
#include "codegen/gl_scene.hpp"
#include "codegen/glsl_expr.hpp"
#include "codegen/glsl_glass.hpp"
#include "core/files.hpp"
#include "litkit/error.hpp"
#include "litkit/glsl.hpp"
#include "litkit/samples.hpp"
#include "litkit/validate.hpp"
#include "scene/float_range.hpp"
#include "scene/transparency.hpp"

namespace litkit {

namespace {

namespace fs = std::filesystem;

using ModelPair = std::pair<Reflection, Shading>;

struct ObjectModels {
    std::vector<ModelPair> pairs;  // each once with its glass flag, in order of first use
    std::vector<bool> glass;       // per pair: its objects have t > 0 (docs/spec.md §10)
    std::vector<int> program;      // per object, an index into `pairs`
};

ObjectModels object_models(const Scene& scene, const ExportOptions& options) {
    const Reflection scene_reflection = scene.reflection.value_or(options.fallback_reflection);
    const Shading scene_shading = scene.shading.value_or(options.fallback_shading);
    ObjectModels models;
    for (const SceneObject& object : scene.objects) {
        const ModelPair pair{object.reflection.value_or(scene_reflection),
                             object.shading.value_or(scene_shading)};
        const bool glass = object.material.transmission > 0.0f;
        std::size_t index = 0;
        while (index < models.pairs.size() &&
               (models.pairs[index] != pair || models.glass[index] != glass))
            ++index;
        if (index == models.pairs.size()) {
            models.pairs.push_back(pair);
            models.glass.push_back(glass);
        }
        models.program.push_back(static_cast<int>(index));
    }
    return models;
}

int light_capacity(const Scene& scene) {
    return std::max<int>(1, static_cast<int>(scene.lights.size()));
}

// "blinn-phong" + "flat" → "blinn-phong-flat" (identifier(): "blinn_phong_flat").
std::string pair_file_stem(const ModelPair& pair) {
    return std::string(to_string(pair.first)) + "-" + std::string(to_string(pair.second));
}
// Program i's file stem: its pair's, with "-glass" for a glass program.
std::string program_stem(const ObjectModels& models, std::size_t i) {
    return pair_file_stem(models.pairs[i]) + (models.glass[i] ? "-glass" : "");
}

// The scene's reflection models, each once in the objects' order (the glass
// programs' model numbers, detail::scene_models).
std::vector<Reflection> reflections_in_order(const ObjectModels& models) {
    std::vector<Reflection> reflections;
    for (const int program : models.program) {
        const Reflection r = models.pairs[static_cast<std::size_t>(program)].first;
        if (std::find(reflections.begin(), reflections.end(), r) == reflections.end())
            reflections.push_back(r);
    }
    return reflections;
}

// What the programs' fragments write: the pixel, or with several samples per
// pixel one sample's light (the host resolves the passes, docs/spec.md §11).
glsl::FragmentOutput fragment_output(const Scene& scene) {
    return scene.output.samples > 1 ? glsl::FragmentOutput::SampleLight
                                    : glsl::FragmentOutput::Pixel;
}

// A glass program (glsl_glass.hpp) for pair i, specialised to the scene's lights.
glsl::Shaders glass_shaders(const ObjectModels& models, std::size_t i, const Scene& scene) {
    std::vector<Light> lights;
    for (const SceneLight& light : scene.lights) lights.push_back(light.light);
    const std::vector<Reflection> reflections = reflections_in_order(models);
    return glsl::generate_glass({models.pairs[i].first, models.pairs[i].second, reflections, lights,
                                 scene.output.gamma, fragment_output(scene)});
}

// A file stem as a C++ identifier: '-' becomes '_'.
std::string identifier(std::string name) {
    for (char& c : name)
        if (c == '-') c = '_';
    return name;
}

// A C++ float literal that reads back as the same float: the GLSL
// generator's shortest round-trip text ("0.05", "20.0", "1e-07") plus "f".
std::string float_literal(float value) { return glsl::float_literal(value) + "f"; }

// "a, b, c" (appended piece by piece: GCC 12 warns falsely on "literal" + string&&).
std::string vec3_components(const glm::vec3& v) {
    std::string text = float_literal(v.x);
    text += ", ";
    text += float_literal(v.y);
    text += ", ";
    text += float_literal(v.z);
    return text;
}

std::string wrapped(std::string_view open, const std::string& text, std::string_view close) {
    std::string out(open);
    out += text;
    out += close;
    return out;
}

std::string vec3_literal(const glm::vec3& v) {
    return wrapped("glm::vec3(", vec3_components(v), ")");
}

// `{a, b, c}` for a brace-initialised glm::vec3 member.
std::string vec3_braces(const glm::vec3& v) { return wrapped("{", vec3_components(v), "}"); }

// Text safe inside a C++ comment or string literal.
std::string printable(std::string_view text) {
    std::string out;
    for (char c : text) out += (c >= 32 && c < 127 && c != '"' && c != '\\') ? c : '_';
    return out;
}

// Replaces every {{MARKER}} of `text` in one pass, so that nothing pasted in
// (a light's name, say) is ever read as a marker. Unknown markers are a bug.
std::string fill_template(std::string_view text,
                          const std::vector<std::pair<std::string_view, std::string>>& values) {
    std::string out;
    out.reserve(text.size());
    std::size_t at = 0;
    for (std::size_t open = text.find("{{"); open != std::string_view::npos;
         open = text.find("{{", at)) {
        const std::size_t close = text.find("}}", open);
        if (close == std::string_view::npos) break;
        const std::string_view marker = text.substr(open + 2, close - open - 2);
        auto value = std::find_if(values.begin(), values.end(),
                                  [&](const auto& entry) { return entry.first == marker; });
        if (value == values.end())
            throw std::logic_error("export: the program template has an unknown marker {{" +
                                   std::string(marker) + "}}");
        out.append(text.substr(at, open - at));
        out += value->second;
        at = close + 2;
    }
    out.append(text.substr(at));
    return out;
}

// `path` as one word for sh: as it is when plain, else in single quotes.
std::string shell_word(const std::string& path) {
    const bool plain = !path.empty() && std::all_of(path.begin(), path.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
               c == '_' || c == '-' || c == '.' || c == '/' || c == '+' || c == ',';
    });
    if (plain) return path;
    std::string word = "'";
    for (char c : path) word += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return word + "'";
}

std::string light_kind_name(equations::PreparedLight::Kind kind) {
    switch (kind) {
        case equations::PreparedLight::Kind::Ambient:
            return "LIGHT_AMBIENT";
        case equations::PreparedLight::Kind::Directional:
            return "LIGHT_DIRECTIONAL";
        case equations::PreparedLight::Kind::Point:
            return "LIGHT_POINT";
        case equations::PreparedLight::Kind::Spot:
            break;
    }
    return "LIGHT_SPOT";
}

// One row of the `lights` table, naming only the fields this kind uses.
std::string lights_source(const Scene& scene) {
    const std::vector<equations::PreparedLight> lights = detail::prepared_lights(scene);
    std::string out;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        using Kind = equations::PreparedLight::Kind;
        const equations::PreparedLight& l = lights[i];
        const std::string& name = scene.lights[i].name;
        const Light& source = scene.lights[i].light;
        out += "    // light " + std::to_string(i);
        if (!name.empty()) out += " \"" + printable(name) + "\"";
        out += ": colour [" + std::to_string(std::lround(source.color.r * 255.0f)) + ", " +
               std::to_string(std::lround(source.color.g * 255.0f)) + ", " +
               std::to_string(std::lround(source.color.b * 255.0f)) + "], intensity " +
               glsl::float_literal(source.intensity);
        if (const auto* spot = std::get_if<SpotLight>(&source.kind))
            out += ", cutoff " + glsl::float_literal(spot->cutoff_degrees) + " degrees";
        out += "\n    {.kind = " + light_kind_name(l.kind) +
               ",\n     .radiance = " + vec3_braces(l.radiance);
        if (l.kind == Kind::Point || l.kind == Kind::Spot) {
            out += ",\n     .position = " + vec3_braces(l.position);
        }
        if (l.kind == Kind::Directional || l.kind == Kind::Spot) {
            out += ",\n     .direction = " + vec3_braces(l.direction);
        }
        if (l.kind == Kind::Point || l.kind == Kind::Spot) {
            out += ",\n     .attenuation = " + vec3_braces(l.attenuation);
        }
        if (l.kind == Kind::Spot) {
            out += ",\n     .cos_cutoff = " + float_literal(l.cos_cutoff);
            out += ",\n     .cos_inner = " + float_literal(l.cos_inner);
            out += ",\n     .exponent = " + float_literal(l.exponent);
        }
        out += "},\n";
    }
    return out;
}

// The C++ program draws with the programs of the OpenGL backend, specialised
// to the scene's lights (glsl::generate_for_scene), so that both draw the
// same picture byte for byte and as fast; `--format glsl` writes the general
// programs, for any lights up to the scene's count.
std::string shaders_source(const ObjectModels& models, const Scene& scene) {
    std::vector<Light> lights;
    for (const SceneLight& light : scene.lights) lights.push_back(light.light);
    std::string out =
        "// The source of one program: a vertex and a fragment shader.\n"
        "struct ProgramSource {\n    const char* vertex;\n    const char* fragment;\n};\n\n";
    std::string table = "const std::vector<ProgramSource> programs = {\n";
    for (std::size_t i = 0; i < models.pairs.size(); ++i) {
        const ModelPair& pair = models.pairs[i];
        const glsl::Shaders shaders =
            models.glass[i] ? glass_shaders(models, i, scene)
                            : glsl::generate_for_scene(pair.first, pair.second, lights,
                                                       scene.output.gamma, fragment_output(scene));
        const std::string id = identifier(program_stem(models, i));
        out += "// Program " + std::to_string(i) + ": reflection " +
               std::string(to_string(pair.first)) + ", shading " +
               std::string(to_string(pair.second)) + (models.glass[i] ? ", glass" : "") + ".\n";
        out += "const char* const " + id + "_vertex = R\"glsl(" + shaders.vertex + ")glsl\";\n\n";
        out +=
            "const char* const " + id + "_fragment = R\"glsl(" + shaders.fragment + ")glsl\";\n\n";
        table += "    {" + id + "_vertex, " + id + "_fragment},\n";
    }
    return out + table + "};\n";
}

struct GeometrySource {
    std::string arrays;                  // the data
    std::string objects;                 // the ObjectData table's rows
    std::uint64_t numbers = 0;           // in `arrays`
    std::vector<detail::GlObject> kept;  // every object's, where some object is glass
};

// 16777216 → "16,777,216".
std::string grouped(std::uint64_t value) {
    const std::string digits = std::to_string(value);
    std::string text;
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) text += ',';
        text += digits[i];
    }
    return text;
}

// main.cpp holds every object's vertex data as numbers in the source, and a
// compiler needs hundreds of bytes of memory for each (docs/reliability.md):
// the error when object i brings them to `numbers`, past the limit.
[[noreturn]] void too_many_numbers(const Scene& scene, std::size_t i, std::uint64_t triangles,
                                   std::uint64_t numbers, bool at_least,
                                   const ExportOptions& options) {
    const SceneObject& object = scene.objects[i];
    std::string who = "objects[" + std::to_string(i) + "]";
    if (!object.name.empty()) who += " '" + object.name + "'";
    throw SceneError({Diagnostic{
        scene.location_of("objects[" + std::to_string(i) + "]"), Severity::Error,
        who + ": the C++ export would write " + (at_least ? "at least " : "") + grouped(numbers) +
            " numbers of vertex data into main.cpp (this object: " + grouped(triangles) +
            " triangles), more than its limit of " + grouped(options.max_source_numbers) +
            " (a compiler needs hundreds of bytes for each); lower the tessellation, or draw it "
            "with `litkit render --backend gl` (docs/reliability.md)"}});
}

// Object i's numbers in main.cpp when drawn flat or not, from its triangles
// and vertices.
std::uint64_t source_numbers(bool flat, std::uint64_t triangles, std::uint64_t vertices) {
    return flat ? 27 * triangles : 6 * vertices + 3 * triangles;
}

// Before any mesh is built: each built-in shape's triangles from its
// parameters (no vertices counted, so a lower bound), all objects together.
void check_source_size_from_parameters(const Scene& scene, const ObjectModels& models,
                                       const ExportOptions& options) {
    std::uint64_t total = 0;
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const ModelPair& pair = models.pairs[static_cast<std::size_t>(models.program[i])];
        const std::uint64_t triangles = triangles_of(scene.objects[i].shape);
        total += source_numbers(pair.second == Shading::Flat, triangles, 0);
        if (total > options.max_source_numbers)
            too_many_numbers(scene, i, triangles, total, true, options);
    }
}

GeometrySource geometry_source(const Scene& scene, const ObjectModels& models,
                               const ExportOptions& options) {
    GeometrySource out;
    std::uint64_t total_numbers = 0;
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& object = scene.objects[i];
        const ModelPair& pair = models.pairs[static_cast<std::size_t>(models.program[i])];
        detail::GlObject gl =
            detail::gl_object(object, pair.first, pair.second, normal_options(scene, object));
        total_numbers += gl.vertices.size() + gl.indices.size();
        if (total_numbers > options.max_source_numbers)
            too_many_numbers(scene, i, gl.triangles, total_numbers, false, options);
        const std::string id = "object" + std::to_string(i);
        const std::string label = (object.name.empty() ? std::string(shape_type_name(object.shape))
                                                       : printable(object.name));
        const bool flat = gl.indices.empty();
        const std::size_t per_vertex = flat ? 9 : 6;

        out.arrays += "// " + id + " \"" + label +
                      "\": " + std::string(shape_type_name(object.shape)) + ", " +
                      std::to_string(gl.triangles) + " triangles\n";
        out.arrays += "const float " + id + "_vertices[] = {\n";
        for (std::size_t v = 0; v < gl.vertices.size(); v += per_vertex) {
            out.arrays += "   ";
            for (std::size_t k = 0; k < per_vertex; ++k) {
                out.arrays += (k % 3 == 0 && k > 0) ? "  " : " ";
                out.arrays += float_literal(gl.vertices[v + k]) + ",";
            }
            out.arrays += "\n";
        }
        out.arrays += "};\n";
        if (!flat) {
            out.arrays += "const std::uint32_t " + id + "_indices[] = {\n";
            for (std::size_t t = 0; t < gl.indices.size(); t += 3) {
                out.arrays += "    " + std::to_string(gl.indices[t]) + ", " +
                              std::to_string(gl.indices[t + 1]) + ", " +
                              std::to_string(gl.indices[t + 2]) + ",\n";
            }
            out.arrays += "};\n";
        }
        out.arrays += "\n";

        const Material& m = object.material;
        std::string parameters;
        for_each_model_parameter(
            [&](const ModelParameter& parameter, const float& value) {
                parameters += std::string(parameters.empty() ? "" : ", ") + "{\"" +
                              std::string(parameter.key) + "\", " + float_literal(value) + "}";
            },
            m);
        out.objects +=
            "    {.name = \"" + label +
            "\",\n     .program = " + std::to_string(models.program[i]) + ",  // " +
            program_stem(models, static_cast<std::size_t>(models.program[i])) +
            "\n     .material = {.color = " + vec3_braces(m.color) +
            ", .ka = " + float_literal(m.ka) + ", .kd = " + float_literal(m.kd) +
            ", .ks = " + float_literal(m.ks) + ", .shininess = " + float_literal(m.shininess) +
            ",\n                  .parameters = {" + parameters + "}},\n     .vertices = " + id +
            "_vertices,\n     .vertex_floats = std::size(" + id + "_vertices)";
        if (!flat) {
            out.objects += ",\n     .indices = " + id +
                           "_indices,\n     .index_count = std::size(" + id + "_indices)";
        }
        out.objects += "},\n";
        if (detail::has_glass(scene)) out.kept.push_back(std::move(gl));
    }
    out.numbers = total_numbers;
    return out;
}

// Before writing anything: every file is new, or replacing is allowed.
void check_new(const std::vector<fs::path>& files, const ExportOptions& options) {
    if (options.replace_existing) return;
    for (const fs::path& file : files) {
        std::error_code error;
        if (fs::exists(fs::symlink_status(file, error)))
            throw IoError(file.string(), "already exists", {}, IoError::Access::Write);
    }
}

// An export never writes over what it reads, even when replacing is allowed.
void refuse_to_overwrite_inputs(const Scene& scene, const std::vector<fs::path>& files,
                                const ExportOptions& options) {
    std::vector<fs::path> inputs = options.inputs;
    for (const SceneObject& object : scene.objects)
        if (const auto* mesh = std::get_if<MeshFileShape>(&object.shape))
            inputs.push_back(mesh->file);
    for (const fs::path& file : files)
        for (const fs::path& input : inputs)
            if (same_file(file, input))
                throw ArgumentError("refusing to write '" + file.string() + "' over input file '" +
                                    input.string() + "'; choose another folder with -o");
}

// The names of `files` within their folder, with their texts.
std::vector<std::pair<std::string, std::string>> named(const std::vector<fs::path>& files,
                                                       std::vector<std::string> texts) {
    std::vector<std::pair<std::string, std::string>> result;
    for (std::size_t i = 0; i < files.size(); ++i)
        result.emplace_back(files[i].filename().string(), std::move(texts[i]));
    return result;
}

// CMake keeps these target names for itself.
bool is_reserved_by_cmake(const std::string& name) {
    static const char* const reserved[] = {
        "all",        "clean",          "help",       "install",       "test",
        "package",    "package_source", "edit_cache", "rebuild_cache", "list_install_components",
        "preinstall", "depend"};
    return std::any_of(std::begin(reserved), std::end(reserved),
                       [&](const char* word) { return name == word; });
}

bool is_identifier(const std::string& name) {
    if (name.empty() || name.size() > 64) return false;
    for (std::size_t i = 0; i < name.size(); ++i) {
        const char c = name[i];
        const bool letter = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
        if (!letter && !(i > 0 && c >= '0' && c <= '9')) return false;
    }
    return true;
}

}  // namespace

std::vector<fs::path> export_glsl(const Scene& scene, const fs::path& directory,
                                  const ExportOptions& options) {
    ObjectModels models = object_models(scene, options);
    if (models.pairs.empty()) {  // no objects: the scene's own models, ready for some
        models.pairs.push_back({scene.reflection.value_or(options.fallback_reflection),
                                scene.shading.value_or(options.fallback_shading)});
        models.glass.push_back(false);
    }
    std::vector<fs::path> files;
    std::vector<std::string> texts;
    for (std::size_t i = 0; i < models.pairs.size(); ++i) {
        const ModelPair& pair = models.pairs[i];
        // Glass programs are specialised to the scene's lights and models,
        // as the C++ program's are (their rays reach every object).
        glsl::Shaders shaders = models.glass[i]
                                    ? glass_shaders(models, i, scene)
                                    : glsl::generate(pair.first, pair.second, light_capacity(scene),
                                                     fragment_output(scene));
        if (scene.output.samples > 1)  // at the end of the comment that heads the shader
            shaders.fragment.insert(shaders.fragment.find("\n\n") + 1,
                                    detail::host_samples_comment(scene));
        const std::string stem = program_stem(models, i);
        files.push_back(directory / (stem + ".vert"));
        texts.push_back(std::move(shaders.vertex));
        files.push_back(directory / (stem + ".frag"));
        texts.push_back(std::move(shaders.fragment));
    }
    refuse_to_overwrite_inputs(scene, files, options);
    check_new(files, options);
    write_folder_atomically(directory, named(files, std::move(texts)));
    return files;
}

std::vector<fs::path> export_cpp(const Scene& input, const fs::path& directory,
                                 const std::string& program_name, const std::string& scene_label,
                                 const ExportOptions& options) {
    // The program draws what the renderers draw: lengths brought into a
    // float's range by a power of two (scene/float_range.hpp; 1 for
    // ordinary scenes).
    const Scene scene = scale_lengths(input, float_safe_length_scale(input));
    if (!is_identifier(program_name))
        throw ArgumentError("program name '" + program_name +
                            "' is not a C identifier (letters, digits, _)");
    if (is_reserved_by_cmake(program_name))
        throw ArgumentError("program name '" + program_name +
                            "' is a target name CMake keeps for itself; choose another");
    const ObjectModels models = object_models(scene, options);
    check_source_size_from_parameters(scene, models, options);
    const GeometrySource geometry =
        geometry_source(scene, models, options);  // reads mesh files first
    detail::GlassSource glass;
    if (detail::has_glass(scene)) {
        std::vector<int> glass_object;
        for (std::size_t i = 0; i < scene.objects.size(); ++i)
            glass_object.push_back(
                scene.objects[i].material.transmission > 0.0f ? static_cast<int>(i) : -1);
        glass = detail::glass_source(detail::glass_data(scene, geometry.kept), glass_object);
        const std::uint64_t numbers = geometry.numbers + glass.numbers;
        if (numbers > options.max_source_numbers)
            throw SceneError({Diagnostic{
                scene.location_of("objects"), Severity::Error,
                "the C++ export would write " + grouped(numbers) +
                    " numbers of vertex and glass data into main.cpp, more than its limit of " +
                    grouped(options.max_source_numbers) +
                    " (a compiler needs hundreds of bytes for each); lower the tessellation, or "
                    "draw it with `litkit render --backend gl` (docs/reliability.md)"}});
    }

    const Observer& o = scene.observer;
    const Rgb8 bg = to_rgb8(scene.output.background);
    const std::string program = fill_template(
        detail::program_template_text,
        {{"CORE", std::string(detail::opengl_core_text) + "\n" + detail::opengl_samples_text},
         {"SHADERS", shaders_source(models, scene)},
         {"WIDTH", std::to_string(scene.output.width)},
         {"HEIGHT", std::to_string(scene.output.height)},
         {"BACKGROUND", "glm::vec3(" + std::to_string(bg[0]) + ", " + std::to_string(bg[1]) + ", " +
                            std::to_string(bg[2]) + ") / 255.0f"},
         {"GAMMA", float_literal(scene.output.gamma)},
         {"SAMPLES", detail::samples_source(scene)},
         {"EYE", vec3_literal(o.position)},
         {"LOOK_AT", vec3_literal(o.look_at)},
         {"UP", vec3_literal(o.up)},
         {"FOV", float_literal(o.fov_degrees)},
         {"NEAR", float_literal(o.near)},
         {"FAR", float_literal(o.far)},
         {"LIGHTS", lights_source(scene)},
         {"GEOMETRY", geometry.arrays + glass.arrays},
         {"GLASS_DECLARATIONS", glass.declarations},
         {"GLASS_SETUP", glass.setup},
         {"OBJECTS", geometry.objects},
         {"SCENE", wrapped("\"", printable(scene_label), "\"")},
         {"VERSION", LITKIT_VERSION},
         {"NAME", program_name}});

    const std::string cmake =
        "# Builds " + program_name +
        " (generated by litkit " LITKIT_VERSION
        ", `litkit export --format cpp`).\n"
        "#   cmake -S . -B build && cmake --build build\n"
        "cmake_minimum_required(VERSION 3.16)\n"
        "project(" +
        program_name +
        " LANGUAGES CXX)\n\n"
        "set(CMAKE_CXX_STANDARD 20)\n"
        "set(CMAKE_CXX_STANDARD_REQUIRED ON)\n"
        "if(NOT CMAKE_BUILD_TYPE)\n"
        "    set(CMAKE_BUILD_TYPE Release)\n"
        "endif()\n\n"
        "find_package(PkgConfig REQUIRED)\n"
        "pkg_check_modules(EPOXY REQUIRED IMPORTED_TARGET epoxy)  # loads EGL and OpenGL\n"
        "find_package(PNG REQUIRED)\n"
        "find_package(glm REQUIRED)\n"
        "find_package(SDL2 QUIET)  # optional: --window\n\n"
        "add_executable(" +
        program_name +
        " main.cpp)\n"
        "target_link_libraries(" +
        program_name +
        " PRIVATE PkgConfig::EPOXY PNG::PNG glm::glm)\n"
        "if(SDL2_FOUND)\n"
        "    target_link_libraries(" +
        program_name +
        " PRIVATE SDL2::SDL2)\n"
        "    target_compile_definitions(" +
        program_name +
        " PRIVATE WITH_SDL2)\n"
        "else()\n"
        "    message(STATUS \"SDL2 not found: " +
        program_name +
        " will have no --window (Debian: libsdl2-dev)\")\n"
        "endif()\n";

    const std::vector<fs::path> written{directory / "main.cpp", directory / "CMakeLists.txt"};
    refuse_to_overwrite_inputs(scene, written, options);
    check_new(written, options);
    write_folder_atomically(directory, named(written, {program, cmake}));
    return written;
}

std::string export_cpp_instructions(const fs::path& directory, const std::string& program_name) {
    const std::string dir = shell_word(directory.string());
    const std::string build = shell_word((directory / "build").string());
    const std::string binary = shell_word((directory / "build" / program_name).string());
    return "cmake -S " + dir + " -B " + build + " && cmake --build " + build + " && " + binary;
}

}  // namespace litkit
