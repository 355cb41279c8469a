// SPDX-License-Identifier: MIT
// Glass through OpenGL (docs/spec.md §10): the same ray tree traced in the
// shaders against the same triangles. Every glass scene of the CPU's suite
// (tests/glass_scenes.hpp: total internal reflection, absorption, two glasses
// in a row, a room of water, a torus, which is not convex, depths 2 and 16,
// Gooch and toon glass, flat and gouraud glass with gamma) and every glass
// example, drawn by --backend gl, must agree with the CPU picture within the
// cross-backend tolerance (tests/picture_agreement.hpp: 2/255 on at least
// 99.5% of the pixels away from silhouettes, and on 99.5% of all pixels); two
// are also held against the independent ray tracer of
// tests/glass_reference.hpp directly. Runs on Mesa's llvmpipe in CI.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "glass_reference.hpp"
#include "glass_scenes.hpp"
#include "litkit/gl_renderer.hpp"
#include "litkit/render.hpp"
#include "litkit/scene.hpp"
#include "picture_agreement.hpp"

namespace {

using namespace glass_scenes;

void expect_gl_matches_cpu(const Scene& scene, const std::string& name) {
    SCOPED_TRACE(name);
    const litkit::Image cpu = litkit::render(scene);
    litkit::GlRenderer gl(scene);
    const litkit::Image gpu = gl.render();
    ASSERT_EQ(gpu.rgb.size(), cpu.rgb.size());
    const litkit_test::Agreement a = litkit_test::agreement(gpu, cpu, litkit_test::labels(scene));
    EXPECT_GE(a.fraction(), litkit_test::required_fraction)
        << a.within << " of " << a.counted << " pixels away from edges within 2/255";
    EXPECT_GE(a.fraction_of_all(), litkit_test::required_fraction) << "edges included";
    // The glass is drawn (a picture without it would differ from the CPU's
    // wherever the glass is): at least one pixel differs from the scene
    // without its glass.
    Scene without = scene;
    std::erase_if(without.objects,
                  [](const SceneObject& o) { return o.material.transmission > 0; });
    EXPECT_NE(litkit::GlRenderer(without).render().rgb, gpu.rgb);
}

// The share of pixels within 2/255 of the reference tracer's (double
// precision, one ray per pixel).
double within_reference(const Scene& scene, const litkit::Image& image) {
    const glass_reference::Tracer reference(scene);
    long within = 0;
    for (int j = 0; j < scene.output.height; ++j)
        for (int i = 0; i < scene.output.width; ++i) {
            const glass_reference::PixelResult want = reference.pixel(i, j);
            const std::uint8_t* got = image.pixel(i, j);
            int difference = 0;
            for (int c = 0; c < 3; ++c)
                difference = std::max(difference, std::abs(int(got[c]) - int(want.rgb[c])));
            within += difference <= 2;
        }
    return double(within) / double(long(scene.output.width) * scene.output.height);
}

}  // namespace

TEST(GlGlass, SphereLensMatchesTheCpu) { expect_gl_matches_cpu(sphere_lens_scene(), "lens"); }
TEST(GlGlass, SlabMatchesTheCpu) { expect_gl_matches_cpu(slab_scene(), "slab"); }
TEST(GlGlass, PrismsTotalInternalReflectionMatchesTheCpu) {
    expect_gl_matches_cpu(prism_scene(), "prism");
}
TEST(GlGlass, AbsorbingCubeMatchesTheCpu) {
    expect_gl_matches_cpu(absorbing_cube_scene(), "absorbing_cube");
}
TEST(GlGlass, TwoGlassesInARowMatchTheCpu) {
    expect_gl_matches_cpu(two_glasses_scene(), "two_glasses");
}
TEST(GlGlass, WaterFilledRoomMatchesTheCpu) {
    expect_gl_matches_cpu(water_room_scene(), "water_room");
}
TEST(GlGlass, TorusNotConvexMatchesTheCpu) { expect_gl_matches_cpu(torus_scene(), "torus"); }
TEST(GlGlass, GoochAndToonGlassMatchTheCpu) {
    expect_gl_matches_cpu(gooch_toon_scene(), "gooch_toon");
}
TEST(GlGlass, FlatAndGouraudGlassWithGammaMatchTheCpu) {
    expect_gl_matches_cpu(flat_gouraud_gamma_scene(), "flat_gouraud_gamma");
}
TEST(GlGlass, MaxDepth2And16MatchTheCpu) {
    for (int depth : {2, 16})
        expect_gl_matches_cpu(max_depth_scene(depth), "max_depth_" + std::to_string(depth));
}

// Glass with anti-aliasing (docs/spec.md §11): each sample's pass traces
// its own rays, and the passes are resolved as the CPU's samples are.
TEST(GlGlass, GlassWithFourSamplesMatchesTheCpu) {
    Scene scene = sphere_lens_scene();
    scene.output.samples = 4;
    scene.output.gamma = 2.2f;
    expect_gl_matches_cpu(scene, "lens, 4 samples");
}

TEST(GlGlass, EveryGlassExampleMatchesTheCpu) {
    const std::filesystem::path examples = std::filesystem::path(LITKIT_SOURCE_DIR) / "examples";
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(examples))
        if (entry.path().extension() == ".toml") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    int glass_examples = 0;
    for (const std::filesystem::path& file : files) {
        Scene scene = litkit::load_scene(std::span(&file, 1));
        if (std::none_of(scene.objects.begin(), scene.objects.end(),
                         [](const SceneObject& o) { return o.material.transmission > 0.0f; }))
            continue;
        ++glass_examples;
        const double aspect = double(scene.output.width) / double(scene.output.height);
        scene.output.width = 200;
        scene.output.height = int(std::lround(200.0 / aspect));
        expect_gl_matches_cpu(scene, file.filename().string());
    }
    EXPECT_EQ(glass_examples, 5);
}

// Against the independent computation, not only against the CPU: the
// reference casts each pixel's ray in double precision (pixels whose centre
// lies within rounding of an edge may pick another triangle: 99%, as in
// tests/test_glass.cpp).
TEST(GlGlass, MatchesTheReferenceTracer) {
    for (const Scene& scene : {two_glasses_scene(), prism_scene()}) {
        litkit::GlRenderer gl(scene);
        EXPECT_GE(within_reference(scene, gl.render()), 0.99);
    }
}

// The panel's sliders and the Python module change materials through
// update(): the picture must be what a new renderer draws, and glass may
// come and go.
TEST(GlGlass, UpdateFollowsTheGlassKeys) {
    const Scene first = sphere_lens_scene();
    litkit::GlRenderer gl(first);
    Scene next = first;
    SceneObject& lens = next.objects.back();
    lens.material.transmission = 0.6f;
    lens.material.ior = 2.0f;
    lens.material.absorption_color = {0.5f, 0.8f, 1.0f};
    next.room.ior = 1.2f;
    next.max_depth = 3;
    gl.update(next);
    const litkit::Image updated = gl.render();
    EXPECT_EQ(updated.rgb, litkit::GlRenderer(next).render().rgb);
    EXPECT_NE(updated.rgb, litkit::GlRenderer(first).render().rgb);
    Scene opaque = next;
    opaque.objects.back().material.transmission = 0.0f;
    gl.update(opaque);
    EXPECT_EQ(gl.render().rgb, litkit::GlRenderer(opaque).render().rgb);
    gl.update(first);
    EXPECT_EQ(gl.render().rgb, litkit::GlRenderer(first).render().rgb);
}
