// SPDX-License-Identifier: MIT
// The meshes a scene's validation built, kept for its renderers
// (Scene::built_meshes), and world_mesh (litkit/scene.hpp) with its
// independent parts run through `parallel` (core/parallel.hpp), for the
// renderer, which lends its threads: the vertex normals (vertex_normals with
// `parallel`) and the move to world space. The same mesh, bit for bit.
#pragma once

#include <cstddef>
#include <deque>
#include <mutex>
#include <optional>
#include <utility>

#include "core/parallel.hpp"
#include "litkit/scene.hpp"

namespace litkit {

// Built-in shapes' (cube, sphere, torus, teapot) local meshes, kept where
// they were built for the next object of the same shape to take instead of
// building it again: validate_scene builds every object's mesh, and the
// renderers of the same scene need them again. A built-in shape's mesh is a
// function of its parameters alone; mesh files and in-memory meshes are not
// kept (a file can change between two reads). Thread-safe: copies of a
// scene share one and may be validated and drawn on several threads.
class BuiltMeshes {
  public:
    // Keeps `mesh` as the mesh of `shape` (nothing for a mesh file or an
    // in-memory mesh); the latest four kept stay.
    void keep(const Shape& shape, Mesh mesh);
    // The mesh kept for a shape with the same parameters, moved out (so
    // each is taken once); nothing when none is kept.
    std::optional<Mesh> take(const Shape& shape);

  private:
    // A scene's objects are validated one after the other and then drawn:
    // a few cover a scene of several shapes, and validating a scene of many
    // keeps no more of their meshes alive beside its hulls than it did one.
    static constexpr std::size_t capacity = 4;

    std::mutex mutex_;
    std::deque<std::pair<Shape, Mesh>> entries_;  // the latest first
};

// The object's local mesh: the one `built` keeps for its shape, taken, or
// else object_mesh's. `built` may be null.
Mesh object_mesh(const SceneObject& object, BuiltMeshes* built);

// `built`: where the local mesh is taken from first (object_mesh above).
WorldMesh world_mesh(const SceneObject& object, const NormalOptions& options,
                     const ParallelFor& parallel, BuiltMeshes* built = nullptr);

}  // namespace litkit
