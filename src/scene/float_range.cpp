// SPDX-License-Identifier: MIT
#include "scene/float_range.hpp"

#include <algorithm>
#include <cmath>
#include <variant>

namespace litkit {

namespace {

// Rooms between these sizes are drawn as written.
constexpr double smallest_unscaled_room = 0x1p-8;
constexpr double largest_unscaled_room = 0x1p16;

float scaled(float length, double factor) { return static_cast<float>(double(length) * factor); }
glm::vec3 scaled(const glm::vec3& point, double factor) {
    return {scaled(point.x, factor), scaled(point.y, factor), scaled(point.z, factor)};
}

// f = 1 / (k_c + k_l·d + k_q·d²) with d = d' / factor.
glm::vec3 scaled_attenuation(const glm::vec3& attenuation, double factor) {
    return {attenuation.x, static_cast<float>(double(attenuation.y) / factor),
            static_cast<float>(double(attenuation.z) / (factor * factor))};
}

struct ScaleShape {
    double factor;
    void operator()(CubeShape& cube) const { cube.size = scaled(cube.size, factor); }
    void operator()(SphereShape& sphere) const { sphere.radius = scaled(sphere.radius, factor); }
    void operator()(TorusShape& torus) const {
        torus.major_radius = scaled(torus.major_radius, factor);
        torus.minor_radius = scaled(torus.minor_radius, factor);
    }
    void operator()(TeapotShape& teapot) const { teapot.size = scaled(teapot.size, factor); }
    void operator()(MeshFileShape&) const {}  // their objects' scale carries the factor
    void operator()(MeshDataShape&) const {}
};

}  // namespace

float float_safe_length_scale(const Scene& scene) {
    const double extent =
        std::max({double(scene.room.width), double(scene.room.height), double(scene.room.depth)});
    if (!(extent > 0.0) || !std::isfinite(extent)) return 1.0f;
    if (extent >= smallest_unscaled_room && extent <= largest_unscaled_room) return 1.0f;
    int exponent = 0;
    std::frexp(extent, &exponent);  // extent = m · 2^exponent, m in [0.5, 1)
    return static_cast<float>(std::ldexp(1.0, 1 - exponent));
}

Observer scale_lengths(const Observer& observer, float factor) {
    Observer result = observer;
    const double k = factor;
    result.position = scaled(observer.position, k);
    result.look_at = scaled(observer.look_at, k);
    result.near = scaled(observer.near, k);
    result.far = scaled(observer.far, k);
    return result;
}

Scene scale_lengths(const Scene& scene, float factor) {
    Scene result = scene;
    if (factor == 1.0f) return result;
    const double k = factor;
    result.room.width = scaled(scene.room.width, k);
    result.room.height = scaled(scene.room.height, k);
    result.room.depth = scaled(scene.room.depth, k);
    result.observer = scale_lengths(scene.observer, factor);
    for (SceneLight& light : result.lights) {
        if (auto* point = std::get_if<PointLight>(&light.light.kind)) {
            point->position = scaled(point->position, k);
            point->attenuation = scaled_attenuation(point->attenuation, k);
        } else if (auto* spot = std::get_if<SpotLight>(&light.light.kind)) {
            spot->position = scaled(spot->position, k);
            spot->attenuation = scaled_attenuation(spot->attenuation, k);
        }
    }
    for (SceneObject& object : result.objects) {
        object.position = scaled(object.position, k);
        object.material.absorption_distance = scaled(object.material.absorption_distance, k);
        if (std::holds_alternative<MeshFileShape>(object.shape) ||
            std::holds_alternative<MeshDataShape>(object.shape)) {
            object.scale = scaled(object.scale, k);
        } else {
            std::visit(ScaleShape{k}, object.shape);
        }
    }
    return result;
}

}  // namespace litkit
