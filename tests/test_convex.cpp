// SPDX-License-Identifier: MIT
// GJK hull tests (convex.hpp) against cases whose answers are plain geometry.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include <glm/common.hpp>

#include "geometry/convex.hpp"

namespace {

// The 8 corners of an axis-aligned box centred at `c` with half-size `h`.
std::vector<glm::vec3> box(glm::vec3 c, float h) {
    std::vector<glm::vec3> corners;
    for (int i = 0; i < 8; ++i)
        corners.push_back(c + h * glm::vec3(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1));
    return corners;
}

// Points on a sphere of radius r about c (a fine polyhedron).
std::vector<glm::vec3> ball(glm::vec3 c, float r) {
    std::vector<glm::vec3> points;
    for (int i = 0; i <= 24; ++i) {
        const float theta = 3.14159265f * i / 24;
        for (int j = 0; j < 48; ++j) {
            const float phi = 2 * 3.14159265f * j / 48;
            points.push_back(c + r * glm::vec3(std::sin(theta) * std::cos(phi), std::cos(theta),
                                               std::sin(theta) * std::sin(phi)));
        }
    }
    return points;
}

}  // namespace

TEST(HullsIntersect, OverlappingBoxesIntersect) {
    EXPECT_TRUE(litkit::hulls_intersect(box({0, 0, 0}, 1), box({1.5f, 0, 0}, 1)));
    EXPECT_TRUE(litkit::hulls_intersect(box({0, 0, 0}, 1), box({1.2f, 1.2f, 1.2f}, 1)));
}

TEST(HullsIntersect, SeparatedBoxesDoNot) {
    EXPECT_FALSE(litkit::hulls_intersect(box({0, 0, 0}, 1), box({2.1f, 0, 0}, 1)));
    // Diagonal neighbours: separated along x although overlapping in y and z.
    EXPECT_FALSE(litkit::hulls_intersect(box({0, 0, 0}, 1), box({2.01f, 0.5f, -0.5f}, 1)));
}

TEST(HullsIntersect, BoxesSharingAFaceOnlyTouch) {
    // Centres 2 apart, half-sizes 1: the faces at x = 1 coincide.
    EXPECT_FALSE(litkit::hulls_intersect(box({0, 0, 0}, 1), box({2, 0, 0}, 1)));
    EXPECT_FALSE(litkit::hulls_intersect(box({0, 0, 0}, 1), box({2, 2, 2}, 1)));  // a corner
}

TEST(HullsIntersect, ContainedHullIntersects) {
    EXPECT_TRUE(litkit::hulls_intersect(box({0, 0, 0}, 2), box({0.1f, 0.2f, 0.3f}, 0.5f)));
    EXPECT_TRUE(litkit::hulls_intersect(box({0.1f, 0.2f, 0.3f}, 0.5f), box({0, 0, 0}, 2)));
}

TEST(HullsIntersect, BallsIntersectExactlyWhenCentresAreCloserThanTheRadii) {
    // Radii 1 and 1: the polyhedra are inscribed, so a gap of 0.05 separates
    // them and an overlap of 0.05 (well above the faceting error) joins them.
    EXPECT_TRUE(litkit::hulls_intersect(ball({0, 0, 0}, 1), ball({1.95f, 0.1f, 0}, 1)));
    EXPECT_FALSE(litkit::hulls_intersect(ball({0, 0, 0}, 1), ball({2.05f, 0.1f, 0}, 1)));
}

TEST(HullsIntersect, AgreesWithTheAxisTestOnRandomBoxes) {
    // Two axis-aligned boxes overlap exactly when their intervals overlap on
    // all three axes; GJK must agree away from the touching cases.
    std::mt19937 random(12345);
    std::uniform_real_distribution<float> offset(-3.0f, 3.0f), size(0.2f, 1.5f);
    int agreements = 0, checked = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const glm::vec3 c{offset(random), offset(random), offset(random)};
        const float ha = size(random), hb = size(random);
        const glm::vec3 gap = glm::abs(c) - glm::vec3(ha + hb);
        if (std::abs(gap.x) < 1e-3f || std::abs(gap.y) < 1e-3f || std::abs(gap.z) < 1e-3f) continue;
        const bool expected = gap.x < 0 && gap.y < 0 && gap.z < 0;
        ++checked;
        agreements += litkit::hulls_intersect(box({0, 0, 0}, ha), box(c, hb)) == expected;
    }
    EXPECT_GT(checked, 1500);
    EXPECT_EQ(agreements, checked);
}

TEST(HullContains, PointInsideBoxAndBall) {
    EXPECT_TRUE(litkit::hull_contains(box({0, -3, 0}, 1), {0, -3, 0}));
    EXPECT_TRUE(litkit::hull_contains(box({0, -3, 0}, 1), {0.9f, -2.1f, -0.9f}));
    EXPECT_TRUE(litkit::hull_contains(ball({1, 1, 1}, 2), {2, 2, 1}));  // distance √2 < 2
}

TEST(HullContains, PointOutside) {
    EXPECT_FALSE(litkit::hull_contains(box({0, -3, 0}, 1), {0, 0, 0}));
    EXPECT_FALSE(litkit::hull_contains(box({0, 0, 0}, 1), {1.01f, 0, 0}));
    EXPECT_FALSE(litkit::hull_contains(ball({0, 0, 0}, 1), {0.8f, 0.8f, 0}));  // distance 1.13
}

TEST(HullContains, PointOnTheBoundaryCountsAsInside) {
    EXPECT_TRUE(litkit::hull_contains(box({0, 0, 0}, 1), {1, 0.3f, -0.2f}));  // on a face
    EXPECT_TRUE(litkit::hull_contains(box({0, 0, 0}, 1), {1, 1, 1}));         // a corner
}

TEST(HullContains, EmptyHullContainsNothing) { EXPECT_FALSE(litkit::hull_contains({}, {0, 0, 0})); }
