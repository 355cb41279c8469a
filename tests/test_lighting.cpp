// SPDX-License-Identifier: MIT
// Unit tests for the lighting equations of docs/spec.md §4 (IM1–IM4, DD3–DD7, lights,
// pixel value). Every expected value is worked out by hand in the comment
// above its check; none is taken from the code under test.
//
// Most tests use the surface point p = (0, 0, 0) with normal N = (0, 1, 0),
// so that N·X is the y component of X, and place lights and the eye where
// the angles are 0°, 30°, 45°, 60° or 90°.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <glm/trigonometric.hpp>
#include <glm/vec3.hpp>
#include <limits>
#include <span>
#include <string_view>
#include <vector>

#include "litkit/equations.hpp"
#include "litkit/error.hpp"
#include "litkit/lighting.hpp"

namespace {

using litkit::AmbientLight;
using litkit::DirectionalLight;
using litkit::Light;
using litkit::Material;
using litkit::PointLight;
using litkit::Reflection;
using litkit::Shading;
using litkit::SpotLight;

constexpr float tolerance = 1e-5f;

const glm::vec3 origin{0.0f, 0.0f, 0.0f};
const glm::vec3 up{0.0f, 1.0f, 0.0f};
const glm::vec3 white{1.0f, 1.0f, 1.0f};
const float sqrt3 = std::sqrt(3.0f);

// A material whose shininess is α and whose other values are the defaults.
litkit::equations::MaterialT<float> with_shininess(float shininess) {
    Material material;
    material.shininess = shininess;
    return litkit::equations::splat<float>(material);
}

constexpr std::array<Reflection, 4> all_reflections{Reflection::Lambert, Reflection::HalfLambert,
                                                    Reflection::Phong, Reflection::BlinnPhong};

Material make_material(const glm::vec3& color, float ka, float kd, float ks, float shininess) {
    Material material;
    material.color = color;
    material.ka = ka;
    material.kd = kd;
    material.ks = ks;
    material.shininess = shininess;
    return material;
}

Light ambient_light(const glm::vec3& color = white, float intensity = 1.0f) {
    Light light;
    light.kind = AmbientLight{};
    light.color = color;
    light.intensity = intensity;
    return light;
}

Light directional_light(const glm::vec3& direction) {
    DirectionalLight kind;
    kind.direction = direction;
    Light light;
    light.kind = kind;
    return light;
}

Light point_light(const glm::vec3& position, const glm::vec3& attenuation = {0.0f, 0.0f, 1.0f}) {
    PointLight kind;
    kind.position = position;
    kind.attenuation = attenuation;
    Light light;
    light.kind = kind;
    return light;
}

Light spot_light(const glm::vec3& position, const glm::vec3& direction, float cutoff_degrees,
                 float exponent, const glm::vec3& attenuation = {0.0f, 0.0f, 1.0f}) {
    SpotLight kind;
    kind.position = position;
    kind.direction = direction;
    kind.cutoff_degrees = cutoff_degrees;
    kind.exponent = exponent;
    kind.attenuation = attenuation;
    Light light;
    light.kind = kind;
    return light;
}

Light colored(Light light, const glm::vec3& color, float intensity) {
    light.color = color;
    light.intensity = intensity;
    return light;
}

// `shade` with a single light.
glm::vec3 shade_one(Reflection reflection, const Material& material, const Light& light,
                    const glm::vec3& position, const glm::vec3& normal, const glm::vec3& eye) {
    return litkit::shade(reflection, material, std::span<const Light>(&light, 1), position, normal,
                         eye);
}

::testing::AssertionResult color_near(const glm::vec3& actual, const glm::vec3& expected) {
    for (int channel = 0; channel < 3; ++channel) {
        if (!(std::abs(actual[channel] - expected[channel]) <= tolerance)) {
            return ::testing::AssertionFailure()
                   << "got (" << actual.x << ", " << actual.y << ", " << actual.z << "), expected ("
                   << expected.x << ", " << expected.y << ", " << expected.z << "), channel "
                   << channel << " differs by more than " << tolerance;
        }
    }
    return ::testing::AssertionSuccess();
}

glm::vec3 gray(float value) { return {value, value, value}; }

// to_pixel as an int, so that failures print numbers rather than characters.
int pixel(float intensity, float gamma) { return litkit::to_pixel(intensity, gamma); }

}  // namespace

// ============================================================================
// Lambert (IM1): D = max(N·L, 0), S = 0.
// ============================================================================

TEST(Lambert, PointLightDirectlyAboveIsAttenuatedByDistanceSquared) {
    // Light at (0,2,0), p = origin: d = 2, L = (0,1,0), N·L = 1.
    // Default attenuation [0,0,1]: f = 1/(0 + 0·2 + 1·4) = 1/4.
    // I = f·I_L·(k_d·D·C + k_s·S) = 1/4 · 1 · (0.8 · 1 · C + 0.5 · 0)
    //   = 0.2·C = 0.2·(1, 0.5, 0.25) = (0.2, 0.1, 0.05). k_s is ignored (S = 0).
    Material material = make_material({1.0f, 0.5f, 0.25f}, 0.1f, 0.8f, 0.5f, 2.0f);
    glm::vec3 color =
        shade_one(Reflection::Lambert, material, point_light({0, 2, 0}), origin, up, {0, 5, 0});
    EXPECT_TRUE(color_near(color, {0.2f, 0.1f, 0.05f}));
}

TEST(Lambert, DirectionalLightAtSixtyDegreesGivesHalf) {
    // direction = (-√3, -1, 0) (length 2, not unit): L = -normalize(direction)
    // = (√3/2, 1/2, 0), 60° from N, N·L = cos 60° = 0.5. f = 1.
    // I = 1 · 1 · (1 · 0.5 · 1) = 0.5.
    Material material = make_material(white, 0.0f, 1.0f, 0.0f, 2.0f);
    glm::vec3 color = shade_one(Reflection::Lambert, material, directional_light({-sqrt3, -1, 0}),
                                origin, up, {0, 5, 0});
    EXPECT_TRUE(color_near(color, gray(0.5f)));
}

TEST(Lambert, SpotLightOnItsAxisActsAsPointLight) {
    // Spot at (0,2,0) aiming (0,-1,0), cutoff 30°, exponent 0, p = origin:
    // L = (0,1,0), c = -L·axis = 1 ≥ cos 30° ⇒ s = 1^0 = 1; d = 2 ⇒ attenuation 1/4.
    // f = 1/4 · 1; N·L = 1. I = 1/4 · (0.6 · 1 · 1) = 0.15.
    Material material = make_material(white, 0.0f, 0.6f, 0.0f, 2.0f);
    glm::vec3 color = shade_one(Reflection::Lambert, material,
                                spot_light({0, 2, 0}, {0, -1, 0}, 30, 0), origin, up, {0, 5, 0});
    EXPECT_TRUE(color_near(color, gray(0.15f)));
}

TEST(Lambert, LightBehindSurfaceGivesBlack) {
    // Point light at (0,-2,0): L = (0,-1,0), N·L = -1 ⇒ D = max(-1, 0) = 0, S = 0.
    // I = 1/4 · (1·0·C + 1·0) = 0.
    Material material = make_material(white, 0.5f, 1.0f, 1.0f, 2.0f);
    glm::vec3 color =
        shade_one(Reflection::Lambert, material, point_light({0, -2, 0}), origin, up, {0, -5, 0});
    EXPECT_TRUE(color_near(color, gray(0.0f)));
}

TEST(Lambert, GrazingLightGivesBlack) {
    // direction (-1,0,0): L = (1,0,0), N·L = 0 ⇒ D = 0. I = 0.
    Material material = make_material(white, 0.0f, 1.0f, 1.0f, 2.0f);
    glm::vec3 color = shade_one(Reflection::Lambert, material, directional_light({-1, 0, 0}),
                                origin, up, {-1, 0, 0});
    EXPECT_TRUE(color_near(color, gray(0.0f)));
}

// ============================================================================
// Half-Lambert (IM2): D = (0.5·(N·L) + 0.5)², S = 0.
// ============================================================================

TEST(HalfLambert, DirectionalLightAtSixtyDegreesIsWrapped) {
    // L = (√3/2, 1/2, 0), N·L = 0.5 ⇒ D = (0.25 + 0.5)² = 0.5625.
    // I = 1 · (0.8 · 0.5625) = 0.45.
    Material material = make_material(white, 0.0f, 0.8f, 0.0f, 2.0f);
    glm::vec3 color = shade_one(Reflection::HalfLambert, material,
                                directional_light({-sqrt3, -1, 0}), origin, up, {0, 5, 0});
    EXPECT_TRUE(color_near(color, gray(0.45f)));
}

TEST(HalfLambert, BackFaceAtSixtyDegreesStillReceivesLight) {
    // direction (-√3, 1, 0): L = (√3/2, -1/2, 0), N·L = -0.5 (the light is behind).
    // D = (0.5·(-0.5) + 0.5)² = 0.25² = 0.0625. I = 1 · (0.8 · 0.0625) = 0.05.
    Material material = make_material(white, 0.0f, 0.8f, 0.0f, 2.0f);
    glm::vec3 color = shade_one(Reflection::HalfLambert, material,
                                directional_light({-sqrt3, 1, 0}), origin, up, {0, 5, 0});
    EXPECT_TRUE(color_near(color, gray(0.05f)));
}

TEST(HalfLambert, BackFaceLitByPointLightBelow) {
    // Point light at (√3, -1, 0): d = √(3 + 1) = 2 ⇒ f = 1/4; L = (√3/2, -1/2, 0),
    // N·L = -0.5 ⇒ D = 0.0625. I = 1/4 · 1 · 0.0625 = 0.015625.
    Material material = make_material(white, 0.0f, 1.0f, 0.0f, 2.0f);
    glm::vec3 color = shade_one(Reflection::HalfLambert, material, point_light({sqrt3, -1, 0}),
                                origin, up, {0, 5, 0});
    EXPECT_TRUE(color_near(color, gray(0.015625f)));
}

TEST(HalfLambert, LightExactlyOppositeTheNormalGivesBlack) {
    // direction (0,1,0): L = (0,-1,0), N·L = -1 ⇒ D = (-0.5 + 0.5)² = 0.
    Material material = make_material(white, 0.0f, 1.0f, 0.0f, 2.0f);
    glm::vec3 color = shade_one(Reflection::HalfLambert, material, directional_light({0, 1, 0}),
                                origin, up, {0, 5, 0});
    EXPECT_TRUE(color_near(color, gray(0.0f)));
}

TEST(HalfLambert, GrazingLightGivesAQuarter) {
    // L = (1,0,0), N·L = 0 ⇒ D = 0.5² = 0.25 (Lambert would give 0). I = 1 · 0.25.
    Material material = make_material(white, 0.0f, 1.0f, 0.0f, 2.0f);
    glm::vec3 color = shade_one(Reflection::HalfLambert, material, directional_light({-1, 0, 0}),
                                origin, up, {0, 5, 0});
    EXPECT_TRUE(color_near(color, gray(0.25f)));
}

TEST(HalfLambert, HasNoSpecularEvenWithEyeAlongReflection) {
    // Point light at (0,2,0): f = 1/4, N·L = 1 ⇒ D = (0.5 + 0.5)² = 1. Eye at (0,3,0)
    // lies on R = N, but S = 0 for half-Lambert, so k_s = 1 adds nothing.
    // I = 1/4 · (0.5 · 1 · 1 + 1 · 0) = 0.125.
    Material material = make_material(white, 0.0f, 0.5f, 1.0f, 1.0f);
    glm::vec3 color =
        shade_one(Reflection::HalfLambert, material, point_light({0, 2, 0}), origin, up, {0, 3, 0});
    EXPECT_TRUE(color_near(color, gray(0.125f)));
}

TEST(HalfLambert, SpotLightOffAxisWithExponent) {
    // Spot at (0,1,0) aiming (0,-1,0), cutoff 60°, exponent 2; p = (1,0,0).
    // p→light = (-1,1,0), d = √2, L = (-1,1,0)/√2. c = -L·axis = 1/√2 ≥ cos 60° = 0.5
    // ⇒ s = (1/√2)² = 0.5. Attenuation 1/d² = 0.5 ⇒ f = 0.25.
    // N·L = 1/√2 ⇒ D = (0.5/√2 + 0.5)² = 0.25·(1 + 1/√2)² = 0.25·(1.5 + √2)
    //   = 0.25 · 2.9142136 = 0.7285534.
    // I = 0.25 · 0.7285534 = 0.1821383.
    Material material = make_material(white, 0.0f, 1.0f, 0.0f, 2.0f);
    glm::vec3 color = shade_one(Reflection::HalfLambert, material,
                                spot_light({0, 1, 0}, {0, -1, 0}, 60, 2), {1, 0, 0}, up, {1, 5, 0});
    EXPECT_TRUE(color_near(color, gray(0.1821383f)));
}

TEST(HalfLambert, SpotLightPastCutoffGivesBlackDespiteWrappedDiffuse) {
    // Spot at (0,1,0) aiming down, cutoff 45°; p = (1.001,0,0) is 45.03° off the axis:
    // c = 1/√(1.001² + 1) = 1/√2.002001 = 0.706753 < cos 45° = 0.707107 ⇒ s = 0 ⇒ f = 0.
    // D would be about 0.73, but f = 0 ⇒ I = 0.
    Material material = make_material(white, 0.0f, 1.0f, 0.0f, 2.0f);
    glm::vec3 color =
        shade_one(Reflection::HalfLambert, material, spot_light({0, 1, 0}, {0, -1, 0}, 45, 0),
                  {1.001f, 0, 0}, up, {1, 5, 0});
    EXPECT_TRUE(color_near(color, gray(0.0f)));
}

// ============================================================================
// Phong (IM3): D = max(N·L, 0), S = max(R·V, 0)^α, R = 2(N·L)N − L, S = 0 where N·L ≤ 0.
// ============================================================================

TEST(Phong, PointLightWithEyeAlongReflectionAddsWhiteHighlight) {
    // Light at (0,2,0): f = 1/4, L = (0,1,0), N·L = 1, R = 2N − L = (0,1,0).
    // Eye at (0,5,0): V = (0,1,0), R·V = 1 ⇒ S = 1² = 1.
    // I = 1/4 · (0.5 · 1 · C + 0.4 · 1) with C = (1, 0.5, 0)
    //   = 1/4 · (0.9, 0.65, 0.4) = (0.225, 0.1625, 0.1).
    Material material = make_material({1.0f, 0.5f, 0.0f}, 0.0f, 0.5f, 0.4f, 2.0f);
    glm::vec3 color =
        shade_one(Reflection::Phong, material, point_light({0, 2, 0}), origin, up, {0, 5, 0});
    EXPECT_TRUE(color_near(color, {0.225f, 0.1625f, 0.1f}));
}

TEST(Phong, PointLightAtSixtyDegreesWithEyeOnReflection) {
    // Light at (√3,1,0): d = 2 ⇒ f = 1/4; L = (√3/2, 1/2, 0), N·L = 0.5.
    // R = 2·0.5·N − L = (-√3/2, 1/2, 0). Eye at (-2√3, 2, 0) ⇒ V = (-√3/2, 1/2, 0) = R,
    // R·V = 1 ⇒ S = 1. I = 1/4 · (1 · 0.5 + 1 · 1) = 0.375.
    Material material = make_material(white, 0.0f, 1.0f, 1.0f, 2.0f);
    glm::vec3 color = shade_one(Reflection::Phong, material, point_light({sqrt3, 1, 0}), origin, up,
                                {-2 * sqrt3, 2, 0});
    EXPECT_TRUE(color_near(color, gray(0.375f)));
}

TEST(Phong, DirectionalLightAtSixtyDegreesWithEyeOnReflection) {
    // L = (√3/2, 1/2, 0), N·L = 0.5, R = (-√3/2, 1/2, 0); eye at (-√3,1,0) ⇒ V = R, S = 1.
    // C = (1, 0.5, 0): I = 0.6·0.5·C + 0.3·1 = (0.3, 0.15, 0) + 0.3 = (0.6, 0.45, 0.3).
    Material material = make_material({1.0f, 0.5f, 0.0f}, 0.0f, 0.6f, 0.3f, 2.0f);
    glm::vec3 color = shade_one(Reflection::Phong, material, directional_light({-sqrt3, -1, 0}),
                                origin, up, {-sqrt3, 1, 0});
    EXPECT_TRUE(color_near(color, {0.6f, 0.45f, 0.3f}));
}

TEST(Phong, SpecularIsReflectionDotEyeSquaredForShininessTwo) {
    // direction (0,-3,0): L = N, R = N. Eye at (√3,1,0): V = (√3/2, 1/2, 0), R·V = 0.5.
    // α = 2 ⇒ S = 0.25. D = 1. I = 0.4 · 1 + 0.8 · 0.25 = 0.6.
    Material material = make_material(white, 0.0f, 0.4f, 0.8f, 2.0f);
    glm::vec3 color = shade_one(Reflection::Phong, material, directional_light({0, -3, 0}), origin,
                                up, {sqrt3, 1, 0});
    EXPECT_TRUE(color_near(color, gray(0.6f)));
}

TEST(Phong, SpecularFollowsShininessExponent) {
    // Same geometry, R·V = 0.5; k_d = 0, k_s = 1 so I = S = 0.5^α:
    // α = 1 ⇒ 0.5; α = 3 ⇒ 0.125; α = 10 ⇒ 1/1024 = 0.0009765625.
    Light light = directional_light({0, -3, 0});
    glm::vec3 eye{sqrt3, 1, 0};
    EXPECT_TRUE(color_near(
        shade_one(Reflection::Phong, make_material(white, 0, 0, 1, 1), light, origin, up, eye),
        gray(0.5f)));
    EXPECT_TRUE(color_near(
        shade_one(Reflection::Phong, make_material(white, 0, 0, 1, 3), light, origin, up, eye),
        gray(0.125f)));
    EXPECT_TRUE(color_near(
        shade_one(Reflection::Phong, make_material(white, 0, 0, 1, 10), light, origin, up, eye),
        gray(0.0009765625f)));
}

TEST(Phong, SpotLightOnAxisWithNonUnitDirection) {
    // Spot at (0,2,0), direction (0,-2,0) (normalised to (0,-1,0)), cutoff 30°, exponent 5.
    // p = origin: L = (0,1,0), c = 1 ⇒ s = 1^5 = 1; d = 2 ⇒ f = 1/4.
    // Eye at (0,4,0): R = V = N ⇒ S = 1. C = (1,0,0):
    // I = 1/4 · (0.5 · 1 · C + 0.5 · 1) = 1/4 · (1, 0.5, 0.5) = (0.25, 0.125, 0.125).
    Material material = make_material({1.0f, 0.0f, 0.0f}, 0.0f, 0.5f, 0.5f, 8.0f);
    glm::vec3 color = shade_one(Reflection::Phong, material,
                                spot_light({0, 2, 0}, {0, -2, 0}, 30, 5), origin, up, {0, 4, 0});
    EXPECT_TRUE(color_near(color, {0.25f, 0.125f, 0.125f}));
}

TEST(Phong, SpecularIsZeroWhenLightIsBehindSurface) {
    // direction (0,1,0): L = (0,-1,0), N·L = -1. R = 2(-1)N − L = (0,-1,0); eye at
    // (0,-5,0) gives V = (0,-1,0), R·V = 1, yet N·L ≤ 0 ⇒ S = 0, and D = 0. I = 0.
    Material material = make_material(white, 0.0f, 1.0f, 1.0f, 2.0f);
    glm::vec3 color = shade_one(Reflection::Phong, material, directional_light({0, 1, 0}), origin,
                                up, {0, -5, 0});
    EXPECT_TRUE(color_near(color, gray(0.0f)));
}

TEST(Phong, SpecularIsZeroForGrazingLight) {
    // L = (1,0,0), N·L = 0 ⇒ R = 0·N − L = (-1,0,0). Eye at (-1,0,0): R·V = 1 > 0, but
    // N·L ≤ 0 (equality) ⇒ S = 0, D = 0. I = 0.
    Material material = make_material(white, 0.0f, 1.0f, 1.0f, 0.0f);
    glm::vec3 color = shade_one(Reflection::Phong, material, directional_light({-1, 0, 0}), origin,
                                up, {-1, 0, 0});
    EXPECT_TRUE(color_near(color, gray(0.0f)));
}

TEST(Phong, NegativeReflectionDotEyeIsClampedBeforeEvenPower) {
    // L = N, R = N. Eye at (1,-1,0): V = (1,-1,0)/√2, R·V = -1/√2. max(-0.707, 0) = 0
    // ⇒ S = 0 (an unclamped square would give 0.5). D = 1. I = 0.5 · 1 + 1 · 0 = 0.5.
    Material material = make_material(white, 0.0f, 0.5f, 1.0f, 2.0f);
    glm::vec3 color = shade_one(Reflection::Phong, material, directional_light({0, -1, 0}), origin,
                                up, {1, -1, 0});
    EXPECT_TRUE(color_near(color, gray(0.5f)));
}

TEST(Phong, ZeroShininessGivesFullSpecularWhereReflectionDotEyeIsPositive) {
    // L = N, R = N. Eye at (1, 0.01, 0): R·V = 0.01/√1.0001 ≈ 0.0099995 > 0
    // ⇒ S = (0.0099995)^0 = 1. k_d = 0 ⇒ I = 0.5 · 1 = 0.5.
    Material material = make_material(white, 0.0f, 0.0f, 0.5f, 0.0f);
    glm::vec3 color = shade_one(Reflection::Phong, material, directional_light({0, -1, 0}), origin,
                                up, {1, 0.01f, 0});
    EXPECT_TRUE(color_near(color, gray(0.5f)));
}

TEST(Phong, ZeroShininessGivesNoSpecularWhereReflectionDotEyeIsZero) {
    // L = N, R = N. Eye at (1,0,0): V = (1,0,0), R·V = 0 exactly. docs/spec.md §4:
    // S = 0 where the base is ≤ 0 whatever α, never 0^0 = 1. k_d = 0 ⇒ I = 0.
    Material material = make_material(white, 0.0f, 0.0f, 0.5f, 0.0f);
    glm::vec3 color = shade_one(Reflection::Phong, material, directional_light({0, -1, 0}), origin,
                                up, {1, 0, 0});
    EXPECT_TRUE(color_near(color, gray(0.0f)));
}

TEST(Phong, ZeroShininessGivesNoSpecularWhereReflectionDotEyeIsNegative) {
    // L = N, R = N. Eye at (1,-1,0): R·V = -1/√2 < 0 ⇒ S = 0 (sharp edge of the lobe).
    Material material = make_material(white, 0.0f, 0.0f, 0.5f, 0.0f);
    glm::vec3 color = shade_one(Reflection::Phong, material, directional_light({0, -1, 0}), origin,
                                up, {1, -1, 0});
    EXPECT_TRUE(color_near(color, gray(0.0f)));
}

TEST(Phong, SpecularTakesTheLightColourNotTheMaterialColour) {
    // direction (0,-1,0): L = N = R; eye at (0,1,0): V = N, R·V = 1 ⇒ S = 1, D = 1.
    // I_L = 1 · (1, 0.5, 0.25); C = (0, 1, 0), k_d = 0.4, k_s = 0.5:
    // k_d·D·C + k_s·S = (0, 0.4, 0) + 0.5 = (0.5, 0.9, 0.5)
    // I = I_L · (0.5, 0.9, 0.5) = (0.5, 0.45, 0.125).
    // (Had the highlight taken C, red and blue would be 0.)
    Material material = make_material({0.0f, 1.0f, 0.0f}, 0.0f, 0.4f, 0.5f, 2.0f);
    Light light = colored(directional_light({0, -1, 0}), {1.0f, 0.5f, 0.25f}, 1.0f);
    glm::vec3 color = shade_one(Reflection::Phong, material, light, origin, up, {0, 1, 0});
    EXPECT_TRUE(color_near(color, {0.5f, 0.45f, 0.125f}));
}

// ============================================================================
// Blinn-Phong (IM4): D = max(N·L, 0), S = max(N·H, 0)^α, H = normalize(L + V),
// S = 0 where N·L ≤ 0.
// ============================================================================

TEST(BlinnPhong, PointLightWithEyeAboveAddsWhiteHighlight) {
    // Light at (0,2,0): f = 1/4, L = (0,1,0). Eye at (0,5,0): V = (0,1,0), H = N ⇒ S = 1.
    // C = (0, 1, 0.5): I = 1/4 · (0.3·C + 0.6) = 1/4 · (0.6, 0.9, 0.75)
    //   = (0.15, 0.225, 0.1875).
    Material material = make_material({0.0f, 1.0f, 0.5f}, 0.0f, 0.3f, 0.6f, 16.0f);
    glm::vec3 color =
        shade_one(Reflection::BlinnPhong, material, point_light({0, 2, 0}), origin, up, {0, 5, 0});
    EXPECT_TRUE(color_near(color, {0.15f, 0.225f, 0.1875f}));
}

TEST(BlinnPhong, DirectionalLightWithMirroredEyeHasHalfwayAlongNormal) {
    // L = (√3/2, 1/2, 0) (direction (-√3,-1,0)); eye at (-√3,1,0): V = (-√3/2, 1/2, 0).
    // L + V = (0,1,0) ⇒ H = N, N·H = 1 ⇒ S = 1 (any α). N·L = 0.5.
    // I = 1 · 0.5 · 1 + 0.5 · 1 = 1.0 (unclamped).
    Material material = make_material(white, 0.0f, 1.0f, 0.5f, 10.0f);
    glm::vec3 color = shade_one(Reflection::BlinnPhong, material,
                                directional_light({-sqrt3, -1, 0}), origin, up, {-sqrt3, 1, 0});
    EXPECT_TRUE(color_near(color, gray(1.0f)));
}

TEST(BlinnPhong, HalfwayAtThirtyDegreesGivesThreeQuartersForShininessTwo) {
    // L = N (direction (0,-1,0)). Eye at (√3,1,0): V = (√3/2, 1/2, 0).
    // L + V = (√3/2, 3/2, 0), |L + V| = √(3/4 + 9/4) = √3 ⇒ H = (1/2, √3/2, 0).
    // N·H = √3/2 ⇒ S = (√3/2)² = 0.75. D = 1. I = 0.2 · 1 + 1 · 0.75 = 0.95.
    // (Phong at the same geometry would have R·V = 0.5, S = 0.25.)
    Material material = make_material(white, 0.0f, 0.2f, 1.0f, 2.0f);
    glm::vec3 color = shade_one(Reflection::BlinnPhong, material, directional_light({0, -1, 0}),
                                origin, up, {sqrt3, 1, 0});
    EXPECT_TRUE(color_near(color, gray(0.95f)));
}

TEST(BlinnPhong, SpotLightOffAxisWithHalfwayAlongNormal) {
    // Spot at (0,1,0) aiming (0,-1,0), cutoff 60°, exponent 2; p = (1,0,0).
    // L = (-1,1,0)/√2, d = √2 ⇒ attenuation 1/2; c = 1/√2 ≥ 0.5 ⇒ s = 1/2 ⇒ f = 1/4.
    // Eye at (2,1,0): V = (1,1,0)/√2; L + V = (0, √2, 0) ⇒ H = N ⇒ S = 1. D = 1/√2.
    // I = 1/4 · (1 · 0.7071068 + 1 · 1) = 0.4267767.
    Material material = make_material(white, 0.0f, 1.0f, 1.0f, 8.0f);
    glm::vec3 color = shade_one(Reflection::BlinnPhong, material,
                                spot_light({0, 1, 0}, {0, -1, 0}, 60, 2), {1, 0, 0}, up, {2, 1, 0});
    EXPECT_TRUE(color_near(color, gray(0.4267767f)));
}

TEST(BlinnPhong, SpecularIsZeroWhenLightIsBehindSurface) {
    // direction (-1,1,0): L = (1,-1,0)/√2, N·L = -1/√2 ≤ 0. Eye at (0,3,0): V = (0,1,0);
    // L + V = (0.707, 0.293, 0) so N·H > 0, yet S = 0 because N·L ≤ 0; D = 0. I = 0.
    Material material = make_material(white, 0.0f, 1.0f, 1.0f, 1.0f);
    glm::vec3 color = shade_one(Reflection::BlinnPhong, material, directional_light({-1, 1, 0}),
                                origin, up, {0, 3, 0});
    EXPECT_TRUE(color_near(color, gray(0.0f)));
}

TEST(BlinnPhong, ZeroShininessGivesFullSpecularWhereNormalDotHalfwayIsPositive) {
    // L = N. Eye at (1,0,0): V = (1,0,0), H = (1,1,0)/√2, N·H = 0.707 > 0 ⇒ S = 1.
    // D = 1. I = 0.25 · 1 + 0.5 · 1 = 0.75.
    Material material = make_material(white, 0.0f, 0.25f, 0.5f, 0.0f);
    glm::vec3 color = shade_one(Reflection::BlinnPhong, material, directional_light({0, -1, 0}),
                                origin, up, {1, 0, 0});
    EXPECT_TRUE(color_near(color, gray(0.75f)));
}

TEST(BlinnPhong, ZeroShininessGivesNoSpecularWhereNormalDotHalfwayIsNegative) {
    // direction (-1,-1,0): L = (1,1,0)/√2, N·L = 0.7071068. Eye below at (0,-3,0):
    // V = (0,-1,0); L + V = (0.707, -0.293, 0) ⇒ N·H < 0 ⇒ S = 0 even with α = 0.
    // I = 1 · 0.7071068 + 1 · 0 = 0.7071068.
    Material material = make_material(white, 0.0f, 1.0f, 1.0f, 0.0f);
    glm::vec3 color = shade_one(Reflection::BlinnPhong, material, directional_light({-1, -1, 0}),
                                origin, up, {0, -3, 0});
    EXPECT_TRUE(color_near(color, gray(0.7071068f)));
}

// ============================================================================
// Ambient lights: k_a · C · I_L, independent of N, V and the reflection model.
// ============================================================================

TEST(AmbientLight, GivesAmbientCoefficientTimesColourTimesRadiance) {
    // k_a = 0.2, C = (1, 0.5, 0), I_L = 2 · (1, 1, 0.5) = (2, 2, 1).
    // I = 0.2 · (1·2, 0.5·2, 0·1) = (0.4, 0.2, 0). k_d, k_s play no part.
    Material material = make_material({1.0f, 0.5f, 0.0f}, 0.2f, 0.9f, 0.9f, 2.0f);
    glm::vec3 color = shade_one(Reflection::Lambert, material,
                                ambient_light({1.0f, 1.0f, 0.5f}, 2.0f), origin, up, {0, 5, 0});
    EXPECT_TRUE(color_near(color, {0.4f, 0.2f, 0.0f}));
}

TEST(AmbientLight, IgnoresTheNormal) {
    // k_a = 0.3, C = (1, 0.5, 0.2), I_L = 2: I = 0.6 · C = (0.6, 0.3, 0.12) whether the
    // normal faces up, down (a back face) or sideways.
    Material material = make_material({1.0f, 0.5f, 0.2f}, 0.3f, 1.0f, 1.0f, 2.0f);
    Light light = ambient_light(white, 2.0f);
    const glm::vec3 expected{0.6f, 0.3f, 0.12f};
    for (glm::vec3 normal : {glm::vec3{0, 1, 0}, glm::vec3{0, -1, 0}, glm::vec3{1, 0, 0}}) {
        SCOPED_TRACE(::testing::Message()
                     << "normal (" << normal.x << ", " << normal.y << ", " << normal.z << ")");
        EXPECT_TRUE(color_near(
            shade_one(Reflection::Lambert, material, light, origin, normal, {0, 5, 0}), expected));
    }
}

TEST(AmbientLight, IsTheSameForEveryReflectionModel) {
    // k_a = 0.5, C = (0.2, 0.4, 0.8), I_L = 1: I = (0.1, 0.2, 0.4) for all four models,
    // with the eye placed where Phong/Blinn-Phong would otherwise see a highlight.
    Material material = make_material({0.2f, 0.4f, 0.8f}, 0.5f, 1.0f, 1.0f, 2.0f);
    for (Reflection reflection : all_reflections) {
        SCOPED_TRACE(litkit::to_string(reflection));
        EXPECT_TRUE(
            color_near(shade_one(reflection, material, ambient_light(), origin, up, {0, 5, 0}),
                       {0.1f, 0.2f, 0.4f}));
    }
}

// ============================================================================
// Directional lights: L = −normalize(direction), f = 1.
// ============================================================================

TEST(DirectionalLight, DirectionNeedNotBeUnitLength) {
    // (0,-7,0) and (0,-1,0) both normalise to (0,-1,0): L = N, D = 1 ⇒ I = k_d = 0.7.
    Material material = make_material(white, 0.0f, 0.7f, 0.0f, 2.0f);
    EXPECT_TRUE(color_near(shade_one(Reflection::Lambert, material, directional_light({0, -7, 0}),
                                     origin, up, {0, 5, 0}),
                           gray(0.7f)));
    EXPECT_TRUE(color_near(shade_one(Reflection::Lambert, material, directional_light({0, -1, 0}),
                                     origin, up, {0, 5, 0}),
                           gray(0.7f)));
}

TEST(DirectionalLight, HasNoDistanceFalloff) {
    // f = 1 wherever p is: at p = (100, -50, 3) with N = (0,1,0) and L = N, I = k_d = 0.7.
    Material material = make_material(white, 0.0f, 0.7f, 0.0f, 2.0f);
    glm::vec3 color = shade_one(Reflection::Lambert, material, directional_light({0, -1, 0}),
                                {100, -50, 3}, up, {100, 0, 3});
    EXPECT_TRUE(color_near(color, gray(0.7f)));
}

// ============================================================================
// Point lights: f = 1 / (k_c + k_l·d + k_q·d²).
// ============================================================================

TEST(PointLight, OffAxisAtSixtyDegrees) {
    // Light at (√3,1,0): d = 2 ⇒ f = 1/4; L = (√3/2, 1/2, 0), N·L = 0.5.
    // I = 1/4 · 0.5 = 0.125.
    Material material = make_material(white, 0.0f, 1.0f, 0.0f, 2.0f);
    glm::vec3 color =
        shade_one(Reflection::Lambert, material, point_light({sqrt3, 1, 0}), origin, up, {0, 5, 0});
    EXPECT_TRUE(color_near(color, gray(0.125f)));
}

TEST(PointLight, AllThreeAttenuationCoefficientsAreApplied) {
    // Light at (0,2,0), attenuation [1, 0.5, 0.25]: 1 + 0.5·2 + 0.25·4 = 3 ⇒ f = 1/3.
    // I = 1/3 · 1 · 1 = 0.3333333.
    Material material = make_material(white, 0.0f, 1.0f, 0.0f, 2.0f);
    glm::vec3 color = shade_one(Reflection::Lambert, material,
                                point_light({0, 2, 0}, {1.0f, 0.5f, 0.25f}), origin, up, {0, 5, 0});
    EXPECT_TRUE(color_near(color, gray(1.0f / 3.0f)));
}

TEST(PointLight, ConstantAttenuationIgnoresDistance) {
    // Light at (0,10,0), attenuation [1,0,0]: f = 1/1 = 1 at d = 10. I = 0.7.
    Material material = make_material(white, 0.0f, 0.7f, 0.0f, 2.0f);
    glm::vec3 color = shade_one(Reflection::Lambert, material,
                                point_light({0, 10, 0}, {1.0f, 0.0f, 0.0f}), origin, up, {0, 5, 0});
    EXPECT_TRUE(color_near(color, gray(0.7f)));
}

TEST(PointLight, LinearAttenuationDividesByDistance) {
    // Light at (0,4,0), attenuation [0,1,0]: f = 1/4. I = 1/4 · 1 = 0.25.
    Material material = make_material(white, 0.0f, 1.0f, 0.0f, 2.0f);
    glm::vec3 color = shade_one(Reflection::Lambert, material,
                                point_light({0, 4, 0}, {0.0f, 1.0f, 0.0f}), origin, up, {0, 5, 0});
    EXPECT_TRUE(color_near(color, gray(0.25f)));
}

TEST(PointLight, SmallConstantAttenuationBrightens) {
    // Light at (0,3,0), attenuation [0.5,0,0]: f = 1/0.5 = 2. I = 2 · 0.25 = 0.5.
    Material material = make_material(white, 0.0f, 0.25f, 0.0f, 2.0f);
    glm::vec3 color = shade_one(Reflection::Lambert, material,
                                point_light({0, 3, 0}, {0.5f, 0.0f, 0.0f}), origin, up, {0, 5, 0});
    EXPECT_TRUE(color_near(color, gray(0.5f)));
}

TEST(PointLight, ColourAndIntensityScaleRadiance) {
    // Light at (0,1,0): d = 1, f = 1, N·L = 1. I_L = 3 · (1, 0.5, 0.2) = (3, 1.5, 0.6).
    // C = (0.2, 1, 0.5), k_d = 0.5: I = I_L · 0.5 · C = (3·0.1, 1.5·0.5, 0.6·0.25)
    //   = (0.3, 0.75, 0.15).
    Material material = make_material({0.2f, 1.0f, 0.5f}, 0.0f, 0.5f, 0.0f, 2.0f);
    Light light = colored(point_light({0, 1, 0}), {1.0f, 0.5f, 0.2f}, 3.0f);
    glm::vec3 color = shade_one(Reflection::Lambert, material, light, origin, up, {0, 5, 0});
    EXPECT_TRUE(color_near(color, {0.3f, 0.75f, 0.15f}));
}

TEST(PointLight, ZeroIntensityGivesBlack) {
    // I_L = 0 ⇒ every term is 0, including the highlight.
    Material material = make_material(white, 1.0f, 1.0f, 1.0f, 2.0f);
    Light light = colored(point_light({0, 2, 0}), white, 0.0f);
    glm::vec3 color = shade_one(Reflection::Phong, material, light, origin, up, {0, 5, 0});
    EXPECT_TRUE(color_near(color, gray(0.0f)));
}

// ============================================================================
// Spot lights: f = attenuation × s, c = −L·normalize(direction),
// s = c^exponent if c ≥ cos(cutoff) (0^0 = 1), else 0.
// ============================================================================

TEST(SpotLight, PointExactlyOnTheFortyFiveDegreeConeIsInside) {
    // Spot at (0,1,0) aiming (0,-1,0), cutoff 45°, exponent 0; p = (1,0,0).
    // L = (-1,1,0)/√2, c = 1/√2 = cos 45°: on the boundary, which is inclusive ⇒ s = 1.
    // d = √2 ⇒ f = 1/2; N·L = 1/√2. I = 0.5 · 0.7071068 = 0.3535534.
    Material material = make_material(white, 0.0f, 1.0f, 0.0f, 2.0f);
    glm::vec3 color = shade_one(Reflection::Lambert, material,
                                spot_light({0, 1, 0}, {0, -1, 0}, 45, 0), {1, 0, 0}, up, {1, 5, 0});
    EXPECT_TRUE(color_near(color, gray(0.3535534f)));
}

TEST(SpotLight, PointExactlyOnTheSixtyDegreeConeIsInside) {
    // Spot at (0,1,0) aiming down, cutoff 60°; p = (√3,0,0): p→light = (-√3,1,0), d = 2,
    // L = (-√3/2, 1/2, 0), c = 1/2 = cos 60° ⇒ inside, s = 1. f = 1/4, N·L = 0.5.
    // I = 1/4 · 0.5 = 0.125.
    Material material = make_material(white, 0.0f, 1.0f, 0.0f, 2.0f);
    glm::vec3 color =
        shade_one(Reflection::Lambert, material, spot_light({0, 1, 0}, {0, -1, 0}, 60, 0),
                  {sqrt3, 0, 0}, up, {sqrt3, 5, 0});
    EXPECT_TRUE(color_near(color, gray(0.125f)));
}

TEST(SpotLight, PointJustPastTheCutoffIsDark) {
    // Cutoff 45°, p = (1.001,0,0): c = 1/√2.002001 = 0.706753 < 0.707107 ⇒ s = 0.
    // (The gap, 3.5e-4, is far wider than the 1e-6 boundary slack.) I = 0.
    Material material = make_material(white, 0.0f, 1.0f, 1.0f, 2.0f);
    glm::vec3 color =
        shade_one(Reflection::Lambert, material, spot_light({0, 1, 0}, {0, -1, 0}, 45, 0),
                  {1.001f, 0, 0}, up, {1, 5, 0});
    EXPECT_TRUE(color_near(color, gray(0.0f)));
}

TEST(SpotLight, PointWellOutsideTheConeIsDarkButAmbientRemains) {
    // Cutoff 30°, p = (1,0,0) is 45° off the axis: c = 0.707 < cos 30° = 0.866 ⇒ s = 0.
    // Only the ambient light (k_a = 0.1, I_L = 1, C = 1) remains: I = 0.1.
    Material material = make_material(white, 0.1f, 1.0f, 1.0f, 2.0f);
    std::vector<Light> lights{spot_light({0, 1, 0}, {0, -1, 0}, 30, 0), ambient_light()};
    glm::vec3 color = litkit::shade(Reflection::Phong, material, lights, {1, 0, 0}, up, {2, 1, 0});
    EXPECT_TRUE(color_near(color, gray(0.1f)));
}

TEST(SpotLight, ExponentRaisesConeCosine) {
    // Spot at (0,1,0) aiming down, cutoff 60°, exponent 3; p = (1,0,0).
    // c = 1/√2 ⇒ s = (1/√2)³ = 0.3535534; attenuation 1/d² = 1/2; N·L = 1/√2.
    // I = 1/2 · (1/√2)³ · 1/√2 = 1/2 · 1/4 = 0.125.
    Material material = make_material(white, 0.0f, 1.0f, 0.0f, 2.0f);
    glm::vec3 color = shade_one(Reflection::Lambert, material,
                                spot_light({0, 1, 0}, {0, -1, 0}, 60, 3), {1, 0, 0}, up, {1, 5, 0});
    EXPECT_TRUE(color_near(color, gray(0.125f)));
}

TEST(SpotLight, ExponentAppliesAtTheCutoffBoundary) {
    // As the 45° boundary case but exponent 2: s = (1/√2)² = 0.5.
    // I = 1/2 · 0.5 · 1/√2 = 0.1767767.
    Material material = make_material(white, 0.0f, 1.0f, 0.0f, 2.0f);
    glm::vec3 color = shade_one(Reflection::Lambert, material,
                                spot_light({0, 1, 0}, {0, -1, 0}, 45, 2), {1, 0, 0}, up, {1, 5, 0});
    EXPECT_TRUE(color_near(color, gray(0.1767767f)));
}

TEST(SpotLight, UsesItsAttenuationCoefficients) {
    // Spot at (0,1,0) aiming down, attenuation [0,1,0], cutoff 60°, exponent 2; p = (1,0,0).
    // d = √2 ⇒ attenuation 1/√2; s = (1/√2)² = 1/2; N·L = 1/√2.
    // I = 1/√2 · 1/2 · 1/√2 = 0.25.
    Material material = make_material(white, 0.0f, 1.0f, 0.0f, 2.0f);
    glm::vec3 color = shade_one(Reflection::Lambert, material,
                                spot_light({0, 1, 0}, {0, -1, 0}, 60, 2, {0.0f, 1.0f, 0.0f}),
                                {1, 0, 0}, up, {1, 5, 0});
    EXPECT_TRUE(color_near(color, gray(0.25f)));
}

TEST(SpotLight, NinetyDegreeCutoffIncludesTheHorizonWithZeroToTheZeroAsOne) {
    // Spot at (0,1,0) aiming (0,-1,0), cutoff 90°, exponent 0. p = (1,1,0), N = (-1,0,0):
    // p→light = (-1,0,0), d = 1, f_att = 1; L = (-1,0,0), c = -L·axis = 0 ≥ cos 90° = 0
    // ⇒ s = 0^0 = 1. N·L = 1. I = 1 · 1 · 1 = 1.
    Material material = make_material(white, 0.0f, 1.0f, 0.0f, 2.0f);
    glm::vec3 color =
        shade_one(Reflection::Lambert, material, spot_light({0, 1, 0}, {0, -1, 0}, 90, 0),
                  {1, 1, 0}, {-1, 0, 0}, {-5, 1, 0});
    EXPECT_TRUE(color_near(color, gray(1.0f)));
}

TEST(SpotLight, NinetyDegreeCutoffWithExponentIsDarkAtTheHorizon) {
    // Same as above with exponent 2: s = 0² = 0 ⇒ I = 0.
    Material material = make_material(white, 0.0f, 1.0f, 0.0f, 2.0f);
    glm::vec3 color =
        shade_one(Reflection::Lambert, material, spot_light({0, 1, 0}, {0, -1, 0}, 90, 2),
                  {1, 1, 0}, {-1, 0, 0}, {-5, 1, 0});
    EXPECT_TRUE(color_near(color, gray(0.0f)));
}

TEST(SpotLight, NinetyDegreeCutoffExcludesPointsBehindTheSpot) {
    // Spot at (0,1,0) aiming (0,-1,0), cutoff 90°. p = (0,2,0), N = (0,-1,0) facing it:
    // L = (0,-1,0), N·L = 1, but c = -L·axis = -1 < cos 90° = 0 ⇒ s = 0. I = 0.
    Material material = make_material(white, 0.0f, 1.0f, 0.0f, 2.0f);
    glm::vec3 color =
        shade_one(Reflection::Lambert, material, spot_light({0, 1, 0}, {0, -1, 0}, 90, 0),
                  {0, 2, 0}, {0, -1, 0}, {0, -5, 0});
    EXPECT_TRUE(color_near(color, gray(0.0f)));
}

// ============================================================================
// Several lights: I is the sum over lights.
// ============================================================================

TEST(SeveralLights, ContributionsSum) {
    // Lambert, C = (1, 0.5, 0.25), k_a = 0.2, k_d = 0.8.
    //   ambient, I_L = 0.5:          0.2 · C · 0.5        = 0.1·C
    //   point at (0,2,0), f = 1/4:   1/4 · 0.8 · 1 · C    = 0.2·C
    //   directional at 60°, D = 0.5: 1 · 0.8 · 0.5 · C    = 0.4·C
    // I = 0.7·C = (0.7, 0.35, 0.175).
    Material material = make_material({1.0f, 0.5f, 0.25f}, 0.2f, 0.8f, 0.0f, 2.0f);
    std::vector<Light> lights{ambient_light(white, 0.5f), point_light({0, 2, 0}),
                              directional_light({-sqrt3, -1, 0})};
    glm::vec3 color = litkit::shade(Reflection::Lambert, material, lights, origin, up, {0, 5, 0});
    EXPECT_TRUE(color_near(color, {0.7f, 0.35f, 0.175f}));
}

TEST(SeveralLights, TwoAmbientLightsAdd) {
    // k_a = 0.5, C = 1, I_L = 0.4 and 0.6: I = 0.5 · (0.4 + 0.6) = 0.5.
    Material material = make_material(white, 0.5f, 1.0f, 1.0f, 2.0f);
    std::vector<Light> lights{ambient_light(white, 0.4f), ambient_light(white, 0.6f)};
    glm::vec3 color =
        litkit::shade(Reflection::BlinnPhong, material, lights, origin, up, {0, 5, 0});
    EXPECT_TRUE(color_near(color, gray(0.5f)));
}

TEST(SeveralLights, SumIsNotClamped) {
    // Phong, two directional lights straight down, eye above: each gives
    // k_d·1·1 + k_s·1 = 0.6 + 0.4 = 1 ⇒ I = 2 (clamping happens only in to_pixel).
    Material material = make_material(white, 0.0f, 0.6f, 0.4f, 2.0f);
    std::vector<Light> lights{directional_light({0, -1, 0}), directional_light({0, -2, 0})};
    glm::vec3 color = litkit::shade(Reflection::Phong, material, lights, origin, up, {0, 5, 0});
    EXPECT_TRUE(color_near(color, gray(2.0f)));
}

TEST(SeveralLights, NoLightsGiveBlack) {
    Material material = make_material(white, 1.0f, 1.0f, 1.0f, 2.0f);
    glm::vec3 color =
        litkit::shade(Reflection::Phong, material, std::span<const Light>{}, origin, up, {0, 5, 0});
    EXPECT_TRUE(color_near(color, gray(0.0f)));
}

// ============================================================================
// The templated pieces of litkit::equations, with T = float.
// ============================================================================

TEST(SpecularPower, RaisesPositiveBaseToShininess) {
    // 0.5² = 0.25; 0.5³ = 0.125; 0.8¹ = 0.8.
    EXPECT_NEAR(litkit::equations::specular_power(0.5f, 2.0f), 0.25f, tolerance);
    EXPECT_NEAR(litkit::equations::specular_power(0.5f, 3.0f), 0.125f, tolerance);
    EXPECT_NEAR(litkit::equations::specular_power(0.8f, 1.0f), 0.8f, tolerance);
}

TEST(SpecularPower, ZeroShininessIsSharpEdgedLobe) {
    // α = 0: 1 where base > 0, 0 where base ≤ 0 (never 0^0 = 1).
    EXPECT_NEAR(litkit::equations::specular_power(0.3f, 0.0f), 1.0f, tolerance);
    EXPECT_NEAR(litkit::equations::specular_power(1e-6f, 0.0f), 1.0f, tolerance);
    EXPECT_NEAR(litkit::equations::specular_power(0.0f, 0.0f), 0.0f, tolerance);
    EXPECT_NEAR(litkit::equations::specular_power(-0.5f, 0.0f), 0.0f, tolerance);
}

TEST(SpecularPower, NegativeBaseGivesZeroEvenForEvenShininess) {
    // max(-0.5, 0)² = 0, not (-0.5)² = 0.25.
    EXPECT_NEAR(litkit::equations::specular_power(-0.5f, 2.0f), 0.0f, tolerance);
}

TEST(SpotFactor, InsideConeRaisesCosineToExponent) {
    using litkit::equations::Vec3;
    const Vec3<float> axis{0.0f, -1.0f, 0.0f};
    // L = (0,1,0): c = 1 ⇒ 1^2 = 1.
    EXPECT_NEAR(litkit::equations::spot_factor(Vec3<float>{0, 1, 0}, axis, 0.5f, 0.5f, 2.0f), 1.0f,
                tolerance);
    // L = (0.6, 0.8, 0) (unit): c = 0.8 ≥ 0.5 ⇒ 0.8³ = 0.512; exponent 0 ⇒ 1.
    EXPECT_NEAR(litkit::equations::spot_factor(Vec3<float>{0.6f, 0.8f, 0}, axis, 0.5f, 0.5f, 3.0f),
                0.512f, tolerance);
    EXPECT_NEAR(litkit::equations::spot_factor(Vec3<float>{0.6f, 0.8f, 0}, axis, 0.5f, 0.5f, 0.0f),
                1.0f, tolerance);
}

TEST(SpotFactor, BoundaryIsInclusive) {
    using litkit::equations::Vec3;
    const Vec3<float> axis{0.0f, -1.0f, 0.0f};
    // c = 0.8 and cos(cutoff) = 0.8: c ≥ cos(cutoff) ⇒ s = 0.8² = 0.64.
    EXPECT_NEAR(litkit::equations::spot_factor(Vec3<float>{0.6f, 0.8f, 0}, axis, 0.8f, 0.8f, 2.0f),
                0.64f, tolerance);
}

TEST(SpotFactor, OutsideConeIsZero) {
    using litkit::equations::Vec3;
    const Vec3<float> axis{0.0f, -1.0f, 0.0f};
    // c = 0.8 < cos(cutoff) = 0.81 ⇒ 0, whatever the exponent.
    EXPECT_NEAR(
        litkit::equations::spot_factor(Vec3<float>{0.6f, 0.8f, 0}, axis, 0.81f, 0.81f, 0.0f), 0.0f,
        tolerance);
    // L = (0,-1,0): c = -1 < cos 90° = 0 ⇒ 0.
    EXPECT_NEAR(litkit::equations::spot_factor(Vec3<float>{0, -1, 0}, axis, 0.0f, 0.0f, 0.0f), 0.0f,
                tolerance);
}

TEST(SpotFactor, ZeroToTheZeroIsOneAtNinetyDegrees) {
    using litkit::equations::Vec3;
    // L = (1,0,0) ⊥ axis: c = 0 ≥ cos 90° = 0 ⇒ 0^0 = 1; with exponent 1 ⇒ 0.
    const Vec3<float> axis{0.0f, -1.0f, 0.0f};
    EXPECT_NEAR(litkit::equations::spot_factor(Vec3<float>{1, 0, 0}, axis, 0.0f, 0.0f, 0.0f), 1.0f,
                tolerance);
    EXPECT_NEAR(litkit::equations::spot_factor(Vec3<float>{1, 0, 0}, axis, 0.0f, 0.0f, 1.0f), 0.0f,
                tolerance);
}

TEST(DistanceAttenuation, IsReciprocalOfQuadraticInDistance) {
    using litkit::equations::Vec3;
    // [0,0,1], d = 2: 1/4.  [1,0.5,0.25], d = 2: 1/(1 + 1 + 1) = 1/3.
    // [0,1,0], d = 4: 1/4.  [1,0,0], d = 100: 1.  [2,3,4], d = 0.5: 1/(2 + 1.5 + 1) = 1/4.5.
    EXPECT_NEAR(litkit::equations::distance_attenuation(Vec3<float>{0, 0, 1}, 2.0f), 0.25f,
                tolerance);
    EXPECT_NEAR(litkit::equations::distance_attenuation(Vec3<float>{1, 0.5f, 0.25f}, 2.0f),
                1.0f / 3.0f, tolerance);
    EXPECT_NEAR(litkit::equations::distance_attenuation(Vec3<float>{0, 1, 0}, 4.0f), 0.25f,
                tolerance);
    EXPECT_NEAR(litkit::equations::distance_attenuation(Vec3<float>{1, 0, 0}, 100.0f), 1.0f,
                tolerance);
    EXPECT_NEAR(litkit::equations::distance_attenuation(Vec3<float>{2, 3, 4}, 0.5f), 0.2222222f,
                tolerance);
}

TEST(ReflectionTerms, EachModelAtSixtyDegreeLightAndEyeAlongNormal) {
    using litkit::equations::reflection_terms;
    using litkit::equations::Terms;
    using litkit::equations::Vec3;
    // N = (0,1,0), L = (√3/2, 1/2, 0) (N·L = 0.5), V = N, α = 2.
    //   Lambert:      D = 0.5,                   S = 0.
    //   Half-Lambert: D = (0.25 + 0.5)² = 0.5625, S = 0.
    //   Phong:        R = (-√3/2, 1/2, 0), R·V = 0.5 ⇒ S = 0.25; D = 0.5.
    //   Blinn-Phong:  L + V = (√3/2, 3/2, 0), |·| = √3 ⇒ H = (1/2, √3/2, 0),
    //                 N·H = √3/2 ⇒ S = 0.75; D = 0.5.
    const Vec3<float> normal{0, 1, 0};
    const Vec3<float> to_light{sqrt3 / 2, 0.5f, 0};
    const Vec3<float> to_eye{0, 1, 0};
    Terms<float> lambert =
        reflection_terms<Reflection::Lambert>(normal, to_light, to_eye, with_shininess(2.0f));
    EXPECT_NEAR(lambert.diffuse, 0.5f, tolerance);
    EXPECT_NEAR(lambert.specular, 0.0f, tolerance);
    Terms<float> half =
        reflection_terms<Reflection::HalfLambert>(normal, to_light, to_eye, with_shininess(2.0f));
    EXPECT_NEAR(half.diffuse, 0.5625f, tolerance);
    EXPECT_NEAR(half.specular, 0.0f, tolerance);
    Terms<float> phong =
        reflection_terms<Reflection::Phong>(normal, to_light, to_eye, with_shininess(2.0f));
    EXPECT_NEAR(phong.diffuse, 0.5f, tolerance);
    EXPECT_NEAR(phong.specular, 0.25f, tolerance);
    Terms<float> blinn =
        reflection_terms<Reflection::BlinnPhong>(normal, to_light, to_eye, with_shininess(2.0f));
    EXPECT_NEAR(blinn.diffuse, 0.5f, tolerance);
    EXPECT_NEAR(blinn.specular, 0.75f, tolerance);
}

TEST(ReflectionTerms, BackFaceGivesZeroExceptHalfLambertWrap) {
    using litkit::equations::reflection_terms;
    using litkit::equations::Terms;
    using litkit::equations::Vec3;
    // N = (0,1,0), L = (√3/2, -1/2, 0) (N·L = -0.5), V = (0,-1,0), α = 0.
    //   Lambert, Phong, Blinn-Phong: D = 0, S = 0 (N·L ≤ 0, whatever α).
    //   Half-Lambert: D = (-0.25 + 0.5)² = 0.0625, S = 0.
    const Vec3<float> normal{0, 1, 0};
    const Vec3<float> to_light{sqrt3 / 2, -0.5f, 0};
    const Vec3<float> to_eye{0, -1, 0};
    Terms<float> lambert =
        reflection_terms<Reflection::Lambert>(normal, to_light, to_eye, with_shininess(0.0f));
    EXPECT_NEAR(lambert.diffuse, 0.0f, tolerance);
    Terms<float> half =
        reflection_terms<Reflection::HalfLambert>(normal, to_light, to_eye, with_shininess(0.0f));
    EXPECT_NEAR(half.diffuse, 0.0625f, tolerance);
    EXPECT_NEAR(half.specular, 0.0f, tolerance);
    Terms<float> phong =
        reflection_terms<Reflection::Phong>(normal, to_light, to_eye, with_shininess(0.0f));
    EXPECT_NEAR(phong.diffuse, 0.0f, tolerance);
    EXPECT_NEAR(phong.specular, 0.0f, tolerance);
    Terms<float> blinn =
        reflection_terms<Reflection::BlinnPhong>(normal, to_light, to_eye, with_shininess(0.0f));
    EXPECT_NEAR(blinn.diffuse, 0.0f, tolerance);
    EXPECT_NEAR(blinn.specular, 0.0f, tolerance);
}

// ============================================================================
// Pixel value: round(255 · clamp(I, 0, 1)^(1/gamma)).
// ============================================================================

TEST(ToPixel, GammaOneMapsEndpointsAndRoundsToNearest) {
    // 0 → 0; 1 → 255; 0.4 → 102; 0.25 → 63.75 → 64; 0.999 → 254.745 → 255 (not truncated
    // to 254); 0.003 → 0.765 → 1; 0.001 → 0.255 → 0.
    EXPECT_EQ(pixel(0.0f, 1.0f), 0);
    EXPECT_EQ(pixel(1.0f, 1.0f), 255);
    EXPECT_EQ(pixel(0.4f, 1.0f), 102);
    EXPECT_EQ(pixel(0.25f, 1.0f), 64);
    EXPECT_EQ(pixel(0.999f, 1.0f), 255);
    EXPECT_EQ(pixel(0.003f, 1.0f), 1);
    EXPECT_EQ(pixel(0.001f, 1.0f), 0);
}

TEST(ToPixel, HalfRoundsUp) {
    // 255 · 0.5 = 127.5 exactly; round() takes halves away from zero ⇒ 128.
    EXPECT_EQ(pixel(0.5f, 1.0f), 128);
}

TEST(ToPixel, GammaTwoPointTwoBrightensMidtones) {
    // 0.5^(1/2.2) = exp(-ln 2 / 2.2) = exp(-0.3150669) = 0.7297400 ⇒ 255 · 0.72974 = 186.08 ⇒ 186.
    // 0.2^(1/2.2) = exp(-1.6094379 / 2.2) = exp(-0.7315627) = 0.4811565 ⇒ 122.70 ⇒ 123.
    // Endpoints are fixed: 0 → 0, 1 → 255.
    EXPECT_EQ(pixel(0.5f, 2.2f), 186);
    EXPECT_EQ(pixel(0.2f, 2.2f), 123);
    EXPECT_EQ(pixel(0.0f, 2.2f), 0);
    EXPECT_EQ(pixel(1.0f, 2.2f), 255);
}

TEST(ToPixel, GammaTwoTakesSquareRoot) {
    // √0.64 = 0.8 ⇒ 204; √0.25 = 0.5 ⇒ 127.5 ⇒ 128.
    EXPECT_EQ(pixel(0.64f, 2.0f), 204);
    EXPECT_EQ(pixel(0.25f, 2.0f), 128);
}

TEST(ToPixel, GammaBelowOneDarkens) {
    // gamma 0.5: 0.5^2 = 0.25 ⇒ 63.75 ⇒ 64.
    EXPECT_EQ(pixel(0.5f, 0.5f), 64);
}

TEST(ToPixel, ClampsOutOfRangeAndNaN) {
    // Above 1 → 255; below 0 → 0; NaN → 0; ±∞ → 255 / 0; with gamma 1 and 2.2 alike
    // (clamping happens before the power, so no NaN from a negative base).
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float infinity = std::numeric_limits<float>::infinity();
    for (float gamma : {1.0f, 2.2f}) {
        SCOPED_TRACE(::testing::Message() << "gamma " << gamma);
        EXPECT_EQ(pixel(1.7f, gamma), 255);
        EXPECT_EQ(pixel(-0.3f, gamma), 0);
        EXPECT_EQ(pixel(nan, gamma), 0);
        EXPECT_EQ(pixel(infinity, gamma), 255);
        EXPECT_EQ(pixel(-infinity, gamma), 0);
    }
}

// ============================================================================
// Scene-file spellings of the enums.
// ============================================================================

TEST(ReflectionNames, UseSceneFileSpelling) {
    EXPECT_EQ(litkit::to_string(Reflection::Lambert), "lambert");
    EXPECT_EQ(litkit::to_string(Reflection::HalfLambert), "half-lambert");
    EXPECT_EQ(litkit::to_string(Reflection::Phong), "phong");
    EXPECT_EQ(litkit::to_string(Reflection::BlinnPhong), "blinn-phong");
}

TEST(ReflectionNames, RoundTripThroughParse) {
    for (Reflection reflection : all_reflections) {
        SCOPED_TRACE(litkit::to_string(reflection));
        EXPECT_EQ(litkit::parse_reflection(litkit::to_string(reflection)), reflection);
    }
}

TEST(ReflectionNames, RejectMisspellings) {
    // Values are lower-case and exact (docs/spec.md §6).
    for (std::string_view text :
         {"Phong", "blinn", "Blinn-Phong", "blinn_phong", "blinnphong", "half_lambert",
          "halflambert", "LAMBERT", " phong", "phong ", ""}) {
        SCOPED_TRACE(text);
        EXPECT_FALSE(litkit::parse_reflection(text).has_value());
    }
}

TEST(ShadingNames, UseSceneFileSpellingAndRoundTrip) {
    EXPECT_EQ(litkit::to_string(Shading::Flat), "flat");
    EXPECT_EQ(litkit::to_string(Shading::Gouraud), "gouraud");
    EXPECT_EQ(litkit::to_string(Shading::Phong), "phong");
    for (Shading shading : {Shading::Flat, Shading::Gouraud, Shading::Phong}) {
        SCOPED_TRACE(litkit::to_string(shading));
        EXPECT_EQ(litkit::parse_shading(litkit::to_string(shading)), shading);
    }
}

TEST(ShadingNames, RejectMisspellings) {
    for (std::string_view text : {"Phong", "Flat", "GOURAUD", "smooth", "blinn", "gouraud ", ""}) {
        SCOPED_TRACE(text);
        EXPECT_FALSE(litkit::parse_shading(text).has_value());
    }
}

// ============================================================================
// The models of docs/spec.md §9.1 and the soft spot edge of §9.3, against
// values computed by hand (each comment shows the arithmetic).

namespace {

litkit::equations::Reflected<float> reflect_at(Reflection reflection, const Material& material,
                                               const glm::vec3& normal, const glm::vec3& to_light,
                                               const glm::vec3& to_eye) {
    using namespace litkit::equations;
    const MaterialT<float> m = splat<float>(material);
    return with_reflection(reflection, [&](auto model) {
        return reflect<decltype(model)::value>(splat<float>(normal), splat<float>(to_light),
                                               splat<float>(to_eye), m);
    });
}

// A unit vector in the xy-plane at `degrees` from +y (N), towards +x.
glm::vec3 at_angle(float degrees) {
    const float radians = glm::radians(degrees);
    return {std::sin(radians), std::cos(radians), 0.0f};
}

}  // namespace

TEST(CookTorrance, HeadOnGivesTheClosedFormSpecular) {
    // L = V = N, r = 0.5: a = 0.25, a² = 0.0625, n_h = 1, m = 1.
    // D_GGX = a²/(π·(1·(a² − 1) + 1)²) = 0.0625/(π·0.0625²) = 16/π = 5.0930.
    // Vis = 0.5/(1·√(1 − a² + a²) + 1·√(1 − a² + a²)) = 0.25.
    // F = f0 + (1 − f0)·(1 − 1)⁵ = 0.04.  S = π·5.0930·0.25·0.04·1 = 0.16; D = 1.
    Material material;
    material.roughness = 0.5f;
    material.f0 = 0.04f;
    const auto r = reflect_at(Reflection::CookTorrance, material, {0, 1, 0}, {0, 1, 0}, {0, 1, 0});
    EXPECT_NEAR(r.specular, 0.16f, 1e-5f);
    EXPECT_NEAR(r.diffuse, material.kd * 1.0f, 1e-6f);
}

TEST(CookTorrance, NoLightFromBehindAndRoughnessClampedAt0045) {
    Material material;
    // N·L < 0: D = S = 0.
    const auto behind =
        reflect_at(Reflection::CookTorrance, material, {0, 1, 0}, {0, -1, 0}, {0, 1, 0});
    EXPECT_EQ(behind.specular, 0.0f);
    EXPECT_EQ(behind.diffuse, 0.0f);
    // roughness 0 acts as 0.045: head on, S = π·D·Vis·F with a = 0.045² and
    // D = 1/(π·a²), Vis = 0.25: S = 0.25·f0/a² = 0.25·0.04/4.100625e-6 = 2438.65.
    material.roughness = 0.0f;
    const auto sharp =
        reflect_at(Reflection::CookTorrance, material, {0, 1, 0}, {0, 1, 0}, {0, 1, 0});
    EXPECT_NEAR(sharp.specular / 2438.65f, 1.0f, 1e-3f);
}

TEST(OrenNayar, ThirtyDegreeSigmaGivesTheClosedFormTerms) {
    // σ = 30° = 0.523599 rad, σ² = 0.274156:
    //   A = 1 − 0.5·0.274156/(0.274156 + 0.33) = 0.773108,
    //   B = 0.45·0.274156/(0.274156 + 0.09) = 0.338784.
    // L and V both 60° from N, same side (L = V): n_l = n_v = 0.5, L·V = 1,
    //   s = 1 − 0.25 = 0.75, t = 0.5: D = 0.5·(A + B·1.5) = 0.640642.
    // Opposite sides: L·V = cos 120° = −0.5, s = −0.75 → 0: D = 0.5·A = 0.386554.
    Material material;
    material.kd = 1.0f;
    material.sigma = 30.0f;
    const auto same =
        reflect_at(Reflection::OrenNayar, material, {0, 1, 0}, at_angle(60), at_angle(60));
    EXPECT_NEAR(same.diffuse, 0.640642f, 1e-5f);
    EXPECT_EQ(same.specular, 0.0f);
    const auto opposite =
        reflect_at(Reflection::OrenNayar, material, {0, 1, 0}, at_angle(60), at_angle(-60));
    EXPECT_NEAR(opposite.diffuse, 0.386554f, 1e-5f);
    // σ = 0: A = 1, B = 0, Lambert.
    material.sigma = 0.0f;
    const auto smooth =
        reflect_at(Reflection::OrenNayar, material, {0, 1, 0}, at_angle(60), at_angle(-20));
    EXPECT_NEAR(smooth.diffuse, 0.5f, 1e-6f);
    // Light behind: 0.
    const auto behind =
        reflect_at(Reflection::OrenNayar, material, {0, 1, 0}, at_angle(100), at_angle(0));
    EXPECT_EQ(behind.diffuse, 0.0f);
}

TEST(Toon, BandsQuantiseTheDiffuseAndTheHighlightIsAStep) {
    // 3 bands: D = min(⌊3·n_l⌋, 2)/2. n_l = 0.5 → ⌊1.5⌋ = 1 → 0.5; n_l = 0.2 → 0;
    // n_l = 1 → min(3, 2)/2 = 1.
    Material material;
    material.kd = 1.0f;
    material.bands = 3;
    material.shininess = 2.0f;
    const glm::vec3 n{0, 1, 0};
    EXPECT_NEAR(reflect_at(Reflection::Toon, material, n, at_angle(60), n).diffuse, 0.5f, 1e-6f);
    EXPECT_EQ(reflect_at(Reflection::Toon, material, n, at_angle(78.463f), n).diffuse, 0.0f);
    EXPECT_EQ(reflect_at(Reflection::Toon, material, n, n, n).diffuse, 1.0f);
    // Highlight: L = V = N gives n_h = 1, 1² ≥ 0.5: S = 1. L at 60°, V = N:
    // H at 30°, n_h = cos 30° = 0.866, n_h² = 0.75 ≥ 0.5: S = 1. L at 120°:
    // N·L < 0, S = 0. L at 80°, V at −80°: H = N... use V at 0°, L at 80°: H at
    // 40°, n_h² = cos²40° = 0.587 ≥ 0.5: 1; L at 100° is behind: 0.
    EXPECT_EQ(reflect_at(Reflection::Toon, material, n, n, n).specular, 1.0f);
    EXPECT_EQ(reflect_at(Reflection::Toon, material, n, at_angle(60), n).specular, 1.0f);
    EXPECT_EQ(reflect_at(Reflection::Toon, material, n, at_angle(120), n).specular, 0.0f);
    // L at 60°, V at −60°: H = N·... H = normalize(L + V) = N, n_h = 1: S = 1;
    // shininess 8 with H at 30°: 0.866⁸ = 0.316 < 0.5: S = 0.
    material.shininess = 8.0f;
    EXPECT_EQ(reflect_at(Reflection::Toon, material, n, at_angle(60), n).specular, 0.0f);
}

TEST(Minnaert, LimbDarkeningFollowsTheClosedForm) {
    Material material;
    material.kd = 1.0f;
    const glm::vec3 n{0, 1, 0};
    // k = 1.5, n_l = 0.5, V = N (n_v = 1): b = 0.5, D = 0.5·0.5^0.5 = 0.353553.
    material.minnaert_k = 1.5f;
    EXPECT_NEAR(reflect_at(Reflection::Minnaert, material, n, at_angle(60), n).diffuse, 0.353553f,
                1e-6f);
    // k = 1: D = n_l (b⁰ = 1), Lambert.
    material.minnaert_k = 1.0f;
    EXPECT_NEAR(reflect_at(Reflection::Minnaert, material, n, at_angle(60), at_angle(-70)).diffuse,
                0.5f, 1e-6f);
    // k = 0.5, n_l = 0.5, n_v = cos 84.26° = 0.1: b = 0.05 → at least 0.1:
    // D = 0.5·0.1^(−0.5) = 1.581139.
    material.minnaert_k = 0.5f;
    const glm::vec3 grazing{std::sqrt(1.0f - 0.01f), 0.1f, 0.0f};
    EXPECT_NEAR(reflect_at(Reflection::Minnaert, material, n, at_angle(60), grazing).diffuse,
                1.581139f, 1e-5f);
    // k = 0 with V ⊥ N (b = 0 → 0.1): D = 0.5·0.1^(−1) = 5; light behind: 0.
    material.minnaert_k = 0.0f;
    EXPECT_NEAR(reflect_at(Reflection::Minnaert, material, n, at_angle(60), {1, 0, 0}).diffuse,
                5.0f, 1e-4f);
    EXPECT_EQ(reflect_at(Reflection::Minnaert, material, n, at_angle(95), n).diffuse, 0.0f);
}

TEST(Gooch, CoolAndWarmEndsAndTheWashBetween) {
    // C = (1, 0, 0), k_d = 1: cool = min(0.2·C + (0, 0, 0.4), 1) = (0.2, 0, 0.4),
    // warm = min(0.6·C + (0.4, 0.4, 0), 1) = (1, 0.4, 0).
    Material material;
    material.color = {1, 0, 0};
    material.kd = 1.0f;
    material.ks = 0.0f;
    const glm::vec3 n{0, 1, 0};
    // N·L = 1: t = 1, all warm; the weight multiplying the colour is 1.
    const auto lit = reflect_at(Reflection::Gooch, material, n, n, n);
    EXPECT_NEAR(lit.diffuse * lit.color.x, 1.0f, 1e-6f);
    EXPECT_NEAR(lit.diffuse * lit.color.y, 0.4f, 1e-6f);
    EXPECT_NEAR(lit.diffuse * lit.color.z, 0.0f, 1e-6f);
    // N·L = −1: t = 0, all cool, and not black.
    const auto unlit = reflect_at(Reflection::Gooch, material, n, -n, n);
    EXPECT_NEAR(unlit.diffuse * unlit.color.x, 0.2f, 1e-6f);
    EXPECT_NEAR(unlit.diffuse * unlit.color.y, 0.0f, 1e-6f);
    EXPECT_NEAR(unlit.diffuse * unlit.color.z, 0.4f, 1e-6f);
    EXPECT_EQ(unlit.specular, 0.0f);
    // N·L = 0: t = 0.5, halfway: (0.6, 0.2, 0.2). Through shade() with a
    // directional light of intensity 2: I = 2·(0.6, 0.2, 0.2).
    Light light = directional_light({-1, 0, 0});
    light.intensity = 2.0f;
    material.ka = 0.0f;
    const glm::vec3 color = shade_one(Reflection::Gooch, material, light, origin, n, {0, 5, 0});
    EXPECT_NEAR(color.x, 1.2f, 1e-5f);
    EXPECT_NEAR(color.y, 0.4f, 1e-5f);
    EXPECT_NEAR(color.z, 0.4f, 1e-5f);
}

TEST(Gooch, OutsideASpotConeThereIsNoWash) {
    // f = 0 outside the cone: the light adds nothing, not even the cool tone.
    SpotLight kind;
    kind.position = {0, 2, 0};
    kind.direction = {1, 0, 0};  // points away from the surface point
    kind.cutoff_degrees = 30.0f;
    Light light;
    light.kind = kind;
    Material material;
    material.ka = 0.0f;
    const glm::vec3 color = shade_one(Reflection::Gooch, material, light, origin, up, {0, 5, 0});
    EXPECT_EQ(color, glm::vec3(0.0f));
}

TEST(SpotPenumbra, SoftEdgeFollowsTheSmoothStep) {
    // cutoff 30°, penumbra 0.5: θi = 15°. A point 20° off the axis:
    // c = cos 20° = 0.939693, t = (c − cos 30°)/(cos 15° − cos 30°)
    //   = (0.939693 − 0.866025)/(0.965926 − 0.866025) = 0.737413,
    // w = t²(3 − 2t) = 0.543778·1.525174 = 0.829356. exponent 0, f = w·1/d²,
    // d = 1, Lambert with N = L: I = w·k_d = 0.829356·0.7 = 0.580549.
    SpotLight kind;
    kind.position = {0, 1, 0};
    kind.direction = {std::sin(glm::radians(20.0f)), -std::cos(glm::radians(20.0f)), 0};
    kind.cutoff_degrees = 30.0f;
    kind.penumbra = 0.5f;
    Light light;
    light.kind = kind;
    Material material;
    material.ka = 0.0f;
    material.color = white;
    const glm::vec3 color = shade_one(Reflection::Lambert, material, light, origin, up, {0, 5, 0});
    EXPECT_NEAR(color.x, 0.580549f, 2e-5f);
    // Inside the inner cone (10° off): w = 1, I = 0.7. Outside the outer cone (35°): 0.
    kind.direction = {std::sin(glm::radians(10.0f)), -std::cos(glm::radians(10.0f)), 0};
    light.kind = kind;
    EXPECT_NEAR(shade_one(Reflection::Lambert, material, light, origin, up, {0, 5, 0}).x, 0.7f,
                1e-6f);
    kind.direction = {std::sin(glm::radians(35.0f)), -std::cos(glm::radians(35.0f)), 0};
    light.kind = kind;
    EXPECT_EQ(shade_one(Reflection::Lambert, material, light, origin, up, {0, 5, 0}).x, 0.0f);
}

TEST(SpotPenumbra, ZeroPenumbraIsTheHardEdgeExactly) {
    // penumbra 0 and penumbra absent give the same bits, inside and on the cone.
    SpotLight hard;
    hard.position = {0, 1, 0};
    hard.cutoff_degrees = 20.0f;
    hard.exponent = 3.0f;
    for (float degrees : {0.0f, 10.0f, 19.999f, 20.0f}) {
        hard.direction = {std::sin(glm::radians(degrees)), -std::cos(glm::radians(degrees)), 0};
        SpotLight explicit_zero = hard;
        explicit_zero.penumbra = 0.0f;
        Light a, b;
        a.kind = hard;
        b.kind = explicit_zero;
        EXPECT_EQ(shade_one(Reflection::Phong, Material{}, a, origin, up, {0, 5, 0}),
                  shade_one(Reflection::Phong, Material{}, b, origin, up, {0, 5, 0}));
    }
}

TEST(ReflectionModels, OneListInTheSpecOrderWithUniqueNames) {
    const auto models = litkit::reflection_models();
    ASSERT_EQ(models.size(), static_cast<std::size_t>(litkit::reflection_count));
    const char* expected[] = {"lambert",     "half-lambert", "phong",
                              "blinn-phong", "oren-nayar",   "cook-torrance",
                              "toon",        "minnaert",     "gooch"};
    for (std::size_t i = 0; i < models.size(); ++i) {
        EXPECT_EQ(static_cast<std::size_t>(models[i].id), i);
        EXPECT_EQ(models[i].name, expected[i]);
        EXPECT_EQ(litkit::parse_reflection(models[i].name), models[i].id);
        EXPECT_EQ(litkit::to_string(models[i].id), models[i].name);
        EXPECT_FALSE(models[i].summary.empty());
    }
}

namespace {

float intermediate(const litkit::LightTerms& terms, const std::string& name) {
    for (const auto& [key, value] : terms.intermediates)
        if (key == name) return value;
    ADD_FAILURE() << "no intermediate " << name;
    return std::numeric_limits<float>::quiet_NaN();
}

}  // namespace

TEST(ShadeTerms, TotalIsShadeBitForBitForEveryModelAndLightKind) {
    std::vector<Light> lights{Light{AmbientLight{}, white, 0.3f}, directional_light({-1, -2, -1}),
                              point_light({1, 2, 1})};
    SpotLight spot;
    spot.position = {0.5f, 2, 0};
    spot.direction = {-0.2f, -1, 0};
    spot.cutoff_degrees = 40.0f;
    spot.exponent = 2.0f;
    spot.penumbra = 0.5f;
    lights.push_back(Light{spot, white, 2.0f});
    const glm::vec3 normal = glm::vec3(0.3f, 0.9f, 0.1f) / std::sqrt(0.91f);
    for (const litkit::ReflectionModel& model : litkit::reflection_models()) {
        const litkit::ShadeTerms terms =
            litkit::shade_terms(model.id, Material{}, lights, origin, normal, {1, 3, 4});
        const glm::vec3 shaded =
            litkit::shade(model.id, Material{}, lights, origin, normal, {1, 3, 4});
        EXPECT_EQ(terms.total, shaded) << model.name;
        ASSERT_EQ(terms.lights.size(), lights.size()) << model.name;
        EXPECT_TRUE(terms.lights[0].ambient);
        glm::vec3 sum{0.0f};
        for (const litkit::LightTerms& light : terms.lights) sum += light.contribution;
        EXPECT_NEAR(sum.x, shaded.x, 1e-6f) << model.name;
        EXPECT_NEAR(sum.z, shaded.z, 1e-6f) << model.name;
    }
}

TEST(ShadeTerms, ShowTheModelsIntermediateValues) {
    const glm::vec3 n{0, 1, 0};
    Material material;
    material.sigma = 30.0f;
    material.roughness = 0.5f;
    material.f0 = 0.04f;
    // A directional light straight down onto N, eye straight above: L = V = N.
    const Light from_above = directional_light({0, -1, 0});
    const auto terms_of = [&](Reflection reflection, const Light& light, const glm::vec3& eye) {
        return litkit::shade_terms(reflection, material, std::span<const Light>(&light, 1), origin,
                                   n, eye)
            .lights.at(0);
    };
    const litkit::LightTerms oren = terms_of(Reflection::OrenNayar, from_above, {0, 5, 0});
    EXPECT_NEAR(intermediate(oren, "A"), 0.773108f, 2e-6f);
    EXPECT_NEAR(intermediate(oren, "B"), 0.338784f, 2e-6f);
    const litkit::LightTerms cook = terms_of(Reflection::CookTorrance, from_above, {0, 5, 0});
    EXPECT_NEAR(intermediate(cook, "D_GGX"), 16.0f / 3.14159265f, 1e-4f);  // 5.0930
    EXPECT_NEAR(intermediate(cook, "Vis"), 0.25f, 1e-6f);
    EXPECT_NEAR(intermediate(cook, "F"), 0.04f, 1e-6f);
    EXPECT_NEAR(cook.specular, 0.16f, 1e-5f);
    EXPECT_EQ(cook.factor, 1.0f);
    EXPECT_EQ(cook.to_light, n);
    // Toon, 3 bands, N·L = 0.5: band ⌊1.5⌋ = 1.
    const litkit::LightTerms toon =
        terms_of(Reflection::Toon, directional_light(-at_angle(60)), {0, 5, 0});
    EXPECT_EQ(intermediate(toon, "band"), 1.0f);
    // Gooch, C = (1, 0, 0), k_d = 1: cool (0.2, 0, 0.4), warm (1, 0.4, 0); N·L = 1: t = 1.
    material.color = {1, 0, 0};
    material.kd = 1.0f;
    const litkit::LightTerms gooch = terms_of(Reflection::Gooch, from_above, {0, 5, 0});
    EXPECT_EQ(intermediate(gooch, "t"), 1.0f);
    EXPECT_NEAR(intermediate(gooch, "cool.r"), 0.2f, 1e-6f);
    EXPECT_NEAR(intermediate(gooch, "cool.b"), 0.4f, 1e-6f);
    EXPECT_NEAR(intermediate(gooch, "warm.r"), 1.0f, 1e-6f);
    EXPECT_NEAR(intermediate(gooch, "warm.g"), 0.4f, 1e-6f);
    // The classic models have none.
    EXPECT_TRUE(terms_of(Reflection::Phong, from_above, {0, 5, 0}).intermediates.empty());
}

TEST(Shade, RefusesANormalThatIsNotUnitLength) {
    const Light light = point_light({0, 2, 0});
    const std::span<const Light> lights(&light, 1);
    EXPECT_THROW(litkit::shade(Reflection::Phong, Material{}, lights, origin, {0, 2, 0}, {0, 5, 0}),
                 litkit::ArgumentError);
    EXPECT_THROW(litkit::shade(Reflection::Phong, Material{}, lights, origin, {0, 0, 0}, {0, 5, 0}),
                 litkit::ArgumentError);
    EXPECT_THROW(
        litkit::shade_terms(Reflection::Phong, Material{}, lights, origin, {0, 0.9f, 0}, {0, 5, 0}),
        litkit::ArgumentError);
    EXPECT_THROW(litkit::shade(Reflection::Phong, Material{}, lights, origin, up, origin),
                 litkit::ArgumentError);
    // Within the tolerance (1e-3) it is used as given.
    EXPECT_NO_THROW(
        litkit::shade(Reflection::Phong, Material{}, lights, origin, {0, 1.0005f, 0}, {0, 5, 0}));
}
