// SPDX-License-Identifier: MIT
// Geometry at any scale (docs/reliability.md): a scene whose lengths are so
// large or so small that a float's squares overflow or underflow (a room of
// 1e19 or of 1e-24) is drawn as the same scene with every length multiplied
// by a power of two, which changes no direction, no angle and no colour.
#pragma once

#include "litkit/scene.hpp"

namespace litkit {

// The power of two that brings the room's largest side into [1, 2), or
// exactly 1 for a room between 2^-8 and 2^16, so that every ordinary scene
// is drawn from its values as written, bit for bit.
float float_safe_length_scale(const Scene& scene);

// `scene` with every length multiplied by `factor` (room, observer position,
// look_at, near, far, light positions, object positions and shape sizes, a
// mesh file's scale) and the attenuation adjusted to match (k_l / factor,
// k_q / factor²), so that every direction, angle and lit colour is unchanged.
Scene scale_lengths(const Scene& scene, float factor);

// The observer alone, as scale_lengths places it.
Observer scale_lengths(const Observer& observer, float factor);

}  // namespace litkit
