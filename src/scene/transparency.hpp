// SPDX-License-Identifier: MIT
// Objects that refract (docs/spec.md §10): the closed-mesh rule of §10.1 as
// validation reports it, and the refusal of the drawers that cannot trace
// rays (§10: a backend that cannot says so rather than draw something else).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

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

// Throws ArgumentError when some object of the scene has a transmission
// above 0: `drawer` ("the OpenGL backend") does not draw refraction yet; the
// message names the object and the CPU backend, which does.
void refuse_refraction(const Scene& scene, std::string_view drawer);

}  // namespace litkit::detail
