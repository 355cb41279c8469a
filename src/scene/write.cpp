// SPDX-License-Identifier: MIT
// A Scene written back as one TOML file that reads as the same scene: every
// number in its shortest form that reads back to the same float, colours as
// the 0-255 integers they came from.
#include <charconv>
#include <cmath>
#include <cstdio>
#include <string>
#include <variant>

#include "litkit/scene.hpp"

namespace litkit {

namespace {

std::string number(float value) {
    char buffer[32];
    const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
    std::string text(buffer, error == std::errc() ? end : buffer);
    // "3" would read as an integer; TOML takes both for a number, but keep
    // the type visible.
    if (text.find_first_of(".eEn") == std::string::npos) text += ".0";
    return text;
}

// std::string("…") + a temporary, not a bare literal: GCC 12 warns falsely
// (-Wrestrict, GCC bug 105329) on a literal + a temporary std::string.
std::string vec3(const glm::vec3& v) {
    return std::string("[") + number(v.x) + ", " + number(v.y) + ", " + number(v.z) + "]";
}

std::string color(const glm::vec3& unit) {
    auto channel = [](float c) { return std::to_string(std::lround(c * 255.0f)); };
    return std::string("[") + channel(unit.x) + ", " + channel(unit.y) + ", " + channel(unit.z) +
           "]";
}

std::string rgb8(const Rgb8& c) {
    return "[" + std::to_string(c[0]) + ", " + std::to_string(c[1]) + ", " + std::to_string(c[2]) +
           "]";
}

// A TOML basic string: quotes, backslashes and control characters escaped.
std::string quoted(const std::string& text) {
    std::string out = "\"";
    for (char c : text) {
        const auto u = static_cast<unsigned char>(c);
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (u < 0x20 || u == 0x7f) {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\u%04X", u);
            out += escaped;
        } else {
            out += c;
        }
    }
    return out + "\"";
}

std::string light_text(const SceneLight& scene_light) {
    const Light& light = scene_light.light;
    std::string text = "\n[[lights]]\n";
    if (!scene_light.name.empty()) text += "name = " + quoted(scene_light.name) + "\n";
    text += "type = \"" + std::string(light_kind_name(light.kind)) + "\"\n";
    std::visit(
        [&](const auto& kind) {
            using K = std::decay_t<decltype(kind)>;
            if constexpr (std::is_same_v<K, AmbientLight>) {
                // no keys of its own
            } else if constexpr (std::is_same_v<K, DirectionalLight>) {
                text += "direction = " + vec3(kind.direction) + "\n";
            } else if constexpr (std::is_same_v<K, PointLight>) {
                text += "position = " + vec3(kind.position) +
                        "\nattenuation = " + vec3(kind.attenuation) + "\n";
            } else {
                text += "position = " + vec3(kind.position) +
                        "\nattenuation = " + vec3(kind.attenuation) +
                        "\ndirection = " + vec3(kind.direction) +
                        "\ncutoff = " + number(kind.cutoff_degrees) +
                        "\nexponent = " + number(kind.exponent) +
                        "\npenumbra = " + number(kind.penumbra) + "\n";
            }
        },
        light.kind);
    text += "color = " + color(light.color) + "\nintensity = " + number(light.intensity) + "\n";
    return text;
}

std::string object_text(const SceneObject& object, const std::filesystem::path& folder) {
    std::string text = "\n[[objects]]\n";
    if (!object.name.empty()) text += "name = " + quoted(object.name) + "\n";
    std::visit(
        [&](const auto& shape) {
            using S = std::decay_t<decltype(shape)>;
            if constexpr (std::is_same_v<S, CubeShape>) {
                text += "type = \"cube\"\nsize = " + number(shape.size) + "\n";
            } else if constexpr (std::is_same_v<S, SphereShape>) {
                text += "type = \"sphere\"\nradius = " + number(shape.radius) +
                        "\nsegments = " + std::to_string(shape.segments) +
                        "\nrings = " + std::to_string(shape.rings) + "\n";
            } else if constexpr (std::is_same_v<S, TorusShape>) {
                text += "type = \"torus\"\nmajor_radius = " + number(shape.major_radius) +
                        "\nminor_radius = " + number(shape.minor_radius) +
                        "\nsegments = " + std::to_string(shape.segments) +
                        "\nsides = " + std::to_string(shape.sides) + "\n";
            } else if constexpr (std::is_same_v<S, TeapotShape>) {
                text += "type = \"teapot\"\nsize = " + number(shape.size) +
                        "\nsubdivisions = " + std::to_string(shape.subdivisions) + "\n";
            } else if constexpr (std::is_same_v<S, MeshDataShape>) {
                throw ArgumentError(
                    (object.name.empty() ? std::string("an object")
                                         : "object '" + object.name + "'") +
                    " has an in-memory mesh, which a scene file cannot hold: write it as an OBJ "
                    "file (litkit::mesh_to_obj) and use a MeshFileShape that names the file");
            } else {
                // Relative to the written file where it can be, else absolute.
                std::filesystem::path file = std::filesystem::absolute(shape.file);
                if (!folder.empty()) {
                    const std::filesystem::path relative =
                        file.lexically_relative(std::filesystem::absolute(folder));
                    if (!relative.empty()) file = relative;
                }
                text += "type = \"mesh\"\nfile = " + quoted(file.generic_string()) + "\n";
                if (shape.format)
                    text += "format = " + quoted(std::string(to_string(*shape.format))) + "\n";
            }
        },
        object.shape);
    text += "position = " + vec3(object.position) +
            "\nrotation = " + vec3(object.rotation_degrees) + "\nscale = " + number(object.scale) +
            "\n";
    if (object.normals) text += "normals = \"" + std::string(to_string(*object.normals)) + "\"\n";
    if (object.crease_angle_degrees)
        text += "crease_angle = " + number(*object.crease_angle_degrees) + "\n";
    if (object.reflection)
        text += "reflection = \"" + std::string(to_string(*object.reflection)) + "\"\n";
    if (object.shading) text += "shading = \"" + std::string(to_string(*object.shading)) + "\"\n";
    const Material& m = object.material;
    text += "material = { color = " + color(m.color) + ", ka = " + number(m.ka) +
            ", kd = " + number(m.kd) + ", ks = " + number(m.ks) +
            ", shininess = " + number(m.shininess);
    for_each_model_parameter(
        [&](const ModelParameter& parameter, const float& value) {
            text += ", " + std::string(parameter.key) + " = " +
                    (parameter.whole ? std::to_string(std::lround(value)) : number(value));
        },
        m);
    text += ", transmission = " + number(m.transmission) + ", ior = " + number(m.ior) +
            ", absorption_color = " + color(m.absorption_color) +
            ", absorption_distance = " + number(m.absorption_distance);
    return text + " }\n";
}

}  // namespace

std::string scene_to_toml(const Scene& scene, const std::filesystem::path& written_as) {
    const std::filesystem::path folder =
        written_as.empty() ? std::filesystem::path() : written_as.parent_path();
    std::string text = "# litkit scene\n\n[room]\nwidth = " + number(scene.room.width) +
                       "\nheight = " + number(scene.room.height) +
                       "\ndepth = " + number(scene.room.depth) +
                       "\nior = " + number(scene.room.ior) + "\n";
    const Observer& o = scene.observer;
    text += "\n[observer]\nposition = " + vec3(o.position) + "\nlook_at = " + vec3(o.look_at) +
            "\nup = " + vec3(o.up) + "\nfov = " + number(o.fov_degrees) +
            "\nnear = " + number(o.near) + "\nfar = " + number(o.far) + "\n";
    text += "\n[lighting]\n";
    if (scene.reflection)
        text += "reflection = \"" + std::string(to_string(*scene.reflection)) + "\"\n";
    if (scene.shading) text += "shading = \"" + std::string(to_string(*scene.shading)) + "\"\n";
    if (scene.normals) text += "normals = \"" + std::string(to_string(*scene.normals)) + "\"\n";
    if (scene.crease_angle_degrees)
        text += "crease_angle = " + number(*scene.crease_angle_degrees) + "\n";
    text += "max_depth = " + std::to_string(scene.max_depth) + "\n";
    text += "\n[output]\nwidth = " + std::to_string(scene.output.width) +
            "\nheight = " + std::to_string(scene.output.height) +
            "\nbackground = " + rgb8(to_rgb8(scene.output.background)) +
            "\ngamma = " + number(scene.output.gamma) + "\n";
    if (scene.output.samples != default_samples)
        text += "samples = " + std::to_string(scene.output.samples) + "\n";
    for (const SceneLight& light : scene.lights) text += light_text(light);
    for (const SceneObject& object : scene.objects) text += object_text(object, folder);
    return text;
}

}  // namespace litkit
