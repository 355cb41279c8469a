// SPDX-License-Identifier: MIT
// The validator as the loader calls it: told which entities already failed
// the loader's shape checks, so their stand-in defaults raise no geometric
// follow-on errors.
#pragma once

#include <cstddef>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "litkit/error.hpp"
#include "litkit/scene.hpp"

namespace litkit {

// Entity names as in Scene::locations: "room", "observer", "output",
// "lighting", "lights[2]", "objects[0]"; "" for a problem with the file as a
// whole (a missing or misspelt table), which leaves out all geometry.
using BrokenEntities = std::set<std::string, std::less<>>;

std::vector<Diagnostic> validate_scene(const Scene& scene, const BrokenEntities& broken,
                                       std::uint64_t triangle_budget = default_triangle_budget);

// docs/spec.md §9.2, normals = "file": the error for a face corner of a mesh
// file without a normal, located at that face's line in the mesh file; and
// the first such error of a mesh, if any.
Diagnostic missing_file_normal_error(const MeshFileShape& file, const Mesh& mesh,
                                     std::size_t triangle);
std::optional<Diagnostic> check_file_normals(const MeshFileShape& file, const Mesh& mesh);

}  // namespace litkit
