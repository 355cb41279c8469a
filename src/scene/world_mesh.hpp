// world_mesh (litkit/scene.hpp) with its independent parts run through
// `parallel` (core/parallel.hpp), for the renderer, which lends its threads:
// the vertex normals (vertex_normals with `parallel`) and the move to world
// space. The same mesh, bit for bit.
#pragma once

#include "core/parallel.hpp"
#include "litkit/scene.hpp"

namespace litkit {

// Keeps a built-in shape's (cube, sphere, torus, teapot) just-built local
// mesh for the next world_mesh of an object of the same shape, which takes
// it instead of building it again: load_scene's validation builds every
// object's mesh, and the renderer of the same scene builds it again
// (issue 16). The last four kept stay; mesh files and in-memory meshes are
// not kept (a file can change between two reads). Thread-safe.
void keep_built_mesh(const Shape& shape, Mesh mesh);

WorldMesh world_mesh(const SceneObject& object, const NormalOptions& options,
                     const ParallelFor& parallel);

}  // namespace litkit
