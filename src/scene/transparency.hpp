// SPDX-License-Identifier: MIT
// Objects that refract (docs/spec.md §10): the closed-mesh rule of §10.1 as
// validation reports it, and which object is the first to refract.
#pragma once

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

}  // namespace litkit::detail
