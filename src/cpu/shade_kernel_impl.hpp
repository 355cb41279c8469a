// SPDX-License-Identifier: MIT
// Template text of the kernels in shade_kernel.hpp, instantiated once per
// instruction set by shade_kernel_<arch>.cpp. The lighting itself is
// equations::shade_point, the same template every other path uses, here with
// T = an xsimd batch of floats. Nothing here instantiates a template on a
// plain scalar type (std::min, shade_point<float>): the AVX2 copy of such an
// inline function could be the one the linker keeps for every caller.
#pragma once

#include <xsimd/xsimd.hpp>

#include <bit>
#include <cstdint>
#include <cstring>

#include "cpu/shade_kernel.hpp"

template <class Arch>
xsimd::batch<float, Arch> litkit::equations::pow(const xsimd::batch<float, Arch>& base,
                                                 const xsimd::batch<float, Arch>& exponent) {
    using Batch = xsimd::batch<float, Arch>;
    // A whole exponent n from 0 to 64, the same in every lane (a material's
    // shininess or a spot's exponent, as scenes mostly give them): base^n by
    // repeated squaring, n's bits from the lowest, at most 11 products where
    // exp and log take about a hundred instructions. Within n · 2^-24 of
    // the exact power, relative (each product rounds once, and a square
    // doubles the error it squares), where exp(n · log base) is within a
    // few ulp; both far inside a pixel level (2 · 10^-6 at n = 32). 0^0 is
    // 1, as docs/spec.md has it for a spot's exponent 0 (the general path
    // below gives 0 there). (Plain arithmetic only: an inline library
    // function compiled here could be the copy every caller gets, AVX-512
    // and all.)
    alignas(64) float lanes[Batch::size];
    exponent.store_aligned(lanes);
    const float n = lanes[0];
    if (n >= 0.0f && n <= 64.0f && static_cast<float>(static_cast<int>(n)) == n &&
        xsimd::all(exponent == Batch(n))) {
        Batch result(1.0f), square = base;
        for (unsigned bits = static_cast<unsigned>(n); bits != 0; bits >>= 1) {
            if (bits & 1u) result = result * square;
            if (bits > 1u) square = square * square;
        }
        return result;
    }
    // xsimd::pow (xsimd/arch/generic/xsimd_generic_math.hpp) computes
    // exp(exponent · log(|base|)) with 0 where the base is 0, then fixes the
    // sign and NaN of negative bases. Where no lane is negative that is all
    // it does; a zero lane's exp(exponent · log 0) is replaced by 0 as there.
    if (xsimd::any(base < Batch(0.0f))) return xsimd::pow(base, exponent);
    return xsimd::select(base == Batch(0.0f), Batch(0.0f), xsimd::exp(exponent * xsimd::log(base)));
}

namespace litkit::kernels::detail {

template <class Arch>
struct Impl {
    using Batch = xsimd::batch<float, Arch>;
    static constexpr std::size_t width = Batch::size;

    template <Reflection R>
    static void shade_run(std::span<const equations::PreparedLight> lights,
                          const Material& material, const SurfaceRun& s, const ColorRun& out) {
        using namespace equations;
        const MaterialT<Batch> m = splat<Batch>(material);
        const RowRays& rays = *s.rays;
        const Vec3<Batch> eye{Batch(rays.eye[0]), Batch(rays.eye[1]), Batch(rays.eye[2])};
        const Vec3<Batch> centre{Batch(rays.centre[0]), Batch(rays.centre[1]),
                                 Batch(rays.centre[2])};
        const Vec3<Batch> across{Batch(rays.across[0]), Batch(rays.across[1]),
                                 Batch(rays.across[2])};
        // k of the lanes after the first: whole numbers, exact in a float.
        alignas(64) float lane_k[width];
        for (std::size_t lane = 0; lane < width; ++lane)
            lane_k[lane] = 2.0f * static_cast<float>(lane);
        const Batch lane_step = Batch::load_aligned(lane_k);
        // Full batches straight from the arrays; the tail through a padded
        // copy. (No float instantiation here: this text is also compiled
        // with -mavx2, and an inline float function built that way could be
        // the copy the linker keeps for every caller.)
        auto shade_batch = [&](std::size_t i, const float* w, const float* nx, const float* ny,
                               const float* nz, float* r, float* g, float* b) {
            // The point at depth w on each pixel's ray (scene/camera.hpp's
            // formulas); rounded(): no product fuses with the sum after it.
            const Batch k = Batch(s.first_k + 2.0f * static_cast<float>(i)) + lane_step;
            const Batch depth = Batch::load_unaligned(w);
            auto round = [](const Batch& value) { return rounded(value); };
            auto along = [&](const Batch& e, const Batch& c, const Batch& a) {
                return point_coordinate(e, direction_coordinate(c, a, k, round), depth, round);
            };
            const Vec3<Batch> p{along(eye.x, centre.x, across.x), along(eye.y, centre.y, across.y),
                                along(eye.z, centre.z, across.z)};
            const Vec3<Batch> n = normalize(Vec3<Batch>{
                Batch::load_unaligned(nx), Batch::load_unaligned(ny), Batch::load_unaligned(nz)});
            const Vec3<Batch> v = normalize(eye - p);
            const Vec3<Batch> color = shade_point<R>(lights, m, p, n, v);
            color.x.store_unaligned(r);
            color.y.store_unaligned(g);
            color.z.store_unaligned(b);
        };
        std::size_t i = 0;
        for (; i + width <= s.count; i += width) {
            shade_batch(i, s.w + i, s.nx + i, s.ny + i, s.nz + i, out.r + i, out.g + i, out.b + i);
        }
        if (i < s.count) {
            alignas(64) float in[4][width];
            alignas(64) float result[3][width];
            const float* sources[4] = {s.w, s.nx, s.ny, s.nz};
            for (int k = 0; k < 4; ++k) {
                for (std::size_t lane = 0; lane < width; ++lane) {
                    // Pad with the last pixel: valid numbers, results unused.
                    in[k][lane] = sources[k][i + lane < s.count ? i + lane : s.count - 1];
                }
            }
            shade_batch(i, in[0], in[1], in[2], in[3], result[0], result[1], result[2]);
            for (std::size_t lane = 0; i + lane < s.count; ++lane) {
                out.r[i + lane] = result[0][lane];
                out.g[i + lane] = result[1][lane];
                out.b[i + lane] = result[2][lane];
            }
        }
    }

    static void shade_phong(Reflection reflection, std::span<const equations::PreparedLight> lights,
                            const Material& material, const SurfaceRun& surface,
                            const ColorRun& out) {
        equations::with_reflection(reflection, [&](auto model) {
            shade_run<decltype(model)::value>(lights, material, surface, out);
        });
    }

    // A value the compiler may not fuse into a multiply-add with what comes
    // next (the kernels are built with -mfma, and GCC contracts a * b + c
    // across intrinsics): interpolate must round exactly as the scalar code.
    static Batch rounded(Batch value) {
#if defined(__x86_64__) || defined(__i386__)
        auto reg = static_cast<typename Batch::register_type>(value);
        asm("" : "+v"(reg));
        return Batch(reg);
#else
        return value;
#endif
    }

    static void transform_vertices(const float* positions, std::size_t count, const float m[16],
                                   float half_width, float half_height, float* clip,
                                   WindowCorner* window) {
        for (std::size_t i = 0; i < count; i += width) {
            const std::size_t lanes = count - i < width ? count - i : width;
            alignas(64) float in[3][width];
            for (std::size_t j = 0; j < width; ++j) {
                // Lanes past the end repeat the last vertex; they are not kept.
                const std::size_t from = i + (j < lanes ? j : lanes - 1);
                for (int k = 0; k < 3; ++k)
                    in[k][j] = positions[3 * from + static_cast<std::size_t>(k)];
            }
            const Batch x = Batch::load_aligned(in[0]);
            const Batch y = Batch::load_aligned(in[1]);
            const Batch z = Batch::load_aligned(in[2]);
            alignas(64) float c[4][width];
            for (int r = 0; r < 4; ++r) {
                // glm's order; M3's product with w = 1 is M3 itself.
                const Batch add0 = rounded(Batch(m[r]) * x) + rounded(Batch(m[4 + r]) * y);
                const Batch add1 = rounded(Batch(m[8 + r]) * z) + Batch(m[12 + r]);
                (add0 + add1).store_aligned(c[r]);
            }
            const Batch cx = Batch::load_aligned(c[0]), cy = Batch::load_aligned(c[1]),
                        cz = Batch::load_aligned(c[2]), cw = Batch::load_aligned(c[3]);
            const Batch band_w = rounded(Batch(guard_band) * cw);
            const Batch zero(0.0f);
            auto bit = [&](const xsimd::batch_bool<float, Arch>& out, float value) {
                return xsimd::select(out, Batch(value), zero);
            };
            // The plane bits as small whole numbers, exact in a float.
            const Batch outside = bit(cz + cw < zero, 1.0f) + bit(cw - cz < zero, 2.0f) +
                                  bit(cx + band_w < zero, 4.0f) + bit(band_w - cx < zero, 8.0f) +
                                  bit(cy + band_w < zero, 16.0f) + bit(band_w - cy < zero, 32.0f);
            const Batch inverse_w = Batch(1.0f) / cw;
            const Batch window_x =
                rounded(rounded(cx * inverse_w) + Batch(1.0f)) * Batch(half_width);
            const Batch window_y =
                rounded(Batch(1.0f) - rounded(cy * inverse_w)) * Batch(half_height);
            // Times subpixel_one (a power of two: exact, as in double, unless
            // it overflows to infinity, which the range test refuses too).
            const Batch fixed_x = window_x * Batch(static_cast<float>(subpixel_one));
            const Batch fixed_y = window_y * Batch(static_cast<float>(subpixel_one));
            const Batch limit(static_cast<float>(largest_fixed_coordinate));
            const auto valid = (xsimd::abs(fixed_x) < limit) & (xsimd::abs(fixed_y) < limit);
            // Half up, as to_window's double arithmetic rounds v (exact, and
            // below 2^30): floor(v) + (v − floor(v) ≥ 0.5). The difference is
            // exact for v ≥ 0 and v ≤ −1 (Sterbenz) and for −1 < v ≤ −0.5
            // (below 0.5, on v's grid); for −0.5 < v < 0 it is above 0.5, and
            // rounding cannot take it below.
            // (Adding the 1 in float is exact: it happens only below 2^23.)
            auto half_up = [&](const Batch& v) {
                const Batch down = xsimd::floor(xsimd::select(valid, v, zero));
                return xsimd::batch_cast<std::int32_t>(down + bit(v - down >= Batch(0.5f), 1.0f));
            };
            alignas(64) std::int32_t fx[width], fy[width], bits[width];
            alignas(64) float iw[width];
            half_up(fixed_x).store_aligned(fx);
            half_up(fixed_y).store_aligned(fy);
            xsimd::batch_cast<std::int32_t>(outside).store_aligned(bits);
            xsimd::select(valid, inverse_w, zero).store_aligned(iw);
            alignas(64) float ok[width];
            xsimd::select(valid, Batch(1.0f), zero).store_aligned(ok);
            for (std::size_t j = 0; j < lanes; ++j) {
                float* out = clip + 4 * (i + j);
                out[0] = c[0][j], out[1] = c[1][j], out[2] = c[2][j], out[3] = c[3][j];
                WindowCorner& corner = window[i + j];
                corner.outside = static_cast<std::uint8_t>(bits[j]);
                corner.valid = ok[j] != 0.0f;
                corner.x = corner.valid ? fx[j] : 0;
                corner.y = corner.valid ? fy[j] : 0;
                corner.inverse_w = iw[j];
            }
        }
    }

    static void accumulate(const float* light, std::size_t count, float* sum) {
        std::size_t i = 0;
        for (; i + width <= count; i += width) {
            const Batch v = Batch::load_unaligned(light + i);
            const Batch clamped =
                xsimd::min(xsimd::select(v > Batch(0.0f), v, Batch(0.0f)), Batch(1.0f));
            (Batch::load_unaligned(sum + i) + clamped).store_unaligned(sum + i);
        }
        for (; i < count; ++i) {  // the last few one at a time, the same operations
            const float v = light[i];
            sum[i] += v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;
        }
    }

    static void perspective_weights(const float* inverse_w, const float* weight1,
                                    const float* weight2, std::size_t count, float* w_out,
                                    float* q0, float* q1, float* q2) {
        auto block = [&](std::size_t i) {
            // rounded(): q0's subtractions must not fuse with the products.
            const Batch w = Batch(1.0f) / Batch::load_unaligned(inverse_w + i);
            const Batch b = rounded(Batch::load_unaligned(weight1 + i) * w);
            const Batch c = rounded(Batch::load_unaligned(weight2 + i) * w);
            w.store_unaligned(w_out + i);
            (Batch(1.0f) - b - c).store_unaligned(q0 + i);
            b.store_unaligned(q1 + i);
            c.store_unaligned(q2 + i);
        };
        std::size_t i = 0;
        for (; i + width <= count; i += width) block(i);
        for (; i < count; ++i) {  // the last few one at a time, the same operations
            const float w = 1.0f / inverse_w[i];
            const float b = weight1[i] * w, c = weight2[i] * w;
            w_out[i] = w;
            q0[i] = 1.0f - b - c;
            q1[i] = b;
            q2[i] = c;
        }
    }

    static void interpolate(const float* q0, const float* q1, const float* q2, std::size_t count,
                            const float (*normal)[3], const NormalOut& out) {
        float* outputs[3] = {out.nx, out.ny, out.nz};
        auto span = [&](std::size_t i, const float* a0, const float* a1, const float* a2,
                        float* const* dest) {
            const Batch w0 = Batch::load_unaligned(a0), w1 = Batch::load_unaligned(a1),
                        w2 = Batch::load_unaligned(a2);
            for (int k = 0; k < 3; ++k) {
                const Batch a = rounded(w0 * Batch(normal[0][k]));
                const Batch b = rounded(w1 * Batch(normal[1][k]));
                const Batch c = rounded(w2 * Batch(normal[2][k]));
                (a + b + c).store_unaligned(dest[k] + i);
            }
        };
        std::size_t i = 0;
        for (; i + width <= count; i += width) span(i, q0 + i, q1 + i, q2 + i, outputs);
        if (i < count) {
            alignas(64) float in[3][width];
            alignas(64) float result[3][width];
            float* dest[3] = {result[0], result[1], result[2]};
            for (std::size_t lane = 0; lane < width; ++lane) {
                // Pad with the last pixel: valid numbers, results unused.
                const std::size_t from = i + lane < count ? i + lane : count - 1;
                in[0][lane] = q0[from];
                in[1][lane] = q1[from];
                in[2][lane] = q2[from];
            }
            span(0, in[0], in[1], in[2], dest);
            for (int k = 0; k < 3; ++k)
                for (std::size_t lane = 0; i + lane < count; ++lane)
                    outputs[k][i + lane] = result[k][lane];
        }
    }

    // Same arithmetic as litkit::to_pixel: clamp (NaN → 0), gamma, ·255,
    // round half up (the values are ≥ 0, so this is lround).
    static Batch to_levels(Batch intensity, float gamma) {
        intensity = xsimd::select(intensity > Batch(0.0f), intensity, Batch(0.0f));  // NaN → 0
        intensity = xsimd::min(intensity, Batch(1.0f));
        if (gamma != 1.0f) intensity = equations::pow(intensity, Batch(1.0f / gamma));
        return xsimd::floor(intensity * Batch(255.0f) + Batch(0.5f));
    }

    static void encode(const float* r, const float* g, const float* b, std::size_t count,
                       float gamma, std::uint8_t* rgb) {
        using Words = xsimd::batch<std::int32_t, Arch>;
        alignas(64) float padded[3][width];
        // Each pixel's three levels (whole numbers 0-255) as one word, r in
        // the lowest byte; written four bytes at a time, the fourth
        // overwritten by the next pixel's r, the last pixel three.
        alignas(64) std::int32_t words[width];
        static_assert(std::endian::native == std::endian::little, "a word's lowest byte first");
        for (std::size_t i = 0; i < count; i += width) {
            const std::size_t lanes = count - i < width ? count - i : width;
            Batch levels[3];
            if (lanes == width) {
                levels[0] = to_levels(Batch::load_unaligned(r + i), gamma);
                levels[1] = to_levels(Batch::load_unaligned(g + i), gamma);
                levels[2] = to_levels(Batch::load_unaligned(b + i), gamma);
            } else {
                for (std::size_t lane = 0; lane < width; ++lane) {
                    const std::size_t from = i + (lane < lanes ? lane : lanes - 1);
                    padded[0][lane] = r[from];
                    padded[1][lane] = g[from];
                    padded[2][lane] = b[from];
                }
                for (int c = 0; c < 3; ++c)
                    levels[c] = to_levels(Batch::load_aligned(padded[c]), gamma);
            }
            const Words packed = xsimd::batch_cast<std::int32_t>(levels[0]) |
                                 (xsimd::batch_cast<std::int32_t>(levels[1]) << 8) |
                                 (xsimd::batch_cast<std::int32_t>(levels[2]) << 16);
            packed.store_aligned(words);
            std::uint8_t* out = rgb + 3 * i;
            for (std::size_t lane = 0; lane + 1 < lanes; ++lane)
                std::memcpy(out + 3 * lane, &words[lane], 4);
            std::memcpy(out + 3 * (lanes - 1), &words[lanes - 1], 3);
        }
    }
};

}  // namespace litkit::kernels::detail
