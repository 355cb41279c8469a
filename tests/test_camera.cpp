// SPDX-License-Identifier: MIT
// The camera of docs/spec.md §1 (src/scene/camera.hpp): the ray through
// each pixel is the spec's, the vertex transform sends the points on it to
// that pixel's centre at their view depth, and the point at depth w is the
// one formula the SIMD kernels light.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include "litkit/scene.hpp"
#include "scene/camera.hpp"

namespace {

struct Case {
    litkit::Observer observer;
    int width, height;
};

std::vector<Case> cases() {
    litkit::Observer tilted;
    tilted.position = {3.5f, 1.0f, 4.0f};
    tilted.look_at = {-0.5f, 0.25f, 0.0f};
    tilted.up = {0.1f, 1.0f, 0.2f};
    tilted.fov_degrees = 32.0f;
    litkit::Observer wide;
    wide.position = {0.0f, 2.0f, -6.0f};
    wide.fov_degrees = 120.0f;
    wide.near = 0.5f;
    wide.far = 50.0f;
    return {{litkit::Observer{}, 64, 48}, {tilted, 101, 57}, {wide, 30, 90}};
}

TEST(Camera, RaysAreTheSpecsCameraSpaceRaysInWorldSpace) {
    for (const Case& c : cases()) {
        const litkit::Camera camera = litkit::make_camera(c.observer, c.width, c.height);
        const glm::dvec3 eye(c.observer.position);
        const glm::dvec3 f = glm::normalize(glm::dvec3(c.observer.look_at) - eye);
        const glm::dvec3 r = glm::normalize(glm::cross(f, glm::dvec3(c.observer.up)));
        const glm::dvec3 u = glm::cross(r, f);
        const double t = std::tan(double(c.observer.fov_degrees) * 3.14159265358979323846 / 360.0);
        const double aspect = double(c.width) / double(c.height);
        for (int j : {0, c.height / 3, c.height - 1}) {
            const litkit::RowRays rays = camera.row_rays(j);
            for (int i : {0, c.width / 2, c.width - 1}) {
                const double x = 2.0 * (i + 0.5) / c.width - 1.0;
                const double y = 1.0 - 2.0 * (j + 0.5) / c.height;
                const glm::dvec3 expected = f + x * t * aspect * r + y * t * u;
                const glm::dvec3 d(litkit::ray_direction(rays, c.width, i));
                EXPECT_LT(glm::length(d - expected), 1e-5 * glm::length(expected))
                    << "pixel (" << i << ", " << j << ") of " << c.width << "x" << c.height;
            }
        }
    }
}

TEST(Camera, TheCentrePixelOfAnOddImageLooksStraightAhead) {
    const Case c = cases()[1];
    ASSERT_EQ(c.width % 2, 1);
    ASSERT_EQ(c.height % 2, 1);
    const litkit::Camera camera = litkit::make_camera(c.observer, c.width, c.height);
    const glm::vec3 d = litkit::ray_direction(camera.row_rays(c.height / 2), c.width, c.width / 2);
    EXPECT_EQ(d, camera.forward);  // k = 0 and y = 0: exactly f
}

TEST(Camera, TheVertexTransformSendsPointsOnARayToItsPixelAtTheirDepth) {
    for (const Case& c : cases()) {
        const litkit::Camera camera = litkit::make_camera(c.observer, c.width, c.height);
        for (int j : {0, c.height / 2, c.height - 1}) {
            const litkit::RowRays rays = camera.row_rays(j);
            for (int i : {0, c.width / 3, c.width - 1}) {
                for (float w : {c.observer.near * 2.0f, 1.0f, c.observer.far / 2.0f}) {
                    const glm::vec3 p = litkit::point_on_ray(rays, c.width, i, w);
                    const glm::vec4 clip = camera.view_projection * glm::vec4(p, 1.0f);
                    EXPECT_NEAR(clip.w, w, 1e-4f * w);
                    const float window_x = (clip.x / clip.w + 1.0f) * 0.5f * float(c.width);
                    const float window_y = (1.0f - clip.y / clip.w) * 0.5f * float(c.height);
                    EXPECT_NEAR(window_x, float(i) + 0.5f, 1e-2f) << "depth " << w;
                    EXPECT_NEAR(window_y, float(j) + 0.5f, 1e-2f) << "depth " << w;
                }
            }
        }
    }
}

// The kernels' shade_phong and Renderer::probe both take the point from
// point_coordinate; this is its formula, each product rounded on its own.
TEST(Camera, ThePointOnARayIsEyePlusDepthTimesDirection) {
    const Case c = cases()[1];
    const litkit::Camera camera = litkit::make_camera(c.observer, c.width, c.height);
    const litkit::RowRays rays = camera.row_rays(7);
    for (int i : {0, 13, c.width - 1}) {
        const float w = 3.75f;
        const glm::vec3 p = litkit::point_on_ray(rays, c.width, i, w);
        const float k = float(2 * i + 1 - c.width);
        for (int a = 0; a < 3; ++a) {
            volatile float along = k * rays.across[a];
            volatile float d = along + rays.centre[a];
            volatile float step = w * d;
            EXPECT_EQ(p[a], rays.eye[a] + step) << "pixel " << i << ", axis " << a;
        }
    }
}

}  // namespace
