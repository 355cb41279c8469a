// SPDX-License-Identifier: MIT
// Using litkit from C++ (docs/cpp-api.md): a scene built in code around a
// mesh given as arrays, drawn from two observers through one prepared
// scene, and errors caught as litkit::Error with where they come from.
#include <litkit/litkit.hpp>

#include <cstdio>

int main() {
    // A square pyramid: four corners on the floor and an apex. Each triangle
    // winds counter-clockwise seen from outside (the base from below).
    litkit::Mesh pyramid;
    pyramid.positions = {{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}, {0, 1.5f, 0}};
    pyramid.triangles = {{0, 1, 2}, {0, 2, 3},                         // base
                         {3, 2, 4}, {2, 1, 4}, {1, 0, 4}, {0, 3, 4}};  // sides

    litkit::Scene scene;  // a 10 × 10 × 10 room, 800 × 600 pixels, no lights or objects
    scene.reflection = litkit::Reflection::BlinnPhong;
    scene.shading = litkit::Shading::Faceted;  // lit per pixel, one normal per face
    scene.output.width = 320;
    scene.output.height = 240;
    scene.output.background = litkit::from_rgb8({20, 24, 32});  // colours are 0-1
    scene.observer.position = {0, 1, 5};
    scene.observer.look_at = {0, 0.5f, 0};

    litkit::SceneLight key;
    key.name = "key";
    key.light.kind = litkit::PointLight{.position = {2, 3, 3}};
    key.light.intensity = 12;
    scene.lights.push_back(key);
    litkit::SceneLight fill;
    fill.light.kind = litkit::AmbientLight{};
    scene.lights.push_back(fill);

    litkit::SceneObject object;
    object.name = "pyramid";
    object.shape = litkit::MeshDataShape(std::move(pyramid));
    object.position = {0, -0.5f, 0};
    object.rotation_degrees = {0, 20, 0};
    object.material.color = {0.9f, 0.55f, 0.2f};  // each channel 0-1
    scene.objects.push_back(object);

    try {
        // Every rule of the scene format, as load_scene applies to files
        // (objects inside the room, no overlaps, ...); warnings are printed.
        for (const litkit::Diagnostic& problem : litkit::validate_scene(scene)) {
            std::fprintf(stderr, "%s\n", problem.to_string().c_str());
            if (problem.severity == litkit::Severity::Error) return 1;
        }

        // One prepared scene, two observers: update() keeps the mesh and its
        // normals when only the camera moves.
        litkit::Renderer renderer(scene);
        const litkit::Image front = renderer.render();
        scene.observer.position = {4, 2.5f, 2};
        renderer.update(scene);
        const litkit::Image side = renderer.render();
        litkit::write_png(front, "front.png");
        litkit::write_png(side, "side.png");
        std::printf("drew front.png and side.png; the mesh was built %zu time(s)\n",
                    renderer.mesh_builds());
        if (renderer.mesh_builds() != 1 || front.rgb == side.rgb) return 1;
    } catch (const litkit::Error& error) {  // every error litkit throws
        std::fprintf(stderr, "%s\n", error.what());
        return 1;
    }

    // A bad scene, from a file's text and from code: one catch for both.
    int caught = 0;
    try {
        litkit::parse_scene(
            "[room]\nwidth = -10\nheight = 10\ndepth = 10\n"
            "[observer]\nposition = [0, 0, 4]\n",
            "bad.toml");
    } catch (const litkit::Error& error) {
        // "bad.toml:2:9: error: room: width must be > 0, found -10"
        const litkit::FileLoc& where = error.location();
        std::printf("caught at %s:%u:%u:\n%s\n", where.file.c_str(), where.line, where.column,
                    error.what());
        caught += where.file == "bad.toml" && where.line == 2;
    }
    try {
        scene.output.width = 0;
        litkit::render(scene);
    } catch (const litkit::Error& error) {
        // "error: output: width must be 1–16384, found 0"
        std::printf("caught: %s\n", error.what());
        ++caught;
    }
    return caught == 2 ? 0 : 1;
}
