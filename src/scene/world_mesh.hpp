// world_mesh (litkit/scene.hpp) with its independent parts run through
// `parallel` (core/parallel.hpp), for the renderer, which lends its threads:
// the vertex normals (vertex_normals with `parallel`) and the move to world
// space. The same mesh, bit for bit.
#pragma once

#include <memory>

#include "core/parallel.hpp"
#include "litkit/scene.hpp"

namespace litkit {

// object_mesh, shared: a built-in shape (cube, sphere, torus, teapot) is
// built once for all callers asking for it with the same parameters while
// it is among the last few asked for (load_scene's validation and the
// renderer of the same scene, issue 16); a mesh file or in-memory mesh is
// built for each call (a file can change between two reads). Thread-safe.
std::shared_ptr<const Mesh> shared_object_mesh(const SceneObject& object);

WorldMesh world_mesh(const SceneObject& object, const NormalOptions& options,
                     const ParallelFor& parallel);

}  // namespace litkit
