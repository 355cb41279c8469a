// The SIMD kernel sets' interpolation of Phong varyings against the scalar
// formulas of the fragment stage (render.cpp), bit for bit: the kernels are
// built with FMA, and a fused multiply-add would round differently. Every
// set this CPU runs is checked; the test says which ran and which it skipped.
#include <gtest/gtest.h>

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

TEST(Kernels, InterpolateRoundsAsTheScalarFormulasOnEverySpanLength) {
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
                set->interpolate(inverse_w.data(), w1.data(), w2.data(), count, corner,
                                 faceted ? face : nullptr,
                                 {out[0].data(), out[1].data(), out[2].data(), out[3].data(),
                                  out[4].data(), out[5].data()});
                for (std::size_t i = 0; i < count; ++i) {
                    volatile float w = 1.0f / inverse_w[i];
                    volatile float q1 = w1[i] * w, q2 = w2[i] * w;
                    const float q0 = 1.0f - q1 - q2;
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
            }
        }
        EXPECT_EQ(compared, 6 * 2 * (70 * 71 / 2));
    }
}
