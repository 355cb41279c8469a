// SPDX-License-Identifier: MIT
// The prepare stage, once per Renderer (like uploading buffers): each
// object's mesh in world space (DD8, DD9), then its lights, materials and
// models, and the setup jobs' triangle ranges. Renderer::update runs only
// prepare_surfaces where the meshes stay.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>

#include "core/parallel.hpp"
#include "cpu/pipeline.hpp"
#include "litkit/mesh.hpp"
#include "scene/world_mesh.hpp"

namespace litkit {

// Everything of the scene but its meshes: lights, materials and models.
void Pipeline::prepare_surfaces() {
    stages_hold_samples = 0;  // the lights, colours or meshes may differ
    lights.clear();
    for (const SceneLight& light : scene.lights)
        lights.push_back(equations::prepare_light(light.light));
    const Reflection scene_reflection = scene.reflection.value_or(options.fallback_reflection);
    const Shading scene_shading = scene.shading.value_or(options.fallback_shading);
    for (std::size_t o = 0; o < objects.size(); ++o) {
        const SceneObject& object = scene.objects[o];
        PreparedObject& prepared = objects[o];
        prepared.material = equations::splat<float>(object.material);
        prepared.raw_material = object.material;
        prepared.reflection = object.reflection.value_or(scene_reflection);
        prepared.shading = object.shading.value_or(scene_shading);
        // Face normals only for the shadings that use them (a 261k-triangle
        // mesh under Phong shading would compute 3 MB for nothing); kept once
        // computed, since the mesh is.
        const bool uses_faces =
            prepared.shading == Shading::Flat || prepared.shading == Shading::Faceted;
        if (uses_faces && prepared.face_normals.empty()) {
            prepared.face_normals.reserve(prepared.triangles.size());
            for (const auto& t : prepared.triangles) {
                prepared.face_normals.push_back(face_normal(
                    prepared.positions[t[0]], prepared.positions[t[1]], prepared.positions[t[2]]));
            }
        }
    }
    prepare_tracer();
}

void Pipeline::prepare() {
    ++mesh_builds;
    ray_tree.reset();  // it and the hierarchy see the old meshes
    accel.reset();
    objects.clear();
    chunks.clear();
    // Mesh building borrows the pool's threads (the same meshes, bit for bit).
    const ParallelFor parallel = [this](std::size_t count, const ParallelJob& job) {
        pool.parallel_for(count, [&](std::size_t index, int) { job(index); });
    };
    for (const SceneObject& object : scene.objects) {
        WorldMesh mesh =
            world_mesh(object, normal_options(scene, object), parallel, scene.built_meshes.get());
        PreparedObject prepared;
        prepared.positions = std::move(mesh.positions);
        prepared.normals = std::move(mesh.normals);
        prepared.triangles = std::move(mesh.triangles);
        objects.push_back(std::move(prepared));
    }
    prepare_surfaces();

    // Setup jobs: fixed triangle ranges, so their output buffers are reused.
    for (std::size_t o = 0; o < objects.size(); ++o) {
        const std::size_t count = objects[o].triangles.size();
        for (std::size_t begin = 0; begin < count; begin += setup_chunk) {
            SetupChunk chunk;
            chunk.object = static_cast<std::uint32_t>(o);
            chunk.begin = begin;
            chunk.end = std::min(count, begin + setup_chunk);
            chunks.push_back(std::move(chunk));
        }
    }
    clip_positions.resize(objects.size());
    window_corners.resize(objects.size());
    vertex_colors.resize(objects.size());
    flat_colors.resize(objects.size());
    scratch.resize(static_cast<std::size_t>(pool.size()));
}

}  // namespace litkit
