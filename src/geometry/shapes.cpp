// SPDX-License-Identifier: MIT
// Built-in shapes (docs/spec.md §2). Scene validation checks the parameters first
// (docs/spec.md §6); the checks here are a guard for callers of the library.
#include "litkit/shapes.hpp"
#include "core/portable_math.hpp"
#include "litkit/error.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace litkit {

namespace {

void require_positive(const char* function, const char* name, float value) {
    if (!(value > 0.0f) || !std::isfinite(value)) {
        throw ArgumentError(std::string(function) + ": " + name +
                            " must be a positive number, got " + std::to_string(value));
    }
}

void require_at_least(const char* function, const char* name, int value, int minimum) {
    if (value < minimum) {
        throw ArgumentError(std::string(function) + ": " + name + " must be at least " +
                            std::to_string(minimum) + ", got " + std::to_string(value));
    }
}

std::uint32_t to_index(int value) { return static_cast<std::uint32_t>(value); }

// The two triangles of a grid cell with corners a, b, c, d counter-clockwise
// seen from outside. Neighbouring cells alternate their diagonal like the
// squares of a chessboard, so that the triangles around a vertex lie
// symmetrically and the DD9 mean of their normals is not pulled sideways;
// with one diagonal everywhere, a sphere's vertex normals at 64 segments lean
// up to 0.01 away from radial.
void add_grid_cell(Mesh& mesh, bool other_diagonal, std::uint32_t a, std::uint32_t b,
                   std::uint32_t c, std::uint32_t d) {
    if (other_diagonal) {
        mesh.triangles.push_back({b, c, d});
        mesh.triangles.push_back({b, d, a});
    } else {
        mesh.triangles.push_back({a, b, c});
        mesh.triangles.push_back({a, c, d});
    }
}

}  // namespace

Mesh make_cube(float size) {
    require_positive("make_cube", "size", size);
    const float half = size / 2.0f;

    Mesh mesh;
    mesh.positions.reserve(24);
    mesh.triangles.reserve(12);
    for (int axis = 0; axis < 3; ++axis) {
        // (axis, first, second) is a cyclic permutation of (x, y, z), so
        // first × second points along +axis.
        const int first = (axis + 1) % 3;
        const int second = (axis + 2) % 3;
        for (const float side : {1.0f, -1.0f}) {
            // The face's corners, counter-clockwise seen from +axis; reversed
            // for the face on the −axis side so that both wind
            // counter-clockwise seen from outside.
            std::array<std::array<float, 2>, 4> corner_signs{
                {{-1.0f, -1.0f}, {1.0f, -1.0f}, {1.0f, 1.0f}, {-1.0f, 1.0f}}};
            if (side < 0.0f) std::swap(corner_signs[1], corner_signs[3]);

            const auto base = static_cast<std::uint32_t>(mesh.positions.size());
            for (const auto& [first_sign, second_sign] : corner_signs) {
                glm::vec3 corner(0.0f);
                corner[axis] = side * half;
                corner[first] = first_sign * half;
                corner[second] = second_sign * half;
                mesh.positions.push_back(corner);
            }
            // The diagonal joins the two corners whose product of the other
            // two coordinates' signs equals the face's side. Those are the
            // corners with x·y·z > 0, so such a corner lies in 2 triangles on
            // each of its 3 faces and every other corner in 1 on each: the
            // plain mean of DD9 then weighs the 3 face normals equally and
            // gives normalize(±1, ±1, ±1).
            const std::uint32_t start = corner_signs[0][0] * corner_signs[0][1] == side ? 0 : 1;
            const std::uint32_t a = base + start;
            const std::uint32_t b = base + (start + 1) % 4;
            const std::uint32_t c = base + (start + 2) % 4;
            const std::uint32_t d = base + (start + 3) % 4;
            mesh.triangles.push_back({a, b, c});
            mesh.triangles.push_back({a, c, d});
        }
    }
    return mesh;
}

Mesh make_sphere(float radius, int segments, int rings) {
    require_positive("make_sphere", "radius", radius);
    require_at_least("make_sphere", "segments", segments, 3);
    require_at_least("make_sphere", "rings", rings, 2);

    // One vertex at each pole and `rings − 1` circles of `segments` vertices
    // between them; the seam needs no duplicate vertices because nothing else
    // (texture coordinates) differs there.
    Mesh mesh;
    const int latitude_circles = rings - 1;
    mesh.positions.reserve(static_cast<std::size_t>(latitude_circles) * to_index(segments) + 2);
    mesh.triangles.reserve(2 * static_cast<std::size_t>(segments) * to_index(latitude_circles));

    // Every circle has the same azimuths: their sines and cosines once.
    std::vector<double> azimuth_sin(to_index(segments));
    std::vector<double> azimuth_cos(to_index(segments));
    // Angles in degrees (core/portable_math.hpp): the same bits in every
    // build, and exact at the right angles.
    for (int segment = 0; segment < segments; ++segment) {
        const SineCosine azimuth = sin_cos_degrees(360.0 * segment / segments);
        azimuth_sin[to_index(segment)] = azimuth.sine;
        azimuth_cos[to_index(segment)] = azimuth.cosine;
    }
    const std::uint32_t north_pole = 0;
    mesh.positions.emplace_back(0.0f, radius, 0.0f);
    for (int circle = 1; circle <= latitude_circles; ++circle) {
        const SineCosine polar_angle = sin_cos_degrees(180.0 * circle / rings);  // from +y
        const double circle_radius = radius * polar_angle.sine;
        const double height = radius * polar_angle.cosine;
        for (int segment = 0; segment < segments; ++segment) {
            mesh.positions.emplace_back(circle_radius * azimuth_sin[to_index(segment)], height,
                                        circle_radius * azimuth_cos[to_index(segment)]);
        }
    }
    const auto south_pole = static_cast<std::uint32_t>(mesh.positions.size());
    mesh.positions.emplace_back(0.0f, -radius, 0.0f);

    // Going down a meridian and then towards increasing azimuth turns
    // counter-clockwise seen from outside: at azimuth 0 (the +z side),
    // (−y) × (+x) = +z. With the alternating diagonals every DD9 normal is
    // radial but on the circles next to the poles: a vertex there lies in
    // the pole's 2 thin triangles and in 2 or 4 of the band's below, which
    // cannot balance for both kinds; those with 4 lean towards the equator
    // by about a sixth of the latitude step.
    auto vertex = [&](int circle, int segment) {
        return 1 + to_index(circle - 1) * to_index(segments) + to_index(segment % segments);
    };
    for (int segment = 0; segment < segments; ++segment) {
        // At the poles one triangle per segment, never a zero-area one.
        mesh.triangles.push_back({north_pole, vertex(1, segment), vertex(1, segment + 1)});
        for (int circle = 1; circle < latitude_circles; ++circle) {
            add_grid_cell(mesh, (circle + segment) % 2 == 1, vertex(circle, segment),
                          vertex(circle + 1, segment), vertex(circle + 1, segment + 1),
                          vertex(circle, segment + 1));
        }
        mesh.triangles.push_back(
            {vertex(latitude_circles, segment), south_pole, vertex(latitude_circles, segment + 1)});
    }
    return mesh;
}

Mesh make_torus(float major_radius, float minor_radius, int segments, int sides) {
    require_positive("make_torus", "major_radius", major_radius);
    require_positive("make_torus", "minor_radius", minor_radius);
    require_at_least("make_torus", "segments", segments, 3);
    require_at_least("make_torus", "sides", sides, 3);
    if (!(minor_radius < major_radius)) {
        // docs/spec.md §6: a thicker tube would pass through the axis and the surface
        // would cross itself.
        throw ArgumentError("make_torus: minor_radius (" + std::to_string(minor_radius) +
                            ") must be below major_radius (" + std::to_string(major_radius) + ")");
    }

    Mesh mesh;
    mesh.positions.reserve(static_cast<std::size_t>(segments) * to_index(sides));
    mesh.triangles.reserve(2 * static_cast<std::size_t>(segments) * to_index(sides));
    for (int segment = 0; segment < segments; ++segment) {
        const SineCosine azimuth = sin_cos_degrees(360.0 * segment / segments);  // around y
        for (int side = 0; side < sides; ++side) {
            // 0 = the outer equator
            const SineCosine tube_angle = sin_cos_degrees(360.0 * side / sides);
            const double distance_from_axis = major_radius + minor_radius * tube_angle.cosine;
            mesh.positions.emplace_back(distance_from_axis * azimuth.sine,
                                        minor_radius * tube_angle.sine,
                                        distance_from_axis * azimuth.cosine);
        }
    }

    // Towards increasing azimuth, then increasing tube angle, turns
    // counter-clockwise seen from outside: at the outer equator on the +z
    // side, (+x) × (+y) = +z.
    auto vertex = [&](int segment, int side) {
        return to_index(segment % segments) * to_index(sides) + to_index(side % sides);
    };
    for (int segment = 0; segment < segments; ++segment) {
        for (int side = 0; side < sides; ++side) {
            add_grid_cell(mesh, (segment + side) % 2 == 1, vertex(segment, side),
                          vertex(segment + 1, side), vertex(segment + 1, side + 1),
                          vertex(segment, side + 1));
        }
    }
    return mesh;
}

}  // namespace litkit
