// SPDX-License-Identifier: MIT
// Geometry at any scale (docs/reliability.md): a scene
// scaled by any factor a float can hold is checked and drawn as the same
// scene; no rendered pixel is NaN; the narrowest field of view draws no
// holes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <variant>
#include <vector>

#include "litkit/render.hpp"
#include "litkit/scene.hpp"
#include "litkit/validate.hpp"

namespace fs = std::filesystem;

namespace {

// Lights whose attenuation does not depend on distance, so that scaling the
// scene changes nothing a viewer could see.
const char* scene_text = R"(
[room]
width = 10
height = 10
depth = 10
[observer]
position = [3.5, 1, 4]
look_at = [-1, -2, -1]
fov = 40
near = 0.05
far = 1000
[lighting]
reflection = "blinn-phong"
shading = "phong"
[output]
width = 160
height = 120
background = [0, 0, 255]
[[lights]]
type = "point"
position = [0, 0, 0]
attenuation = [1, 0, 0]
intensity = 0.8
[[lights]]
type = "spot"
position = [0, 4, 0]
direction = [-0.3, -1, -0.3]
cutoff = 40
attenuation = [1, 0, 0]
[[lights]]
type = "directional"
direction = [1, -1, -1]
intensity = 0.3
[[objects]]
type = "cube"
size = 2
position = [-2, -3, -2]
rotation = [0, 30, 0]
material = { color = [200, 80, 60] }
[[objects]]
type = "sphere"
radius = 1
segments = 24
rings = 12
position = [0.5, -3, -2.5]
material = { color = [80, 200, 60] }
)";

litkit::Scene base_scene() { return litkit::parse_scene(scene_text, "scale.toml"); }

// The test's own scaling (decimal factors, not the renderer's powers of two):
// every length times `s`, rounded to float as a scene file would be read.
float times(float value, double s) { return static_cast<float>(double(value) * s); }
glm::vec3 times(const glm::vec3& v, double s) {
    return {times(v.x, s), times(v.y, s), times(v.z, s)};
}

litkit::Scene scaled(litkit::Scene scene, double s) {
    scene.room = {times(scene.room.width, s), times(scene.room.height, s),
                  times(scene.room.depth, s)};
    scene.observer.position = times(scene.observer.position, s);
    scene.observer.look_at = times(scene.observer.look_at, s);
    scene.observer.near = times(scene.observer.near, s);
    scene.observer.far = times(scene.observer.far, s);
    for (litkit::SceneLight& light : scene.lights) {
        if (auto* point = std::get_if<litkit::PointLight>(&light.light.kind))
            point->position = times(point->position, s);
        if (auto* spot = std::get_if<litkit::SpotLight>(&light.light.kind))
            spot->position = times(spot->position, s);
    }
    for (litkit::SceneObject& object : scene.objects) {
        object.position = times(object.position, s);
        if (auto* cube = std::get_if<litkit::CubeShape>(&object.shape))
            cube->size = times(cube->size, s);
        if (auto* sphere = std::get_if<litkit::SphereShape>(&object.shape))
            sphere->radius = times(sphere->radius, s);
    }
    return scene;
}

std::vector<std::string> errors_of(const litkit::Scene& scene) {
    std::vector<std::string> errors;
    for (const litkit::Diagnostic& d : litkit::validate_scene(scene))
        if (d.severity == litkit::Severity::Error) errors.push_back(d.message);
    return errors;
}

std::size_t diagnostics_count(const litkit::Scene& scene) {
    return litkit::validate_scene(scene).size();
}

const double factors[] = {1e-35, 1e-30, 1e-25, 1e-24, 1e-20, 1e-9, 1e9, 1e19, 1e30, 1e35};

}  // namespace

TEST(Scale, AScaledSceneIsCheckedAsTheSameScene) {
    const litkit::Scene scene = base_scene();
    ASSERT_TRUE(errors_of(scene).empty());
    const std::size_t diagnostics = diagnostics_count(scene);
    for (const double s : factors) {
        const litkit::Scene big_or_small = scaled(scene, s);
        EXPECT_TRUE(errors_of(big_or_small).empty())
            << "scale " << s << ": " << errors_of(big_or_small).front();
        EXPECT_EQ(diagnostics_count(big_or_small), diagnostics) << "scale " << s;
    }
}

TEST(Scale, AScaledSceneDrawsTheSamePicture) {
    const litkit::Scene scene = base_scene();
    const litkit::Image reference = litkit::render(scene);
    std::size_t covered = 0;
    for (std::size_t i = 0; i < reference.rgb.size(); i += 3)
        covered += reference.rgb[i + 2] != 255;
    ASSERT_GT(covered, 3000u);  // both objects are in view
    for (const double s : factors) {
        const litkit::Image picture = litkit::render(scaled(scene, s));
        ASSERT_EQ(picture.rgb.size(), reference.rgb.size());
        // The scaled inputs are the nearest floats to s times the values, not
        // exactly s times them: a pixel may move by one step along an edge.
        std::size_t differing = 0;
        for (std::size_t i = 0; i < reference.rgb.size(); i += 3) {
            const bool same = std::equal(&picture.rgb[i], &picture.rgb[i] + 3, &reference.rgb[i]);
            differing += !same;
        }
        EXPECT_LE(differing, reference.rgb.size() / 3 / 200) << "scale " << s;
    }
}

TEST(Scale, InverseSquareAttenuationScalesWithTheIntensity) {
    // With f = 1/d², a scene s times larger with s² times the intensity is lit
    // the same.
    litkit::Scene scene = base_scene();
    for (litkit::SceneLight& light : scene.lights) {
        if (auto* point = std::get_if<litkit::PointLight>(&light.light.kind)) {
            point->attenuation = {0.0f, 0.0f, 1.0f};
            light.light.intensity = 12.0f;
        }
    }
    const litkit::Image reference = litkit::render(scene);
    for (const double s : {1e-12, 1e12}) {
        litkit::Scene big_or_small = scaled(scene, s);
        for (litkit::SceneLight& light : big_or_small.lights)
            if (std::holds_alternative<litkit::PointLight>(light.light.kind))
                light.light.intensity = static_cast<float>(12.0 * s * s);
        const litkit::Image picture = litkit::render(big_or_small);
        int worst = 0;
        std::size_t differing = 0;
        for (std::size_t i = 0; i < reference.rgb.size(); ++i) {
            const int d = std::abs(int(picture.rgb[i]) - int(reference.rgb[i]));
            worst = std::max(worst, d);
            differing += d > 1;
        }
        EXPECT_LE(differing, reference.rgb.size() / 200) << "scale " << s;
    }
}

TEST(Scale, ALightInsideATinyObjectIsStillFound) {
    // At 1e-25 a light inside the cube, and one just outside, are judged as at 1.
    for (const double s : {1.0, 1e-25, 1e25}) {
        litkit::Scene scene = scaled(base_scene(), s);
        auto& point = std::get<litkit::PointLight>(scene.lights[0].light.kind);
        point.position = times(glm::vec3(-2.0f, -3.0f, -2.0f), s);  // the cube's centre
        const std::vector<std::string> inside = errors_of(scene);
        ASSERT_EQ(inside.size(), 1u) << "scale " << s;
        EXPECT_NE(inside[0].find("is inside"), std::string::npos) << inside[0];
        point.position = times(glm::vec3(-2.0f, -1.9f, -2.0f), s);  // 0.1 above its top face
        EXPECT_TRUE(errors_of(scene).empty()) << "scale " << s;
    }
}

TEST(Scale, TheNarrowestFieldOfViewDrawsNoHoles) {
    // Looking at the middle of the cube's face with fov 0.01 at the largest
    // image height: every pixel is the cube.
    litkit::Scene scene = base_scene();
    scene.objects.pop_back();  // the sphere
    scene.observer.position = {-2.0f, -3.0f, 3.0f};
    scene.observer.look_at = {-2.0f, -3.0f, -2.0f};
    scene.objects[0].rotation_degrees = glm::vec3(0.0f);
    scene.observer.fov_degrees = litkit::smallest_fov_degrees;
    scene.output.width = 4;
    scene.output.height = 16384;
    ASSERT_TRUE(errors_of(scene).empty());
    const litkit::Image picture = litkit::render(scene);
    std::size_t holes = 0;
    for (std::size_t i = 0; i < picture.rgb.size(); i += 3) holes += picture.rgb[i + 2] == 255;
    EXPECT_EQ(holes, 0u);

    scene.observer.fov_degrees = 0.0099f;
    const std::vector<std::string> errors = errors_of(scene);
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_EQ(errors[0], "observer: fov must be in [0.01, 180) degrees, found 0.0099");
}

// Every pixel's intensity before clamping, read through Renderer::probe
// (the 8-bit picture would show a NaN as 0, like black).
std::size_t non_finite_pixels(const litkit::Scene& scene) {
    litkit::Renderer renderer(scene, {.threads = 1});
    std::size_t bad = 0;
    for (int y = 0; y < scene.output.height; ++y) {
        for (int x = 0; x < scene.output.width; ++x) {
            const litkit::PixelProbe probe = renderer.probe(x, y);
            if (!probe.hit) continue;
            for (int c = 0; c < 3; ++c) bad += !std::isfinite(probe.intensity[c]);
        }
    }
    return bad;
}

TEST(Scale, ANaNInTheSceneIsRefusedBeforeDrawing) {
    // A scene built in code with a NaN intensity (a file cannot say NaN) is
    // refused by the renderer (check_renderable), so the scan below covers
    // what remains: finite inputs whose arithmetic could give a NaN.
    litkit::Scene scene = base_scene();
    scene.lights[0].light.intensity = std::nanf("");
    EXPECT_THROW(litkit::Renderer(scene, {.threads = 1}), litkit::SceneError);
}

TEST(Scale, NoPixelOfAnyExampleIsNaN) {
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(fs::path(LITKIT_SOURCE_DIR) / "examples"))
        if (entry.path().extension() == ".toml") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    ASSERT_GE(files.size(), 20u);
    for (const fs::path& file : files) {
        litkit::Scene scene = litkit::load_scene(std::span(&file, 1));
        // Small, keeping the aspect, so that every pixel can be probed.
        scene.output.height = 24 * scene.output.height / scene.output.width;
        scene.output.width = 24;
        EXPECT_EQ(non_finite_pixels(scene), 0u) << file;
    }
    for (const double s : factors) {
        litkit::Scene scene = scaled(base_scene(), s);
        scene.output.width = 32;
        scene.output.height = 24;
        EXPECT_EQ(non_finite_pixels(scene), 0u) << "scale " << s;
    }
}
