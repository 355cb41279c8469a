// SPDX-License-Identifier: MIT
// Directions free of scale (src/core/scale_free.hpp, docs/reliability.md):
// an observer looking at a point 1e-30 or 1e+30 away, a light direction or
// an `up` of such a length, draws and is checked as the same scene at
// length 1, by the CPU renderer and by OpenGL. In float, those lengths
// square to 0 or to infinity.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "core/scale_free.hpp"
#include "litkit/gl_renderer.hpp"
#include "litkit/render.hpp"
#include "litkit/scene.hpp"
#include "litkit/validate.hpp"

namespace fs = std::filesystem;

namespace {

// The observer at the origin looks at the cube's centre, [-2, -3, -2].
const char* scene_text = R"(
[room]
width = 10
height = 10
depth = 10
[observer]
position = [0, 0, 0]
look_at = LOOK_AT
fov = 60
[lighting]
reflection = "blinn-phong"
shading = "phong"
[output]
width = 96
height = 72
background = [0, 0, 255]
[[lights]]
type = "point"
position = [1, 1, 1]
[[lights]]
type = "spot"
position = [0, 4, 0]
direction = [-0.3, -1, -0.3]
cutoff = 40
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
)";

litkit::Scene scene_looking_at(const std::string& look_at) {
    std::string text = scene_text;
    text.replace(text.find("LOOK_AT"), 7, look_at);
    return litkit::parse_scene(text, "scale-free.toml");
}

const char* const look_ats[] = {"[-2e-30, -3e-30, -2e-30]", "[-2e+30, -3e+30, -2e+30]"};

std::size_t covered_pixels(const litkit::Image& image) {
    std::size_t covered = 0;
    for (std::size_t i = 0; i < image.rgb.size(); i += 3) covered += image.rgb[i + 2] != 255;
    return covered;
}

float times(float value, double s) { return static_cast<float>(double(value) * s); }
glm::vec3 times(const glm::vec3& v, double s) {
    return {times(v.x, s), times(v.y, s), times(v.z, s)};
}

}  // namespace

TEST(ScaleFree, UnitIsGlmsNormaliseAtOrdinaryLengthsAndFiniteAtAnyOther) {
    // Exactly glm's result where glm's squares are ordinary floats.
    const glm::vec3 ordinary[] = {{-2, -3, -2}, {0.3f, -1, 0.25f}, {1e-12f, 7, 0}, {1e18f, 1, 3}};
    for (const glm::vec3& v : ordinary) EXPECT_EQ(litkit::scale_free::unit(v), glm::normalize(v));
    // 1e-30 and 1e+30: glm gives NaN or zero; the unit vector computed in
    // double, independently, to within a float's rounding.
    const glm::dvec3 expected = glm::normalize(glm::dvec3(-2, -3, -2));
    for (const double s : {1e-30, 1e+30}) {
        const glm::vec3 v = times(glm::vec3(-2, -3, -2), s);
        const glm::vec3 unit = litkit::scale_free::unit(v);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(unit[c], expected[c], 2e-7) << "scale " << s;
    }
    EXPECT_EQ(litkit::scale_free::unit(glm::vec3(0.0f)), glm::vec3(0.0f));
}

TEST(ScaleFree, LookAtIsGlmsAtOrdinaryLengths) {
    const glm::vec3 eye(3.5f, 1, 4), center(-1, -2, -1), up(0, 1, 0);
    EXPECT_EQ(litkit::scale_free::look_at(eye, center, up), glm::lookAt(eye, center, up));
    EXPECT_EQ(litkit::scale_free::look_at(eye, center, glm::vec3(0.1f, 2, 0)),
              glm::lookAt(eye, center, glm::vec3(0.1f, 2, 0)));
}

TEST(ScaleFree, ATinyOrHugeViewDirectionDrawsTheSamePicture) {
    const litkit::Image reference = litkit::render(scene_looking_at("[-2, -3, -2]"));
    ASSERT_GT(covered_pixels(reference), 1000u);  // the cube and the sphere are in view
    for (const char* look_at : look_ats) {
        const litkit::Image picture = litkit::render(scene_looking_at(look_at));
        EXPECT_EQ(picture.rgb, reference.rgb) << look_at;
    }
}

TEST(ScaleFree, ATinyOrHugeViewDirectionDrawsTheSamePictureThroughOpenGL) {
    litkit::GlRenderer reference_renderer(scene_looking_at("[-2, -3, -2]"));
    const litkit::Image reference = reference_renderer.render();
    ASSERT_GT(covered_pixels(reference), 1000u);
    for (const char* look_at : look_ats) {
        litkit::GlRenderer renderer(scene_looking_at(look_at));
        EXPECT_EQ(renderer.render().rgb, reference.rgb) << look_at;
    }
}

TEST(ScaleFree, TinyOrHugeLightDirectionsAndUpDrawTheSamePicture) {
    // Set in code, past the loader (which makes a file's tiny or huge
    // directions unit length): the renderers' own arithmetic must hold.
    const litkit::Scene scene = scene_looking_at("[-2, -3, -2]");
    const litkit::Image reference = litkit::render(scene);
    for (const double s : {1e-30, 1e+30}) {
        litkit::Scene scaled = scene;
        scaled.observer.up = times(scene.observer.up, s);
        for (litkit::SceneLight& light : scaled.lights) {
            if (auto* spot = std::get_if<litkit::SpotLight>(&light.light.kind))
                spot->direction = times(spot->direction, s);
            if (auto* directional = std::get_if<litkit::DirectionalLight>(&light.light.kind))
                directional->direction = times(directional->direction, s);
        }
        EXPECT_EQ(litkit::render(scaled).rgb, reference.rgb) << "scale " << s;
        litkit::GlRenderer gl(scaled);
        litkit::GlRenderer gl_reference(scene);
        EXPECT_EQ(gl.render().rgb, gl_reference.render().rgb) << "scale " << s;
    }
}

TEST(ScaleFree, AnObjectOutOfViewIsFoundWhateverTheViewDirectionsLength) {
    // Looking the other way, at [2, 3, 2] (times a scale): both objects are
    // behind the observer.
    for (const char* look_at : {"[2, 3, 2]", "[2e-30, 3e-30, 2e-30]", "[2e+30, 3e+30, 2e+30]"}) {
        std::size_t outside = 0;
        for (const litkit::Diagnostic& d : litkit::validate_scene(scene_looking_at(look_at)))
            outside += d.message.find("entirely outside the view") != std::string::npos;
        EXPECT_EQ(outside, 2u) << look_at;
    }
}

TEST(ScaleFree, AGlassSceneAtAnyScaleDrawsTheSamePicture) {
    // The tracer works in the lengths scene/float_range.hpp brings the room
    // to, so refraction's rays, their offsets and the Fresnel mix see the
    // same numbers at 1e-30 and 1e+30 (a power of two away) as at 1: the
    // glass lens example, every length scaled, draws the same bytes.
    const fs::path file = fs::path(LITKIT_SOURCE_DIR) / "examples" / "glass-lens.toml";
    litkit::Scene scene = litkit::load_scene(std::span(&file, 1));
    scene.output.width = 96;
    scene.output.height = 72;
    const litkit::Image reference = litkit::render(scene);
    for (const double s : {1e-30, 1e+30}) {
        litkit::Scene scaled = scene;
        scaled.room.width = times(scene.room.width, s);
        scaled.room.height = times(scene.room.height, s);
        scaled.room.depth = times(scene.room.depth, s);
        scaled.observer.position = times(scene.observer.position, s);
        scaled.observer.look_at = times(scene.observer.look_at, s);
        scaled.observer.near = times(scene.observer.near, s);
        scaled.observer.far = times(scene.observer.far, s);
        ASSERT_TRUE(scene.lights.size() == 2 &&
                    std::holds_alternative<litkit::AmbientLight>(scene.lights[0].light.kind) &&
                    std::holds_alternative<litkit::DirectionalLight>(scene.lights[1].light.kind))
            << "the example's lights have no position to scale";
        for (litkit::SceneObject& object : scaled.objects) {
            object.position = times(object.position, s);
            if (auto* cube = std::get_if<litkit::CubeShape>(&object.shape))
                cube->size = times(cube->size, s);
            else if (auto* sphere = std::get_if<litkit::SphereShape>(&object.shape))
                sphere->radius = times(sphere->radius, s);
            else
                FAIL() << "the example has only cubes and spheres";
        }
        EXPECT_EQ(litkit::render(scaled).rgb, reference.rgb) << "scale " << s;
    }
}
