// SPDX-License-Identifier: MIT
// Normals (docs/spec.md §2, §9.2, DD8, DD9): each face's, each vertex's as
// the faces at its welded vertex weight them, and each corner's under a
// crease angle; the scene-file names of the weightings.
#include "core/portable_math.hpp"
#include "geometry/corner_angle.hpp"
#include "geometry/creased_normals.hpp"
#include "geometry/weld.hpp"
#include "litkit/error.hpp"
#include "litkit/mesh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec3.hpp>
#include <limits>
#include <numbers>
#include <numeric>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace litkit {

using detail::weld;
using detail::Welding;

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
        const __m128d cross[3] = {_mm_sub_pd(_mm_mul_pd(e1[1], e2[2]), _mm_mul_pd(e2[1], e1[2])),
                                  _mm_sub_pd(_mm_mul_pd(e1[2], e2[0]), _mm_mul_pd(e2[2], e1[0])),
                                  _mm_sub_pd(_mm_mul_pd(e1[0], e2[1]), _mm_mul_pd(e2[0], e1[1]))};
        const __m128d length = _mm_sqrt_pd(
            _mm_add_pd(_mm_add_pd(_mm_mul_pd(cross[0], cross[0]), _mm_mul_pd(cross[1], cross[1])),
                       _mm_mul_pd(cross[2], cross[2])));
        alignas(16) double unit[3][2], lengths[2];
        for (int axis = 0; axis < 3; ++axis)
            _mm_store_pd(unit[axis], _mm_div_pd(cross[axis], length));
        _mm_store_pd(lengths, length);
        for (int lane = 0; lane < 2; ++lane) {
            out[lane] =
                !(lengths[lane] > 0.0) || !std::isfinite(lengths[lane])
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
        throw ArgumentError(std::string(function) +
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
bool triangle_weights(Normals weighting, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
                      glm::vec3* out, glm::vec3& unit_normal) {
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
        case Normals::Area:
            out[0] = out[1] = out[2] = glm::vec3(cross);
            break;
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

#if defined(__SSE2__)
// a where mask is set, b elsewhere.
__m128d select(__m128d mask, __m128d a, __m128d b) {
    return _mm_or_pd(_mm_and_pd(mask, a), _mm_andnot_pd(mask, b));
}

// corner_angle(y, x) in each lane: its very operations (one of its two
// divisions, chosen before dividing; the same series), so the very bits.
__m128d corner_angles(__m128d y, __m128d x) {
    constexpr double atan_of_quarter[5] = {0.0, 0.24497866312686414, 0.4636476090008061,
                                           0.6435011087932844, 0.7853981633974483};
    const __m128d run = _mm_andnot_pd(_mm_set1_pd(-0.0), x);
    const __m128d steep = _mm_cmpgt_pd(y, run);
    const __m128d t = _mm_div_pd(select(steep, run, y), select(steep, y, run));
    const __m128i k =
        _mm_cvttpd_epi32(_mm_add_pd(_mm_mul_pd(t, _mm_set1_pd(4.0)), _mm_set1_pd(0.5)));
    const __m128d b = _mm_mul_pd(_mm_set1_pd(0.25), _mm_cvtepi32_pd(k));
    const __m128d u = _mm_div_pd(_mm_sub_pd(t, b), _mm_add_pd(_mm_set1_pd(1.0), _mm_mul_pd(t, b)));
    const __m128d u2 = _mm_mul_pd(u, u);
    __m128d series = _mm_set1_pd(-1.0 / 15.0);
    for (const double c :
         {1.0 / 13.0, -1.0 / 11.0, 1.0 / 9.0, -1.0 / 7.0, 1.0 / 5.0, -1.0 / 3.0, 1.0})
        series = _mm_add_pd(_mm_mul_pd(series, u2), _mm_set1_pd(c));
    // k is 0..4 where corner_angle is asked (y > 0); a lane of a zero-area
    // triangle, whose result is not used, may hold anything.
    const auto quarter = [&](int lane_k) {
        return atan_of_quarter[lane_k >= 0 && lane_k <= 4 ? lane_k : 0];
    };
    const __m128d table =
        _mm_set_pd(quarter(_mm_cvtsi128_si32(_mm_srli_si128(k, 4))), quarter(_mm_cvtsi128_si32(k)));
    const __m128d atan_t = _mm_add_pd(table, _mm_mul_pd(u, series));
    const __m128d from_x_axis =
        select(steep, _mm_sub_pd(_mm_set1_pd(1.5707963267948966), atan_t), atan_t);
    return select(_mm_cmplt_pd(x, _mm_setzero_pd()),
                  _mm_sub_pd(_mm_set1_pd(3.141592653589793), from_x_axis), from_x_axis);
}

// triangle_weights(Normals::Angle, ...) of triangles t and t + 1 in the two
// lanes of double vectors, operation for operation (glm's cross and dot,
// the square root, the divisions, corner_angle): the same bits, in about
// half the time (divisions take as long for two lanes as for one). out
// holds 3 weights a triangle, unit_normals 1; returns which take part
// (bit 0: t, bit 1: t + 1).
int angle_weights_of_two(const Mesh& mesh, std::size_t t, glm::vec3* out, glm::vec3* unit_normals) {
    const auto& p = mesh.positions;
    const auto& first = mesh.triangles[t];
    const auto& second = mesh.triangles[t + 1];
    __m128d corner[3][3];  // [corner][axis]
    for (int c = 0; c < 3; ++c)
        for (int axis = 0; axis < 3; ++axis)
            corner[c][axis] = _mm_set_pd(double(p[second[c]][axis]), double(p[first[c]][axis]));
    auto minus = [&](int a, int b, int axis) {
        return _mm_sub_pd(corner[a][axis], corner[b][axis]);
    };
    auto dot = [](const __m128d* a, const __m128d* b) {
        return _mm_add_pd(_mm_add_pd(_mm_mul_pd(a[0], b[0]), _mm_mul_pd(a[1], b[1])),
                          _mm_mul_pd(a[2], b[2]));
    };
    const __m128d e1[3] = {minus(1, 0, 0), minus(1, 0, 1), minus(1, 0, 2)};
    const __m128d e2[3] = {minus(2, 0, 0), minus(2, 0, 1), minus(2, 0, 2)};
    const __m128d cross[3] = {_mm_sub_pd(_mm_mul_pd(e1[1], e2[2]), _mm_mul_pd(e2[1], e1[2])),
                              _mm_sub_pd(_mm_mul_pd(e1[2], e2[0]), _mm_mul_pd(e2[2], e1[0])),
                              _mm_sub_pd(_mm_mul_pd(e1[0], e2[1]), _mm_mul_pd(e2[0], e1[1]))};
    const __m128d length = _mm_sqrt_pd(dot(cross, cross));
    __m128d unit[3];
    for (int axis = 0; axis < 3; ++axis) unit[axis] = _mm_div_pd(cross[axis], length);
    const __m128d f1[3] = {minus(2, 1, 0), minus(2, 1, 1), minus(2, 1, 2)};
    const __m128d f2[3] = {minus(0, 1, 0), minus(0, 1, 1), minus(0, 1, 2)};
    const __m128d angle0 = corner_angles(length, dot(e1, e2));
    const __m128d angle1 = corner_angles(length, dot(f1, f2));
    // std::max(0.0, v): (0 < v ? v : 0), −0 included, written as that
    // comparison (maxpd's rule for −0 is not every SSE2 emulation's).
    const __m128d rest = _mm_sub_pd(_mm_sub_pd(_mm_set1_pd(std::numbers::pi), angle0), angle1);
    const __m128d angle2 = select(_mm_cmplt_pd(_mm_setzero_pd(), rest), rest, _mm_setzero_pd());
    const __m128d angles[3] = {angle0, angle1, angle2};
    alignas(16) double lengths[2], units[3][2], weights[3][3][2];  // [corner][axis][lane]
    _mm_store_pd(lengths, length);
    for (int axis = 0; axis < 3; ++axis) {
        _mm_store_pd(units[axis], unit[axis]);
        for (int k = 0; k < 3; ++k)
            _mm_store_pd(weights[k][axis], _mm_mul_pd(angles[k], unit[axis]));
    }
    int taking_part = 0;
    for (int lane = 0; lane < 2; ++lane) {
        glm::vec3* weight = out + 3 * lane;
        if (!(lengths[lane] > 0.0) || !std::isfinite(lengths[lane])) {
            weight[0] = weight[1] = weight[2] = unit_normals[lane] = glm::vec3(0.0f);
            continue;
        }
        taking_part |= 1 << lane;
        unit_normals[lane] =
            glm::vec3(float(units[0][lane]), float(units[1][lane]), float(units[2][lane]));
        for (int k = 0; k < 3; ++k)
            weight[k] = glm::vec3(float(weights[k][0][lane]), float(weights[k][1][lane]),
                                  float(weights[k][2][lane]));
    }
    return taking_part;
}
#endif

// The checks every weighting starts with.
void check_weighting(const Mesh& mesh, Normals weighting, const char* function) {
    if (weighting == Normals::File) {
        throw ArgumentError(std::string(function) +
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
    // Two corners welded into one vertex make the triangle zero-area in
    // the welded mesh, whatever its tiny area before welding.
    const auto welded_flat = [&](std::size_t t) {
        const auto& triangle = mesh.triangles[t];
        const std::uint32_t vertex_a = vertex_of_position[triangle[0]];
        const std::uint32_t vertex_b = vertex_of_position[triangle[1]];
        const std::uint32_t vertex_c = vertex_of_position[triangle[2]];
        return vertex_a == vertex_b || vertex_b == vertex_c || vertex_c == vertex_a;
    };
    std::size_t t = 0;
#if defined(__SSE2__)
    if (weighting == Normals::Angle) {
        // Two triangles at a time (angle_weights_of_two), visited in order.
        for (; t + 1 < mesh.triangles.size(); t += 2) {
            glm::vec3 weights[6];
            glm::vec3 unit_normals[2];
            const int taking_part = angle_weights_of_two(mesh, t, weights, unit_normals);
            for (std::size_t lane = 0; lane < 2; ++lane)
                if ((taking_part >> lane & 1) && !welded_flat(t + lane))
                    visit(t + lane, weights + 3 * lane, unit_normals[lane]);
        }
    }
#endif
    for (; t < mesh.triangles.size(); ++t) {
        const auto& triangle = mesh.triangles[t];
        if (welded_flat(t)) continue;
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
        for_each_weighted_triangle(mesh, weighting, vertex_of_position,
                                   [&](std::size_t t, const glm::vec3* weights, const glm::vec3&) {
                                       for (int k = 0; k < 3; ++k)
                                           normal_sums[vertex_of_position[mesh.triangles[t][k]]] +=
                                               weights[k];
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
        throw ArgumentError("corner_normals: crease angle " + std::to_string(crease_angle_degrees) +
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

    const double limit = cos_degrees(crease_angle_degrees);
    // A shortcut that decides most vertices in one pass over the triangles:
    // if every n̂_g at v lies within half the crease angle of one direction
    // (the vertex normal), any two lie within the crease angle of each other,
    // so nothing splits there and every corner at v has v's normal. The
    // margin keeps the shortcut to vertices where the pairwise test below,
    // in float, would find no split either.
    const double half_limit = cos_degrees(double(crease_angle_degrees) / 2.0) + 1e-5;
    std::vector<std::uint8_t> pairwise(position_count, 0);
    std::size_t pairwise_count = 0;
    for (std::size_t t = 0; t < triangle_count; ++t) {
        if (!usable[t]) continue;
        for (const std::uint32_t position : mesh.triangles[t]) {
            const std::uint32_t vertex = vertex_of_position[position];
            if (pairwise[vertex]) continue;
            const glm::vec3& centre = vertex_normal[vertex];
            if (centre == glm::vec3(0.0f) ||
                !(double(glm::dot(centre, unit_normals[t])) > half_limit)) {
                pairwise[vertex] = 1;
                ++pairwise_count;
            }
        }
    }

    CreasedNormals result;
    const auto finish = [&] {
        result.vertex_of_position = std::move(vertex_of_position);
        result.vertex_normals = std::move(vertex_normal);
        result.may_split = std::move(pairwise);
        return std::move(result);
    };
    // Nothing can split anywhere (a smooth mesh: a sphere under any crease
    // it can have): no corner to list, and no pass over them to find none.
    if (pairwise_count == 0) return finish();

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
    if (first_corner.back() == 0) return finish();

    // The usable ones grouped by vertex (a counting sort, keeping triangle
    // order), each as its place in split_corners.
    std::vector<std::uint32_t> corners_at_vertex(first_corner.back());
    {
        std::vector<std::uint32_t> next(first_corner.begin(), first_corner.end() - 1);
        for (std::uint32_t at = 0; at < result.split_corners.size(); ++at) {
            const std::uint32_t corner = result.split_corners[at];
            if (!usable[corner / 3]) continue;
            const std::uint32_t vertex = vertex_of_position[mesh.triangles[corner / 3][corner % 3]];
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
        for (int k = 0; k < 3; ++k)
            normals[3 * t + k] = creased.position_normal(mesh.triangles[t][k]);
    for (std::size_t at = 0; at < creased.split_corners.size(); ++at)
        normals[creased.split_corners[at]] = creased.split_normals[at];
    return normals;
}

std::string_view to_string(Normals normals) {
    const auto index = static_cast<std::size_t>(normals);
    return index < normals_names.size() ? normals_names[index] : "?";
}

std::optional<Normals> parse_normals(std::string_view text) {
    for (std::size_t i = 0; i < normals_names.size(); ++i)
        if (normals_names[i] == text) return static_cast<Normals>(i);
    return std::nullopt;
}

}  // namespace litkit
