// SPDX-License-Identifier: MIT
#include "geometry/convex.hpp"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace litkit {

namespace {

using glm::dvec3;

// A hull as GJK sees it: its support function, optionally scaled about its
// centre by `scale` (slightly below 1 to let touching hulls pass, slightly
// above 1 to let a point on the boundary count as inside).
struct Hull {
    std::span<const glm::vec3> points;
    dvec3 centre{0.0};
    double scale = 1.0;

    Hull(std::span<const glm::vec3> p, double s) : points(p), scale(s) {
        for (const glm::vec3& q : points) centre += dvec3(q);
        if (!points.empty()) centre /= static_cast<double>(points.size());
    }
    dvec3 support(const dvec3& direction) const {
        double best = -std::numeric_limits<double>::infinity();
        dvec3 best_point = centre;
        for (const glm::vec3& q : points) {
            const dvec3 p(q);
            const double d = glm::dot(p, direction);
            if (d > best) {
                best = d;
                best_point = p;
            }
        }
        return centre + scale * (best_point - centre);
    }
    double extent() const {
        double r = 0.0;
        for (const glm::vec3& q : points) r = std::max(r, glm::length(dvec3(q) - centre));
        return r;
    }
};

// The triangle-and-tetrahedron case analysis of GJK ("do simplex"): reduces
// `simplex` (newest point last) to the feature nearest the origin and sets
// the next search direction. Returns true when the origin is enclosed.
struct Simplex {
    std::array<dvec3, 4> points;
    int size = 0;
};

bool zero(const dvec3& v, double scale) { return glm::dot(v, v) <= 1e-24 * scale * scale; }

bool line_case(Simplex& s, dvec3& direction, double scale) {
    const dvec3 a = s.points[1], b = s.points[0];
    const dvec3 ab = b - a, ao = -a;
    if (glm::dot(ab, ao) > 0.0) {
        direction = glm::cross(glm::cross(ab, ao), ab);
        if (zero(direction, scale * scale * scale)) return true;  // origin on the segment
    } else {
        s.points[0] = a;
        s.size = 1;
        direction = ao;
    }
    return false;
}

bool triangle_case(Simplex& s, dvec3& direction, double scale) {
    const dvec3 a = s.points[2], b = s.points[1], c = s.points[0];
    const dvec3 ab = b - a, ac = c - a, ao = -a;
    const dvec3 abc = glm::cross(ab, ac);
    if (glm::dot(glm::cross(abc, ac), ao) > 0.0) {
        if (glm::dot(ac, ao) > 0.0) {
            s.points[0] = c;
            s.points[1] = a;
            s.size = 2;
            direction = glm::cross(glm::cross(ac, ao), ac);
            return zero(direction, scale * scale * scale);
        }
        s.points[0] = b;
        s.points[1] = a;
        s.size = 2;
        return line_case(s, direction, scale);
    }
    if (glm::dot(glm::cross(ab, abc), ao) > 0.0) {
        s.points[0] = b;
        s.points[1] = a;
        s.size = 2;
        return line_case(s, direction, scale);
    }
    const double side = glm::dot(abc, ao);
    if (std::abs(side) <= 1e-12 * scale * scale * scale) return true;  // origin in the triangle
    if (side > 0.0) {
        direction = abc;
    } else {
        s.points[0] = b;
        s.points[1] = c;
        direction = -abc;
    }
    return false;
}

bool tetrahedron_case(Simplex& s, dvec3& direction, double scale) {
    const dvec3 a = s.points[3], b = s.points[2], c = s.points[1], d = s.points[0];
    const dvec3 ao = -a;
    const dvec3 abc = glm::cross(b - a, c - a);
    const dvec3 acd = glm::cross(c - a, d - a);
    const dvec3 adb = glm::cross(d - a, b - a);
    // Each face normal points away from the fourth point by construction of
    // triangle_case's winding; test the origin against each face.
    if (glm::dot(abc, ao) > 0.0) {
        s.points[0] = c;
        s.points[1] = b;
        s.points[2] = a;
        s.size = 3;
        return triangle_case(s, direction, scale);
    }
    if (glm::dot(acd, ao) > 0.0) {
        s.points[0] = d;
        s.points[1] = c;
        s.points[2] = a;
        s.size = 3;
        return triangle_case(s, direction, scale);
    }
    if (glm::dot(adb, ao) > 0.0) {
        s.points[0] = b;
        s.points[1] = d;
        s.points[2] = a;
        s.size = 3;
        return triangle_case(s, direction, scale);
    }
    return true;
}

// GJK on the Minkowski difference A − B: do the hulls share a point?
bool gjk_intersect(const Hull& a, const Hull& b) {
    if (a.points.empty() || b.points.empty()) return false;
    // The hulls' own size sets every tolerance, so the test is free of scale
    // (a scene of 1e-25 is judged as one of 1); two single points compare
    // exactly.
    const double scale = std::max({a.extent(), b.extent(), std::numeric_limits<double>::min()});
    auto support = [&](const dvec3& d) { return a.support(d) - b.support(-d); };

    dvec3 direction = a.centre - b.centre;
    if (zero(direction, scale)) direction = dvec3(1.0, 0.0, 0.0);
    Simplex simplex;
    simplex.points[0] = support(direction);
    simplex.size = 1;
    direction = -simplex.points[0];
    for (int iteration = 0; iteration < 128; ++iteration) {
        if (zero(direction, scale)) return true;  // origin is a support point
        const dvec3 w = support(direction);
        // The new point does not pass the origin: a separating plane exists.
        if (glm::dot(w, direction) <= 0.0) return false;
        simplex.points[simplex.size++] = w;
        bool enclosed = false;
        switch (simplex.size) {
            case 2:
                enclosed = line_case(simplex, direction, scale);
                break;
            case 3:
                enclosed = triangle_case(simplex, direction, scale);
                break;
            case 4:
                enclosed = tetrahedron_case(simplex, direction, scale);
                break;
        }
        if (enclosed) return true;
    }
    // No convergence: only near-degenerate touching configurations get here;
    // count them as touching, not overlapping.
    return false;
}

// Relative margins: hulls shrink by this fraction about their centres to let
// touching pass; a hull grows by it to count boundary points as inside.
constexpr double touch_margin = 1e-6;

}  // namespace

bool hulls_intersect(std::span<const glm::vec3> a, std::span<const glm::vec3> b) {
    return gjk_intersect(Hull(a, 1.0 - touch_margin), Hull(b, 1.0 - touch_margin));
}

bool hull_contains(std::span<const glm::vec3> hull, const glm::vec3& point) {
    const glm::vec3 single[1] = {point};
    return gjk_intersect(Hull(hull, 1.0 + touch_margin), Hull(std::span(single, 1), 1.0));
}

}  // namespace litkit
