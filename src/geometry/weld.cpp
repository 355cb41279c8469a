// SPDX-License-Identifier: MIT
// Welding (docs/spec.md §2, DD9): positions within 1e-6 × the bounding-box
// diagonal are one vertex, transitively. Points are sorted into a grid of
// cells and each compared with its neighbours in its own and, near a face,
// the adjacent cells.
#include "geometry/weld.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <numeric>
#include <utility>
#include <vector>

namespace litkit::detail {

namespace {

// docs/spec.md §2, DD9: positions within this fraction of the bounding-box diagonal
// are one vertex.
constexpr double weld_fraction_of_diagonal = 1e-6;

// Welding looks points up in a grid of cubic cells. A cell edge of many weld
// distances means that most points are farther than the weld distance from
// every face of their cell, so they look only in their own cell; a point near
// a face, edge or corner also looks in the neighbouring cells (at most 7) that
// the box of half-width weld distance around it reaches, which makes welding
// exact at cell borders.
constexpr double cells_per_weld_distance = 1024.0;

// Cell coordinates are packed into one 32-bit key with as many bits per axis
// as that axis needs: the largest coordinate is at most diagonal / (1024 ×
// 1e-6 × diagonal) < 977 < 2^10, so the key has at most 30 bits (the clamp to
// 10 bits per axis is only a guard). The cell size changes only the speed,
// never the result: with 64 weld distances a 261k-triangle sphere needed
// three radix passes more and five times as many neighbour lookups.
constexpr int most_bits_per_cell_axis = 10;
static_assert(1.0 / (weld_fraction_of_diagonal * cells_per_weld_distance) <
                  double(1 << most_bits_per_cell_axis),
              "a cell coordinate needs more bits than the key gives it");
constexpr std::uint32_t largest_cell_coordinate = (std::uint32_t{1} << most_bits_per_cell_axis) - 1;

// The points are sorted by cell with a least-significant-digit radix sort of
// (cell, index) pairs, this many bits per pass (1024 buckets: a 4 KiB count
// table, in the first level of cache; three passes for the largest key).
// Sorting the 8-byte pairs and not the 20-byte points, with few buckets,
// took the 261k-triangle sphere's sort from 3 ms to under 1.
constexpr int radix_bits = 10;

bool is_finite(const glm::vec3& point) {
    return std::isfinite(point.x) && std::isfinite(point.y) && std::isfinite(point.z);
}

// Disjoint sets over position indices: welding is the transitive closure of
// "within the weld distance", so a chain of close points is one vertex.
class DisjointSets {
  public:
    explicit DisjointSets(std::size_t count) : parent_(count) {
        std::iota(parent_.begin(), parent_.end(), std::uint32_t{0});
    }

    std::uint32_t find(std::uint32_t element) {
        while (parent_[element] != element) {
            parent_[element] = parent_[parent_[element]];  // path halving
            element = parent_[element];
        }
        return element;
    }

    void unite(std::uint32_t a, std::uint32_t b) {
        a = find(a);
        b = find(b);
        if (a < b) {
            parent_[b] = a;
        } else if (b < a) {
            parent_[a] = b;
        }
    }

  private:
    std::vector<std::uint32_t> parent_;
};

// A placed position: its cell << 32 | its index into the mesh's positions.
using GridPoint = std::uint64_t;
std::uint32_t cell_of(GridPoint point) { return static_cast<std::uint32_t>(point >> 32); }
std::uint32_t index_of(GridPoint point) { return static_cast<std::uint32_t>(point); }

// std::floor, without a call into the maths library in the usual case
// (x86-64's baseline has no rounding instruction, and the grid takes three
// floors a point: 0.3 of the 4 ms it took to place a 261k-triangle
// sphere's points): for 0 ≤ v < 2^52, truncation is the floor, exactly.
double floor_of(double v) {
    return v >= 0.0 && v < 4503599627370496.0 ? static_cast<double>(static_cast<std::int64_t>(v))
                                              : std::floor(v);
}

// Within a cell, sorting by x, y, z orders the points by x for the sweep and
// puts exact duplicates next to one another.
bool position_order(const glm::vec3& a, const glm::vec3& b) {
    if (a.x != b.x) return a.x < b.x;
    if (a.y != b.y) return a.y < b.y;
    return a.z < b.z;
}

// Sorts (cell << 32 | index) pairs by cell, `key_bits` wide: a stable sort by
// cell, and as every pair is distinct, the pairs' own order. O(n) per pass.
void sort_by_cell(std::vector<std::uint64_t>& pairs, int key_bits) {
    constexpr std::size_t bucket_count = std::size_t{1} << radix_bits;
    constexpr std::uint64_t digit_mask = bucket_count - 1;
    if (key_bits == 0) return;
    // A small mesh (a cube, a quad) costs a comparison sort less than
    // clearing the count tables.
    if (pairs.size() < bucket_count) {
        std::sort(pairs.begin(), pairs.end());
        return;
    }
    const int passes = (key_bits + radix_bits - 1) / radix_bits;
    // Every pass's counts in one read of the pairs.
    std::vector<std::array<std::uint32_t, bucket_count>> bucket_start(
        static_cast<std::size_t>(passes));
    for (const std::uint64_t pair : pairs) {
        for (int pass = 0; pass < passes; ++pass)
            ++bucket_start[static_cast<std::size_t>(pass)]
                          [((pair >> 32) >> (pass * radix_bits)) & digit_mask];
    }
    // Passes go back and forth between the pairs and a buffer that is
    // written before it is read (not zero-filled first).
    const std::size_t count = pairs.size();
    // (new T[n], not make_unique_for_overwrite, which the web build's
    // C++ library lacks: the same default-initialised array.)
    const std::unique_ptr<std::uint64_t[]> buffer(new std::uint64_t[count]);
    std::uint64_t* from = pairs.data();
    std::uint64_t* to = buffer.get();
    for (int pass = 0; pass < passes; ++pass) {
        auto& start = bucket_start[static_cast<std::size_t>(pass)];
        std::uint32_t next = 0;
        for (std::uint32_t& bucket : start) next += std::exchange(bucket, next);
        const int shift = 32 + pass * radix_bits;
        for (std::size_t i = 0; i < count; ++i)
            to[start[(from[i] >> shift) & digit_mask]++] = from[i];
        std::swap(from, to);
    }
    if (from != pairs.data()) std::copy_n(from, count, pairs.data());
}

double squared_distance(const glm::vec3& a, const glm::vec3& b) {
    const double dx = double(a.x) - double(b.x);
    const double dy = double(a.y) - double(b.y);
    const double dz = double(a.z) - double(b.z);
    return dx * dx + dy * dy + dz * dz;
}

}  // namespace

// The grid of cells over the finite positions, and the weld distance.
class WeldGrid {
  public:
    // `lowest` and `highest` bound the finite positions.
    WeldGrid(glm::dvec3 lowest, glm::dvec3 highest, double weld_distance)
        : origin_(lowest), weld_distance_(weld_distance) {
        // Without a positive weld distance (all points equal, or an infinite
        // box) only exact duplicates weld: everything goes into cell 0.
        if (weld_distance > 0.0 && std::isfinite(weld_distance)) {
            cell_size_ = cells_per_weld_distance * weld_distance;
            inverse_cell_size_ = 1.0 / cell_size_;
            for (int axis = 0; axis < 3; ++axis) {
                bits_[axis] = std::bit_width(cell_coordinate(highest[axis], axis));
                largest_[axis] = (std::uint32_t{1} << bits_[axis]) - 1;
                key_bits_ += bits_[axis];
            }
        }
    }

    // Positions [begin, end) placed in their cells: pairs[i] = cell << 32 | i,
    // or no_cell for a non-finite position (a NaN would break the sort's
    // ordering); near_face[i] = 1 for those near a face of their cell.
    // Returns whether every one was finite.
    bool place(const std::vector<glm::vec3>& positions, std::size_t begin, std::size_t end,
               std::uint64_t* pairs, std::uint8_t* near_face) const {
        // Most points lie well inside their cell: only those within two
        // weld distances of a face (twice, so that rounding can never hide
        // one) look into the neighbouring cells.
        const double margin = 2.0 / cells_per_weld_distance;
        const bool use_cells = cell_size_ > 0.0;
        bool all_finite = true;
        for (std::size_t index = begin; index < end; ++index) {
            const glm::vec3& position = positions[index];
            near_face[index] = 0;
            if (!is_finite(position)) {
                pairs[index] = no_cell;
                all_finite = false;
                continue;
            }
            std::uint32_t coordinate[3] = {0, 0, 0};
            if (use_cells) {
                for (int axis = 0; axis < 3; ++axis) {
                    const double place = cell_place(position[axis], axis);
                    const double cell = floor_of(place);
                    coordinate[axis] = clamped_cell(cell, axis);
                    const double within = place - cell;  // 0 to 1 across the cell
                    if (within < margin || within > 1.0 - margin) near_face[index] = 1;
                }
            }
            pairs[index] =
                std::uint64_t{pack_cell(coordinate[0], coordinate[1], coordinate[2])} << 32 | index;
        }
        return all_finite;
    }
    static constexpr std::uint64_t no_cell = ~std::uint64_t{0};

    // Unites, in `sets`, every pair of the placed positions (without the
    // non-finite ones) within the weld distance. In one pass over the
    // points sorted by cell, each cell of several points is put in position
    // order, its exact duplicates collapsed and its close points welded, the
    // points compacted as they go; then the points near a face of their
    // cell look into the neighbouring cells (found by cell in the sorted
    // points). Positions are read through the points' indices: most cells
    // hold one point, and a point far from its cell's faces is never read.
    // The sets' roots are their least index, whatever the order of the
    // unions.
    void weld(std::vector<GridPoint>& points, const std::vector<glm::vec3>& positions,
              const std::vector<std::uint8_t>& near_face, DisjointSets& sets) {
        sort_by_cell(points, key_bits_);
        positions_ = &positions;
        std::vector<std::uint32_t> near_faces;  // places in `points`, once compacted
        std::size_t kept = 0;                   // points[0, kept): compacted
        for (std::size_t begin = 0, end = 0; begin < points.size(); begin = end) {
            const std::uint32_t cell = cell_of(points[begin]);
            while (end < points.size() && cell_of(points[end]) == cell) ++end;
            const std::size_t first = kept;
            if (end - begin == 1) {
                points[kept++] = points[begin];
            } else {
                kept = weld_within_cell(points, begin, end, kept, sets);
            }
            if (cell_size_ > 0.0) {
                for (std::size_t point = first; point < kept; ++point)
                    if (near_face[index_of(points[point])])
                        near_faces.push_back(static_cast<std::uint32_t>(point));
            }
        }
        points.resize(kept);
        for (const std::uint32_t point : near_faces) weld_with_neighbour_cells(points, point, sets);
        positions_ = nullptr;
    }

  private:
    std::uint32_t pack_cell(std::uint32_t x, std::uint32_t y, std::uint32_t z) const {
        return (((x << bits_[1]) | y) << bits_[2]) | z;
    }

    // Clamped to the grid: a lookup beyond its last cell finds that cell,
    // whose points the distance test then rejects.
    std::uint32_t cell_coordinate(double value, int axis) const {
        return clamped_cell(std::floor(cell_place(value, axis)), axis);
    }
    // A multiplication, not a division: the same (monotonic) function
    // places the points and looks them up, which is all exactness needs.
    double cell_place(double value, int axis) const {
        return (value - origin_[axis]) * inverse_cell_size_;
    }
    std::uint32_t clamped_cell(double cell, int axis) const {
        if (!(cell > 0.0)) return 0;
        if (cell >= double(largest_[axis])) return largest_[axis];
        return static_cast<std::uint32_t>(cell);
    }

    const glm::vec3& position_of(GridPoint point) const { return (*positions_)[index_of(point)]; }

    void weld_if_close(GridPoint a, GridPoint b, DisjointSets& sets) const {
        if (squared_distance(position_of(a), position_of(b)) <= weld_distance_ * weld_distance_) {
            sets.unite(index_of(a), index_of(b));
        }
    }

    // One cell's points, points[begin, end), put in position order (by x,
    // then y, then z: exact duplicates side by side) and moved to
    // points[kept, ...); its exact duplicates (a cube's face corners, a
    // sphere's pole) weld without distance tests and leave one point per
    // position, so that many copies of one position cost linear time, not
    // quadratic; then each point welds with the later ones while their x is
    // within reach. Returns the new end of the compacted points.
    std::size_t weld_within_cell(std::vector<GridPoint>& points, std::size_t begin, std::size_t end,
                                 std::size_t kept, DisjointSets& sets) const {
        const auto from = points.begin() + static_cast<std::ptrdiff_t>(begin);
        std::sort(from, points.begin() + static_cast<std::ptrdiff_t>(end),
                  [this](GridPoint a, GridPoint b) {
                      return position_order(position_of(a), position_of(b));
                  });
        const std::size_t first = kept;
        points[kept++] = points[begin];
        for (std::size_t i = begin + 1; i < end; ++i) {
            const GridPoint point = points[i];
            if (position_of(points[kept - 1]) == position_of(point)) {
                sets.unite(index_of(points[kept - 1]), index_of(point));
                continue;
            }
            points[kept++] = point;
        }
        for (std::size_t point = first; point < kept; ++point) {
            const double here_x = position_of(points[point]).x;
            for (std::size_t other = point + 1; other < kept; ++other) {
                if (double(position_of(points[other]).x) - here_x > weld_distance_) break;
                weld_if_close(points[point], points[other], sets);
            }
        }
        return kept;
    }

    // Neighbouring cells that the box of half-width weld_distance around the
    // point reaches. Each pair of points in different cells is tested once,
    // from the point in the cell with the smaller key.
    void weld_with_neighbour_cells(const std::vector<GridPoint>& points, std::size_t point,
                                   DisjointSets& sets) const {
        const GridPoint here = points[point];
        const glm::vec3& position = position_of(here);
        std::uint32_t low[3];
        std::uint32_t high[3];
        for (int axis = 0; axis < 3; ++axis) {
            low[axis] = cell_coordinate(double(position[axis]) - weld_distance_, axis);
            high[axis] = cell_coordinate(double(position[axis]) + weld_distance_, axis);
        }
        if (low[0] == high[0] && low[1] == high[1] && low[2] == high[2]) return;

        for (std::uint32_t x = low[0]; x <= high[0]; ++x) {
            for (std::uint32_t y = low[1]; y <= high[1]; ++y) {
                for (std::uint32_t z = low[2]; z <= high[2]; ++z) {
                    const std::uint32_t cell = pack_cell(x, y, z);
                    if (cell > cell_of(here)) weld_with_cell(points, here, cell, sets);
                }
            }
        }
    }

    void weld_with_cell(const std::vector<GridPoint>& points, GridPoint here, std::uint32_t cell,
                        DisjointSets& sets) const {
        // The cell's points, found in the points themselves (sorted by
        // cell): a table of cells would be as large as the points, in fresh
        // memory.
        const auto begin =
            std::lower_bound(points.begin(), points.end(), cell,
                             [](GridPoint p, std::uint32_t c) { return cell_of(p) < c; });
        const auto end = std::upper_bound(
            begin, points.end(), cell, [](std::uint32_t c, GridPoint p) { return c < cell_of(p); });
        if (begin == end) return;
        const double here_x = position_of(here).x;
        const double lowest_x = here_x - weld_distance_;
        auto other = std::lower_bound(begin, end, lowest_x, [this](GridPoint p, double x) {
            return double(position_of(p).x) < x;
        });
        for (; other != end; ++other) {
            if (double(position_of(*other).x) - here_x > weld_distance_) break;
            weld_if_close(here, *other, sets);
        }
    }

    glm::dvec3 origin_;
    double weld_distance_;
    double cell_size_ = 0.0;
    double inverse_cell_size_ = 0.0;
    std::array<int, 3> bits_{0, 0, 0};  // key bits per axis
    int key_bits_ = 0;
    std::array<std::uint32_t, 3> largest_{largest_cell_coordinate, largest_cell_coordinate,
                                          largest_cell_coordinate};
    const std::vector<glm::vec3>* positions_ = nullptr;  // while welding
};

Welding::Welding(const std::vector<glm::vec3>& positions, std::size_t parts)
    : positions_(positions), parts_(parts), lowest_(parts), highest_(parts), all_finite_(parts) {}

Welding::~Welding() = default;

void Welding::bound(std::size_t part) {
    glm::dvec3 lowest(std::numeric_limits<double>::infinity());
    glm::dvec3 highest(-std::numeric_limits<double>::infinity());
    const auto [begin, end] = range(part);
    for (std::size_t i = begin; i < end; ++i) {
        const glm::vec3& position = positions_[i];
        if (!is_finite(position)) continue;
        lowest = glm::min(lowest, glm::dvec3(position));
        highest = glm::max(highest, glm::dvec3(position));
    }
    lowest_[part] = lowest;
    highest_[part] = highest;
}

void Welding::make_grid() {
    glm::dvec3 lowest(std::numeric_limits<double>::infinity());
    glm::dvec3 highest(-std::numeric_limits<double>::infinity());
    for (std::size_t part = 0; part < parts_; ++part) {
        lowest = glm::min(lowest, lowest_[part]);
        highest = glm::max(highest, highest_[part]);
    }
    if (!(lowest.x <= highest.x)) return;  // no finite position: nothing welds
    const double weld_distance = weld_fraction_of_diagonal * glm::length(highest - lowest);
    grid_ = std::make_unique<WeldGrid>(lowest, highest, weld_distance);
    pairs_.resize(positions_.size());
    near_face_.resize(positions_.size());
}

void Welding::place(std::size_t part) {
    if (!grid_) return;
    const auto [begin, end] = range(part);
    all_finite_[part] =
        grid_->place(positions_, begin, end, pairs_.data(), near_face_.data()) ? 1 : 0;
}

std::vector<std::uint32_t> Welding::finish() {
    DisjointSets sets(positions_.size());
    if (grid_) {
        if (std::find(all_finite_.begin(), all_finite_.end(), 0) != all_finite_.end())
            std::erase(pairs_, WeldGrid::no_cell);
        grid_->weld(pairs_, positions_, near_face_, sets);
        grid_.reset();
        std::vector<std::uint64_t>().swap(pairs_);
        std::vector<std::uint8_t>().swap(near_face_);
    }
    std::vector<std::uint32_t> vertex_of_position(positions_.size());
    for (std::size_t index = 0; index < positions_.size(); ++index) {
        vertex_of_position[index] = sets.find(static_cast<std::uint32_t>(index));
    }
    return vertex_of_position;
}

std::vector<std::uint32_t> weld(const std::vector<glm::vec3>& positions) {
    Welding welding(positions, 1);
    welding.bound(0);
    welding.make_grid();
    welding.place(0);
    return welding.finish();
}

}  // namespace litkit::detail
