#include "litkit/mesh.hpp"
#include "litkit/error.hpp"
#include "geometry/corner_angle.hpp"
#include "geometry/creased_normals.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec3.hpp>
#include <limits>
#include <memory>
#include <numbers>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace litkit {

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
        for (std::size_t i = 0; i < count; ++i) to[start[(from[i] >> shift) & digit_mask]++] = from[i];
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
            pairs[index] = std::uint64_t{pack_cell(coordinate[0], coordinate[1], coordinate[2])} << 32 | index;
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
                    if (near_face[index_of(points[point])]) near_faces.push_back(static_cast<std::uint32_t>(point));
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
        std::sort(from, points.begin() + static_cast<std::ptrdiff_t>(end), [this](GridPoint a, GridPoint b) {
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
        const auto begin = std::lower_bound(points.begin(), points.end(), cell,
                                            [](GridPoint p, std::uint32_t c) { return cell_of(p) < c; });
        const auto end = std::upper_bound(begin, points.end(), cell,
                                          [](std::uint32_t c, GridPoint p) { return c < cell_of(p); });
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

// Welding (docs/spec.md §2, DD9) in steps, so that a caller with threads
// can run the steps over positions in parts, on any threads, beside its own
// work: bound(part) for every part, make_grid(), place(part) for every
// part, then finish(). The parts split the positions only; the result is
// the same whatever their number and order (weld() is the steps in order,
// in one part).
class Welding {
  public:
    Welding(const std::vector<glm::vec3>& positions, std::size_t parts)
        : positions_(positions), parts_(parts), lowest_(parts), highest_(parts), all_finite_(parts) {}

    // The bounds of a part's finite positions (exact: min and max).
    void bound(std::size_t part) {
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

    // The weld distance, a fraction of the bounding box's diagonal, and the
    // grid of cells over the box.
    void make_grid() {
        glm::dvec3 lowest(std::numeric_limits<double>::infinity());
        glm::dvec3 highest(-std::numeric_limits<double>::infinity());
        for (std::size_t part = 0; part < parts_; ++part) {
            lowest = glm::min(lowest, lowest_[part]);
            highest = glm::max(highest, highest_[part]);
        }
        if (!(lowest.x <= highest.x)) return;  // no finite position: nothing welds
        const double weld_distance = weld_fraction_of_diagonal * glm::length(highest - lowest);
        grid_.emplace(lowest, highest, weld_distance);
        pairs_.resize(positions_.size());
        near_face_.resize(positions_.size());
    }

    void place(std::size_t part) {
        if (!grid_) return;
        const auto [begin, end] = range(part);
        all_finite_[part] = grid_->place(positions_, begin, end, pairs_.data(), near_face_.data()) ? 1 : 0;
    }

    // For each position, the index of the first position of its welded
    // vertex. Non-finite positions weld with nothing.
    std::vector<std::uint32_t> finish() {
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

  private:
    std::pair<std::size_t, std::size_t> range(std::size_t part) const {
        const std::size_t count = positions_.size();
        return {count * part / parts_, count * (part + 1) / parts_};
    }

    const std::vector<glm::vec3>& positions_;
    std::size_t parts_;
    std::vector<glm::dvec3> lowest_, highest_;  // per part
    std::vector<std::uint8_t> all_finite_;      // per part (not vector<bool>: parts write apart)
    std::optional<WeldGrid> grid_;
    std::vector<std::uint64_t> pairs_;  // per position: cell << 32 | index
    std::vector<std::uint8_t> near_face_;
};

// For each position, the index of the first position of its welded vertex
// (docs/spec.md §2, DD9). Non-finite positions weld with nothing.
std::vector<std::uint32_t> weld(const std::vector<glm::vec3>& positions) {
    Welding welding(positions, 1);
    welding.bound(0);
    welding.make_grid();
    welding.place(0);
    return welding.finish();
}

}  // namespace

glm::vec3 face_normal(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    // In double, so that thin or tiny triangles still get an accurate
    // direction; only an exactly zero (or non-finite) cross product counts as
    // zero area.
    const glm::dvec3 cross =
        glm::cross(glm::dvec3(b) - glm::dvec3(a), glm::dvec3(c) - glm::dvec3(a));
    const double length = glm::length(cross);
    if (!(length > 0.0) || !std::isfinite(length)) return glm::vec3(0.0f);
    return glm::vec3(cross / length);
}

namespace {

// face_normal of triangles[t] and, where there is one, triangles[t + 1]:
// with SSE2, the two in the lanes of its double vectors, the very
// operations of face_normal (glm's cross, its dot (x·x + y·y) + z·z, the
// square root, three divisions), so the very bits; about twice as fast
// (its square root and divisions take as long for two lanes as for one).
// Returns how many it made (1 or 2).
std::size_t face_normals_from(const Mesh& mesh, std::size_t t, std::size_t end, glm::vec3* out) {
#if defined(__SSE2__)
    if (t + 1 < end) {
        const auto& p = mesh.positions;
        const auto& first = mesh.triangles[t];
        const auto& second = mesh.triangles[t + 1];
        auto lanes = [&](int corner, int axis) {
            return _mm_set_pd(double(p[second[corner]][axis]), double(p[first[corner]][axis]));
        };
        __m128d e1[3], e2[3];
        for (int axis = 0; axis < 3; ++axis) {
            const __m128d a = lanes(0, axis);
            e1[axis] = _mm_sub_pd(lanes(1, axis), a);
            e2[axis] = _mm_sub_pd(lanes(2, axis), a);
        }
        const __m128d cross[3] = {
            _mm_sub_pd(_mm_mul_pd(e1[1], e2[2]), _mm_mul_pd(e2[1], e1[2])),
            _mm_sub_pd(_mm_mul_pd(e1[2], e2[0]), _mm_mul_pd(e2[2], e1[0])),
            _mm_sub_pd(_mm_mul_pd(e1[0], e2[1]), _mm_mul_pd(e2[0], e1[1]))};
        const __m128d length = _mm_sqrt_pd(_mm_add_pd(
            _mm_add_pd(_mm_mul_pd(cross[0], cross[0]), _mm_mul_pd(cross[1], cross[1])),
            _mm_mul_pd(cross[2], cross[2])));
        alignas(16) double unit[3][2], lengths[2];
        for (int axis = 0; axis < 3; ++axis) _mm_store_pd(unit[axis], _mm_div_pd(cross[axis], length));
        _mm_store_pd(lengths, length);
        for (int lane = 0; lane < 2; ++lane) {
            out[lane] = !(lengths[lane] > 0.0) || !std::isfinite(lengths[lane])
                            ? glm::vec3(0.0f)
                            : glm::vec3(float(unit[0][lane]), float(unit[1][lane]), float(unit[2][lane]));
        }
        return 2;
    }
#endif
    (void)end;
    const auto& triangle = mesh.triangles[t];
    out[0] = face_normal(mesh.positions[triangle[0]], mesh.positions[triangle[1]],
                         mesh.positions[triangle[2]]);
    return 1;
}

void check_triangle_indices(const Mesh& mesh, const char* function) {
    const std::size_t position_count = mesh.positions.size();
    if (position_count > std::numeric_limits<std::uint32_t>::max()) {
        throw std::length_error(std::string(function) +
                                ": more positions than 32-bit indices can reach");
    }
    for (const auto& triangle : mesh.triangles) {
        for (const std::uint32_t corner : triangle) {
            if (corner >= position_count) {
                throw ArgumentError(std::string(function) + ": triangle index " +
                                        std::to_string(corner) + " out of range (" +
                                        std::to_string(position_count) + " positions)");
            }
        }
    }
}

// Each triangle's part in the normal of each of its corners (entry 3·t + k),
// with the weights of docs/spec.md §9.2, and whether it takes part at all.
// The weighted normals of triangle (a, b, c) at its corners; false for a
// triangle that takes no part (zero area, which includes a zero-length
// edge, or non-finite).
bool triangle_weights(Normals weighting, const glm::vec3& a, const glm::vec3& b,
                      const glm::vec3& c, glm::vec3* out, glm::vec3& unit_normal) {
    if (weighting == Normals::Mean) {
        // DD9 exactly as before docs/spec.md §9.2: the DD8 normal, in float.
        unit_normal = face_normal(a, b, c);
        out[0] = out[1] = out[2] = unit_normal;
        return unit_normal != glm::vec3(0.0f);
    }
    const glm::dvec3 corners[3] = {glm::dvec3(a), glm::dvec3(b), glm::dvec3(c)};
    // (b − a) × (c − a): the same vector, e1 × e2, at every corner.
    const glm::dvec3 cross = glm::cross(corners[1] - corners[0], corners[2] - corners[0]);
    const double length = glm::length(cross);
    if (!(length > 0.0) || !std::isfinite(length)) {
        out[0] = out[1] = out[2] = unit_normal = glm::vec3(0.0f);
        return false;
    }
    const glm::dvec3 unit = cross / length;
    unit_normal = glm::vec3(unit);  // face_normal(a, b, c), without computing it again
    switch (weighting) {
        case Normals::Area: out[0] = out[1] = out[2] = glm::vec3(cross); break;
        case Normals::Angle: {
            // θ = atan2(‖e1 × e2‖, e1·e2) at two corners; the third is
            // π minus those (a triangle's angles sum to π), one call fewer.
            // corner_angle, not std::atan2: the same bits in every build.
            const double angle0 =
                corner_angle(length, glm::dot(corners[1] - corners[0], corners[2] - corners[0]));
            const double angle1 =
                corner_angle(length, glm::dot(corners[2] - corners[1], corners[0] - corners[1]));
            const double angle2 = std::max(0.0, std::numbers::pi - angle0 - angle1);
            out[0] = glm::vec3(angle0 * unit);
            out[1] = glm::vec3(angle1 * unit);
            out[2] = glm::vec3(angle2 * unit);
            break;
        }
        default:  // Normals::Max (Max 1999)
            for (int k = 0; k < 3; ++k) {
                const glm::dvec3 e1 = corners[(k + 1) % 3] - corners[k];
                const glm::dvec3 e2 = corners[(k + 2) % 3] - corners[k];
                out[k] = glm::vec3(cross / (glm::dot(e1, e1) * glm::dot(e2, e2)));
            }
            break;
    }
    return true;
}

// The checks every weighting starts with.
void check_weighting(const Mesh& mesh, Normals weighting, const char* function) {
    if (weighting == Normals::File) {
        throw std::invalid_argument(std::string(function) +
                                    ": \"file\" normals come from the mesh file, not from "
                                    "weighting faces");
    }
    check_triangle_indices(mesh, function);
}

// The checks, then the welded vertex of each position.
std::vector<std::uint32_t> welded_vertices(const Mesh& mesh, Normals weighting,
                                           const char* function) {
    check_weighting(mesh, weighting, function);
    return weld(mesh.positions);
}

// Calls visit(t, weights, unit_normal) for each triangle t that takes part,
// in order, with its corners' weighted normals.
template <class Visit>
void for_each_weighted_triangle(const Mesh& mesh, Normals weighting,
                                const std::vector<std::uint32_t>& vertex_of_position,
                                Visit&& visit) {
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& triangle = mesh.triangles[t];
        const std::uint32_t vertex_a = vertex_of_position[triangle[0]];
        const std::uint32_t vertex_b = vertex_of_position[triangle[1]];
        const std::uint32_t vertex_c = vertex_of_position[triangle[2]];
        // Two corners welded into one vertex make the triangle zero-area in
        // the welded mesh, whatever its tiny area before welding.
        if (vertex_a == vertex_b || vertex_b == vertex_c || vertex_c == vertex_a) continue;
        glm::vec3 weights[3];
        glm::vec3 unit_normal;
        if (triangle_weights(weighting, mesh.positions[triangle[0]], mesh.positions[triangle[1]],
                             mesh.positions[triangle[2]], weights, unit_normal))
            visit(t, weights, unit_normal);
    }
}

glm::vec3 normalized_or_zero(const glm::vec3& sum) {
    const float length = glm::length(sum);
    return length > 0.0f ? sum / length : glm::vec3(0.0f);
}

}  // namespace

std::vector<glm::vec3> vertex_normals(const Mesh& mesh) {
    return vertex_normals(mesh, Normals::Mean);
}

std::vector<glm::vec3> vertex_normals(const Mesh& mesh, Normals weighting) {
    return vertex_normals(mesh, weighting, ParallelFor{});
}

std::vector<glm::vec3> vertex_normals(const Mesh& mesh, Normals weighting,
                                      const ParallelFor& parallel) {
    check_weighting(mesh, weighting, "vertex_normals");
    const std::size_t position_count = mesh.positions.size();
    const std::size_t triangle_count = mesh.triangles.size();

    // Summing the weighted normals and normalising gives the direction of
    // their weighted mean (DD9, docs/spec.md §9.2), whatever the count.
    // (Made once the welding is done, in memory it may have freed.)
    std::vector<glm::vec3> normal_sums;
    std::vector<std::uint32_t> vertex_of_position;
    // With threads and a weighting of one vector a triangle (the same at
    // its three corners), the weights are computed beside the welding, and
    // then summed as for_each_weighted_triangle would visit them. Otherwise
    // summed as they come: no per-triangle array (3 MB of fresh memory for
    // 261k triangles, 9 MB with a vector a corner).
    if (parallel && (weighting == Normals::Mean || weighting == Normals::Area)) {
        std::vector<glm::vec3> weight(triangle_count);
        std::vector<std::uint8_t> takes_part(triangle_count);
        // The welding's steps over positions in halves, then the rest of it
        // (sorting by cell and welding: one job) beside the triangles'
        // weights in pieces, which the other threads share.
        constexpr std::size_t halves = 2;
        Welding welding(mesh.positions, halves);
        run_parallel(parallel, halves, [&](std::size_t half) { welding.bound(half); });
        welding.make_grid();
        run_parallel(parallel, halves, [&](std::size_t half) { welding.place(half); });
        constexpr std::size_t weight_piece = 16384;
        const std::size_t pieces = (triangle_count + weight_piece - 1) / weight_piece;
        run_parallel(parallel, 1 + pieces, [&](std::size_t job) {
            if (job == 0) {
                vertex_of_position = welding.finish();
                return;
            }
            const std::size_t begin = (job - 1) * weight_piece;
            const std::size_t end = std::min(triangle_count, begin + weight_piece);
            if (weighting == Normals::Mean) {
                // triangle_weights' Mean: the DD8 normal at every corner.
                for (std::size_t t = begin; t < end;) {
                    glm::vec3 normal[2];
                    const std::size_t made = face_normals_from(mesh, t, end, normal);
                    for (std::size_t k = 0; k < made; ++k, ++t) {
                        weight[t] = normal[k];
                        takes_part[t] = normal[k] != glm::vec3(0.0f);
                    }
                }
                return;
            }
            for (std::size_t t = begin; t < end; ++t) {
                const auto& triangle = mesh.triangles[t];
                glm::vec3 weights[3];
                glm::vec3 unit_normal;
                takes_part[t] = triangle_weights(weighting, mesh.positions[triangle[0]],
                                                 mesh.positions[triangle[1]],
                                                 mesh.positions[triangle[2]], weights, unit_normal);
                weight[t] = weights[0];
            }
        });
        normal_sums.assign(position_count, glm::vec3(0.0f));
        for (std::size_t t = 0; t < triangle_count; ++t) {
            const auto& triangle = mesh.triangles[t];
            const std::uint32_t vertex_a = vertex_of_position[triangle[0]];
            const std::uint32_t vertex_b = vertex_of_position[triangle[1]];
            const std::uint32_t vertex_c = vertex_of_position[triangle[2]];
            // The two tests of for_each_weighted_triangle, in its order.
            if (vertex_a == vertex_b || vertex_b == vertex_c || vertex_c == vertex_a) continue;
            if (!takes_part[t]) continue;
            normal_sums[vertex_a] += weight[t];
            normal_sums[vertex_b] += weight[t];
            normal_sums[vertex_c] += weight[t];
        }
    } else {
        vertex_of_position = weld(mesh.positions);
        normal_sums.assign(position_count, glm::vec3(0.0f));
        for_each_weighted_triangle(
            mesh, weighting, vertex_of_position,
            [&](std::size_t t, const glm::vec3* weights, const glm::vec3&) {
                for (int k = 0; k < 3; ++k)
                    normal_sums[vertex_of_position[mesh.triangles[t][k]]] += weights[k];
            });
    }

    std::vector<glm::vec3> normals(position_count);
    parallel_chunks(parallel, position_count, 16384, [&](std::size_t index) {
        normals[index] = normalized_or_zero(normal_sums[vertex_of_position[index]]);
    });
    return normals;
}

CreasedNormals creased_normals(const Mesh& mesh, Normals weighting, float crease_angle_degrees) {
    if (!(crease_angle_degrees > 0.0f && crease_angle_degrees <= 180.0f)) {
        throw std::invalid_argument("corner_normals: crease angle " +
                                    std::to_string(crease_angle_degrees) +
                                    " is outside (0, 180] degrees");
    }
    std::vector<std::uint32_t> vertex_of_position =
        welded_vertices(mesh, weighting, "corner_normals");
    const std::size_t triangle_count = mesh.triangles.size();
    const std::size_t position_count = mesh.positions.size();

    // Vertex normals, summed exactly as vertex_normals sums them, and each
    // usable triangle's DD8 normal. The corners' weights are not kept (9 MB
    // for 261k triangles): the few corners that need them again, at the
    // vertices compared pairwise, compute them again below.
    std::vector<glm::vec3> vertex_normal(position_count, glm::vec3(0.0f));
    std::vector<glm::vec3> unit_normals(triangle_count);
    std::vector<std::uint8_t> usable(triangle_count, 0);
    for_each_weighted_triangle(
        mesh, weighting, vertex_of_position,
        [&](std::size_t t, const glm::vec3* weights, const glm::vec3& unit_normal) {
            usable[t] = 1;
            unit_normals[t] = unit_normal;
            for (int k = 0; k < 3; ++k)
                vertex_normal[vertex_of_position[mesh.triangles[t][k]]] += weights[k];
        });
    for (glm::vec3& normal : vertex_normal) normal = normalized_or_zero(normal);

    const double limit = std::cos(glm::radians(double(crease_angle_degrees)));
    // A shortcut that decides most vertices in one pass over the triangles:
    // if every n̂_g at v lies within half the crease angle of one direction
    // (the vertex normal), any two lie within the crease angle of each other,
    // so nothing splits there and every corner at v has v's normal. The
    // margin keeps the shortcut to vertices where the pairwise test below,
    // in float, would find no split either.
    const double half_limit = std::cos(glm::radians(double(crease_angle_degrees)) / 2.0) + 1e-5;
    std::vector<std::uint8_t> pairwise(position_count, 0);
    for (std::size_t t = 0; t < triangle_count; ++t) {
        if (!usable[t]) continue;
        for (const std::uint32_t position : mesh.triangles[t]) {
            const std::uint32_t vertex = vertex_of_position[position];
            const glm::vec3& centre = vertex_normal[vertex];
            if (centre == glm::vec3(0.0f) ||
                !(double(glm::dot(centre, unit_normals[t])) > half_limit))
                pairwise[vertex] = 1;
        }
    }

    CreasedNormals result;

    // The corners at the other vertices, in corner order; an unusable
    // triangle (a sliver between welded corners) takes its corners'
    // unsplit vertex normals.
    std::vector<std::uint32_t> first_corner(position_count + 1, 0);
    for (std::size_t t = 0; t < triangle_count; ++t) {
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t vertex = vertex_of_position[mesh.triangles[t][k]];
            if (!pairwise[vertex]) continue;
            result.split_corners.push_back(static_cast<std::uint32_t>(3 * t + k));
            result.split_normals.push_back(vertex_normal[vertex]);
            if (usable[t]) ++first_corner[vertex + 1];
        }
    }
    std::partial_sum(first_corner.begin(), first_corner.end(), first_corner.begin());
    const auto finish = [&] {
        result.vertex_of_position = std::move(vertex_of_position);
        result.vertex_normals = std::move(vertex_normal);
        result.may_split = std::move(pairwise);
        return std::move(result);
    };
    if (first_corner.back() == 0) return finish();

    // The usable ones grouped by vertex (a counting sort, keeping triangle
    // order), each as its place in split_corners.
    std::vector<std::uint32_t> corners_at_vertex(first_corner.back());
    {
        std::vector<std::uint32_t> next(first_corner.begin(), first_corner.end() - 1);
        for (std::uint32_t at = 0; at < result.split_corners.size(); ++at) {
            const std::uint32_t corner = result.split_corners[at];
            if (!usable[corner / 3]) continue;
            const std::uint32_t vertex =
                vertex_of_position[mesh.triangles[corner / 3][corner % 3]];
            corners_at_vertex[next[vertex]++] = at;
        }
    }
    // Their weights, computed as the sums above computed them.
    std::vector<glm::vec3> split_weights(result.split_corners.size());
    for (std::uint32_t at = 0; at < result.split_corners.size(); ++at) {
        const std::uint32_t corner = result.split_corners[at];
        const auto& triangle = mesh.triangles[corner / 3];
        if (!usable[corner / 3]) continue;
        glm::vec3 weights[3];
        glm::vec3 unit_normal;
        triangle_weights(weighting, mesh.positions[triangle[0]], mesh.positions[triangle[1]],
                         mesh.positions[triangle[2]], weights, unit_normal);
        split_weights[at] = weights[corner % 3];
    }
    for (std::size_t vertex = 0; vertex < position_count; ++vertex) {
        const std::uint32_t begin = first_corner[vertex], end = first_corner[vertex + 1];
        // docs/spec.md §9.2: corner f sums the triangles g with
        // n̂_f·n̂_g > cos(crease angle), and always itself.
        for (std::uint32_t own = begin; own < end; ++own) {
            const std::uint32_t f = result.split_corners[corners_at_vertex[own]] / 3;
            glm::vec3 part(0.0f);
            for (std::uint32_t at = begin; at < end; ++at) {
                const std::uint32_t corner = result.split_corners[corners_at_vertex[at]];
                const std::uint32_t g = corner / 3;
                if (g == f || double(glm::dot(unit_normals[f], unit_normals[g])) > limit)
                    part += split_weights[corners_at_vertex[at]];
            }
            result.split_normals[corners_at_vertex[own]] = normalized_or_zero(part);
        }
    }
    return finish();
}

std::vector<glm::vec3> corner_normals(const Mesh& mesh, Normals weighting,
                                      float crease_angle_degrees) {
    const CreasedNormals creased = creased_normals(mesh, weighting, crease_angle_degrees);
    std::vector<glm::vec3> normals(mesh.triangles.size() * 3);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) normals[3 * t + k] = creased.position_normal(mesh.triangles[t][k]);
    for (std::size_t at = 0; at < creased.split_corners.size(); ++at)
        normals[creased.split_corners[at]] = creased.split_normals[at];
    return normals;
}

std::string_view to_string(Normals normals) {
    switch (normals) {
        case Normals::Mean: return "mean";
        case Normals::Area: return "area";
        case Normals::Angle: return "angle";
        case Normals::Max: return "max";
        case Normals::File: return "file";
    }
    return "mean";
}

std::optional<Normals> parse_normals(std::string_view text) {
    for (int i = 0; i < normals_count; ++i) {
        const auto normals = static_cast<Normals>(i);
        if (to_string(normals) == text) return normals;
    }
    return std::nullopt;
}

Bounds bounds(const Mesh& mesh) {
    if (mesh.positions.empty()) return {};
    Bounds box{mesh.positions.front(), mesh.positions.front()};
    for (const glm::vec3& position : mesh.positions) {
        box.min = glm::min(box.min, position);
        box.max = glm::max(box.max, position);
    }
    return box;
}

}  // namespace litkit
