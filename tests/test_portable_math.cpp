// SPDX-License-Identifier: MIT
// src/core/portable_math.hpp: sine and cosine of degrees and powers built
// from IEEE operations only, checked against the C library in long double
// (x87's 64-bit significand: 11 bits beyond a double) and against C's rules
// for powf's special cases.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include "core/portable_math.hpp"  // internal
#include "litkit/equations.hpp"

namespace {

using litkit::power;
using litkit::sin_cos_degrees;

constexpr long double pi_long = 3.141592653589793238462643383279502884L;

// The float nearest x, rounded once from long double.
float nearest_float(long double x) { return static_cast<float>(x); }

TEST(SinCosDegrees, RightAnglesAreExact) {
    const double sines[4] = {0.0, 1.0, 0.0, -1.0}, cosines[4] = {1.0, 0.0, -1.0, 0.0};
    for (int k = -12; k <= 12; ++k) {
        const litkit::SineCosine angle = sin_cos_degrees(90.0 * k);
        const int quarter = ((k % 4) + 4) % 4;
        EXPECT_EQ(angle.sine, sines[quarter]) << 90 * k;
        EXPECT_EQ(angle.cosine, cosines[quarter]) << 90 * k;
        EXPECT_FALSE(std::signbit(angle.sine) && angle.sine == 0.0) << "-0 at " << 90 * k;
    }
}

TEST(SinCosDegrees, WholeTurnsComeOffExactly) {
    const litkit::SineCosine turned = sin_cos_degrees(10000.0), reduced = sin_cos_degrees(280.0);
    EXPECT_EQ(turned.sine, reduced.sine);
    EXPECT_EQ(turned.cosine, reduced.cosine);
    std::mt19937 random(7);
    std::uniform_real_distribution<float> degrees(-360.0f, 360.0f);
    for (int i = 0; i < 1000; ++i) {
        const double d = degrees(random);
        const int turns = static_cast<int>(random() % 2001) - 1000;
        const litkit::SineCosine a = sin_cos_degrees(d), b = sin_cos_degrees(d + 360.0 * turns);
        EXPECT_EQ(a.sine, b.sine) << d << " + " << turns << " turns";
        EXPECT_EQ(a.cosine, b.cosine) << d << " + " << turns << " turns";
    }
}

TEST(SinCosDegrees, WithinTwoDoubleUlpsOfTheTrueValues) {
    std::mt19937 random(11);
    std::uniform_real_distribution<float> degrees(-1e4f, 1e4f);
    int floats_off = 0;
    for (int i = 0; i < 100000; ++i) {
        const float d = degrees(random);
        const long double radians = std::fmod(static_cast<long double>(d), 360.0L) * pi_long / 180;
        const long double sine = std::sin(radians), cosine = std::cos(radians);
        const litkit::SineCosine angle = sin_cos_degrees(d);
        ASSERT_LE(std::fabs(static_cast<long double>(angle.sine) - sine), 4.5e-16L) << d;
        ASSERT_LE(std::fabs(static_cast<long double>(angle.cosine) - cosine), 4.5e-16L) << d;
        // Rounded to float (as rotations use them): the nearest float but for ties.
        if (static_cast<float>(angle.sine) != nearest_float(sine)) ++floats_off;
        if (static_cast<float>(angle.cosine) != nearest_float(cosine)) ++floats_off;
    }
    EXPECT_LE(floats_off, 5);
}

// The special cases of C17 F.10.4.4, as the C library's powf gives them.
TEST(Power, SpecialCasesAreCs) {
    const float infinity = std::numeric_limits<float>::infinity();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float values[] = {0.0f, -0.0f, 1.0f,     -1.0f,     2.0f, -2.0f,  0.5f,  -0.5f,
                            3.0f, -3.0f, infinity, -infinity, nan,  1e-40f, 1e30f, -1e30f};
    for (float base : values) {
        for (float exponent : values) {
            const float ours = power(base, exponent), c = std::pow(base, exponent);
            if (std::isnan(c)) {
                EXPECT_TRUE(std::isnan(ours)) << base << "^" << exponent;
            } else {
                EXPECT_EQ(std::bit_cast<std::uint32_t>(ours), std::bit_cast<std::uint32_t>(c))
                    << base << "^" << exponent << ": " << ours << " against " << c;
            }
        }
    }
    EXPECT_TRUE(std::isnan(power(-0.5f, 2.5f)));  // a negative base, a fractional exponent
    EXPECT_EQ(power(-0.5f, 3.0f), -0.125f);
    EXPECT_EQ(power(-0.5f, 64.0f), 0x1p-64f);
}

TEST(Power, IsTheNearestFloatOfTheTruePower) {
    // Bases of the lighting (0 to 1), whole and fractional exponents up to
    // 10000 (shininess), gamma's 1/2.2 and bases above 1 with negative exponents.
    std::mt19937 random(3);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f), large(1.0f, 100.0f);
    int off = 0;
    for (int i = 0; i < 200000; ++i) {
        float base = unit(random), exponent = 0.0f;
        switch (i % 5) {
            case 0:
                exponent = std::floor(unit(random) * 65.0f);
                break;
            case 1:
                exponent = unit(random) * 10000.0f;
                break;
            case 2:
                exponent = unit(random) * 5.0f;
                break;
            case 3:
                exponent = 1.0f / 2.2f;
                break;
            default:
                base = large(random);
                exponent = -unit(random) * 15.0f;
        }
        const long double exact = std::pow(static_cast<long double>(base), exponent);
        const float ours = power(base, exponent);
        const float nearest = nearest_float(exact);
        if (ours != nearest) {
            ++off;
            ASSERT_EQ(ours, std::nextafter(nearest, ours)) << base << "^" << exponent;
        }
    }
    EXPECT_LE(off, 5);
}

TEST(Power, IsTheEquationsPowerOfFloats) {
    for (float base : {0.0f, 0.25f, 0.9f, 0.999f})
        for (float exponent : {0.0f, 1.0f, 2.0f, 32.0f, 37.3f, 10000.0f})
            EXPECT_EQ(litkit::equations::pow(base, exponent), power(base, exponent));
}

}  // namespace
