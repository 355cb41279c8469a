// SPDX-License-Identifier: MIT
/// \file
/// Anti-aliasing's sample patterns (docs/spec.md §11): where in a pixel each
/// of its 1, 4, 8 or 16 samples lies, written once for every path (the CPU
/// renderer, the teaching tools, the OpenGL backend and the exports). The
/// positions are the standard multisample patterns of Direct3D, Vulkan and
/// Metal, measured from the pixel's top-left corner with y down; every one
/// is a multiple of 1/16, so it is exact in a float and in the CPU
/// rasterizer's fixed point.
#pragma once

#include <array>
#include <span>

namespace litkit {

/// A sample's place within its pixel, each coordinate in [0, 1).
struct SamplePosition {
    float x;  ///< from the pixel's left edge
    float y;  ///< from the pixel's top edge (y down)
};

/// The default of OutputSettings::samples: one sample, at the centre.
inline constexpr int default_samples = 1;
/// The counts of samples per pixel that docs/spec.md §11 allows.
inline constexpr std::array<int, 4> sample_counts{1, 4, 8, 16};

namespace detail {
inline constexpr std::array<SamplePosition, 1> pattern1{{{0.5f, 0.5f}}};
inline constexpr std::array<SamplePosition, 4> pattern4{
    {{0.375f, 0.125f}, {0.875f, 0.375f}, {0.125f, 0.625f}, {0.625f, 0.875f}}};
inline constexpr std::array<SamplePosition, 8> pattern8{{{0.5625f, 0.3125f},
                                                         {0.4375f, 0.6875f},
                                                         {0.8125f, 0.5625f},
                                                         {0.3125f, 0.1875f},
                                                         {0.1875f, 0.8125f},
                                                         {0.0625f, 0.4375f},
                                                         {0.6875f, 0.9375f},
                                                         {0.9375f, 0.0625f}}};
inline constexpr std::array<SamplePosition, 16> pattern16{{{0.5625f, 0.5625f},
                                                           {0.4375f, 0.3125f},
                                                           {0.3125f, 0.625f},
                                                           {0.75f, 0.4375f},
                                                           {0.1875f, 0.375f},
                                                           {0.625f, 0.8125f},
                                                           {0.8125f, 0.6875f},
                                                           {0.6875f, 0.1875f},
                                                           {0.375f, 0.875f},
                                                           {0.5f, 0.0625f},
                                                           {0.25f, 0.125f},
                                                           {0.125f, 0.75f},
                                                           {0.0f, 0.5f},
                                                           {0.9375f, 0.25f},
                                                           {0.875f, 0.9375f},
                                                           {0.0625f, 0.0f}}};
}  // namespace detail

/// True for a count of samples docs/spec.md §11 allows (1, 4, 8, 16).
constexpr bool valid_sample_count(int samples) {
    for (int count : sample_counts)
        if (count == samples) return true;
    return false;
}

/// The positions of `samples` samples per pixel, in the order of the table
/// of docs/spec.md §11; empty for a count that is not allowed.
constexpr std::span<const SamplePosition> sample_pattern(int samples) {
    switch (samples) {
        case 1:
            return detail::pattern1;
        case 4:
            return detail::pattern4;
        case 8:
            return detail::pattern8;
        case 16:
            return detail::pattern16;
        default:
            return {};
    }
}

}  // namespace litkit
