// SPDX-License-Identifier: MIT
// litkit explain: the renderer's own record of a pixel (Renderer::probe),
// with the equations evaluated again, term by term, where it evaluated them.
#include "litkit/explain.hpp"
#include "litkit/error.hpp"

#include <glm/geometric.hpp>
#include <optional>
#include <stdexcept>
#include <vector>

#include "litkit/mesh.hpp"

namespace litkit {

namespace {

std::vector<Light> scene_lights(const Scene& scene) {
    std::vector<Light> lights;
    lights.reserve(scene.lights.size());
    for (const SceneLight& light : scene.lights) lights.push_back(light.light);
    return lights;
}

PointEvaluation evaluate(Reflection reflection, const Material& material,
                         const std::vector<Light>& lights, const glm::vec3& position,
                         const glm::vec3& normal, const glm::vec3& eye) {
    PointEvaluation point;
    point.position = position;
    point.normal = normal;
    point.to_eye = glm::normalize(eye - position);
    point.terms = shade_terms(reflection, material, lights, position, normal, eye);
    return point;
}

// (1/sqrt(v·v))·v, as every path normalises (equations::normalize).
glm::vec3 unit(const glm::vec3& v) { return (1.0f / std::sqrt(glm::dot(v, v))) * v; }

}  // namespace

struct PixelExplainer::Impl {
    Impl(const Scene& scene_in, const RenderOptions& options_in)
        : scene(scene_in),
          options(options_in),
          renderer(scene, options),
          lights(scene_lights(scene)),
          meshes(scene.objects.size()) {}

    // The object in the world as the renderer has it (the same function),
    // built the first time one of its pixels is explained.
    const WorldMesh& mesh(std::size_t object) {
        std::optional<WorldMesh>& slot = meshes.at(object);
        if (!slot) {
            const SceneObject& o = scene.objects.at(object);
            slot = world_mesh(o, normal_options(scene, o));
        }
        return *slot;
    }

    Scene scene;
    RenderOptions options;
    Renderer renderer;
    std::vector<Light> lights;
    std::vector<std::optional<WorldMesh>> meshes;
};

PixelExplainer::PixelExplainer(const Scene& scene, RenderOptions options)
    : impl_(std::make_unique<Impl>(scene, options)) {}

PixelExplainer::~PixelExplainer() = default;

PixelExplanation PixelExplainer::explain(int x, int y) {
    const Scene& scene = impl_->scene;
    const RenderOptions& options = impl_->options;
    const PixelProbe probe = impl_->renderer.probe(x, y);
    PixelExplanation explanation;
    explanation.x = x;
    explanation.y = y;
    explanation.rgb = probe.rgb;
    explanation.gamma = scene.output.gamma;
    explanation.hit = probe.hit;
    explanation.samples = probe.samples;
    if (!probe.hit) return explanation;

    const SceneObject& object = scene.objects.at(probe.object);
    explanation.object = probe.object;
    explanation.object_name = object.name;
    explanation.triangle = probe.triangle;
    explanation.reflection =
        object.reflection.value_or(scene.reflection.value_or(options.fallback_reflection));
    explanation.shading = object.shading.value_or(scene.shading.value_or(options.fallback_shading));
    explanation.clipped = probe.clipped;
    explanation.weights = probe.weights;
    explanation.sum = probe.intensity;
    explanation.ray_tree = probe.ray_tree;

    const WorldMesh& mesh = impl_->mesh(probe.object);
    for (int k = 0; k < 3; ++k) {
        explanation.corners[static_cast<std::size_t>(k)] =
            mesh.positions.at(probe.vertices[static_cast<std::size_t>(k)]);
        explanation.corner_normals[static_cast<std::size_t>(k)] =
            mesh.normals.at(probe.vertices[static_cast<std::size_t>(k)]);
    }
    // The corners come in the rasterizer's order (the order of the weights);
    // the face normal takes the mesh's winding.
    const auto& c = explanation.corners;
    const auto& wound = mesh.triangles.at(probe.triangle);
    explanation.face_normal = face_normal(mesh.positions.at(wound[0]), mesh.positions.at(wound[1]),
                                          mesh.positions.at(wound[2]));

    const std::vector<Light>& lights = impl_->lights;
    const glm::vec3 eye = scene.observer.position;
    switch (explanation.shading) {
        case Shading::Flat:
            explanation.evaluations.push_back(evaluate(explanation.reflection, object.material,
                                                       lights, (c[0] + c[1] + c[2]) / 3.0f,
                                                       explanation.face_normal, eye));
            break;
        case Shading::Gouraud:
            for (int k = 0; k < 3; ++k) {
                explanation.evaluations.push_back(evaluate(
                    explanation.reflection, object.material, lights, c[static_cast<std::size_t>(k)],
                    explanation.corner_normals[static_cast<std::size_t>(k)], eye));
            }
            break;
        default:
            explanation.evaluations.push_back(evaluate(explanation.reflection, object.material,
                                                       lights, probe.position, unit(probe.normal),
                                                       eye));
            break;
    }
    return explanation;
}

PixelExplanation explain_pixel(const Scene& scene, int x, int y, const RenderOptions& options) {
    return PixelExplainer(scene, options).explain(x, y);
}

PointEvaluation explain_point(const Scene& scene, Reflection reflection, const Material& material,
                              const glm::vec3& position, const glm::vec3& normal) {
    if (glm::dot(normal, normal) == 0.0f)
        throw ArgumentError("explain_point: the normal must not be the zero vector");
    return evaluate(reflection, material, scene_lights(scene), position, unit(normal),
                    scene.observer.position);
}

}  // namespace litkit
