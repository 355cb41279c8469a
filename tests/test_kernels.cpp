// The SIMD kernel sets' interpolation of Phong varyings against the scalar
// formulas of the fragment stage (render.cpp), bit for bit: the kernels are
// built with FMA, and a fused multiply-add would round differently. Every
// set this CPU runs is checked; the test says which ran and which it skipped.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <random>
#include <vector>

#include "cpu/shade_kernel.hpp"

namespace {

using litkit::kernels::Kernels;

std::vector<const Kernels*> runnable_sets() {
    std::vector<const Kernels*> sets{&litkit::kernels::portable_kernels};
    if (litkit::kernels::cpu_has_avx2()) sets.push_back(&litkit::kernels::avx2_kernels);
    else std::printf("skipped the avx2 set: this CPU lacks AVX2 or FMA\n");
    if (litkit::kernels::cpu_has_avx512()) sets.push_back(&litkit::kernels::avx512_kernels);
    else std::printf("skipped the avx512 set: this CPU lacks AVX-512 F/BW/DQ/VL\n");
    return sets;
}

// The fragment stage's formulas (render.cpp: shade_row, interpolate_surface),
// each product rounded on its own. `volatile` keeps this file's compiler
// from fusing them as well.
float mix(float q0, float q1, float q2, float a, float b, float c) {
    volatile float x = q0 * a, y = q1 * b, z = q2 * c;
    return x + y + z;
}

}  // namespace

TEST(Kernels, WeightsAndInterpolationRoundAsTheScalarFormulasOnEveryLength) {
    std::mt19937 random(16);
    std::uniform_real_distribution<float> depth(0.05f, 3.0f), weight(0.0f, 1.0f),
        value(-20.0f, 20.0f);
    for (const Kernels* set : runnable_sets()) {
        std::printf("checking the %s set\n", set->name);
        int compared = 0;
        for (std::size_t count = 1; count <= 70; ++count) {
            for (bool faceted : {false, true}) {
                std::vector<float> inverse_w(count), w1(count), w2(count);
                for (std::size_t i = 0; i < count; ++i) {
                    inverse_w[i] = depth(random);
                    // b1/w1 and b2/w2 with b1 + b2 ≤ 1, as the rasterizer makes them.
                    const float b1 = weight(random), b2 = weight(random) * (1.0f - b1);
                    w1[i] = b1 * inverse_w[i] * weight(random);
                    w2[i] = b2 * inverse_w[i] * weight(random);
                }
                float corner[3][6];
                for (auto& c : corner)
                    for (float& v : c) v = value(random);
                const float face[3] = {0.0f, 0.6f, 0.8f};
                std::vector<float> out[6];
                for (auto& o : out) o.assign(count + 1, -1.0f);  // one past: must stay
                std::vector<float> weights[3];
                for (auto& q : weights) q.assign(count + 1, -1.0f);
                set->perspective_weights(inverse_w.data(), w1.data(), w2.data(), count,
                                         weights[0].data(), weights[1].data(), weights[2].data());
                set->interpolate(weights[0].data(), weights[1].data(), weights[2].data(), count,
                                 corner, faceted ? face : nullptr,
                                 {out[0].data(), out[1].data(), out[2].data(), out[3].data(),
                                  out[4].data(), out[5].data()});
                for (std::size_t i = 0; i < count; ++i) {
                    volatile float w = 1.0f / inverse_w[i];
                    volatile float q1 = w1[i] * w, q2 = w2[i] * w;
                    const float q0 = 1.0f - q1 - q2;
                    const float expected_weights[3] = {q0, q1, q2};
                    for (int k = 0; k < 3; ++k)
                        ASSERT_EQ(std::memcmp(&expected_weights[k], &weights[k][i], sizeof(float)), 0)
                            << set->name << ": " << count << " pixels, pixel " << i << ", q" << k
                            << ": " << weights[k][i] << " instead of " << expected_weights[k];
                    for (int k = 0; k < 6; ++k) {
                        const float expected = faceted && k >= 3
                                                   ? face[k - 3]
                                                   : mix(q0, q1, q2, corner[0][k], corner[1][k],
                                                         corner[2][k]);
                        ASSERT_EQ(std::memcmp(&expected, &out[k][i], sizeof(float)), 0)
                            << set->name << ": span of " << count << ", pixel " << i
                            << ", varying " << k << ": " << out[k][i] << " instead of "
                            << expected;
                        ++compared;
                    }
                }
                for (int k = 0; k < 6; ++k) ASSERT_EQ(out[k][count], -1.0f) << "wrote past the span";
                for (int k = 0; k < 3; ++k) ASSERT_EQ(weights[k][count], -1.0f) << "wrote past the row";
            }
        }
        EXPECT_EQ(compared, 6 * 2 * (70 * 71 / 2));
    }
}

// The visibility kernels (render.cpp's wide-triangle rows and small
// triangles) against the rule written out here pixel by pixel: random edge
// functions and depths (some NaN, some equal to the new 1/w), every row
// length and box width, so that every lane, the last partial vector and the
// ninth pixel of a small triangle's row are exercised.
namespace {

struct VisibilityBuffers {
    std::vector<float> depth, weight1, weight2;
    std::vector<const void*> visible;
    explicit VisibilityBuffers(std::size_t n) : depth(n), weight1(n), weight2(n), visible(n) {}
    bool operator==(const VisibilityBuffers& other) const {
        return std::memcmp(depth.data(), other.depth.data(), depth.size() * sizeof(float)) == 0 &&
               std::memcmp(weight1.data(), other.weight1.data(), depth.size() * sizeof(float)) == 0 &&
               std::memcmp(weight2.data(), other.weight2.data(), depth.size() * sizeof(float)) == 0 &&
               visible == other.visible;
    }
};

// One pixel's test and writes, as render.cpp states them.
void expect_pixel(float p0, float p1, float p2, const void* triangle, VisibilityBuffers& b, std::size_t i) {
    volatile float sum = p0 + p1;
    const float inverse_w = sum + p2;
    if (inverse_w <= b.depth[i]) return;
    b.depth[i] = inverse_w;
    b.visible[i] = triangle;
    b.weight1[i] = p1;
    b.weight2[i] = p2;
}

}  // namespace

TEST(Kernels, VisibilityRowsMatchThePixelRuleOnEveryLength) {
    std::mt19937 random(61);
    std::uniform_int_distribution<std::int64_t> value(-(std::int64_t{1} << 40), std::int64_t{1} << 40),
        step(-(std::int64_t{1} << 20), std::int64_t{1} << 20);
    std::uniform_real_distribution<float> depth(0.0f, 2.0f), weight(1e-13f, 1e-11f);
    int triangle_tag = 0;
    for (const Kernels* set : runnable_sets()) {
        std::printf("checking the %s set's visibility_row\n", set->name);
        for (std::size_t count = 0; count <= 40; ++count) {
            for (int trial = 0; trial < 20; ++trial) {
                const std::int64_t v[3] = {value(random), value(random), value(random)};
                const std::int64_t s[3] = {step(random), step(random), step(random)};
                const float w[3] = {weight(random), weight(random), weight(random)};
                VisibilityBuffers got(count + 1), expected(count + 1);
                for (std::size_t i = 0; i <= count; ++i) {
                    got.depth[i] = i % 7 == 3 ? std::nanf("") : depth(random);
                    got.weight1[i] = got.weight2[i] = -1.0f;
                }
                expected = got;
                const void* triangle = &triangle_tag;
                set->visibility_row(v, s, w, count, got.depth.data(), got.visible.data(), triangle,
                                    got.weight1.data(), got.weight2.data());
                for (std::size_t i = 0; i < count; ++i) {
                    const auto at = static_cast<std::int64_t>(i);
                    expect_pixel(static_cast<float>(v[0] + at * s[0]) * w[0],
                                 static_cast<float>(v[1] + at * s[1]) * w[1],
                                 static_cast<float>(v[2] + at * s[2]) * w[2], triangle, expected, i);
                }
                ASSERT_TRUE(got == expected) << set->name << ": a row of " << count << ", trial " << trial;
            }
        }
    }
}

TEST(Kernels, SmallTrianglesMatchThePixelRuleInEveryLane) {
    std::mt19937 random(62);
    std::uniform_int_distribution<std::int32_t> edge(-3000, 3000), along(-700, 700);
    std::uniform_int_distribution<int> bias(-1, 0), offset(0, 5);
    std::uniform_real_distribution<float> depth(0.0f, 2.0f), weight(1e-5f, 1e-3f);
    int triangle_tag = 0;
    int sets_with_kernel = 0;
    for (const Kernels* set : runnable_sets()) {
        if (!set->visibility_small) {
            std::printf("the %s set has no visibility_small (render.cpp tests pixels one by one)\n", set->name);
            continue;
        }
        ++sets_with_kernel;
        std::printf("checking the %s set's visibility_small\n", set->name);
        int covered_ninth = 0;
        for (int span = 0; span <= 8; ++span) {
            for (int rows = 1; rows <= 9; ++rows) {
                for (int trial = 0; trial < 40; ++trial) {
                    litkit::kernels::SmallTriangle t{};
                    for (int k = 0; k < 3; ++k) {
                        t.bias[k] = bias(random);
                        // Mostly inside, so that whole rows are covered too.
                        t.origin[k] = edge(random) + 2000 + t.bias[k];
                        t.step_x[k] = along(random);
                        t.step_y[k] = along(random);
                        t.weight[k] = weight(random);
                    }
                    t.rows = rows;
                    t.span = span;
                    t.min_x = offset(random);
                    t.triangle = &triangle_tag;
                    const std::size_t stride = static_cast<std::size_t>(t.min_x + span + 3);
                    VisibilityBuffers got(stride * static_cast<std::size_t>(rows)), expected = got;
                    for (std::size_t i = 0; i < got.depth.size(); ++i) {
                        got.depth[i] = i % 5 == 2 ? std::nanf("") : depth(random);
                        got.weight1[i] = got.weight2[i] = -1.0f;
                    }
                    expected = got;
                    std::vector<int> begin_got(static_cast<std::size_t>(rows), 100), end_got(begin_got.size(), 0);
                    std::vector<int> begin_expected = begin_got, end_expected = end_got;
                    set->visibility_small(t, got.depth.data(), got.visible.data(), got.weight1.data(),
                                          got.weight2.data(), stride, begin_got.data(), end_got.data());
                    for (int r = 0; r < rows; ++r) {
                        for (int x = 0; x <= span; ++x) {
                            std::int32_t e[3];
                            bool inside = true;
                            for (int k = 0; k < 3; ++k) {
                                e[k] = t.origin[k] + r * t.step_y[k] + x * t.step_x[k];
                                inside = inside && e[k] >= 0;
                            }
                            if (!inside) continue;
                            if (x == 8) ++covered_ninth;
                            begin_expected[r] = std::min(begin_expected[r], t.min_x + x);
                            end_expected[r] = std::max(end_expected[r], t.min_x + x + 1);
                            expect_pixel(static_cast<float>(e[0] - t.bias[0]) * t.weight[0],
                                         static_cast<float>(e[1] - t.bias[1]) * t.weight[1],
                                         static_cast<float>(e[2] - t.bias[2]) * t.weight[2], t.triangle,
                                         expected, static_cast<std::size_t>(r) * stride +
                                                       static_cast<std::size_t>(t.min_x + x));
                        }
                    }
                    ASSERT_TRUE(got == expected) << set->name << ": span " << span << ", rows " << rows;
                    ASSERT_EQ(begin_got, begin_expected) << set->name << ": span " << span << ", rows " << rows;
                    ASSERT_EQ(end_got, end_expected) << set->name << ": span " << span << ", rows " << rows;
                }
            }
        }
        EXPECT_GT(covered_ninth, 50) << "the ninth pixel of a row was covered too rarely to test it";
    }
    if (sets_with_kernel == 0) std::printf("no set on this CPU has visibility_small\n");
}
