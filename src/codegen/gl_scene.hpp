// SPDX-License-Identifier: MIT
// A scene reduced to what the OpenGL programs draw (src/gl/opengl_core.inc):
// per object, world-space vertex arrays in the programs' layout, its
// material and its reflection × shading model. Shared by the GL backend
// (litkit::gl) and the C++ exporter, so both draw the same numbers.
#pragma once

#include <cstdint>
#include <vector>

#include "litkit/equations.hpp"
#include "litkit/scene.hpp"

namespace litkit::detail {

struct GlObject {
    // Flat: 9 floats per vertex (position, face normal, centroid), three
    // unshared vertices per triangle, no indices. Gouraud, Phong, faceted: 6 floats per
    // vertex (position, vertex normal) and three indices per triangle.
    std::vector<float> vertices;
    std::vector<std::uint32_t> indices;
    std::size_t triangles = 0;
    Material material;
    Reflection reflection = default_reflection;
    Shading shading = default_shading;
};

// Throws IoError for an unreadable mesh file.
// `normals`: how its vertex normals are found (normal_options, docs/spec.md §9.2).
// `built`: the scene's built meshes (Scene::built_meshes) to take the local
// mesh from, else null.
GlObject gl_object(const SceneObject& object, Reflection reflection, Shading shading,
                   const NormalOptions& normals, BuiltMeshes* built = nullptr);

std::vector<equations::PreparedLight> prepared_lights(const Scene& scene);

}  // namespace litkit::detail
