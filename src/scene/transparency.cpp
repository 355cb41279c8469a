// SPDX-License-Identifier: MIT
// Objects that refract (transparency.hpp).
#include "scene/transparency.hpp"

#include <charconv>
#include <cmath>
#include <variant>

#include "core/portable_math.hpp"
#include "geometry/closed_mesh.hpp"
#include "geometry/mesh_formats.hpp"

namespace litkit::detail {

namespace {

std::string number_text(float value) {
    char buffer[32];
    auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
    return error == std::errc() ? std::string(buffer, end) : std::string("?");
}

// "[x, y, z]", as validation writes positions.
std::string position_text(const glm::vec3& p) {
    std::string text("[");
    text += number_text(p.x);
    text += ", ";
    text += number_text(p.y);
    text += ", ";
    text += number_text(p.z);
    text += ']';
    return text;
}

}  // namespace

std::string closed_mesh_problem(const SceneObject& object, const Mesh& mesh) {
    const std::optional<UnclosedEdge> edge = find_unclosed_edge(mesh);
    if (!edge) return {};
    const auto* file = std::get_if<MeshFileShape>(&object.shape);
    std::string text = "transmission " + number_text(object.material.transmission) +
                       " needs a closed mesh (docs/spec.md §10.1), and ";
    text += file ? "mesh file '" + file->file.filename().string() + "'"
                 : std::string("the in-memory mesh");
    text += " is not closed: its edge from " + position_text(mesh.positions[edge->from]) + " to " +
            position_text(mesh.positions[edge->to]);
    if (file && edge->triangle < mesh.triangle_faces.size()) {
        const std::uint32_t face = mesh.triangle_faces[edge->triangle];
        text += " (face " + std::to_string(face + 1);
        const std::uint32_t line =
            mesh_format(file->file, file->format).line_of_face(file->file, face);
        if (line > 0) text += ", line " + std::to_string(line);
        text += ")";
    } else {
        text += " (triangle " + std::to_string(edge->triangle) + ")";
    }
    const std::size_t uses = edge->forward + edge->backward;
    if (uses == 1)
        text += " belongs to one triangle only";
    else if (edge->backward == 0)
        text += " is used by " + std::to_string(uses) +
                " triangles in the same direction (their windings disagree)";
    else
        text += " is used by " + std::to_string(uses) +
                " triangles (a closed surface has two at each edge, once in each direction)";
    return text;
}

std::optional<std::size_t> first_transparent_object(const Scene& scene) {
    for (std::size_t i = 0; i < scene.objects.size(); ++i)
        if (scene.objects[i].material.transmission > 0.0f) return i;
    return std::nullopt;
}

float secondary_min_distance(const Room& room) {
    return 1e-6f *
           std::sqrt(room.width * room.width + room.height * room.height + room.depth * room.depth);
}

glm::vec3 background_light(const OutputSettings& output) {
    const glm::vec3 background = output.background;
    const float gamma = output.gamma;
    return {power(background.x, gamma), power(background.y, gamma), power(background.z, gamma)};
}

}  // namespace litkit::detail
