// SPDX-License-Identifier: MIT
// Properties of the renderer that hold whatever the scene: the same picture
// on any number of threads and with either set of SIMD kernels, and the
// pipeline's edge cases (back faces, the near plane, empty scenes).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "litkit/error.hpp"
#include "litkit/explain.hpp"
#include "litkit/render.hpp"
#include "litkit/scene.hpp"

namespace fs = std::filesystem;

namespace {

std::vector<fs::path> example_scenes() {
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(fs::path(LITKIT_SOURCE_DIR) / "examples"))
        if (entry.path().extension() == ".toml") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

litkit::Scene small(litkit::Scene scene) {
    scene.output.width = 200;
    scene.output.height = 150;
    return scene;
}

int max_difference(const litkit::Image& a, const litkit::Image& b) {
    int worst = 0;
    for (std::size_t i = 0; i < a.rgb.size(); ++i)
        worst = std::max(worst, std::abs(int(a.rgb[i]) - int(b.rgb[i])));
    return worst;
}

int covered_pixels(const litkit::Image& image, const litkit::Rgb8& background) {
    int covered = 0;
    for (std::size_t i = 0; i < image.rgb.size(); i += 3)
        covered += image.rgb[i] != background[0] || image.rgb[i + 1] != background[1] ||
                   image.rgb[i + 2] != background[2];
    return covered;
}

}  // namespace

TEST(Render, ThreadCountDoesNotChangeThePicture) {
    const std::vector<fs::path> files = example_scenes();
    ASSERT_GE(files.size(), 10u);
    for (const fs::path& file : files) {
        const litkit::Scene scene = small(litkit::load_scene(std::span(&file, 1)));
        const litkit::Image one = litkit::render(scene, {.threads = 1});
        const litkit::Image three = litkit::render(scene, {.threads = 3});
        EXPECT_EQ(one.rgb, three.rgb) << file;
    }
}

// Exactly: the AVX2 kernels are compiled without FMA contraction
// (src/CMakeLists.txt), so every CPU, and the WebAssembly build of
// docs/web.md, draws the same bytes.
TEST(Render, PortableAndBestKernelsDrawTheSamePicture) {
    const std::vector<fs::path> files = example_scenes();
    ASSERT_GE(files.size(), 10u);
    for (const fs::path& file : files) {
        const litkit::Scene scene = small(litkit::load_scene(std::span(&file, 1)));
        litkit::RenderOptions portable;
        portable.kernels = litkit::RenderOptions::Kernels::Portable;
        const litkit::Image best = litkit::render(scene);
        const litkit::Image fallback = litkit::render(scene, portable);
        EXPECT_EQ(max_difference(best, fallback), 0) << file;
        EXPECT_GT(covered_pixels(best, litkit::to_rgb8(scene.output.background)), 0) << file;
    }
}

// The 16-lane AVX-512 set, the 8-lane AVX2 set and the portable set run the
// same template text, none with fused multiply-adds (-ffp-contract=off): their
// pictures agree byte for byte, on every example, the bench scenes and every
// reflection model under every shading.
TEST(Render, Avx512Avx2AndPortableKernelsDrawTheSameBytes) {
    using litkit::RenderOptions;
    if (!litkit::kernel_set_available(RenderOptions::Kernels::Avx512))
        GTEST_SKIP() << "this CPU lacks AVX-512 F/BW/DQ/VL (or the OS keeps it off): "
                        "only the AVX2 and portable sets can run here";
    ASSERT_TRUE(litkit::kernel_set_available(RenderOptions::Kernels::Avx2));
    {
        litkit::Renderer best(small(litkit::default_scene()));
        std::printf("best kernel set on this CPU: %s\n", best.kernel_set());
        EXPECT_STREQ(best.kernel_set(), "avx512");
    }
    std::vector<litkit::Scene> scenes;
    for (const fs::path& file : example_scenes())
        scenes.push_back(small(litkit::load_scene(std::span(&file, 1))));
    for (const char* name : {"fill.toml", "sphere-65k.toml", "teapot-64.toml"}) {
        const fs::path file = fs::path(LITKIT_SOURCE_DIR) / "bench" / "scenes" / name;
        litkit::Scene scene = litkit::load_scene(std::span(&file, 1));
        scene.output.width = 320;  // odd run lengths and tails of every size
        scene.output.height = 181;
        scenes.push_back(scene);
    }
    // Triangles of every size around the small-triangle rasterizer's limit
    // (8 pixels across: rows of 9 pixels, one more than an AVX2 vector).
    for (int width = 96; width <= 420; width += 27) {
        litkit::Scene scene = small(litkit::default_scene());
        litkit::SceneObject sphere;
        sphere.name = "sphere";
        sphere.shape = litkit::SphereShape{1.2f, 40, 20};
        sphere.material = scene.objects.front().material;
        scene.objects = {sphere};
        scene.output.width = width;
        scene.output.height = width * 2 / 3 + 1;
        scenes.push_back(scene);
    }
    const litkit::Scene base = small(litkit::default_scene());
    for (int model = 0; model < litkit::reflection_count; ++model) {
        const auto reflection = static_cast<litkit::Reflection>(model);
        for (litkit::Shading shading : {litkit::Shading::Flat, litkit::Shading::Gouraud,
                                        litkit::Shading::Phong, litkit::Shading::Faceted}) {
            litkit::Scene scene = base;
            scene.reflection = reflection;
            scene.shading = shading;
            scene.output.gamma = 2.2f;
            scenes.push_back(scene);
        }
    }
    ASSERT_GE(scenes.size(), 40u);
    for (std::size_t i = 0; i < scenes.size(); ++i) {
        litkit::Renderer wide(scenes[i], {.kernels = RenderOptions::Kernels::Avx512});
        litkit::Renderer narrow(scenes[i], {.kernels = RenderOptions::Kernels::Avx2});
        litkit::Renderer portable(scenes[i], {.kernels = RenderOptions::Kernels::Portable});
        ASSERT_STREQ(wide.kernel_set(), "avx512");
        ASSERT_STREQ(narrow.kernel_set(), "avx2");
        const litkit::Image a = wide.render();
        const litkit::Image b = narrow.render();
        const litkit::Image c = portable.render();
        EXPECT_GT(covered_pixels(a, litkit::to_rgb8(scenes[i].output.background)), 0)
            << "scene " << i;
        EXPECT_TRUE(a.rgb == b.rgb)
            << "scene " << i << ": largest difference " << max_difference(a, b);
        EXPECT_TRUE(a.rgb == c.rgb)
            << "scene " << i << ": largest difference from portable " << max_difference(a, c);
    }
}

// docs/spec.md §3: Phong shading lights the point each pixel shows, on its
// ray (§1) where that meets the triangle: here to within 1/128 of the
// pixel's footprint on the triangle (the rasterizer snaps corners to 1/256
// pixel) and float rounding, against the intersection computed in double
// from the camera. A floor seen at a grazing angle and two balls.
TEST(Render, PhongLightsThePointWhereThePixelsRayMeetsTheTriangle) {
    const fs::path file = fs::path(LITKIT_SOURCE_DIR) / "examples" / "soft-spot.toml";
    const litkit::Scene scene = small(litkit::load_scene(std::span(&file, 1)));
    litkit::PixelExplainer explainer(scene);
    const litkit::Observer& o = scene.observer;
    const glm::dvec3 eye(o.position);
    const glm::dvec3 forward = glm::normalize(glm::dvec3(o.look_at) - eye);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(o.up)));
    const glm::dvec3 up = glm::cross(right, forward);
    const double tan_half = std::tan(glm::radians(double(o.fov_degrees)) / 2.0);
    const double width = scene.output.width, height = scene.output.height;
    auto ray = [&](double i, double j) {
        const double x = 2.0 * (i + 0.5) / width - 1.0, y = 1.0 - 2.0 * (j + 0.5) / height;
        return forward + x * tan_half * (width / height) * right + y * tan_half * up;
    };
    int checked = 0;
    for (int j = 0; j < scene.output.height; j += 4) {
        for (int i = 0; i < scene.output.width; i += 4) {
            const litkit::PixelExplanation e = explainer.explain(i, j);
            if (!e.hit) continue;
            ASSERT_EQ(e.shading, litkit::Shading::Phong);
            const glm::dvec3 c0(e.corners[0]), c1(e.corners[1]), c2(e.corners[2]);
            const glm::dvec3 normal = glm::cross(c1 - c0, c2 - c0);
            auto meet = [&](const glm::dvec3& d) {
                return eye + glm::dot(c0 - eye, normal) / glm::dot(d, normal) * d;
            };
            const glm::dvec3 expected = meet(ray(i, j));
            const double footprint = glm::length(meet(ray(i + 1, j)) - expected) +
                                     glm::length(meet(ray(i, j + 1)) - expected);
            const double off = glm::length(glm::dvec3(e.evaluations.at(0).position) - expected);
            EXPECT_LE(off, footprint / 128.0 + 1e-6 * glm::length(expected - eye))
                << "pixel " << i << "," << j << ": footprint " << footprint;
            ++checked;
        }
    }
    EXPECT_GT(checked, 400);
}

TEST(Render, AKernelSetTheCpuLacksIsAnError) {
    using litkit::RenderOptions;
    for (RenderOptions::Kernels set :
         {RenderOptions::Kernels::Avx2, RenderOptions::Kernels::Avx512}) {
        if (litkit::kernel_set_available(set)) {
            EXPECT_NO_THROW(litkit::Renderer(small(litkit::default_scene()), {.kernels = set}));
        } else {
            EXPECT_THROW(litkit::Renderer(small(litkit::default_scene()), {.kernels = set}),
                         litkit::ArgumentError);
        }
    }
    litkit::Renderer portable(small(litkit::default_scene()),
                              {.kernels = RenderOptions::Kernels::Portable});
    EXPECT_STREQ(portable.kernel_set(), "portable");
}

TEST(Render, RenderingTwiceIntoTheSameImageGivesTheSamePicture) {
    // The visibility buffers are reused between frames: a second frame must
    // not see anything of the first.
    litkit::Renderer renderer(small(litkit::default_scene()));
    litkit::Image first, second;
    renderer.render_into(first);
    renderer.render_into(second);
    renderer.render_into(second);
    EXPECT_EQ(first.rgb, second.rgb);
}

TEST(Render, ShadedPixelCountIsTheCoveredPixels) {
    // Each covered pixel is shaded once, so the count equals the pixels that
    // differ from the background (the default cube never matches it).
    litkit::Scene scene = small(litkit::default_scene());
    litkit::Renderer renderer(scene);
    litkit::Image image;
    renderer.render_into(image);
    const int covered = covered_pixels(image, litkit::to_rgb8(scene.output.background));
    EXPECT_GT(covered, 1000);
    EXPECT_EQ(renderer.shaded_pixel_count(), static_cast<std::size_t>(covered));
}

TEST(Render, SceneWithoutObjectsIsAllBackground) {
    litkit::Scene scene = small(litkit::default_scene());
    scene.objects.clear();
    scene.output.background = litkit::from_rgb8({12, 34, 56});
    const litkit::Image image = litkit::render(scene);
    EXPECT_EQ(covered_pixels(image, litkit::to_rgb8(scene.output.background)), 0);
}

TEST(Render, ObjectSeenFromInsideShowsOnlyBackFacesSoNothing) {
    // A sphere around the camera shows the camera only its inside, whose
    // triangles wind clockwise on screen: all culled.
    litkit::Scene scene = small(litkit::default_scene());
    scene.objects.resize(1);
    scene.objects[0].shape = litkit::SphereShape{3.0f, 32, 16};
    scene.objects[0].position = scene.observer.position;
    const litkit::Image image = litkit::render(scene);
    EXPECT_EQ(covered_pixels(image, litkit::to_rgb8(scene.output.background)), 0);
}

TEST(Render, ObjectCrossingTheNearPlaneIsClippedNotDropped) {
    // A cube turned 45° about y shows the camera (on +z) its front edge at
    // z = √2 ≈ 1.41. With the eye at z = 3 and near = 1.8 the near plane sits
    // at z = 1.2 and cuts through both visible faces: the strip around the
    // edge is clipped away, the rest of the faces is still drawn.
    litkit::Scene scene = small(litkit::default_scene());
    scene.observer.position = {0, 0, 3};
    scene.observer.look_at = {0, 0, 0};
    scene.objects.resize(1);
    scene.objects[0].shape = litkit::CubeShape{2.0f};
    scene.objects[0].position = {0, 0, 0};
    scene.objects[0].rotation_degrees = {0, 45, 0};
    scene.lights.resize(1);
    scene.lights[0].light = litkit::Light{litkit::AmbientLight{}};

    scene.observer.near = 0.05f;
    const int whole =
        covered_pixels(litkit::render(scene), litkit::to_rgb8(scene.output.background));
    scene.observer.near = 1.8f;
    const litkit::Image clipped_image = litkit::render(scene);
    const int clipped = covered_pixels(clipped_image, litkit::to_rgb8(scene.output.background));
    EXPECT_GT(whole, 200 * 150 / 4);
    EXPECT_GT(clipped, whole / 10) << "the parts beyond the near plane must stay";
    EXPECT_LT(clipped, whole * 9 / 10) << "the parts before the near plane must go";
    // The centre column (the front edge, z ≈ 1.41 > 1.2) is clipped away.
    const std::uint8_t* centre = clipped_image.pixel(100, 75);
    const litkit::Rgb8 background = litkit::to_rgb8(scene.output.background);
    EXPECT_EQ(centre[0], background[0]);
    EXPECT_EQ(centre[1], background[1]);
    EXPECT_EQ(centre[2], background[2]);
}

// A prepared scene: another observer, image size, models,
// material or light re-renders without building the meshes again, and draws
// what a fresh renderer of the changed scene draws.
TEST(Renderer, UpdateKeepsTheMeshesUnlessAnObjectMoves) {
    litkit::Scene scene = litkit::default_scene();
    scene.output.width = 160;
    scene.output.height = 120;
    litkit::Renderer renderer(scene);
    EXPECT_EQ(renderer.mesh_builds(), 1u);
    const litkit::Image first = renderer.render();

    litkit::Scene changed = scene;
    changed.observer.position = {4.0f, 2.0f, 3.0f};
    changed.output.width = 200;
    changed.output.height = 100;
    changed.reflection = litkit::Reflection::Toon;
    changed.shading = litkit::Shading::Gouraud;
    changed.objects[0].material.kd = 0.3f;
    changed.lights[0].light.intensity = 30.0f;
    changed.output.gamma = 2.2f;
    renderer.update(changed);
    EXPECT_EQ(renderer.mesh_builds(), 1u) << "nothing moved: no new meshes";
    const litkit::Image updated = renderer.render();
    EXPECT_EQ(updated.width, 200);
    EXPECT_EQ(updated.rgb, litkit::render(changed).rgb);
    EXPECT_NE(updated.rgb, first.rgb);

    // Back to the first scene: the first picture again.
    renderer.update(scene);
    EXPECT_EQ(renderer.render().rgb, first.rgb);
    EXPECT_EQ(renderer.mesh_builds(), 1u);

    // Shadings that use face normals (computed only for them) after one
    // that does not, without new meshes.
    for (const litkit::Shading shading : {litkit::Shading::Flat, litkit::Shading::Faceted}) {
        litkit::Scene faces = scene;
        faces.shading = shading;
        renderer.update(faces);
        EXPECT_EQ(renderer.render().rgb, litkit::render(faces).rgb);
        EXPECT_NE(renderer.render().rgb, first.rgb);
    }
    EXPECT_EQ(renderer.mesh_builds(), 1u);

    // Moving the object builds its mesh again.
    litkit::Scene moved = scene;
    moved.objects[0].position.x += 0.5f;
    renderer.update(moved);
    EXPECT_EQ(renderer.mesh_builds(), 2u);
    EXPECT_EQ(renderer.render().rgb, litkit::render(moved).rgb);
}
