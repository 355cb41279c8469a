// SPDX-License-Identifier: MIT
// Welding (docs/spec.md §2, DD9): which positions of a mesh count as one
// vertex. weld.cpp finds them with a grid of cells; normals.cpp sums the
// faces' normals over them.
#pragma once

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace litkit::detail {

class WeldGrid;  // weld.cpp

// Welding in steps, so that a caller with threads can run the steps over
// positions in parts, on any threads, beside its own work: bound(part) for
// every part, make_grid(), place(part) for every part, then finish(). The
// parts split the positions only; the result is the same whatever their
// number and order (weld() is the steps in order, in one part).
class Welding {
  public:
    Welding(const std::vector<glm::vec3>& positions, std::size_t parts);
    ~Welding();
    Welding(const Welding&) = delete;
    Welding& operator=(const Welding&) = delete;

    // The bounds of a part's finite positions (exact: min and max).
    void bound(std::size_t part);
    // The weld distance, a fraction of the bounding box's diagonal, and the
    // grid of cells over the box.
    void make_grid();
    void place(std::size_t part);
    // For each position, the index of the first position of its welded
    // vertex. Non-finite positions weld with nothing.
    std::vector<std::uint32_t> finish();

  private:
    std::pair<std::size_t, std::size_t> range(std::size_t part) const {
        const std::size_t count = positions_.size();
        return {count * part / parts_, count * (part + 1) / parts_};
    }

    const std::vector<glm::vec3>& positions_;
    std::size_t parts_;
    std::vector<glm::dvec3> lowest_, highest_;  // per part
    std::vector<std::uint8_t> all_finite_;      // per part (not vector<bool>: parts write apart)
    std::unique_ptr<WeldGrid> grid_;
    std::vector<std::uint64_t> pairs_;  // per position: cell << 32 | index
    std::vector<std::uint8_t> near_face_;
};

// For each position, the index of the first position of its welded vertex
// (docs/spec.md §2, DD9). Non-finite positions weld with nothing.
std::vector<std::uint32_t> weld(const std::vector<glm::vec3>& positions);

}  // namespace litkit::detail
