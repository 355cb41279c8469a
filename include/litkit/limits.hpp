// SPDX-License-Identifier: MIT
/// \file
/// Limits that several layers share, each defined once: validation, the
/// renderers, the PNG reader, the teaching tools, the command line and the
/// Python binding check against these constants, and tests/test_spec.cpp
/// checks the docs' tables against them.
#pragma once

namespace litkit {

/// The largest image side, in pixels (docs/spec.md §6): a scene's
/// output.width and output.height are 1–max_image_side, and so are a
/// compare sheet's tiles and a PNG that litkit reads. The CPU renderer's
/// per-triangle rows fit in 16 bits because of it (src/cpu/shade_kernel.hpp).
inline constexpr int max_image_side = 16384;

}  // namespace litkit
