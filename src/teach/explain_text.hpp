// SPDX-License-Identifier: MIT
// What explain's text and JSON writers share (teach/explain_format.cpp,
// teach/explain_tree.cpp): numbers as the shortest text that reads back as
// the same float, vectors, and an object's label.
#pragma once

#include <charconv>
#include <cmath>
#include <cstddef>
#include <glm/vec3.hpp>
#include <string>

#include "core/json.hpp"
#include "litkit/explain.hpp"
#include "litkit/scene.hpp"

namespace litkit::detail {

// Shortest text that reads back as the same float.
inline std::string num(float value) {
    if (std::isnan(value)) return "nan";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    char buffer[32];
    const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
    return error == std::errc() ? std::string(buffer, end) : "?";
}

// std::string("…") + a temporary, not a bare literal: GCC 12 warns falsely
// (-Wrestrict, GCC bug 105329) on a literal + a temporary std::string.
inline std::string vec(const glm::vec3& v) {
    return std::string("(") + num(v.x) + ", " + num(v.y) + ", " + num(v.z) + ")";
}

// A vector as a JSON array (core/json.hpp: a non-finite component is null).
inline std::string json_vec(const glm::vec3& v) {
    return std::string("[") + json::number(v.x) + ", " + json::number(v.y) + ", " +
           json::number(v.z) + "]";
}

// "objects[2] 'lens' (sphere)".
inline std::string object_label(const Scene& scene, std::size_t index) {
    const SceneObject& object = scene.objects[index];
    return "objects[" + std::to_string(index) + "]" +
           (object.name.empty() ? "" : " '" + object.name + "'") + " (" +
           std::string(shape_type_name(object.shape)) + ")";
}

// The ray tree of a glass pixel (docs/spec.md §10.3) as text: one short
// block per ray, indented by depth, the rays that bring less than 1/255 of
// the pixel's largest channel counted and summed in one line; then the sum
// of the contributions. Empty for a pixel without a tree.
std::string ray_tree_text(const PixelExplanation& explanation, const Scene& scene);
// The ray tree as a JSON array, every node (no summary); "[]" without one.
std::string ray_tree_json(const PixelExplanation& explanation, const Scene& scene);

}  // namespace litkit::detail
