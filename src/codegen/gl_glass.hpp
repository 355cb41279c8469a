// SPDX-License-Identifier: MIT
// The scene as the glass programs' rays see it (codegen/glsl_glass.hpp has
// the layouts): the triangles of every object in world space under a
// bounding-volume hierarchy, the objects' surfaces and glass, and the
// settings of docs/spec.md §10.2, as the texture buffers' texels. Built from
// the very vertex arrays OpenGL draws (gl_scene.hpp), so that a fragment's
// triangle and a ray's are the same numbers. Shared by the GL backend and
// the C++ exporter.
#pragma once

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "codegen/gl_scene.hpp"
#include "litkit/scene.hpp"

namespace litkit::detail {

struct GlassData {
    // RGBA32F texels, four floats each.
    std::vector<float> triangles, nodes, objects, faces;
    int node_count = 0;
    // Per object: its first triangle in `faces` (drawing order).
    std::vector<int> face_base;
    // The scene's reflection models, each once (model k of `objects`).
    std::vector<Reflection> models;
    float room_ior = 1.0f;
    int max_depth = default_max_depth;
    float min_distance = 0.0f;         // 1e-6 × the room's diagonal
    glm::vec3 background_light{0.0f};  // (background / 255)^γ
};

// Whether some object of the scene has t > 0.
bool has_glass(const Scene& scene);

// The scene's reflection models, each once, in the objects' order.
std::vector<Reflection> scene_models(std::span<const GlObject> objects);

// Everything, for `objects` = gl_object of each of the scene's objects.
// Throws std::runtime_error where the hierarchy is deeper than the shaders'
// stack.
GlassData glass_data(const Scene& scene, std::span<const GlObject> objects);

// What changes with the objects' materials and the scene's settings alone
// (no geometry): `data`'s objects and settings, for the same models.
void update_glass_data(GlassData& data, const Scene& scene, std::span<const GlObject> objects);

// The C++ export's text for a scene with glass (export_glass.cpp): what
// program.cpp.in's markers GLASS_DECLARATIONS and GLASS_SETUP take, the
// arrays for the end of the file, and how many numbers those hold.
struct GlassSource {
    std::string declarations;
    std::string setup;
    std::string arrays;
    std::uint64_t numbers = 0;
};
// `glass_object`: per scene object, its number for the glass programs or -1.
GlassSource glass_source(const GlassData& data, std::span<const int> glass_object);

}  // namespace litkit::detail
