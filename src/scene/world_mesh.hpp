// world_mesh (litkit/scene.hpp) with its independent parts run through
// `parallel` (core/parallel.hpp), for the renderer, which lends its threads:
// the vertex normals (vertex_normals with `parallel`) and the move to world
// space. The same mesh, bit for bit.
#pragma once

#include "core/parallel.hpp"
#include "litkit/scene.hpp"

namespace litkit {

WorldMesh world_mesh(const SceneObject& object, const NormalOptions& options,
                     const ParallelFor& parallel);

}  // namespace litkit
