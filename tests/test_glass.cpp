// SPDX-License-Identifier: MIT
// Glass in the CPU renderer (docs/spec.md §10): its pictures against an
// independent ray tracer in double precision (tests/glass_reference.hpp), and
// values computed by hand, through whole pictures and Renderer::probe's ray
// tree.
//
// The renderer rasterizes what a pixel sees first; the reference casts the
// camera's ray. Where a pixel centre lies within float rounding of an edge
// (of the first surface, or of a surface some later ray passes), the two may
// pick different triangles or objects and the pixel differs completely; such
// pixels are few. So the pictures are compared whole, and at least 99% of the
// pixels whose first surface is glass must be within 2/255 in every channel,
// with a mean absolute difference below 0.3/255 over those pixels' channels.
//
// Set LITKIT_REFERENCE_DUMP to a folder to get both pictures of every case as
// PPM files there.

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include "glass_reference.hpp"
#include "glass_scenes.hpp"
#include "litkit/image.hpp"
#include "litkit/ray_tree.hpp"
#include "litkit/render.hpp"
#include "litkit/scene.hpp"

namespace {

using litkit::RayNode;
using litkit::Scene;
using litkit::SceneObject;

using namespace glass_scenes;

// ---- Comparison with the reference ----

void write_ppm(const std::filesystem::path& path, int width, int height,
               const std::vector<std::uint8_t>& rgb) {
    std::ofstream out(path, std::ios::binary);
    out << "P6\n" << width << ' ' << height << "\n255\n";
    out.write(reinterpret_cast<const char*>(rgb.data()), std::streamsize(rgb.size()));
}

void expect_matches_reference(const Scene& scene, const std::string& name) {
    const litkit::Image image = litkit::render(scene);
    const glass_reference::Tracer reference(scene);
    const int width = scene.output.width, height = scene.output.height;
    std::vector<std::uint8_t> expected;
    long glass_pixels = 0, glass_within = 0, all_within = 0, rays = 0;
    double glass_difference = 0.0;  // Σ |render − reference| over glass pixels' channels
    int worst = -1;
    std::string worst_text;
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i) {
            const glass_reference::PixelResult want =
                scene.output.samples > 1 ? reference.supersampled(i, j) : reference.pixel(i, j);
            expected.insert(expected.end(), want.rgb.begin(), want.rgb.end());
            rays += want.rays;
            const std::uint8_t* got = image.pixel(i, j);
            int difference = 0, sum = 0;
            for (int c = 0; c < 3; ++c) {
                const int d = std::abs(int(got[c]) - int(want.rgb[c]));
                difference = std::max(difference, d);
                sum += d;
            }
            all_within += difference <= 2;
            const bool on_glass = want.object >= 0 &&
                                  scene.objects[std::size_t(want.object)].material.transmission > 0;
            if (!on_glass) continue;
            ++glass_pixels;
            glass_within += difference <= 2;
            glass_difference += sum;
            if (difference > worst) {
                worst = difference;
                std::ostringstream out;
                out << "pixel (" << i << ", " << j << "): render (" << int(got[0]) << ", "
                    << int(got[1]) << ", " << int(got[2]) << "), reference (" << int(want.rgb[0])
                    << ", " << int(want.rgb[1]) << ", " << int(want.rgb[2]) << "), L = ("
                    << want.light.x << ", " << want.light.y << ", " << want.light.z << ")";
                worst_text = out.str();
            }
        }
    if (const char* folder = std::getenv("LITKIT_REFERENCE_DUMP"); folder && *folder) {
        std::filesystem::create_directories(folder);
        write_ppm(std::filesystem::path(folder) / (name + "_reference.ppm"), width, height,
                  expected);
        write_ppm(std::filesystem::path(folder) / (name + "_render.ppm"), width, height, image.rgb);
    }
    const long pixels = long(width) * height;
    const double mean = glass_pixels ? glass_difference / (3.0 * double(glass_pixels)) : 0.0;
    std::ostringstream summary;
    summary << name << ": " << glass_within << " of " << glass_pixels
            << " glass pixels within 2/255, mean |difference| " << mean
            << "/255 over their channels; " << all_within << " of " << pixels
            << " pixels in all within 2/255; " << rays << " reference rays; worst " << worst_text;
    ASSERT_GT(glass_pixels, pixels / 20) << summary.str();  // the scene shows its glass
    EXPECT_GE(double(glass_within), 0.99 * double(glass_pixels)) << summary.str();
    EXPECT_LT(mean, 0.3) << summary.str();
    EXPECT_GE(double(all_within), 0.99 * double(pixels)) << summary.str();
    std::printf("%s\n", summary.str().c_str());
}

// ---- The pictures ----

TEST(GlassReference, SphereLensBeforeCubes) {
    expect_matches_reference(sphere_lens_scene(), "sphere_lens");
}

// Anti-aliased (docs/spec.md §11): every sample traced, averaged in linear
// light; the lens's silhouette and the cubes' edges seen through it.
TEST(GlassReference, SphereLensWithFourAndEightSamples) {
    for (int samples : {4, 8}) {
        Scene scene = base_scene();
        add_cubes(scene, -3.0f);
        scene.objects.push_back(glass(litkit::SphereShape{1.5f, 24, 12}, {0.1f, -0.05f, 1.0f}));
        scene.output.samples = samples;
        scene.output.gamma = 2.2f;
        expect_matches_reference(scene, "sphere_lens_" + std::to_string(samples));
    }
}

TEST(GlassReference, SlabBeforeBar) { expect_matches_reference(slab_scene(), "slab"); }

// Total internal reflection at the hypotenuse: light coming in through the
// face z = 1 leaves through x = −1 (and the picture shows what lies to the left).
TEST(GlassReference, PrismReflectsTotally) { expect_matches_reference(prism_scene(), "prism"); }

TEST(GlassReference, AbsorbingCube) {
    expect_matches_reference(absorbing_cube_scene(), "absorbing_cube");
}

TEST(GlassReference, TwoGlassesInARow) {
    expect_matches_reference(two_glasses_scene(), "two_glasses");
}

TEST(GlassReference, WaterFilledRoom) {
    expect_matches_reference(water_room_scene(), "water_room");
}

// Not convex: rays leave the tube and come back into it.
TEST(GlassReference, Torus) { expect_matches_reference(torus_scene(), "torus"); }

TEST(GlassReference, MaxDepth2And16) {
    for (int depth : {2, 16})
        expect_matches_reference(max_depth_scene(depth), "max_depth_" + std::to_string(depth));
}

// Gooch's wash and toon's bands are I_ad, their highlights I_s; t < 1 keeps
// (1 − t)·I_ad in the picture.
TEST(GlassReference, GoochAndToonGlass) {
    expect_matches_reference(gooch_toon_scene(), "gooch_toon");
}

// Flat and gouraud glass: the local part by the shading model (flat: at the
// centroid; gouraud: the corners' values mixed), the bracket per pixel with
// N_s (the face normal; the interpolated one). With gamma 2.2, so that rays
// that leave the scene bring (background/255)^2.2 back to be corrected again.
TEST(GlassReference, FlatAndGouraudGlassWithGamma) {
    expect_matches_reference(flat_gouraud_gamma_scene(), "flat_gouraud_gamma");
}

// Every example with glass (examples/*.toml where some object's transmission
// is above 0; tests/test_render_reference.cpp checks the others), 160 pixels
// wide with its aspect ratio kept.
TEST(GlassReference, EveryGlassExample) {
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
        SCOPED_TRACE(file.filename().string());
        const double aspect = double(scene.output.width) / double(scene.output.height);
        scene.output.width = 160;
        scene.output.height = int(std::lround(160.0 / aspect));
        expect_matches_reference(scene, "example_" + file.stem().string());
    }
    EXPECT_EQ(glass_examples, 5);  // glass-lens, water-slab, prism, coloured-glass, two-glasses
}

// ---- Closed forms ----

int largest_difference(const litkit::Image& a, const litkit::Image& b, std::string& where) {
    int worst = 0;
    for (int j = 0; j < a.height; ++j)
        for (int i = 0; i < a.width; ++i)
            for (int c = 0; c < 3; ++c) {
                const int d = std::abs(int(a.pixel(i, j)[c]) - int(b.pixel(i, j)[c]));
                if (d > worst) {
                    worst = d;
                    where = "pixel (" + std::to_string(i) + ", " + std::to_string(j) + ")";
                }
            }
    return worst;
}

// Clear glass (n_o = n_r = 1, t = 1, k_s = 0, a white): η = 1, so
// k = 1 − (1 − c₁²) = c₁², c₂ = c₁, T = d + (c₁ − c₁)·n = d, r_s = r_p = 0,
// F = 0; the local part is (1 − 1)·I_ad + 0 = 0 and A = 1. Every ray goes
// straight through, and L is what lies behind, lit with V = −d as the
// camera sees it: the picture without the glass.
//
// The layout is not symmetric (camera off the axis, cubes turned and shifted
// unevenly): in a symmetric one, pixel centres fall exactly on cube edges,
// where the rasterizer's fill rule and the ray's watertight test may choose
// different triangles. The cubes behind are lit by `phong` reflection but
// shaded `faceted` (the face normal, the same in both): the rasterizer snaps
// corners to 1/256 pixel, so its interpolated vertex normals are those of a
// point up to 1/512 pixel away, about 2e-4 off in I on a pillowed cube
// (0.05/255: within the opaque pictures' tolerance, but enough to turn a
// byte here and there), where the ray's are exact.
TEST(GlassClosedForm, ClearGlassChangesNothing) {
    Scene plain = base_scene();
    plain.shading = litkit::Shading::Faceted;
    add_cubes(plain, -3.0f);
    Scene scene = plain;
    SceneObject clear = glass(litkit::SphereShape{1.5f, 24, 12}, {0.1f, -0.05f, 1.0f}, 1.0f);
    clear.material.ks = 0.0f;
    clear.shading = litkit::Shading::Phong;  // with η = 1 no normal bends a ray
    scene.objects.push_back(clear);
    SceneObject block = glass(litkit::CubeShape{1.0f}, {2.3f, 1.1f, 0.5f}, 1.0f);
    block.material.ks = 0.0f;
    block.rotation_degrees = {17.0f, 29.0f, 6.0f};
    block.shading = litkit::Shading::Faceted;
    scene.objects.push_back(block);
    const litkit::Image with = litkit::render(scene), without = litkit::render(plain);
    std::string where;
    EXPECT_EQ(largest_difference(with, without, where), 0) << where;
}

// max_depth = 1: the rays the first hit spawns have depth 2 and are not
// traced (L = 0), so L = (1 − t)·I_ad + I_s + t·0 = I_s with t = 1: the
// same object opaque with k_a = k_d = 0, whose I is I_s alone.
TEST(GlassClosedForm, MaxDepth1IsTheLocalPart) {
    Scene scene = base_scene();
    scene.max_depth = 1;
    add_cubes(scene, -3.0f);
    SceneObject lens = glass(litkit::SphereShape{1.5f, 24, 12}, {0.1f, -0.05f, 1.0f});
    lens.material.color = {0.4f, 0.7f, 0.9f};
    scene.objects.push_back(lens);
    Scene opaque = scene;
    litkit::Material& m = opaque.objects.back().material;
    m.transmission = 0.0f;
    m.ka = 0.0f;
    m.kd = 0.0f;
    std::string where;
    EXPECT_LE(largest_difference(litkit::render(scene), litkit::render(opaque), where), 1) << where;
}

// A unit glass cube (n_o = 1.5, t = 1, k_s = 0, faceted) seen face-on by the
// middle pixel, whose ray is the view direction d = (0, 0, −1); behind it an
// opaque backdrop under an ambient light only: L_b = k_a·C·I_L = 1·0.8·1 = 0.8.
// Every hit is at normal incidence: c₁ = c₂ = 1, T = d, and from either side
// r_s = ±(1 − 1.5)/(1 + 1.5) → F = 0.2² = 0.04. Inside, ℓ = 1 per crossing,
// A = a^(ℓ/D) = a², a = (1, 0.6, 0.2), D = 0.5: A = (1, 0.36, 0.04). The
// local part is (1 − 1)·I_ad + 0 = 0. The tree (weights: largest channel):
//   depth 2: R out of the front face → background (black): 0;
//            T in, weight 0.96;
//   depth 3: at the back face, T out → L_b, weight 0.96·A·0.96 = 0.9216;
//            R back inside, weight 0.96·A·0.04 = 0.0384;
//   depth 4: at the front face, T out → background: 0;
//            R inside, weight 0.96·A²·0.04² = 0.001536 ≥ 2⁻¹⁰ = 0.000977;
//   depth 5: at the back face, T out → L_b, weight 0.96²·A³·0.04² = 0.00147 ≥ 2⁻¹⁰;
//            R inside, weight 0.96·A³·0.04³ = 0.0000614 < 2⁻¹⁰: not traced.
// (Depth 5 ≤ max_depth 8: only the weight stops it.) The weights use the
// largest channel, red's, so every channel gets both terms:
//   L = (1 − F)²·A·L_b·(1 + F²·A²)
//     = 0.9216·0.8·A·(1 + 0.0016·A²)
//     = (0.738459, 0.265476, 0.0294913) → bytes (188, 68, 8)
// (without the second pass, red would be 0.737280).
TEST(GlassClosedForm, AbsorbingCubeFaceOn) {
    Scene scene = axis_scene(5.0f);
    scene.shading = litkit::Shading::Faceted;
    // Shifted off the axis so that the middle ray meets no triangle's diagonal.
    SceneObject backdrop = cube(4.0f, {0.3f, 0.2f, -4.0f}, {0.8f, 0.8f, 0.8f});
    backdrop.material.ka = 1.0f;
    scene.objects.push_back(backdrop);
    SceneObject c = glass(litkit::CubeShape{1.0f}, {0.1f, 0.07f, 0.0f});
    c.material.ks = 0.0f;
    c.material.absorption_color = {1.0f, 0.6f, 0.2f};
    c.material.absorption_distance = 0.5f;
    scene.objects.push_back(c);
    litkit::Renderer renderer(scene);
    const litkit::PixelProbe probe = renderer.probe(80, 60);
    ASSERT_TRUE(probe.hit);
    EXPECT_EQ(probe.object, 1u);
    EXPECT_NEAR(probe.intensity.x, 0.738459, 1e-5);
    EXPECT_NEAR(probe.intensity.y, 0.265476, 1e-5);
    EXPECT_NEAR(probe.intensity.z, 0.0294913, 1e-5);
    const litkit::Image image = renderer.render();
    const std::uint8_t* rgb = image.pixel(80, 60);
    EXPECT_NEAR(rgb[0], 188, 1);
    EXPECT_NEAR(rgb[1], 68, 1);
    EXPECT_NEAR(rgb[2], 8, 1);
    // The deepest traced ray reaches the backdrop at depth 5; its sibling is not traced.
    int deepest_surface = 0, untraced_at_5 = 0;
    for (const RayNode& n : probe.ray_tree) {
        if (n.outcome == RayNode::Outcome::Surface)
            deepest_surface = std::max(deepest_surface, n.depth);
        untraced_at_5 += n.outcome == RayNode::Outcome::Untraced && n.depth == 5;
    }
    EXPECT_EQ(deepest_surface, 5);
    EXPECT_EQ(untraced_at_5, 1);
}

// A slab 2 units thick (n_o = 1.5) turned 30° about y, seen by the middle
// pixel along d = (0, 0, −1): θ₁ = 30°, sin θ₂ = sin 30°/1.5 = 1/3,
// cos θ₂ = √(8/9) = 0.942809, θ₂ = 19.4712°. Inside, ℓ = 2/cos θ₂ = 2.121320;
// the ray leaves parallel to d, shifted sideways by
//   2·sin(θ₁ − θ₂)/cos θ₂ = 2·(0.5·0.942809 − 0.866025/3)/0.942809 = 0.387628.
TEST(GlassClosedForm, SlabShiftsSideways) {
    Scene scene = axis_scene(8.0f);
    SceneObject slab = glass(box({5.0f, 5.0f, 1.0f}), {0.0f, 0.0f, 0.0f});
    slab.rotation_degrees = {0.0f, 30.0f, 0.0f};
    slab.shading = litkit::Shading::Faceted;
    scene.objects.push_back(slab);
    litkit::Renderer renderer(scene);
    const litkit::PixelProbe probe = renderer.probe(80, 60);
    const std::vector<RayNode>& tree = probe.ray_tree;
    ASSERT_FALSE(tree.empty());
    EXPECT_NEAR(tree[0].theta1, 30.0, 1e-3);
    EXPECT_NEAR(tree[0].theta2, 19.4712, 1e-3);
    int inside = -1, out = -1;
    for (std::size_t k = 0; k < tree.size(); ++k)
        if (tree[k].kind == RayNode::Kind::Refracted && tree[k].parent == 0) inside = int(k);
    ASSERT_GE(inside, 0);
    EXPECT_TRUE(tree[std::size_t(inside)].inside);
    EXPECT_NEAR(tree[std::size_t(inside)].length, 2.121320, 1e-3);
    for (std::size_t k = 0; k < tree.size(); ++k)
        if (tree[k].kind == RayNode::Kind::Refracted && tree[k].parent == inside) out = int(k);
    ASSERT_GE(out, 0);
    const RayNode& exit = tree[std::size_t(out)];
    EXPECT_FALSE(exit.inside);
    const glm::dvec3 d(0.0, 0.0, -1.0), eye(0.0, 0.0, 8.0);
    const glm::dvec3 direction = glass_reference::to_double(exit.direction);
    EXPECT_GT(glm::dot(direction, d), 1.0 - 1e-6);  // parallel to the camera's ray
    const glm::dvec3 origin = glass_reference::to_double(exit.origin);
    EXPECT_NEAR(glm::length(glm::cross(origin - eye, d)), 0.387628, 1e-3);
}

// A right-angled prism (n_o = 1.5, faceted) with its face z = 1 towards the
// camera at (0, 0, 6). Pixel (70, 60) of 161 × 121 at 45°: its ray is
// (x, 0, −1) with x = (2·70.5/161 − 1)·tan 22.5°·161/121 = −0.068465, θ =
// atan 0.068465 = 3.9166° from the face's normal; inside sin θ₂ = sin θ/1.5,
// θ₂ = 2.6100°, heading to −x. At the hypotenuse (outward normal
// (1, 0, −1)/√2) it meets θ₁ = 45° + θ₂ = 47.610°, beyond the critical angle
// asin(1/1.5) = 41.810°: total internal reflection, F = 1, no refracted ray.
TEST(GlassClosedForm, PrismReflectsTotally) {
    Scene scene = axis_scene(6.0f);
    SceneObject p = glass(prism(1.0f), {0.0f, 0.0f, 0.0f});
    p.shading = litkit::Shading::Faceted;
    scene.objects.push_back(p);
    litkit::Renderer renderer(scene);
    const litkit::PixelProbe probe = renderer.probe(70, 60);
    const std::vector<RayNode>& tree = probe.ray_tree;
    ASSERT_FALSE(tree.empty());
    EXPECT_NEAR(tree[0].theta1, 3.9166, 1e-3);
    int total = -1;
    for (std::size_t k = 0; k < tree.size(); ++k)
        if (tree[k].total_internal_reflection) {
            total = int(k);
            break;
        }
    ASSERT_GE(total, 0);
    const RayNode& n = tree[std::size_t(total)];
    EXPECT_EQ(n.fresnel, 1.0f);
    EXPECT_EQ(n.kind, RayNode::Kind::Refracted);
    EXPECT_EQ(n.parent, 0);
    EXPECT_EQ(n.depth, 2);
    EXPECT_TRUE(n.inside);
    EXPECT_NEAR(n.theta1, 47.610, 1e-2);
    int children = 0;
    for (const RayNode& child : tree)
        if (child.parent == total) {
            ++children;
            EXPECT_EQ(child.kind, RayNode::Kind::Reflected);
            EXPECT_TRUE(child.inside);
        }
    EXPECT_EQ(children, 1);
}

// The nodes' shares add up to the pixel's L, for pixels of two scenes.
TEST(GlassClosedForm, SharesAddUpToThePixel) {
    Scene lens = base_scene(80, 60);
    add_cubes(lens, -3.0f);
    lens.objects.push_back(glass(litkit::SphereShape{1.5f, 24, 12}, {0.1f, -0.05f, 1.0f}));
    Scene tinted = lens;
    litkit::Material& m = tinted.objects.back().material;
    m.transmission = 0.7f;
    m.absorption_color = {0.9f, 0.5f, 0.2f};
    m.absorption_distance = 0.5f;
    int probed = 0;
    for (const Scene& scene : {lens, tinted}) {
        litkit::Renderer renderer(scene);
        for (int j = 24; j <= 34; j += 10)
            for (int i = 32; i <= 48; i += 8) {
                const litkit::PixelProbe probe = renderer.probe(i, j);
                if (probe.ray_tree.empty()) continue;
                ++probed;
                glm::dvec3 sum(0.0);
                for (const RayNode& n : probe.ray_tree)
                    sum += glass_reference::to_double(n.contribution);
                for (int c = 0; c < 3; ++c)
                    EXPECT_NEAR(sum[c], probe.intensity[c], 1e-5 * std::abs(probe.intensity[c]))
                        << "pixel (" << i << ", " << j << "), channel " << c;
            }
    }
    EXPECT_EQ(probed, 12);  // every one of them on the glass
}

}  // namespace
