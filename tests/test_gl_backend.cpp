// SPDX-License-Identifier: MIT
// The OpenGL backend against the CPU backend: the same scene drawn
// by both must agree within 2/255 on at least 99.5% of the pixels that lie
// away from the edges of objects (tests/picture_agreement.hpp). Runs on
// whatever EGL offers: Mesa's llvmpipe in CI.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "litkit/gl_renderer.hpp"
#include "litkit/render.hpp"
#include "litkit/scene.hpp"
#include "picture_agreement.hpp"

namespace fs = std::filesystem;

namespace {

using litkit_test::agreement;
using litkit_test::Agreement;
using litkit_test::labels;
using litkit_test::required_fraction;

struct Comparison {
    Agreement agreement;
    std::size_t pixels = 0;
};

Comparison compare_backends(const litkit::Scene& scene) {
    const litkit::Image cpu = litkit::render(scene);
    litkit::GlRenderer gl(scene);
    const litkit::Image gpu = gl.render();
    EXPECT_EQ(gpu.width, cpu.width);
    EXPECT_EQ(gpu.height, cpu.height);
    return {agreement(gpu, cpu, labels(scene)), cpu.rgb.size() / 3};
}

// Beyond the interior: the background exactly, and every pixel, edges
// included, nearly everywhere (an offset of half a pixel, a flipped row or a
// wrong clear colour would fail these).
void expect_edges_and_background_agree(const Agreement& a) {
    EXPECT_GT(a.background_counted, 0u);
    EXPECT_EQ(a.background_differing, 0u);
    EXPECT_GE(a.fraction_of_all(), 0.995) << "edges included";
}

// The matrix scenes: one object, one light of the kind asked for (plus a dim
// ambient light with the others, so unlit parts are not all black).
enum class Shape { Sphere, Cube };
enum class LightType { Ambient, Directional, Point, Spot, SoftSpot };

litkit::Scene matrix_scene(Shape shape, LightType light_type, litkit::Reflection reflection,
                           litkit::Shading shading) {
    litkit::Scene scene;
    scene.output.width = 160;
    scene.output.height = 120;
    scene.output.background = litkit::from_rgb8({20, 30, 40});
    scene.observer.position = {0.0f, 1.0f, 4.0f};
    scene.reflection = reflection;
    scene.shading = shading;

    litkit::SceneObject object;
    if (shape == Shape::Sphere)
        object.shape = litkit::SphereShape{1.0f, 24, 12};
    else
        object.shape = litkit::CubeShape{1.4f};
    object.rotation_degrees = {25.0f, 35.0f, 0.0f};
    object.material = {glm::vec3(200.0f, 120.0f, 60.0f) / 255.0f, 0.2f, 0.7f, 0.6f, 24.0f};
    scene.objects.push_back(object);

    litkit::Light light;
    switch (light_type) {
        case LightType::Ambient:
            light.kind = litkit::AmbientLight{};
            break;
        case LightType::Directional:
            light.kind = litkit::DirectionalLight{{-1.0f, -1.5f, -1.0f}};
            break;
        case LightType::Point:
            light.kind = litkit::PointLight{{1.5f, 2.0f, 2.0f}, {1.0f, 0.0f, 0.05f}};
            break;
        case LightType::Spot:
            // Aimed off-centre with a narrow cone, so the cone's edge crosses the object.
            light.kind = litkit::SpotLight{
                {0.5f, 2.5f, 2.0f}, {1.0f, 0.0f, 0.02f}, {-0.3f, -1.0f, -0.9f}, 20.0f, 2.0f};
            break;
        case LightType::SoftSpot:
            // The same cone with a soft edge over its outer half (docs/spec.md §9.3).
            light.kind = litkit::SpotLight{
                {0.5f, 2.5f, 2.0f}, {1.0f, 0.0f, 0.02f}, {-0.3f, -1.0f, -0.9f}, 20.0f, 2.0f, 0.5f};
            break;
    }
    light.color = glm::vec3(255.0f, 240.0f, 220.0f) / 255.0f;
    scene.lights.push_back({"light", light});
    if (light_type != LightType::Ambient) {
        litkit::Light fill{litkit::AmbientLight{}, glm::vec3(1.0f), 0.3f};
        scene.lights.push_back({"fill", fill});
    }
    return scene;
}

}  // namespace

TEST(GlBackend, ReportsTheRenderer) {
    litkit::GlRenderer gl(litkit::default_scene());
    // "<GL_RENDERER>, OpenGL <major>.<minor> ...", with a version of at least 3.3.
    const std::string description = gl.description();
    const std::size_t at = description.find(", OpenGL ");
    ASSERT_NE(at, std::string::npos) << description;
    EXPECT_GT(at, 0u) << "no renderer name: " << description;
    const int major = std::atoi(description.c_str() + at + 9);
    EXPECT_GE(major, 3) << description;
    EXPECT_EQ(gl.triangle_count(), 12u);
}

TEST(GlBackend, ReadBackAtEverySizeKeepsEveryRowAndPixelInPlace) {
    // The read-back (opengl_core.inc's read_rgb, or gl_renderer.cpp's
    // read_rgb_in_step, which converts each band on a helper thread while
    // the next is read, from two buffers in turn) goes in bands of rows and
    // converts eight pixels at a time where the CPU has AVX2, the rest one
    // by one: widths around and between those multiples, and heights of one
    // band (1920 wide: 34 rows), several, and a part of one.
    for (const auto& [width, height] : std::vector<std::pair<int, int>>{{1, 5},
                                                                        {7, 3},
                                                                        {8, 4},
                                                                        {9, 9},
                                                                        {15, 2},
                                                                        {16, 7},
                                                                        {17, 11},
                                                                        {37, 23},
                                                                        {161, 40},
                                                                        {1920, 34},
                                                                        {1920, 101}}) {
        litkit::Scene scene = litkit::default_scene();
        scene.output.width = width;
        scene.output.height = height;
        const Comparison comparison = compare_backends(scene);
        SCOPED_TRACE(std::to_string(width) + "x" + std::to_string(height));
        EXPECT_EQ(comparison.agreement.background_differing, 0u);
        EXPECT_GE(comparison.agreement.fraction_of_all(), 0.99);
    }
}

TEST(GlBackend, SeveralRenderersInOneProcessEachDrawTheirOwnScene) {
    const litkit::Scene sphere_scene = matrix_scene(
        Shape::Sphere, LightType::Point, litkit::Reflection::Phong, litkit::Shading::Phong);
    const litkit::Scene cube_scene = matrix_scene(
        Shape::Cube, LightType::Spot, litkit::Reflection::Lambert, litkit::Shading::Flat);
    litkit::Image sphere_alone, cube_alone;
    {
        litkit::GlRenderer gl(sphere_scene);
        sphere_alone = gl.render();
    }
    {
        litkit::GlRenderer gl(cube_scene);
        cube_alone = gl.render();
    }
    ASSERT_NE(sphere_alone.rgb, cube_alone.rgb);

    auto sphere = std::make_unique<litkit::GlRenderer>(sphere_scene);
    auto cube = std::make_unique<litkit::GlRenderer>(cube_scene);  // created last
    EXPECT_EQ(sphere->render().rgb, sphere_alone.rgb);
    EXPECT_EQ(cube->render().rgb, cube_alone.rgb);
    EXPECT_EQ(sphere->render().rgb, sphere_alone.rgb);
    cube.reset();  // ending one leaves the other working
    EXPECT_EQ(sphere->render().rgb, sphere_alone.rgb);
    cube = std::make_unique<litkit::GlRenderer>(cube_scene);
    sphere.reset();
    EXPECT_EQ(cube->render().rgb, cube_alone.rgb);
}

TEST(GlBackend, SceneWithoutLightsOrObjectsMatchesCpuExactly) {
    litkit::Scene dark = matrix_scene(Shape::Cube, LightType::Point, litkit::Reflection::Phong,
                                      litkit::Shading::Phong);
    dark.lights.clear();  // black cube on the background
    EXPECT_EQ(litkit::GlRenderer(dark).render().rgb, litkit::render(dark).rgb);
    litkit::Scene empty = dark;
    empty.objects.clear();  // background only
    EXPECT_EQ(litkit::GlRenderer(empty).render().rgb, litkit::render(empty).rgb);
}

TEST(GlBackend, MoreLightsThanAShaderHoldsIsAClearError) {
    // 10,000 lights need about 240,000 uniform components; OpenGL 3.3 promises
    // 1,024 and real drivers offer tens of thousands.
    litkit::Scene scene = matrix_scene(Shape::Sphere, LightType::Ambient, litkit::Reflection::Phong,
                                       litkit::Shading::Phong);
    for (int i = 0; i < 10000; ++i) {
        litkit::Light light{litkit::PointLight{{0.001f * static_cast<float>(i), 3.0f, 3.0f}}};
        scene.lights.push_back({"crowd", light});
    }
    try {
        litkit::GlRenderer gl(scene);
        FAIL() << "10,000 lights linked";
    } catch (const litkit::GlError& error) {
        EXPECT_NE(std::string(error.what()).find("the scene has 10001 lights"), std::string::npos)
            << error.what();
    }
}

TEST(GlBackend, ManyLights) {
    // 40 point lights around the sphere: one program sized for all of them.
    litkit::Scene scene = matrix_scene(Shape::Sphere, LightType::Ambient,
                                       litkit::Reflection::BlinnPhong, litkit::Shading::Phong);
    for (int i = 0; i < 40; ++i) {
        const float angle = 0.157f * static_cast<float>(i);
        litkit::Light light{
            litkit::PointLight{{3.0f * std::cos(angle), 1.5f, 3.0f * std::sin(angle)},
                               {1.0f, 0.0f, 0.0f}},
            glm::vec3(1.0f), 0.03f};
        scene.lights.push_back({"ring", light});
    }
    const Comparison c = compare_backends(scene);
    EXPECT_GE(c.agreement.fraction(), required_fraction) << "worst " << c.agreement.worst;
    expect_edges_and_background_agree(c.agreement);
}

TEST(GlBackend, MatchesCpuForEveryModelAndLightOnSphereAndCube) {
    std::vector<litkit::Reflection> reflections;
    for (const litkit::ReflectionModel& model : litkit::reflection_models())
        reflections.push_back(model.id);
    const litkit::Shading shadings[] = {litkit::Shading::Flat, litkit::Shading::Gouraud,
                                        litkit::Shading::Phong, litkit::Shading::Faceted};
    const LightType lights[] = {LightType::Ambient, LightType::Directional, LightType::Point,
                                LightType::Spot, LightType::SoftSpot};
    int cases = 0;
    double lowest = 1.0;
    int worst = 0;
    for (Shape shape : {Shape::Sphere, Shape::Cube}) {
        for (litkit::Reflection reflection : reflections) {
            for (litkit::Shading shading : shadings) {
                for (LightType light : lights) {
                    const Comparison c =
                        compare_backends(matrix_scene(shape, light, reflection, shading));
                    SCOPED_TRACE(std::string(shape == Shape::Sphere ? "sphere " : "cube ") +
                                 std::string(litkit::to_string(reflection)) + " " +
                                 std::string(litkit::to_string(shading)) + " light " +
                                 std::to_string(static_cast<int>(light)));
                    // The object fills a good part of the picture, so the check is not vacuous.
                    EXPECT_GT(c.agreement.counted, c.pixels / 10);
                    EXPECT_GE(c.agreement.fraction(), required_fraction)
                        << "worst " << c.agreement.worst << "/255";
                    expect_edges_and_background_agree(c.agreement);
                    lowest = std::min(lowest, c.agreement.fraction());
                    worst = std::max(worst, c.agreement.worst);
                    ++cases;
                }
            }
        }
    }
    EXPECT_EQ(cases, 2 * litkit::reflection_count * litkit::shading_count * 5);
    std::cout << "matrix: " << cases << " scenes, lowest fraction within 2/255 " << lowest
              << ", largest difference " << worst << "/255\n";
}

TEST(GlBackend, MatchesCpuOnEveryExample) {
    std::vector<std::vector<fs::path>> scenes;
    for (const auto& entry : fs::directory_iterator(fs::path(LITKIT_SOURCE_DIR) / "examples"))
        if (entry.path().extension() == ".toml") scenes.push_back({entry.path()});
    std::vector<fs::path> multi;
    for (const auto& entry :
         fs::directory_iterator(fs::path(LITKIT_SOURCE_DIR) / "examples" / "multi-file"))
        if (entry.path().extension() == ".toml") multi.push_back(entry.path());
    std::sort(multi.begin(), multi.end());
    scenes.push_back(multi);
    ASSERT_GE(scenes.size(), 18u);  // 17 single files and the multi-file pair
    std::size_t glass_examples = 0;
    for (const std::vector<fs::path>& files : scenes) {
        SCOPED_TRACE(files.front().filename().string());
        litkit::Scene scene = litkit::load_scene(files);
        if (!scene.reflection) scene.reflection = litkit::default_reflection;
        if (!scene.shading) scene.shading = litkit::default_shading;
        const bool glass = std::any_of(
            scene.objects.begin(), scene.objects.end(),
            [](const litkit::SceneObject& o) { return o.material.transmission > 0.0f; });
        if (glass) {
            // The glass examples: tests/test_gl_glass.cpp compares them, smaller
            // (each pixel traces its ray tree on llvmpipe).
            ++glass_examples;
            continue;
        }
        const Comparison c = compare_backends(scene);
        EXPECT_GT(c.agreement.counted, c.pixels / 50);
        EXPECT_GE(c.agreement.fraction(), required_fraction)
            << "worst " << c.agreement.worst << "/255";
        expect_edges_and_background_agree(c.agreement);
        std::cout << files.front().filename().string() << ": " << c.agreement.counted
                  << " interior pixels, fraction within 2/255 " << c.agreement.fraction()
                  << ", largest difference " << c.agreement.worst << "/255\n";
    }
    EXPECT_EQ(glass_examples, 5u);  // glass-lens, water-slab, prism, coloured-glass, two-glasses
}

TEST(GlBackend, ComparisonCatchesAWrongPicture) {
    // The check above must be able to fail: the CPU drawing Lambert against
    // OpenGL drawing Phong on a shiny sphere is far outside the tolerance.
    litkit::Scene phong = matrix_scene(Shape::Sphere, LightType::Point, litkit::Reflection::Phong,
                                       litkit::Shading::Phong);
    litkit::Scene lambert = phong;
    lambert.reflection = litkit::Reflection::Lambert;
    litkit::GlRenderer gl(phong);
    const Agreement a = agreement(gl.render(), litkit::render(lambert), labels(phong));
    EXPECT_GT(a.counted, 1000u);
    EXPECT_LT(a.fraction(), required_fraction);
}

TEST(GlBackend, PerObjectOverridesUseTheirOwnPrograms) {
    // Two objects, each overriding the scene's models differently.
    litkit::Scene scene = matrix_scene(Shape::Sphere, LightType::Point, litkit::Reflection::Lambert,
                                       litkit::Shading::Gouraud);
    scene.objects[0].position = {-1.2f, 0.0f, 0.0f};
    scene.objects[0].scale = 0.8f;
    scene.objects[0].reflection = litkit::Reflection::BlinnPhong;
    scene.objects[0].shading = litkit::Shading::Phong;
    litkit::SceneObject cube = scene.objects[0];
    cube.shape = litkit::CubeShape{1.0f};
    cube.position = {1.2f, 0.0f, 0.0f};
    cube.reflection = litkit::Reflection::HalfLambert;
    cube.shading = litkit::Shading::Flat;
    scene.objects.push_back(cube);
    const Comparison c = compare_backends(scene);
    EXPECT_GT(c.agreement.counted, c.pixels / 20);
    EXPECT_GE(c.agreement.fraction(), required_fraction) << "worst " << c.agreement.worst;
}

TEST(GlBackend, DrawsSeveralFramesAlike) {
    litkit::GlRenderer gl(matrix_scene(Shape::Cube, LightType::Spot, litkit::Reflection::Phong,
                                       litkit::Shading::Phong));
    litkit::Image first = gl.render();
    litkit::Image second;
    gl.render_into(second);
    gl.render_into(second);
    EXPECT_EQ(first.rgb, second.rgb);
}

TEST(GlBackend, WeightedAndCreasedNormalsMatchCpu) {
    // docs/spec.md §9.2 reaches OpenGL through the same world_mesh: a cube
    // creased at 60° (flat faces) under Phong and Gouraud shading, and a
    // sphere with angle-weighted normals.
    for (const litkit::Shading shading : {litkit::Shading::Phong, litkit::Shading::Gouraud}) {
        litkit::Scene scene =
            matrix_scene(Shape::Cube, LightType::Point, litkit::Reflection::BlinnPhong, shading);
        scene.objects[0].position = {-1.1f, 0.0f, 0.0f};
        scene.objects[0].scale = 0.8f;
        scene.objects[0].crease_angle_degrees = 60.0f;
        litkit::SceneObject sphere = scene.objects[0];
        sphere.shape = litkit::SphereShape{0.7f, 10, 6};
        sphere.position = {1.1f, 0.0f, 0.0f};
        sphere.crease_angle_degrees.reset();
        sphere.normals = litkit::Normals::Angle;
        scene.objects.push_back(sphere);
        SCOPED_TRACE(std::string(litkit::to_string(shading)));
        const Comparison c = compare_backends(scene);
        EXPECT_GT(c.agreement.counted, c.pixels / 20);
        EXPECT_GE(c.agreement.fraction(), required_fraction) << "worst " << c.agreement.worst;
        expect_edges_and_background_agree(c.agreement);
    }
}

TEST(GlBackend, MatchesCpuOnAScaledScene) {
    // docs/reliability.md "Geometry at any scale": the OpenGL backend draws a
    // room of 1e19 or of 1e-25 as the CPU backend does (both bring its
    // lengths into a float's range by the same power of two).
    for (const char* scale : {"e19", "e-25"}) {
        const std::string s = scale;
        const std::string text =
            "[room]\nwidth = 10" + s + "\nheight = 10" + s + "\ndepth = 10" + s +
            "\n[observer]\nposition = [3.5" + s + ", 1" + s + ", 4" + s + "]\nlook_at = [-2" + s +
            ", -3" + s + ", -2" + s + "]\nnear = 0.05" + s + "\nfar = 1000" + s +
            "\n[lighting]\nreflection = \"phong\"\nshading = \"phong\"\n[output]\nwidth = 160\n"
            "height = 120\n[[lights]]\ntype = \"point\"\nposition = [0, 0, 0]\nattenuation = [1, "
            "0, "
            "0]\n[[objects]]\ntype = \"cube\"\nsize = 2" +
            s + "\nposition = [-2" + s + ", -3" + s + ", -2" + s + "]\nrotation = [0, 30, 0]\n";
        const litkit::Scene scene = litkit::parse_scene(text, "scaled.toml");
        const Comparison c = compare_backends(scene);
        EXPECT_GT(c.agreement.counted, c.pixels / 20) << scale;  // the cube is drawn
        EXPECT_GE(c.agreement.fraction(), required_fraction) << scale;
        expect_edges_and_background_agree(c.agreement);
    }
}

// The refraction keys without transmission change nothing (docs/spec.md
// §10.1: ignored while t = 0); glass itself is tests/test_gl_glass.cpp's.
TEST(GlBackend, RefractionKeysWithoutTransmissionChangeNothing) {
    litkit::Scene scene = matrix_scene(Shape::Cube, LightType::Point, litkit::Reflection::Phong,
                                       litkit::Shading::Phong);
    litkit::Scene keys = scene;
    keys.room.ior = 1.33f;
    keys.max_depth = 2;
    keys.objects[0].material.ior = 2.42f;
    keys.objects[0].material.absorption_color = {0.2f, 0.4f, 1.0f};
    keys.objects[0].material.absorption_distance = 0.5f;
    litkit::GlRenderer gl(keys);
    EXPECT_EQ(gl.render().rgb, litkit::GlRenderer(scene).render().rgb);
}
