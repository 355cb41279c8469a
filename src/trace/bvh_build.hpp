// SPDX-License-Identifier: MIT
// The binary tree the hierarchy (accel.cpp) is collapsed from: a bounding-
// volume hierarchy over boxes (an object's triangles, or the objects), split
// by the binned surface-area heuristic (I. Wald, "On fast Construction of
// SAH-based Bounding Volume Hierarchies", IEEE Symposium on Interactive Ray
// Tracing 2007). Its cost counts a leaf's primitives in blocks of four, the
// triangles the traversal tests at once.
#pragma once

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "core/parallel.hpp"

namespace litkit::trace::build {

struct Box {
    float lo[3] = {std::numeric_limits<float>::infinity(), std::numeric_limits<float>::infinity(),
                   std::numeric_limits<float>::infinity()};
    float hi[3] = {-std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
                   -std::numeric_limits<float>::infinity()};
};

// An inner node (count == 0) has children `a` and `b`; a leaf holds the
// primitives order[a], …, order[a + count − 1].
struct Node {
    Box box;
    std::uint32_t a = 0, b = 0, count = 0;
};

struct Tree {
    std::vector<Node> nodes;  // the root first (none when there are no primitives)
    std::vector<std::uint32_t> order;
};

// Builds over primitives 0 … boxes.size() − 1 with at most `max_leaf` in a
// leaf. Whatever `parallel` lends, the tree is the same.
Tree build_tree(std::span<const Box> boxes, std::uint32_t max_leaf, const ParallelFor& parallel);

// The same over triangles (corners positions[t[0]], [t[1]], [t[2]]): their
// boxes made where build_tree copies them, in one pass.
Tree build_triangles(std::span<const glm::vec3> positions,
                     std::span<const std::array<std::uint32_t, 3>> triangles,
                     std::uint32_t max_leaf, const ParallelFor& parallel);

}  // namespace litkit::trace::build
