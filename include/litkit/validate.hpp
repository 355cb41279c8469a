/// \file
/// The value and geometry rules of docs/spec.md §6 (R2, R8), checked on a loaded
/// scene before anything renders. The loader (scene.hpp) checks the shape of
/// the input (types, keys, spelling); this checks what the values mean.
#pragma once

#include <cstdint>
#include <vector>

#include "litkit/error.hpp"
#include "litkit/scene.hpp"

namespace litkit {

/// Every problem of `scene`, errors and warnings, each located through
/// scene.locations: first the values (room, output, observer, lights,
/// objects, names), then the geometry (objects against the room, each other
/// and the observer; lights inside objects), then the warnings.
/// Shape parameters are checked before any mesh is built, so a huge
/// `segments` is refused before it allocates. Mesh files are read to test
/// their geometry: one that cannot be read throws IoError located at its
/// `file` key. Returns the problems rather than throwing them: the scene is
/// valid when none has Severity::Error.
std::vector<Diagnostic> validate_scene(const Scene& scene);

/// The same, with a triangle budget other than default_triangle_budget: the
/// most triangles all the scene's objects may make together.
std::vector<Diagnostic> validate_scene(const Scene& scene, std::uint64_t triangle_budget);

/// The triangles `shape` will be made of, from its parameters alone (nothing
/// is built); 0 for a mesh file, whose size is bounded by the file size limit.
std::uint64_t triangles_of(const Shape& shape);

}  // namespace litkit
