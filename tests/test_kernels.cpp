// SPDX-License-Identifier: MIT
// The SIMD kernel sets' interpolation of Phong varyings against the scalar
// formulas of the fragment stage (src/cpu/fragment.cpp), bit for bit: the kernels are
// built with FMA, and a fused multiply-add would round differently. Every
// set this CPU runs is checked; the test says which ran and which it skipped.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

#include <glm/geometric.hpp>

#include "cpu/shade_kernel.hpp"
#include "cpu/shade_kernel_impl.hpp"  // equations::pow of batches
#include "litkit/lighting.hpp"        // to_pixel

namespace {

using litkit::kernels::Kernels;

std::vector<const Kernels*> runnable_sets() {
    std::vector<const Kernels*> sets{&litkit::kernels::portable_kernels};
    if (litkit::kernels::cpu_has_avx2())
        sets.push_back(&litkit::kernels::avx2_kernels);
    else
        std::printf("skipped the avx2 set: this CPU lacks AVX2 or FMA\n");
    if (litkit::kernels::cpu_has_avx512())
        sets.push_back(&litkit::kernels::avx512_kernels);
    else
        std::printf("skipped the avx512 set: this CPU lacks AVX-512 F/BW/DQ/VL\n");
    return sets;
}

// The fragment stage's formulas (fragment.cpp: shade_row, interpolate_normal),
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
            std::vector<float> inverse_w(count), w1(count), w2(count);
            for (std::size_t i = 0; i < count; ++i) {
                inverse_w[i] = depth(random);
                // b1/w1 and b2/w2 with b1 + b2 ≤ 1, as the rasterizer makes them.
                const float b1 = weight(random), b2 = weight(random) * (1.0f - b1);
                w1[i] = b1 * inverse_w[i] * weight(random);
                w2[i] = b2 * inverse_w[i] * weight(random);
            }
            float normal[3][3];
            for (auto& c : normal)
                for (float& v : c) v = value(random);
            std::vector<float> out[3];
            for (auto& o : out) o.assign(count + 1, -1.0f);  // one past: must stay
            std::vector<float> weights[4];                   // w, q0, q1, q2
            for (auto& q : weights) q.assign(count + 1, -1.0f);
            set->perspective_weights(inverse_w.data(), w1.data(), w2.data(), count,
                                     weights[0].data(), weights[1].data(), weights[2].data(),
                                     weights[3].data());
            set->interpolate(weights[1].data(), weights[2].data(), weights[3].data(), count, normal,
                             {out[0].data(), out[1].data(), out[2].data()});
            for (std::size_t i = 0; i < count; ++i) {
                volatile float w = 1.0f / inverse_w[i];
                volatile float q1 = w1[i] * w, q2 = w2[i] * w;
                const float q0 = 1.0f - q1 - q2;
                const float expected_weights[4] = {w, q0, q1, q2};
                for (int k = 0; k < 4; ++k)
                    ASSERT_EQ(std::memcmp(&expected_weights[k], &weights[k][i], sizeof(float)), 0)
                        << set->name << ": " << count << " pixels, pixel " << i << ", value " << k
                        << " (w, q0, q1, q2): " << weights[k][i] << " instead of "
                        << expected_weights[k];
                for (int k = 0; k < 3; ++k) {
                    const float expected =
                        mix(q0, q1, q2, normal[0][k], normal[1][k], normal[2][k]);
                    ASSERT_EQ(std::memcmp(&expected, &out[k][i], sizeof(float)), 0)
                        << set->name << ": span of " << count << ", pixel " << i << ", normal " << k
                        << ": " << out[k][i] << " instead of " << expected;
                    ++compared;
                }
            }
            for (int k = 0; k < 3; ++k) ASSERT_EQ(out[k][count], -1.0f) << "wrote past the span";
            for (int k = 0; k < 4; ++k) ASSERT_EQ(weights[k][count], -1.0f) << "wrote past the row";
        }
        EXPECT_EQ(compared, 3 * (70 * 71 / 2));
    }
}

// The visibility kernels (rasterize.cpp's wide-triangle rows and small
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
               std::memcmp(weight1.data(), other.weight1.data(), depth.size() * sizeof(float)) ==
                   0 &&
               std::memcmp(weight2.data(), other.weight2.data(), depth.size() * sizeof(float)) ==
                   0 &&
               visible == other.visible;
    }
};

#if defined(__linux__)
// A copy of `values` that ends where an inaccessible page begins: a kernel
// that touches memory past the end, even with every lane masked off,
// faults (GCC turns a masked extract and store into one instruction, and
// the CPU was seen to fault on it with a mask of 0).
template <class T>
class GuardedCopy {
  public:
    explicit GuardedCopy(const std::vector<T>& values) : size_(values.size()) {
        const auto page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
        const std::size_t bytes = size_ * sizeof(T);
        mapped_ = (bytes + page - 1) / page * page + page;
        base_ = mmap(nullptr, mapped_, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
        if (base_ == MAP_FAILED) throw std::runtime_error("mmap failed");
        char* const guard = static_cast<char*>(base_) + mapped_ - page;
        if (mprotect(guard, page, PROT_NONE) != 0) throw std::runtime_error("mprotect failed");
        data_ = reinterpret_cast<T*>(guard - bytes);
        std::memcpy(static_cast<void*>(data_), values.data(), bytes);
    }
    GuardedCopy(const GuardedCopy&) = delete;
    GuardedCopy& operator=(const GuardedCopy&) = delete;
    ~GuardedCopy() { munmap(base_, mapped_); }
    T* data() { return data_; }
    std::vector<T> values() const { return std::vector<T>(data_, data_ + size_); }

  private:
    std::size_t size_;
    std::size_t mapped_ = 0;
    void* base_ = nullptr;
    T* data_ = nullptr;
};
#endif

// One pixel's test and writes, as rasterize.cpp states them.
void expect_pixel(float p0, float p1, float p2, const void* triangle, VisibilityBuffers& b,
                  std::size_t i) {
    volatile float sum = p0 + p1;
    const float inverse_w = sum + p2;
    if (inverse_w <= b.depth[i]) return;
    b.depth[i] = inverse_w;
    b.visible[i] = triangle;
    b.weight1[i] = p1;
    b.weight2[i] = p2;
}

}  // namespace

// shade_phong lights each pixel at the point on its ray (RowRays) at its
// view depth: against the scalar lighting (equations::shade_scalar) at
// p = eye + w · (centre + k · across), k = first_k + 2i, on every length.
// The rays fan out fast and the light is near, so a pixel's p taken from a
// neighbour's ray (or the wrong depth) changes its colour far beyond the
// tolerance, which only covers SIMD against scalar roundings.
TEST(Kernels, ShadePhongLightsThePointOnEachPixelsRay) {
    std::mt19937 random(11);
    std::uniform_real_distribution<float> depth(2.0f, 4.0f), tilt(-0.3f, 0.3f);
    const litkit::RowRays rays{{0.0f, 0.5f, 5.0f}, {0.0f, -0.1f, -1.0f}, {0.004f, 0.001f, 0.0f}};
    const std::vector<litkit::equations::PreparedLight> lights{litkit::equations::prepare_light(
        litkit::Light{litkit::PointLight{{0.3f, 1.0f, 2.5f}}, {1, 1, 1}, 3.0f})};
    litkit::Material material;
    material.shininess = 40.0f;
    material.ks = 0.6f;
    for (const Kernels* set : runnable_sets()) {
        std::printf("checking the %s set\n", set->name);
        for (std::size_t count = 1; count <= 40; ++count) {
            const float first_k = -37.0f + static_cast<float>(count);
            std::vector<float> w(count), normals[3], r(count), g(count), b(count);
            for (std::size_t i = 0; i < count; ++i) {
                w[i] = depth(random);
                const glm::vec3 n = glm::normalize(glm::vec3(tilt(random), tilt(random), 1.0f));
                for (int c = 0; c < 3; ++c) normals[c].push_back(n[c]);
            }
            set->shade_phong(litkit::Reflection::Phong, lights, material,
                             {&rays, first_k, w.data(), normals[0].data(), normals[1].data(),
                              normals[2].data(), count},
                             {r.data(), g.data(), b.data()});
            for (std::size_t i = 0; i < count; ++i) {
                const float k = first_k + 2.0f * static_cast<float>(i);
                glm::vec3 p;
                for (int c = 0; c < 3; ++c) {
                    volatile float along = k * rays.across[c];
                    volatile float d = along + rays.centre[c];
                    volatile float step = w[i] * d;
                    p[c] = rays.eye[c] + step;
                }
                const glm::vec3 n(normals[0][i], normals[1][i], normals[2][i]);
                const glm::vec3 expected = litkit::equations::shade_scalar(
                    litkit::Reflection::Phong, lights, litkit::equations::splat<float>(material), p,
                    n, glm::vec3(rays.eye[0], rays.eye[1], rays.eye[2]));
                const float got[3] = {r[i], g[i], b[i]};
                for (int c = 0; c < 3; ++c)
                    ASSERT_NEAR(got[c], expected[c], 1e-5f + 1e-5f * std::abs(expected[c]))
                        << set->name << ": " << count << " pixels, pixel " << i << ", channel "
                        << c;
            }
        }
    }
}

// encode against litkit::to_pixel, the public scalar rule (docs/spec.md §4
// pixel values), on every length: intensities in and out of [0, 1], NaN,
// gamma 1 and 2.2. Inputs and output end at an inaccessible page, so that a
// kernel reading or writing past the row faults.
TEST(Kernels, EncodeWritesToPixelsBytesOnEveryLength) {
    std::mt19937 random(7);
    std::uniform_real_distribution<float> intensity(-0.2f, 1.3f);
    for (const Kernels* set : runnable_sets()) {
        std::printf("checking the %s set\n", set->name);
        for (const float gamma : {1.0f, 2.2f}) {
            for (std::size_t count = 1; count <= 70; ++count) {
                std::vector<float> channel[3];
                for (auto& c : channel) {
                    for (std::size_t i = 0; i < count; ++i) c.push_back(intensity(random));
                    c[random() % count] = std::numeric_limits<float>::quiet_NaN();
                }
                std::vector<std::uint8_t> expected;
                for (std::size_t i = 0; i < count; ++i)
                    for (const auto& c : channel) expected.push_back(litkit::to_pixel(c[i], gamma));
#if defined(__linux__)
                GuardedCopy<float> r(channel[0]), g(channel[1]), b(channel[2]);
                GuardedCopy<std::uint8_t> out(std::vector<std::uint8_t>(3 * count, 7));
                set->encode(r.data(), g.data(), b.data(), count, gamma, out.data());
                const std::vector<std::uint8_t> written = out.values();
#else
                std::vector<std::uint8_t> written(3 * count, 7);
                set->encode(channel[0].data(), channel[1].data(), channel[2].data(), count, gamma,
                            written.data());
#endif
                ASSERT_EQ(written, expected)
                    << set->name << ", " << count << " pixels, gamma " << gamma;
            }
        }
    }
}

TEST(Kernels, VisibilityRowsMatchThePixelRuleOnEveryLength) {
    std::mt19937 random(61);
    std::uniform_int_distribution<std::int64_t> value(-(std::int64_t{1} << 40),
                                                      std::int64_t{1} << 40),
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
                                 static_cast<float>(v[2] + at * s[2]) * w[2], triangle, expected,
                                 i);
                }
                ASSERT_TRUE(got == expected)
                    << set->name << ": a row of " << count << ", trial " << trial;
            }
        }
    }
}

// Random small triangles (at most 8 pixels across and down, as setup.cpp
// calls them small), their corners often on pixel centres and edges through
// them (the top-left rule's ties), partly left of the image or starting
// above the band: the kernels' coverage and writes against the rule written
// out here from the corners, in 64 bits, pixel by pixel.
TEST(Kernels, SmallTrianglesMatchThePixelRuleInEveryLane) {
    constexpr std::int32_t one = static_cast<std::int32_t>(litkit::kernels::subpixel_one);
    std::mt19937 random(62);
    std::uniform_int_distribution<std::int32_t> base(-3 * one, 6 * one), extent(0, 8 * one),
        coin(0, 3);
    std::uniform_real_distribution<float> depth(0.0f, 2.0f), weight(1e-9f, 1e-7f);
    int triangle_tag = 0;
    int sets_with_kernel = 0;
    for (const Kernels* set : runnable_sets()) {
        if (!set->visibility_small) {
            std::printf(
                "the %s set has no visibility_small (rasterize.cpp tests pixels one by one)\n",
                set->name);
            continue;
        }
        ++sets_with_kernel;
        std::printf("checking the %s set's visibility_small\n", set->name);
        int triangles = 0, on_edges = 0;
        std::vector<int> covered_at(9, 0);  // covered pixels by column within the box
        std::vector<int> spans(9, 0);
        while (triangles < 6000) {
            litkit::kernels::RasterTriangle t{};
            const std::int32_t bx = base(random), by = base(random);
            for (int k = 0; k < 3; ++k) {
                t.x[k] = bx + extent(random);
                t.y[k] = by + extent(random);
                // Often on the half-pixel grid: corners on pixel centres and
                // edges through them.
                if (coin(random) != 0) t.x[k] = t.x[k] / (one / 2) * (one / 2);
                if (coin(random) != 0) t.y[k] = t.y[k] / (one / 2) * (one / 2);
            }
            if (triangles % 8 == 0) {
                // A top edge from pixel centre to pixel centre 8 pixels on:
                // a box 9 pixels wide (the ninth, on the right corner, is
                // never covered: a right edge passes through it).
                t.x[0] = bx / one * one + one / 2;
                t.y[0] = t.y[1] = by / one * one + one / 2;
                t.x[1] = t.x[0] + 8 * one;
                t.y[2] = t.y[0] + 1 + extent(random);
            }
            // At most 8 pixels across and down (the grid may have widened it).
            const auto [min_fx, max_fx] = std::minmax({t.x[0], t.x[1], t.x[2]});
            const auto [min_fy, max_fy] = std::minmax({t.y[0], t.y[1], t.y[2]});
            if (max_fx - min_fx > 8 * one || max_fy - min_fy > 8 * one) continue;
            std::int64_t area = std::int64_t{t.x[1] - t.x[0]} * (t.y[2] - t.y[0]) -
                                std::int64_t{t.y[1] - t.y[0]} * (t.x[2] - t.x[0]);
            if (area == 0) continue;
            if (area < 0) {  // the rasterizer's order: a positive doubled area
                std::swap(t.x[1], t.x[2]);
                std::swap(t.y[1], t.y[2]);
            }
            // Its pixel box (centres i + 0.5 within the corners' range), the
            // image starting at column and row 0.
            const int left = std::max(0, static_cast<int>((min_fx - one / 2 + one - 1) >> 8));
            const int right = static_cast<int>((max_fx - one / 2) >> 8);
            const int top = std::max(0, static_cast<int>((min_fy - one / 2 + one - 1) >> 8));
            const int bottom = static_cast<int>((max_fy - one / 2) >> 8);
            if (left > right || top > bottom) continue;
            t.min_x = static_cast<std::int16_t>(left);
            t.max_x = static_cast<std::int16_t>(right);
            t.min_y = static_cast<std::int16_t>(top);
            t.max_y_small = static_cast<std::uint16_t>(bottom | 0x8000);
            for (float& w : t.weight) w = weight(random);
            // Sometimes the band starts below its first row.
            const int first_row = top + (coin(random) == 0 ? std::uniform_int_distribution<int>(
                                                                 0, bottom - top)(random)
                                                           : 0);
            const int rows = bottom - first_row + 1;
            const int span = right - left;
            ++triangles;
            ++spans[static_cast<std::size_t>(span)];

            const std::size_t stride = static_cast<std::size_t>(right + 3);
            VisibilityBuffers got(stride * static_cast<std::size_t>(rows)), expected = got;
            for (std::size_t i = 0; i < got.depth.size(); ++i) {
                got.depth[i] = i % 5 == 2 ? std::nanf("") : depth(random) * 1e-7f;
                got.weight1[i] = got.weight2[i] = -1.0f;
            }
            expected = got;
            std::vector<int> begin_got(static_cast<std::size_t>(rows), 100),
                end_got(begin_got.size(), 0);
            std::vector<int> begin_expected = begin_got, end_expected = end_got;
#if defined(__linux__)
            {
                // The same call on buffers that end at an inaccessible page:
                // it must not touch past them, and writes the same.
                GuardedCopy<float> depth_copy(got.depth), weight1_copy(got.weight1),
                    weight2_copy(got.weight2);
                GuardedCopy<const void*> visible_copy(got.visible);
                GuardedCopy<int> begin_copy(begin_got), end_copy(end_got);
                set->visibility_small(t, first_row, rows, &triangle_tag, depth_copy.data(),
                                      visible_copy.data(), weight1_copy.data(), weight2_copy.data(),
                                      stride, begin_copy.data(), end_copy.data());
                VisibilityBuffers guarded = got;
                guarded.depth = depth_copy.values();
                guarded.weight1 = weight1_copy.values();
                guarded.weight2 = weight2_copy.values();
                guarded.visible = visible_copy.values();
                set->visibility_small(t, first_row, rows, &triangle_tag, got.depth.data(),
                                      got.visible.data(), got.weight1.data(), got.weight2.data(),
                                      stride, begin_got.data(), end_got.data());
                ASSERT_TRUE(guarded == got) << set->name << ": triangle " << triangles;
                ASSERT_EQ(begin_copy.values(), begin_got);
                ASSERT_EQ(end_copy.values(), end_got);
            }
#else
            set->visibility_small(t, first_row, rows, &triangle_tag, got.depth.data(),
                                  got.visible.data(), got.weight1.data(), got.weight2.data(),
                                  stride, begin_got.data(), end_got.data());
#endif
            for (int r = 0; r < rows; ++r) {
                for (int x = left; x <= right; ++x) {
                    // The pixel centre in fixed point, and the rule.
                    const std::int64_t px = std::int64_t{x} * one + one / 2;
                    const std::int64_t py = std::int64_t{first_row + r} * one + one / 2;
                    std::int64_t e[3];
                    bool inside = true;
                    for (int k = 0; k < 3; ++k) {
                        const int a = (k + 1) % 3, b = (k + 2) % 3;
                        const std::int64_t dx = t.x[b] - t.x[a], dy = t.y[b] - t.y[a];
                        e[k] = dx * (py - t.y[a]) - dy * (px - t.x[a]);
                        const bool top_left = dy < 0 || (dy == 0 && dx > 0);
                        inside = inside && (e[k] > 0 || (e[k] == 0 && top_left));
                        on_edges += e[k] == 0;
                    }
                    if (!inside) continue;
                    ++covered_at[static_cast<std::size_t>(x - left)];
                    begin_expected[r] = std::min(begin_expected[r], x);
                    end_expected[r] = std::max(end_expected[r], x + 1);
                    expect_pixel(
                        static_cast<float>(e[0]) * t.weight[0],
                        static_cast<float>(e[1]) * t.weight[1],
                        static_cast<float>(e[2]) * t.weight[2], &triangle_tag, expected,
                        static_cast<std::size_t>(r) * stride + static_cast<std::size_t>(x));
                }
            }
            ASSERT_TRUE(got == expected) << set->name << ": triangle " << triangles << ", span "
                                         << span << ", rows " << rows;
            ASSERT_EQ(begin_got, begin_expected) << set->name << ": triangle " << triangles;
            ASSERT_EQ(end_got, end_expected) << set->name << ": triangle " << triangles;
        }
        for (int span = 0; span <= 8; ++span)
            EXPECT_GT(spans[static_cast<std::size_t>(span)], 20) << "span " << span;
        for (int x = 0; x < 8; ++x)
            EXPECT_GT(covered_at[static_cast<std::size_t>(x)], 20)
                << "pixel " << x << " of a box's row";
        EXPECT_GT(on_edges, 1000) << "pixel centres on edges (the top-left rule) too rarely";
    }
    if (sets_with_kernel == 0) std::printf("no set on this CPU has visibility_small\n");
}

// The vertex stage (vertex.cpp's vertex_stage: glm's matrix product, then
// to_window) against its rule written out here vertex by vertex, every
// product rounded on its own: random matrices and points, points behind the
// eye and outside each clip plane, w = 0, NaN and coordinates far beyond the
// fixed-point range, and fixed-point values at, just below and just above
// every half between −3 and 3 (the rounding half up), for every count up to
// two vectors and a bit.
namespace {

struct ExpectedVertex {
    float clip[4];
    litkit::kernels::WindowCorner corner;
};

ExpectedVertex expected_vertex(const float m[16], const float p[3], float half_width,
                               float half_height) {
    using namespace litkit::kernels;
    ExpectedVertex e;
    for (int r = 0; r < 4; ++r) {
        volatile float mul0 = m[r] * p[0], mul1 = m[4 + r] * p[1], mul2 = m[8 + r] * p[2],
                       mul3 = m[12 + r] * 1.0f;
        volatile float add0 = mul0 + mul1, add1 = mul2 + mul3;
        e.clip[r] = add0 + add1;
    }
    const float x = e.clip[0], y = e.clip[1], z = e.clip[2], w = e.clip[3];
    const float band_w = guard_band * w;
    e.corner.outside = static_cast<std::uint8_t>(
        (z + w < 0.0f ? 1 : 0) | (w - z < 0.0f ? 2 : 0) | (x + band_w < 0.0f ? 4 : 0) |
        (band_w - x < 0.0f ? 8 : 0) | (y + band_w < 0.0f ? 16 : 0) | (band_w - y < 0.0f ? 32 : 0));
    const float inverse_w = 1.0f / w;
    volatile float px = x * inverse_w, py = y * inverse_w;
    volatile float sx = px + 1.0f, sy = 1.0f - py;
    const double fixed_x = static_cast<double>(sx * half_width) * static_cast<double>(subpixel_one);
    const double fixed_y =
        static_cast<double>(sy * half_height) * static_cast<double>(subpixel_one);
    if (!(std::abs(fixed_x) < largest_fixed_coordinate &&
          std::abs(fixed_y) < largest_fixed_coordinate))
        return e;
    e.corner.x = static_cast<std::int32_t>(std::floor(fixed_x + 0.5));  // exact in double
    e.corner.y = static_cast<std::int32_t>(std::floor(fixed_y + 0.5));
    e.corner.inverse_w = inverse_w;
    e.corner.valid = true;
    return e;
}

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

TEST(Kernels, TransformVerticesFollowsTheVertexStageRuleInEveryLane) {
    std::mt19937 random(61);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f), wide(-40.0f, 40.0f);
    // Scenes' matrices: random perspective-like ones; and the identity, for
    // which the fixed-point x is (x + 1) · half_width · 256 and can be aimed.
    std::vector<std::array<float, 16>> matrices;
    for (int n = 0; n < 6; ++n) {
        std::array<float, 16> m{};
        for (float& v : m) v = unit(random) * 2.0f;
        m[11] = -1.0f, m[15] = 0.0f;  // w = −z_view, as a perspective matrix has it
        matrices.push_back(m);
    }
    const std::array<float, 16> identity{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    matrices.push_back(identity);

    std::vector<float> points;
    auto add = [&](float x, float y, float z) { points.insert(points.end(), {x, y, z}); };
    for (int n = 0; n < 300; ++n) add(wide(random), wide(random), wide(random));
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (float v : {0.0f, 1e30f, -1e30f, 3e38f, nan}) add(v, v * 0.5f, v);
    // Fixed-point targets at halves (with the identity and half_width 0.5:
    // fixed x = (x + 1) · 128), and the floats either side of each.
    for (int half = -6; half <= 6; ++half) {
        const float x = static_cast<float>(half) * 0.5f / 128.0f - 1.0f;
        for (float v : {std::nextafter(x, -2.0f), x, std::nextafter(x, 2.0f)}) add(v, -v, 0.5f);
    }
    const std::size_t vertices = points.size() / 3;

    for (const Kernels* set : runnable_sets()) {
        std::printf("checking the %s set\n", set->name);
        int checked = 0, valid = 0, invalid = 0, halves = 0;
        for (const auto& m : matrices) {
            const bool aimed = &m == &matrices.back();
            const float half_width = aimed ? 0.5f : 960.0f, half_height = aimed ? 0.5f : 540.0f;
            for (std::size_t count : {std::size_t{1}, std::size_t{7}, std::size_t{16},
                                      std::size_t{17}, std::size_t{33}, vertices}) {
                for (std::size_t first = 0; first + count <= vertices; first += count) {
                    std::vector<float> clip(4 * count + 4, -7.0f);  // one past: must stay
                    std::vector<litkit::kernels::WindowCorner> window(count + 1);
                    window[count].x = -7;
                    set->transform_vertices(&points[3 * first], count, m.data(), half_width,
                                            half_height, clip.data(), window.data());
                    for (std::size_t i = 0; i < count; ++i) {
                        const ExpectedVertex e = expected_vertex(m.data(), &points[3 * (first + i)],
                                                                 half_width, half_height);
                        const auto& got = window[i];
                        for (int r = 0; r < 4; ++r)
                            ASSERT_TRUE(
                                same_bits(clip[4 * i + static_cast<std::size_t>(r)], e.clip[r]))
                                << set->name << ": vertex " << first + i << " clip " << r;
                        ASSERT_EQ(got.valid, e.corner.valid)
                            << set->name << ": vertex " << first + i;
                        ASSERT_EQ(got.outside, e.corner.outside)
                            << set->name << ": vertex " << first + i;
                        ASSERT_EQ(got.x, e.corner.x) << set->name << ": vertex " << first + i;
                        ASSERT_EQ(got.y, e.corner.y) << set->name << ": vertex " << first + i;
                        ASSERT_TRUE(same_bits(got.inverse_w, e.corner.inverse_w))
                            << set->name << ": vertex " << first + i;
                        ++checked;
                        (e.corner.valid ? valid : invalid) += 1;
                        if (aimed && e.corner.valid) {
                            const double fixed =
                                (static_cast<double>(points[3 * (first + i)]) + 1.0) * 128.0;
                            halves += std::abs(fixed - std::round(fixed)) == 0.5;
                        }
                    }
                    ASSERT_EQ(clip[4 * count], -7.0f) << "wrote past the last vertex";
                    ASSERT_EQ(window[count].x, -7) << "wrote past the last vertex";
                }
            }
        }
        EXPECT_GT(valid, 1000);
        EXPECT_GT(invalid, 20);  // NaN, far beyond the range, w = 0
        EXPECT_GT(halves, 20);   // exact halves were met
        EXPECT_GT(checked, 10000);
    }
}

// pow of batches (equations.hpp), which every kernel set's lighting uses:
// whole exponents n of 0–64 alike in every lane by repeated squaring, within
// n · 2^-24 of the power computed in double; anything else exactly xsimd::pow's
// result. Checked at the portable width (the same text as the others').
TEST(Kernels, PowOfBatchesIsThePowerForWholeExponentsAndXsimdsOtherwise) {
    using Batch = xsimd::batch<float, xsimd::default_arch>;
    constexpr std::size_t lanes = Batch::size;
    std::mt19937 random(64);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<float> bases{0.0f, 1.0f, 0.5f, 0.999999f, 1e-3f, 2.0f, 1.0001f};
    for (int i = 0; i < 200; ++i) bases.push_back(unit(random));
    while (bases.size() % lanes) bases.push_back(unit(random));
    int checked = 0;
    for (int n = 0; n <= 64; ++n) {
        for (std::size_t i = 0; i < bases.size(); i += lanes) {
            alignas(64) float got[lanes];
            litkit::equations::pow(Batch::load_unaligned(&bases[i]), Batch(static_cast<float>(n)))
                .store_aligned(got);
            for (std::size_t j = 0; j < lanes; ++j) {
                const float b = bases[i + j];
                if (b == 0.0f) {
                    EXPECT_EQ(got[j], n == 0 ? 1.0f : 0.0f) << "0^" << n;  // 0^0 = 1, docs/spec.md
                    continue;
                }
                const double exact = std::pow(static_cast<double>(b), n);
                if (exact < 1e-30) continue;  // underflowing: relative error means nothing
                EXPECT_LE(std::abs(got[j] - exact), std::max(n, 1) * std::ldexp(exact, -24))
                    << b << "^" << n << " = " << got[j] << ", exactly " << exact;
                ++checked;
            }
        }
    }
    EXPECT_GT(checked, 10000);
    // Not a whole number from 0 to 64 in every lane: xsimd::pow, bit for bit.
    alignas(64) float mixed[lanes];
    for (std::size_t j = 0; j < lanes; ++j) mixed[j] = j % 2 ? 32.0f : 31.0f;
    for (const Batch exponent :
         {Batch(2.5f), Batch(65.0f), Batch(-2.0f), Batch::load_aligned(mixed)}) {
        for (std::size_t i = 0; i < bases.size(); i += lanes) {
            const Batch base = Batch::load_unaligned(&bases[i]);
            alignas(64) float got[lanes], expected[lanes];
            litkit::equations::pow(base, exponent).store_aligned(got);
            xsimd::select(base == Batch(0.0f), Batch(0.0f), xsimd::pow(base, exponent))
                .store_aligned(expected);
            for (std::size_t j = 0; j < lanes; ++j)
                ASSERT_TRUE(same_bits(got[j], expected[j])) << bases[i + j] << " lane " << j;
        }
    }
}
