// SPDX-License-Identifier: MIT
/// \file
/// `litkit compare`: one picture of a scene under every reflection × shading
/// pair of the family, as a labelled grid (docs/learning.md).
#pragma once

#include <vector>

#include "litkit/image.hpp"
#include "litkit/lighting.hpp"
#include "litkit/scene.hpp"

namespace litkit {

/// What compare_models draws.
struct CompareOptions {
    /// Each tile's width in pixels; 0: the scene's output width halved (at least 1).
    int tile_width = 0;
    /// Each tile's height in pixels; 0: the scene's output height halved (at least 1).
    int tile_height = 0;
    /// Which models vary: every pair, or one row (reflection models, with the
    /// scene's shading) or one column (shading models, with its reflection).
    enum class Vary {
        Both,        ///< Every reflection × shading pair: a grid.
        Reflection,  ///< A row per reflection model, in one column of the scene's shading.
        Shading      ///< A column per shading model, in one row of the scene's reflection.
    };
    /// Which models vary.
    Vary vary = Vary::Both;
    /// Row and column labels in a margin; without them the grid is exactly
    /// the tiles, edge to edge.
    bool labels = true;
    int threads = 0;  ///< tiles rendered at once; 0: one per hardware thread
    /// Used where the scene leaves [lighting] out (the caller decides, per
    /// R11, whether that is allowed).
    Reflection fallback_reflection = default_reflection;
    /// The shading model used where the scene leaves it out (as fallback_reflection).
    Shading fallback_shading = default_shading;
};

/// The grid compare_models drew, and where its tiles are.
struct CompareGrid {
    /// The whole picture: margins and tiles.
    Image image;
    std::vector<Reflection> rows;  ///< top to bottom
    std::vector<Shading> columns;  ///< left to right
    /// One tile's width in pixels.
    int tile_width = 0;
    /// One tile's height in pixels.
    int tile_height = 0;
    int left_margin = 0;  ///< where the tiles start (0 without labels)
    /// Where the tiles start vertically (0 without labels).
    int top_margin = 0;
    /// Objects whose own reflection or shading the grid replaced (by index).
    std::vector<std::size_t> overridden_objects;
};

/// Every tile is `render` of the scene with that tile's models for every
/// object (objects' own overrides replaced) at the tile size. The labels use
/// DejaVu Sans (Debian's fonts-dejavu-core) through FreeType; throws IoError
/// when no such font is installed, naming the package (labels = false needs
/// no font).
CompareGrid compare_models(const Scene& scene, const CompareOptions& options = {});

}  // namespace litkit
