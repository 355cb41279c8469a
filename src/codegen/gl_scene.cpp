// SPDX-License-Identifier: MIT
#include "codegen/gl_scene.hpp"

#include "litkit/mesh.hpp"
#include "scene/world_mesh.hpp"

namespace litkit::detail {

GlObject gl_object(const SceneObject& object, Reflection reflection, Shading shading,
                   const NormalOptions& normals, BuiltMeshes* built) {
    WorldMesh mesh = world_mesh(object, normals, ParallelFor{}, built);
    GlObject gl;
    gl.triangles = mesh.triangles.size();
    gl.material = object.material;
    gl.reflection = reflection;
    gl.shading = shading;
    auto put = [&gl](const glm::vec3& v) {
        gl.vertices.insert(gl.vertices.end(), {v.x, v.y, v.z});
    };
    if (shading == Shading::Flat) {
        // docs/spec.md §3 flat: every corner carries the triangle's DD8 normal and
        // centroid, so the colour is the same whichever corner OpenGL uses.
        gl.vertices.reserve(mesh.triangles.size() * 27);
        for (const auto& t : mesh.triangles) {
            const glm::vec3 &a = mesh.positions[t[0]], &b = mesh.positions[t[1]],
                            &c = mesh.positions[t[2]];
            const glm::vec3 normal = face_normal(a, b, c);
            const glm::vec3 centroid = (a + b + c) / 3.0f;
            for (const glm::vec3* corner : {&a, &b, &c}) {
                put(*corner);
                put(normal);
                put(centroid);
            }
        }
    } else {
        // Gouraud, Phong and faceted (whose shaders find the face normal
        // themselves and leave a_normal unused) share this layout.
        gl.vertices.reserve(mesh.positions.size() * 6);
        for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
            put(mesh.positions[i]);
            put(mesh.normals[i]);
        }
        gl.indices.reserve(mesh.triangles.size() * 3);
        for (const auto& t : mesh.triangles)
            gl.indices.insert(gl.indices.end(), t.begin(), t.end());
    }
    return gl;
}

std::vector<equations::PreparedLight> prepared_lights(const Scene& scene) {
    std::vector<equations::PreparedLight> lights;
    lights.reserve(scene.lights.size());
    for (const SceneLight& light : scene.lights)
        lights.push_back(equations::prepare_light(light.light));
    return lights;
}

}  // namespace litkit::detail
