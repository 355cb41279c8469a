// SPDX-License-Identifier: MIT
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
/// `file` key. The built-in shapes' meshes it builds go to
/// scene.built_meshes where that is set, for the renderers (and are taken
/// from there first). Returns the problems rather than throwing them: the
/// scene is valid when none has Severity::Error.
std::vector<Diagnostic> validate_scene(const Scene& scene);

/// The same, with a triangle budget other than default_triangle_budget: the
/// most triangles all the scene's objects may make together.
std::vector<Diagnostic> validate_scene(const Scene& scene, std::uint64_t triangle_budget);

/// What every renderer (Renderer, render(), GlRenderer, compare, explain,
/// turntable) checks before it draws, and throws as SceneError listing every
/// problem: the rules of docs/spec.md §6 about each value on its own — sizes
/// in range (the image 1–max_image_side pixels each way, shape parameters, scale),
/// every number finite (a NaN or infinite camera, light or object), a usable
/// view (fov, near < far, look_at not the position, up not parallel to the
/// view), materials and lights in range, an in-memory mesh checked as a
/// mesh file is (check_mesh_data). Cheap: no mesh is built and nothing is
/// compared with anything else, O(lights + objects) plus the in-memory
/// meshes' size. It does not check the relations between entities (objects
/// overlapping or outside the room, lights inside objects, repeated names
/// or positions) nor the triangle budget: those need validate_scene, which
/// load_scene and parse_scene run; a scene that breaks only them renders,
/// drawn as it is. Locations are those of scene.locations (empty for values
/// set in code; the message names the value, e.g. "objects[0]: radius must
/// be > 0, found -1").
void check_renderable(const Scene& scene);

/// The triangles `shape` will be made of, from its parameters alone (nothing
/// is built): the count the triangle budget (default_triangle_budget) is
/// checked against. 0 for a mesh file, whose size is bounded by the file
/// size limit; the triangle count of an in-memory mesh (0 if it holds none).
std::uint64_t triangles_of(const Shape& shape);

}  // namespace litkit
