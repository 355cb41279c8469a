// SPDX-License-Identifier: MIT
#include "scene/camera.hpp"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "core/scale_free.hpp"

namespace litkit {

namespace {

// Floats need no guard against fusing (camera.hpp).
float as_is(float v) { return v; }

}  // namespace

Camera make_camera(const Observer& observer, int width, int height) {
    Camera camera;
    const glm::mat4 projection(glm::perspective(glm::radians(double(observer.fov_degrees)),
                                                double(width) / double(height),
                                                double(observer.near), double(observer.far)));
    // glm's lookAt, free of scale: a look_at of 1e-30 draws what one of 1 draws.
    camera.view_projection =
        projection * scale_free::look_at(observer.position, observer.look_at, observer.up);
    // The rays' basis in double, rounded once to float, as the projection.
    const glm::dvec3 eye = glm::dvec3(observer.position);
    const glm::dvec3 f = glm::normalize(glm::dvec3(observer.look_at) - eye);
    const glm::dvec3 right = glm::normalize(glm::cross(f, glm::dvec3(observer.up)));
    const glm::dvec3 up = glm::cross(right, f);
    const double tan_half = std::tan(glm::radians(double(observer.fov_degrees)) / 2.0);
    const double aspect = double(width) / double(height);
    camera.eye = observer.position;
    camera.forward = glm::vec3(f);
    camera.up = glm::vec3(tan_half * up);
    camera.across = glm::vec3(tan_half * aspect / double(width) * right);  // per unit of k
    camera.width = width;
    camera.height = height;
    return camera;
}

RowRays Camera::row_rays(int j, SamplePosition sample) const {
    // Exact: H − 2j and 2 · sample.y (a multiple of 1/8) are, and so is
    // their difference; at the centre it is H − 2j − 1.
    const double numerator = double(height - 2 * j) - 2.0 * double(sample.y);
    const float y = static_cast<float>(numerator / double(height));
    const glm::vec3 centre = forward + y * up;
    return {{eye.x, eye.y, eye.z},
            {centre.x, centre.y, centre.z},
            {across.x, across.y, across.z},
            2.0f * sample.x - 1.0f};
}

glm::vec3 ray_direction(const RowRays& rays, int width, int i) {
    const float k = pixel_k(i, width) + rays.k_shift;
    glm::vec3 d;
    for (int c = 0; c < 3; ++c)
        d[c] = direction_coordinate(rays.centre[c], rays.across[c], k, as_is);
    return d;
}

glm::vec3 point_on_ray(const RowRays& rays, int width, int i, float w) {
    const glm::vec3 d = ray_direction(rays, width, i);
    glm::vec3 p;
    for (int c = 0; c < 3; ++c) p[c] = point_coordinate(rays.eye[c], d[c], w, as_is);
    return p;
}

}  // namespace litkit
