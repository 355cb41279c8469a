// SPDX-License-Identifier: MIT
// The equations of refraction (include/litkit/refraction.hpp, docs/spec.md
// §10.2) against values a reader can recompute. The expected numbers come
// from the angle form of the same laws, in double, not from the vector form
// the header uses:
//   Snell:   n₁ sin θ₁ = n₂ sin θ₂, so sin θ₂ = η sin θ₁ (η = n₁/n₂);
//   Fresnel: F = ½[(sin(θ₁ − θ₂)/sin(θ₁ + θ₂))² + (tan(θ₁ − θ₂)/tan(θ₁ + θ₂))²]
//            (Born and Wolf, Principles of Optics, §1.5.2), and at normal
//            incidence its limit ((n₁ − n₂)/(n₁ + n₂))².
#include <gtest/gtest.h>

#include <array>
#include <cfenv>
#include <cmath>
#include <string>
#include <vector>

#include "../src/codegen/glsl_expr.hpp"
#include "cpu/shade_kernel_impl.hpp"  // xsimd, and equations::pow of batches
#include "litkit/refraction.hpp"

namespace {

namespace eq = litkit::equations;
using eq::Vec3;

constexpr double pi = 3.14159265358979323846;
double radians(double degrees) { return degrees * pi / 180.0; }

// A frame that is not the coordinate axes, so that no component is trivially
// 0: the unit normal n = (0.6, 0.8, 0) and the unit tangent t = (0.8, −0.6,
// 0), with t·n = 0. A ray at θ₁ from the normal, travelling against it, has
// d = sin θ₁·t − cos θ₁·n, and c₁ = −d·n = cos θ₁.
const Vec3<double> normal_d{0.6, 0.8, 0.0};
const Vec3<double> tangent_d{0.8, -0.6, 0.0};

Vec3<float> to_float(const Vec3<double>& v) {
    return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)};
}
const Vec3<float> normal = to_float(normal_d);

Vec3<float> incoming(double theta1_degrees) {
    const double theta = radians(theta1_degrees);
    return to_float(std::sin(theta) * tangent_d - std::cos(theta) * normal_d);
}

eq::Interface<float> at(double theta1_degrees, double eta) {
    return eq::refract_interface(incoming(theta1_degrees), normal, static_cast<float>(eta));
}

double dot(const Vec3<float>& a, const Vec3<double>& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
double length(const Vec3<float>& v) {
    return std::sqrt(double(v.x) * v.x + double(v.y) * v.y + double(v.z) * v.z);
}

// The angle form of Fresnel (above), in double: the independent reference.
double fresnel_reference(double theta1_degrees, double eta) {
    const double theta1 = radians(theta1_degrees);
    const double sin2 = eta * std::sin(theta1);
    if (sin2 >= 1.0) return 1.0;  // total internal reflection
    const double theta2 = std::asin(sin2);
    if (theta1 == 0.0) return ((eta - 1.0) / (eta + 1.0)) * ((eta - 1.0) / (eta + 1.0));
    const double s = std::sin(theta1 - theta2) / std::sin(theta1 + theta2);
    const double p = std::tan(theta1 - theta2) / std::tan(theta1 + theta2);
    return 0.5 * (s * s + p * p);
}

}  // namespace

// n₁ sin θ₁ = n₂ sin θ₂ and |T| = 1, entering glass (1 → 1.5) and water
// (1 → 1.33) and leaving glass (1.5 → 1) below its critical angle 41.81°.
// In the frame above, sin θ₂ is T's component along t (T·t) and the refracted
// ray goes on through the surface (T·n = −cos θ₂ < 0). Example: entering
// glass at 30°, sin θ₂ = sin 30°/1.5 = 1/3, θ₂ = 19.4712°, so T·t = 0.333333
// and T·n = −cos θ₂ = −0.942809.
TEST(Refraction, SnellsLawHoldsAndTheRefractedRayIsUnit) {
    struct Media {
        double n1, n2;
    };
    const std::array<Media, 3> media{{{1.0, 1.5}, {1.0, 1.33}, {1.5, 1.0}}};
    for (const Media& m : media) {
        const double eta = m.n1 / m.n2;
        for (double theta1 : {0.0, 10.0, 30.0, 41.0, 60.0, 80.0}) {
            if (eta * std::sin(radians(theta1)) >= 1.0) continue;  // TIR: below
            SCOPED_TRACE(testing::Message() << m.n1 << " -> " << m.n2 << " at " << theta1);
            const eq::Interface<float> hit = at(theta1, eta);
            ASSERT_FALSE(hit.total_internal_reflection);
            const double sin2 = dot(hit.refracted, tangent_d);
            EXPECT_NEAR(m.n1 * std::sin(radians(theta1)), m.n2 * sin2, 1e-6);
            EXPECT_NEAR(length(hit.refracted), 1.0, 1e-6);
            // θ₂ from the angle form: cos θ₂ = √(1 − η² sin² θ₁).
            const double cos2 = std::cos(std::asin(eta * std::sin(radians(theta1))));
            EXPECT_NEAR(dot(hit.refracted, normal_d), -cos2, 1e-6);
            EXPECT_NEAR(hit.cos_refracted, cos2, 1e-6);
            EXPECT_NEAR(hit.cos_incident, std::cos(radians(theta1)), 1e-6);
        }
    }
    const eq::Interface<float> glass = at(30.0, 1.0 / 1.5);
    EXPECT_NEAR(dot(glass.refracted, tangent_d), 1.0 / 3.0, 1e-6);
    EXPECT_NEAR(dot(glass.refracted, normal_d), -0.942809, 1e-6);
}

// Reflectance of glass (n = 1.5) from air:
// - normal incidence: ((1 − 1.5)/(1 + 1.5))² = (−0.5/2.5)² = 0.2² = 0.04;
// - at 80°: sin θ₂ = sin 80°/1.5 = 0.656539, θ₂ = 41.0364°;
//   θ₁ − θ₂ = 38.9636°, θ₁ + θ₂ = 121.0364°;
//   (sin 38.9636°/sin 121.0364°)² = (0.628826/0.856840)² = 0.538595,
//   (tan 38.9636°/tan 121.0364°)² = (0.808732/−1.661886)² = 0.236814,
//   F = (0.538595 + 0.236814)/2 = 0.3877044 ≈ 0.388.
TEST(Refraction, FresnelFromAir) {
    const double eta = 1.0 / 1.5;
    EXPECT_NEAR(at(0.0, eta).fresnel, 0.04, 1e-6);
    EXPECT_NEAR(at(0.0, eta).fresnel, fresnel_reference(0.0, eta), 1e-6);
    EXPECT_NEAR(at(80.0, eta).fresnel, 0.388, 5e-4);
    EXPECT_NEAR(at(80.0, eta).fresnel, fresnel_reference(80.0, eta), 1e-5);
    EXPECT_NEAR(fresnel_reference(80.0, eta), 0.3877044, 1e-7);
    for (double theta1 : {10.0, 30.0, 50.0, 70.0, 85.0}) {
        EXPECT_NEAR(at(theta1, eta).fresnel, fresnel_reference(theta1, eta), 1e-5) << theta1;
    }
}

// Inside glass, leaving into air (η = 1.5), at 40°: sin θ₂ = 1.5 sin 40° =
// 0.964181, θ₂ = 74.6186°; θ₁ − θ₂ = −34.6186°, θ₁ + θ₂ = 114.6186°;
// (sin(−34.6186°)/sin 114.6186°)² = (−0.568110/0.909101)² = 0.390518,
// (tan(−34.6186°)/tan 114.6186°)² = (−0.690332/−2.182321)² = 0.100064,
// F = (0.390518 + 0.100064)/2 = 0.2452912 ≈ 0.245.
TEST(Refraction, FresnelInsideGlass) {
    EXPECT_NEAR(at(40.0, 1.5).fresnel, 0.2452912, 1e-5);
    EXPECT_NEAR(fresnel_reference(40.0, 1.5), 0.2452912, 1e-7);
    for (double theta1 : {5.0, 20.0, 35.0, 41.0}) {
        EXPECT_NEAR(at(theta1, 1.5).fresnel, fresnel_reference(theta1, 1.5), 1e-5) << theta1;
    }
}

// Total internal reflection leaving glass: the critical angle is
// asin(1/1.5) = 41.8103°. At 41.8°, k = 1 − 2.25(1 − cos² 41.8°) =
// 1 − 2.25·0.444266 = 0.000403 > 0: a grazing refracted ray, F < 1. At 42°,
// 60°, 89°, k < 0: TIR, F = 1 exactly, and the refracted field holds the
// mirror direction, never NaN. At 90° (c₁ = 0), where η c₁ + c₂ = 0, and at
// η = 1 grazing (k = 0), F is still 1 and nothing is NaN.
TEST(Refraction, TotalInternalReflectionBeyondTheCriticalAngle) {
    EXPECT_NEAR(std::asin(1.0 / 1.5) * 180.0 / pi, 41.8103, 1e-4);
    const eq::Interface<float> below = at(41.8, 1.5);
    EXPECT_FALSE(below.total_internal_reflection);
    EXPECT_GT(below.k, 0.0f);
    EXPECT_NEAR(below.k, 0.000403, 2e-6);
    EXPECT_LT(below.fresnel, 1.0f);
    EXPECT_NEAR(below.fresnel, fresnel_reference(41.8, 1.5), 1e-3);
    for (double theta1 : {42.0, 60.0, 89.0, 90.0}) {
        SCOPED_TRACE(theta1);
        const eq::Interface<float> hit = at(theta1, 1.5);
        EXPECT_TRUE(hit.total_internal_reflection);
        EXPECT_LE(hit.k, 0.0f);
        EXPECT_EQ(hit.cos_refracted, 0.0f);
        EXPECT_EQ(hit.fresnel, 1.0f);
        EXPECT_EQ(hit.refracted.x, hit.reflected.x);
        EXPECT_EQ(hit.refracted.y, hit.reflected.y);
        EXPECT_EQ(hit.refracted.z, hit.reflected.z);
    }
    // Exactly grazing at η = 1: c₁ = 0 and k = 0, so both Fresnel
    // denominators are 0; the guard divides by 1 there instead (no 0/0 even
    // in the lane that select discards: no invalid-operation flag is raised).
    volatile float one = 1.0f;  // not folded at compile time
    std::feclearexcept(FE_ALL_EXCEPT);
    const eq::Interface<float> grazing =
        eq::refract_interface(Vec3<float>{one, 0, 0}, Vec3<float>{0, one, 0}, float(one));
    EXPECT_FALSE(std::fetestexcept(FE_INVALID | FE_DIVBYZERO));
    // The same with a SIMD batch, where select is a blend and both of its
    // sides are always computed: the guard is what keeps 0/0 away.
    using Batch = xsimd::batch<float, xsimd::default_arch>;
    std::feclearexcept(FE_ALL_EXCEPT);
    const eq::Interface<Batch> grazing_lanes =
        eq::refract_interface(Vec3<Batch>{Batch(one), Batch(0.0f), Batch(0.0f)},
                              Vec3<Batch>{Batch(0.0f), Batch(one), Batch(0.0f)}, Batch(float(one)));
    EXPECT_FALSE(std::fetestexcept(FE_INVALID | FE_DIVBYZERO));
    EXPECT_TRUE(xsimd::all(grazing_lanes.fresnel == Batch(1.0f)));
    EXPECT_TRUE(grazing.total_internal_reflection);
    EXPECT_EQ(grazing.fresnel, 1.0f);
    EXPECT_FALSE(std::isnan(grazing.refracted.x) || std::isnan(grazing.fresnel));
}

// Fresnel is the same both ways through an interface: F(θ₁, η) = F(θ₂, 1/η).
// Entering glass at 35°: sin θ₂ = sin 35°/1.5 = 0.382384, θ₂ = 22.4814°;
// θ₁ − θ₂ = 12.5186°, θ₁ + θ₂ = 57.4814°;
// (sin 12.5186°/sin 57.4814°)² = (0.216756/0.843217)² = 0.066079,
// (tan 12.5186°/tan 57.4814°)² = (0.222034/1.568565)² = 0.020037,
// F = (0.066079 + 0.020037)/2 = 0.0430579 ≈ 0.04306; leaving glass at
// 22.4814° swaps θ₁ and θ₂, and both squared ratios only change sign inside.
TEST(Refraction, FresnelIsTheSameBothWays) {
    const double theta2 = std::asin(std::sin(radians(35.0)) / 1.5) * 180.0 / pi;
    EXPECT_NEAR(theta2, 22.4814, 1e-4);
    const float in = at(35.0, 1.0 / 1.5).fresnel;
    const float out = at(theta2, 1.5).fresnel;
    EXPECT_NEAR(in, 0.0430579, 1e-6);
    EXPECT_NEAR(out, 0.0430579, 1e-6);
    EXPECT_NEAR(in, out, 1e-6);
}

// R = d − 2(d·n)n, computed here from d and n directly: at 30° in the frame
// above, d = (0.5·0.8 − 0.866025·0.6, 0.5·(−0.6) − 0.866025·0.8, 0) =
// (−0.119615, −0.992820, 0), d·n = −0.866025, R = d + 1.732051·n =
// (0.919615, 0.392820, 0): |R| = 1 and R·n = 0.866025 = c₁.
TEST(Refraction, MirrorDirection) {
    const eq::Interface<float> at30 = at(30.0, 1.0 / 1.5);
    EXPECT_NEAR(at30.reflected.x, 0.919615, 1e-6);
    EXPECT_NEAR(at30.reflected.y, 0.392820, 1e-6);
    EXPECT_NEAR(at30.reflected.z, 0.0, 1e-6);
    for (double eta : {1.0 / 1.5, 1.5}) {
        for (double theta1 : {0.0, 30.0, 42.0, 75.0}) {
            SCOPED_TRACE(testing::Message() << eta << " at " << theta1);
            const Vec3<float> d = incoming(theta1);
            const eq::Interface<float> hit = eq::refract_interface(d, normal, float(eta));
            const double d_dot_n = dot(d, normal_d);
            EXPECT_NEAR(hit.reflected.x, d.x - 2.0 * d_dot_n * normal_d.x, 1e-6);
            EXPECT_NEAR(hit.reflected.y, d.y - 2.0 * d_dot_n * normal_d.y, 1e-6);
            EXPECT_NEAR(hit.reflected.z, d.z - 2.0 * d_dot_n * normal_d.z, 1e-6);
            EXPECT_NEAR(length(hit.reflected), 1.0, 1e-6);
            EXPECT_NEAR(dot(hit.reflected, normal_d), std::cos(radians(theta1)), 1e-6);
            EXPECT_NEAR(dot(hit.reflected, normal_d), hit.cos_incident, 1e-6);
        }
    }
}

// Beer–Lambert, A = (a/255)^(ℓ/D): white (a = 255) absorbs nothing, black
// (a = 0) everything after any distance but nothing at ℓ = 0; a = 128 leaves
// 128/255 = 0.501961 after D and (128/255)² = 0.251965 after 2D, and
// √(128/255) = 0.708492 after D/2.
TEST(Refraction, BeerLambertAbsorption) {
    const float d = 2.5f;  // D
    EXPECT_EQ(eq::absorption(1.0f, 3.7f, d), 1.0f);
    EXPECT_EQ(eq::absorption(0.0f, 0.1f, d), 0.0f);
    EXPECT_EQ(eq::absorption(0.0f, 3.7f, d), 0.0f);
    EXPECT_EQ(eq::absorption(0.0f, 0.0f, d), 1.0f);
    EXPECT_EQ(eq::absorption(128.0f / 255.0f, 0.0f, d), 1.0f);
    EXPECT_NEAR(eq::absorption(128.0f / 255.0f, d, d), 0.501961, 1e-6);
    EXPECT_NEAR(eq::absorption(128.0f / 255.0f, 2.0f * d, d), 0.251965, 1e-6);
    EXPECT_NEAR(eq::absorption(128.0f / 255.0f, 0.5f * d, d), 0.708492, 1e-6);
    const Vec3<float> a = eq::absorption(Vec3<float>{1.0f, 128.0f / 255.0f, 0.0f}, 2.0f * d, d);
    EXPECT_EQ(a.x, 1.0f);
    EXPECT_NEAR(a.y, 0.251965, 1e-6);
    EXPECT_EQ(a.z, 0.0f);
}

// The same text with T = an xsimd batch: each lane gives what float gives,
// here with a TIR lane (leaving glass at 60°) between lanes that refract,
// and a grazing lane, none of them NaN.
TEST(Refraction, BatchLanesMatchFloat) {
    using Batch = xsimd::batch<float, xsimd::default_arch>;
    constexpr std::size_t lanes = Batch::size;
    struct Case {
        double theta1, eta;
        float color, length;
    };
    const std::array<Case, 4> cases{{{30.0, 1.0 / 1.5, 0.5f, 1.0f},
                                     {60.0, 1.5, 0.0f, 0.0f},
                                     {20.0, 1.5, 0.0f, 2.0f},
                                     {90.0, 1.5, 128.0f / 255.0f, 3.0f}}};
    alignas(64) std::array<float, lanes> dx{}, dy{}, dz{}, eta{}, color{}, length{};
    for (std::size_t i = 0; i < lanes; ++i) {
        const Case& c = cases[i % cases.size()];
        const Vec3<float> d = incoming(c.theta1);
        dx[i] = d.x;
        dy[i] = d.y;
        dz[i] = d.z;
        eta[i] = static_cast<float>(c.eta);
        color[i] = c.color;
        length[i] = c.length;
    }
    const auto load = [](const std::array<float, lanes>& values) {
        return Batch::load_aligned(values.data());
    };
    const Vec3<Batch> d{load(dx), load(dy), load(dz)};
    const Vec3<Batch> n{Batch(normal.x), Batch(normal.y), Batch(normal.z)};
    const eq::Interface<Batch> batch = eq::refract_interface(d, n, load(eta));
    const Batch absorbed = eq::absorption(load(color), load(length), Batch(2.0f));
    const auto lane = [](const Batch& b, std::size_t i) {
        alignas(64) std::array<float, lanes> values;
        b.store_aligned(values.data());
        return values[i];
    };
    bool saw_tir = false, saw_refraction = false;
    for (std::size_t i = 0; i < lanes; ++i) {
        SCOPED_TRACE(i);
        const eq::Interface<float> one =
            eq::refract_interface(Vec3<float>{dx[i], dy[i], dz[i]}, normal, eta[i]);
        const std::array<std::pair<float, float>, 11> pairs{{
            {lane(batch.cos_incident, i), one.cos_incident},
            {lane(batch.k, i), one.k},
            {lane(batch.cos_refracted, i), one.cos_refracted},
            {lane(batch.fresnel, i), one.fresnel},
            {lane(batch.refracted.x, i), one.refracted.x},
            {lane(batch.refracted.y, i), one.refracted.y},
            {lane(batch.refracted.z, i), one.refracted.z},
            {lane(batch.reflected.x, i), one.reflected.x},
            {lane(batch.reflected.y, i), one.reflected.y},
            {lane(batch.reflected.z, i), one.reflected.z},
            {lane(absorbed, i), eq::absorption(color[i], length[i], 2.0f)},
        }};
        for (const auto& [from_batch, from_float] : pairs) {
            EXPECT_FALSE(std::isnan(from_batch));
            EXPECT_NEAR(from_batch, from_float, 1e-6f);
        }
        const bool tir = batch.total_internal_reflection.get(i);
        EXPECT_EQ(tir, one.total_internal_reflection);
        (tir ? saw_tir : saw_refraction) = true;
    }
    EXPECT_TRUE(saw_tir);
    EXPECT_TRUE(saw_refraction);
}

// The same text with T = a GLSL expression: the printed statements contain
// the operations of the equations (√ of max(k, 0), the TIR comparison k ≤ 0,
// selects, pow for absorption), and the expression DAG, evaluated, gives
// the float results, TIR included.
TEST(Refraction, GlslExpressionsPrintAndEvaluateAsFloat) {
    using litkit::glsl::Expr;
    const Vec3<Expr> d = litkit::glsl::vec3_variable("d");
    const Vec3<Expr> n = litkit::glsl::vec3_variable("n");
    const Expr eta = Expr::variable("eta");
    const eq::Interface<Expr> hit = eq::refract_interface(d, n, eta);
    const Expr absorbed =
        eq::absorption(Expr::variable("a"), Expr::variable("l"), Expr::variable("D"));
    const std::vector<litkit::glsl::Output> outputs{
        {"F", hit.fresnel},       {"T.x", hit.refracted.x}, {"T.y", hit.refracted.y},
        {"T.z", hit.refracted.z}, {"R.x", hit.reflected.x}, {"R.y", hit.reflected.y},
        {"R.z", hit.reflected.z}, {"A", absorbed}};
    const std::string glsl = litkit::glsl::print_statements(outputs, {}, {}, "");
    SCOPED_TRACE(glsl);
    EXPECT_NE(glsl.find("sqrt(max("), std::string::npos);
    EXPECT_NE(glsl.find("<= 0.0"), std::string::npos);
    EXPECT_NE(glsl.find(" ? 1.0 : 0.5 * "), std::string::npos);  // F = 1 under TIR
    EXPECT_EQ(litkit::glsl::to_glsl(absorbed),
              "(l / D > 0.0 ? (a > 0.0 ? pow(max(a, 0.0), l / D) : 0.0) : 1.0)");
    EXPECT_NE(glsl.find("F = "), std::string::npos);
    EXPECT_EQ(glsl.find("nan"), std::string::npos);

    for (const auto& [theta1, eta_value] : std::array<std::pair<double, double>, 4>{
             {{0.0, 1.0 / 1.5}, {80.0, 1.0 / 1.5}, {40.0, 1.5}, {60.0, 1.5}}}) {
        SCOPED_TRACE(theta1);
        const Vec3<float> dv = incoming(theta1);
        const litkit::glsl::Bindings bindings{{"d.x", dv.x},
                                              {"d.y", dv.y},
                                              {"d.z", dv.z},
                                              {"n.x", normal.x},
                                              {"n.y", normal.y},
                                              {"n.z", normal.z},
                                              {"eta", float(eta_value)},
                                              {"a", 0.5f},
                                              {"l", 3.0f},
                                              {"D", 2.0f}};
        const eq::Interface<float> one = eq::refract_interface(dv, normal, float(eta_value));
        EXPECT_EQ(evaluate(hit.fresnel, bindings), one.fresnel);
        EXPECT_EQ(evaluate(hit.refracted.x, bindings), one.refracted.x);
        EXPECT_EQ(evaluate(hit.refracted.y, bindings), one.refracted.y);
        EXPECT_EQ(evaluate(hit.reflected.x, bindings), one.reflected.x);
        EXPECT_EQ(evaluate(hit.total_internal_reflection, bindings), one.total_internal_reflection);
        EXPECT_EQ(evaluate(absorbed, bindings), eq::absorption(0.5f, 3.0f, 2.0f));
    }
}
