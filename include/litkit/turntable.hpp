// SPDX-License-Identifier: MIT
/// \file
/// `litkit turntable`: the observer circles `look_at` once; frames as an
/// animated GIF or numbered PNGs (docs/learning.md).
#pragma once

#include <filesystem>
#include <span>

#include "litkit/image.hpp"
#include "litkit/scene.hpp"

namespace litkit {

/// The observer turned by `degrees` about the axis through `look_at` along
/// `up` (counter-clockwise seen from above, right-handed): position moves on
/// its circle, look_at, up and the rest stay.
Observer orbit(const Observer& observer, double degrees);

/// Writes the frames as a looping animated GIF, whole or not at all, each
/// frame shown `delay_ms` (GIF counts hundredths of a second). Each frame is
/// reduced to its own palette of at most 256 colours by giflib's median-cut
/// quantizer (GifQuantizeBuffer), so a frame's colours are never limited by
/// another's. Throws IoError on failure; every frame must have one size.
void write_gif(std::span<const Image> frames, const std::filesystem::path& path, int delay_ms = 40);

}  // namespace litkit
