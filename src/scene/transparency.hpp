// SPDX-License-Identifier: MIT
// Objects that refract (docs/spec.md §10): the closed-mesh rule of §10.1 as
// validation reports it, which object is the first to refract, and what the
// tracers take from the scene.
#pragma once

#include <glm/vec3.hpp>

#include <cstddef>
#include <optional>
#include <string>

#include "litkit/mesh.hpp"
#include "litkit/scene.hpp"

namespace litkit::detail {

// Why `mesh`, the local mesh of `object` (a mesh file or an in-memory mesh),
// breaks the closed-mesh rule, naming one edge by its two positions in the
// mesh's own coordinates and, for a file, the face and line that use it;
// empty when it is closed.
std::string closed_mesh_problem(const SceneObject& object, const Mesh& mesh);

// The first object whose transmission is above 0, if any.
std::optional<std::size_t> first_transparent_object(const Scene& scene);

// What the ray tree of docs/spec.md §10.2 item 8 takes from the scene, for
// every tracer (the CPU's and the shaders'): hits of secondary rays closer
// than 10⁻⁶ × the room's diagonal are ignored, and a ray that leaves the
// scene brings (background/255)^γ.
float secondary_min_distance(const Room& room);
glm::vec3 background_light(const OutputSettings& output);

}  // namespace litkit::detail
