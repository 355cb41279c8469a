// SPDX-License-Identifier: MIT
// The glass tests' scenes (docs/spec.md §10), shared by the CPU's
// (test_glass.cpp) and OpenGL's (test_gl_glass.cpp) suites.
#pragma once

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "litkit/mesh.hpp"
#include "litkit/scene.hpp"

namespace glass_scenes {

using litkit::Scene;
using litkit::SceneObject;

// The pictures' scenes: a camera a little off the z axis, looking at the
// origin, a sun and a dim ambient light.
inline Scene base_scene(int width = 160, int height = 120) {
    Scene scene;
    scene.room = {20.0f, 20.0f, 20.0f};
    scene.observer.position = {0.31f, 0.23f, 8.0f};
    scene.observer.look_at = {0.0f, 0.0f, 0.0f};
    scene.output.width = width;
    scene.output.height = height;
    scene.output.background = litkit::from_rgb8({30, 40, 60});
    scene.reflection = litkit::Reflection::Phong;
    scene.shading = litkit::Shading::Phong;
    litkit::SceneLight sun;
    sun.light.kind = litkit::DirectionalLight{{-0.3f, -0.4f, -1.0f}};
    scene.lights.push_back(sun);
    litkit::SceneLight ambient;
    ambient.light.kind = litkit::AmbientLight{};
    ambient.light.intensity = 0.3f;
    scene.lights.push_back(ambient);
    return scene;
}

// The closed forms' scenes: the camera on the z axis at distance `z`,
// looking at the origin, 161 × 121 pixels, so that the middle pixel (80,
// 60) has x = y = 0 in §1 and its ray is the view direction (0, 0, −1);
// one ambient light of intensity 1, no background.
inline Scene axis_scene(float z) {
    Scene scene;
    scene.room = {20.0f, 20.0f, 20.0f};
    scene.observer.position = {0.0f, 0.0f, z};
    scene.output.width = 161;
    scene.output.height = 121;
    litkit::SceneLight ambient;
    ambient.light.kind = litkit::AmbientLight{};
    scene.lights.push_back(ambient);
    return scene;
}

inline SceneObject cube(float size, glm::vec3 position, glm::vec3 color) {
    SceneObject object;
    object.shape = litkit::CubeShape{size};
    object.position = position;
    object.material.color = color;
    return object;
}

inline SceneObject glass(litkit::Shape shape, glm::vec3 position, float ior = 1.5f) {
    SceneObject object;
    object.shape = std::move(shape);
    object.position = position;
    object.material.transmission = 1.0f;
    object.material.ior = ior;
    object.material.ks = 0.5f;
    return object;
}

// A wall of coloured cubes at depth z, slightly turned, not in a symmetric grid.
inline void add_cubes(Scene& scene, float z, int columns = 5, int rows = 3) {
    const glm::vec3 colours[] = {{1.0f, 0.2f, 0.2f},
                                 {0.2f, 1.0f, 0.2f},
                                 {0.2f, 0.2f, 1.0f},
                                 {1.0f, 1.0f, 0.2f},
                                 {0.9f, 0.5f, 0.9f}};
    int k = 0;
    for (int i = 0; i < columns; ++i)
        for (int j = 0; j < rows; ++j) {
            const float x = (float(i) - 0.5f * float(columns - 1)) * 1.5f + 0.07f * float(j);
            const float y = (float(j) - 0.5f * float(rows - 1)) * 1.5f + 0.05f * float(i);
            SceneObject c = cube(1.1f, {x, y, z}, colours[k % 5]);
            c.rotation_degrees = {7.0f * float(j), 11.0f * float(i), 3.0f};
            scene.objects.push_back(c);
            ++k;
        }
}

// A convex mesh from its corners and faces (each face's corners in order
// around it): fans, each triangle turned to face away from the centre.
inline litkit::Mesh convex_mesh(std::vector<glm::vec3> corners,
                                const std::vector<std::vector<std::uint32_t>>& faces) {
    litkit::Mesh mesh;
    mesh.positions = std::move(corners);
    glm::vec3 centre(0.0f);
    for (const glm::vec3& p : mesh.positions) centre += p;
    centre /= float(mesh.positions.size());
    for (const auto& face : faces)
        for (std::size_t k = 1; k + 1 < face.size(); ++k) {
            std::array<std::uint32_t, 3> t{face[0], face[k], face[k + 1]};
            const glm::vec3 &a = mesh.positions[t[0]], &b = mesh.positions[t[1]],
                            &c = mesh.positions[t[2]];
            if (glm::dot(glm::cross(b - a, c - a), (a + b + c) / 3.0f - centre) < 0.0f)
                std::swap(t[1], t[2]);
            mesh.triangles.push_back(t);
        }
    return mesh;
}

// A box of half extents h (uniform scale cannot make one from a cube).
inline litkit::MeshDataShape box(glm::vec3 h) {
    std::vector<glm::vec3> corners;
    for (int k = 0; k < 8; ++k)
        corners.push_back({k & 1 ? h.x : -h.x, k & 2 ? h.y : -h.y, k & 4 ? h.z : -h.z});
    return litkit::MeshDataShape(convex_mesh(
        corners,
        {{0, 1, 3, 2}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 3, 7, 5}}));
}

// A right-angled prism along y (from −h to h): in the xz-plane its section
// has the corners (−1, 1), (1, 1) and (−1, −1), so the face z = 1 looks
// along +z, the face x = −1 along −x, and the hypotenuse along (1, 0, −1)/√2.
inline litkit::MeshDataShape prism(float h) {
    std::vector<glm::vec3> corners{{-1, -h, 1}, {1, -h, 1}, {-1, -h, -1},
                                   {-1, h, 1},  {1, h, 1},  {-1, h, -1}};
    return litkit::MeshDataShape(
        convex_mesh(corners, {{0, 1, 2}, {3, 4, 5}, {0, 1, 4, 3}, {0, 2, 5, 3}, {1, 2, 5, 4}}));
}

// ---- The pictures' scenes ----

inline Scene sphere_lens_scene() {
    Scene scene = base_scene();
    add_cubes(scene, -3.0f);
    scene.objects.push_back(glass(litkit::SphereShape{1.5f, 24, 12}, {0.1f, -0.05f, 1.0f}));
    return scene;
}

inline Scene slab_scene() {
    Scene scene = base_scene();
    SceneObject bar;
    bar.shape = box({0.25f, 2.0f, 0.25f});
    bar.position = {0.2f, 0.0f, -2.0f};
    bar.rotation_degrees = {0.0f, 0.0f, 12.0f};
    bar.material.color = {0.9f, 0.6f, 0.1f};
    scene.objects.push_back(bar);
    add_cubes(scene, -4.0f, 3, 2);
    SceneObject slab = glass(box({1.8f, 1.4f, 0.4f}), {0.0f, 0.1f, 1.5f}, 1.33f);
    slab.rotation_degrees = {10.0f, 35.0f, 0.0f};
    slab.shading = litkit::Shading::Faceted;
    scene.objects.push_back(slab);
    return scene;
}

// Total internal reflection at the hypotenuse: light coming in through the
// face z = 1 leaves through x = −1 (and the picture shows what lies to the left).
inline Scene prism_scene() {
    Scene scene = base_scene();
    add_cubes(scene, -3.0f);
    SceneObject side = cube(1.2f, {-4.0f, 0.3f, 1.0f}, {0.2f, 0.9f, 0.3f});
    scene.objects.push_back(side);
    SceneObject p = glass(prism(1.2f), {0.2f, 0.0f, 1.5f});
    p.rotation_degrees = {4.0f, 8.0f, 0.0f};
    p.shading = litkit::Shading::Faceted;
    scene.objects.push_back(p);
    return scene;
}

inline Scene absorbing_cube_scene() {
    Scene scene = base_scene();
    add_cubes(scene, -3.0f);
    SceneObject c = glass(litkit::CubeShape{2.2f}, {0.1f, 0.0f, 1.0f});
    c.rotation_degrees = {20.0f, 30.0f, 0.0f};
    c.shading = litkit::Shading::Faceted;
    c.material.absorption_color = {0.9f, 0.5f, 0.2f};
    c.material.absorption_distance = 0.5f;
    scene.objects.push_back(c);
    return scene;
}

inline Scene two_glasses_scene() {
    Scene scene = base_scene();
    add_cubes(scene, -4.0f);
    SceneObject back = glass(litkit::CubeShape{1.8f}, {-0.2f, 0.1f, -1.0f});
    back.rotation_degrees = {15.0f, 25.0f, 5.0f};
    back.shading = litkit::Shading::Faceted;
    back.material.absorption_color = {0.6f, 0.8f, 1.0f};
    scene.objects.push_back(back);
    scene.objects.push_back(glass(litkit::SphereShape{1.2f, 24, 12}, {0.3f, -0.1f, 2.0f}));
    return scene;
}

inline Scene water_room_scene() {
    Scene scene = base_scene();
    scene.room.ior = 1.33f;
    add_cubes(scene, -3.0f);
    scene.objects.push_back(glass(litkit::SphereShape{1.4f, 24, 12}, {-0.3f, 0.1f, 1.0f}));
    SceneObject bubble = glass(litkit::CubeShape{0.9f}, {2.2f, -0.6f, 1.5f}, 1.0f);
    bubble.rotation_degrees = {30.0f, 40.0f, 0.0f};
    bubble.shading = litkit::Shading::Faceted;
    scene.objects.push_back(bubble);
    return scene;
}

// Not convex: rays leave the tube and come back into it.
inline Scene torus_scene() {
    Scene scene = base_scene();
    add_cubes(scene, -3.0f);
    SceneObject torus = glass(litkit::TorusShape{1.6f, 0.55f, 24, 12}, {0.0f, 0.1f, 1.0f});
    torus.rotation_degrees = {65.0f, 10.0f, 0.0f};
    scene.objects.push_back(torus);
    return scene;
}

// Gooch's wash and toon's bands are I_ad, their highlights I_s; t < 1 keeps
// (1 − t)·I_ad in the picture.
inline Scene gooch_toon_scene() {
    Scene scene = base_scene();
    add_cubes(scene, -3.0f);
    SceneObject gooch = glass(litkit::SphereShape{1.1f, 24, 12}, {-1.3f, 0.0f, 1.0f});
    gooch.reflection = litkit::Reflection::Gooch;
    gooch.material.transmission = 0.6f;
    gooch.material.color = {0.3f, 0.6f, 0.9f};
    scene.objects.push_back(gooch);
    SceneObject toon = glass(litkit::SphereShape{1.1f, 24, 12}, {1.4f, 0.1f, 1.0f}, 1.4f);
    toon.reflection = litkit::Reflection::Toon;
    toon.shading = litkit::Shading::Faceted;
    toon.material.transmission = 0.5f;
    toon.material.color = {0.9f, 0.4f, 0.3f};
    scene.objects.push_back(toon);
    return scene;
}

// Flat and gouraud glass: the local part by the shading model (flat: at the
// centroid; gouraud: the corners' values mixed), the bracket per pixel with
// N_s (the face normal; the interpolated one). With gamma 2.2, so that rays
// that leave the scene bring (background/255)^2.2 back to be corrected again.
inline Scene flat_gouraud_gamma_scene() {
    Scene scene = base_scene();
    scene.output.gamma = 2.2f;
    add_cubes(scene, -3.0f);
    SceneObject flat = glass(litkit::SphereShape{1.1f, 24, 12}, {-1.3f, 0.0f, 1.0f});
    flat.shading = litkit::Shading::Flat;
    flat.material.transmission = 0.5f;
    flat.material.color = {0.3f, 0.9f, 0.6f};
    scene.objects.push_back(flat);
    SceneObject gouraud = glass(litkit::SphereShape{1.1f, 24, 12}, {1.4f, 0.1f, 1.0f}, 1.6f);
    gouraud.shading = litkit::Shading::Gouraud;
    gouraud.material.transmission = 0.5f;
    gouraud.material.color = {0.9f, 0.7f, 0.3f};
    scene.objects.push_back(gouraud);
    return scene;
}

inline Scene max_depth_scene(int depth) {
    Scene scene = base_scene();
    scene.max_depth = depth;
    add_cubes(scene, -3.0f);
    SceneObject c = glass(litkit::CubeShape{2.0f}, {0.1f, 0.0f, 1.0f}, 1.8f);
    c.rotation_degrees = {25.0f, 35.0f, 10.0f};
    c.shading = litkit::Shading::Faceted;
    c.material.absorption_color = {0.95f, 0.9f, 0.8f};
    scene.objects.push_back(c);
    return scene;
}

}  // namespace glass_scenes
