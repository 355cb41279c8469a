// SPDX-License-Identifier: MIT
// Glass in the CPU renderer (docs/spec.md §10): the tracer of src/trace/,
// built for a scene where some object has t > 0, and the fragment stage's
// last step for the pixels whose first surface is such an object. Their
// local part (1 − t)·I_ad + I_s follows the object's shading model, as the
// rest of the fragment stage does (flat: at the centroid; gouraud: the
// corners' values mixed; phong and faceted: at the pixel's point), and the
// ray tree adds t·[F·L(R) + (1 − F)·L(T)] at the pixel's point p with its
// N_s. A scene without glass builds nothing here and runs none of it.
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>

#include "core/parallel.hpp"
#include "cpu/pipeline.hpp"
#include "scene/transparency.hpp"

namespace litkit {

namespace {

// p's barycentric weights in the triangle (a, b, c), p on its plane.
glm::vec3 barycentric(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b,
                      const glm::vec3& c) {
    const glm::vec3 e1 = b - a, e2 = c - a, q = p - a;
    const float d11 = glm::dot(e1, e1), d12 = glm::dot(e1, e2), d22 = glm::dot(e2, e2);
    const float q1 = glm::dot(q, e1), q2 = glm::dot(q, e2);
    const float denominator = d11 * d22 - d12 * d12;
    if (!(denominator > 0.0f)) return {1.0f, 0.0f, 0.0f};
    const float v = (d22 * q1 - d12 * q2) / denominator;
    const float w = (d11 * q2 - d12 * q1) / denominator;
    return {1.0f - v - w, v, w};
}

}  // namespace

void Pipeline::prepare_tracer() {
    ray_tree.reset();
    traced.clear();
    const bool glass =
        std::any_of(scene.objects.begin(), scene.objects.end(),
                    [](const SceneObject& o) { return o.material.transmission > 0; });
    if (!glass) {
        accel.reset();  // no memory for a scene without glass
        return;
    }
    if (!accel) {
        std::vector<trace::MeshView> meshes;
        meshes.reserve(objects.size());
        for (const PreparedObject& object : objects)
            meshes.push_back({object.positions, object.triangles});
        const ParallelFor parallel = [this](std::size_t count, const ParallelJob& job) {
            pool.parallel_for(count, [&](std::size_t index, int) { job(index); });
        };
        accel = std::make_unique<trace::Accel>(meshes, parallel);
    }
    traced.reserve(objects.size());
    for (std::size_t o = 0; o < objects.size(); ++o) {
        const PreparedObject& object = objects[o];
        const Material& material = scene.objects[o].material;
        trace::TracedObject t;
        t.positions = object.positions;
        t.normals = object.normals;
        t.triangles = object.triangles;
        t.material = object.material;
        t.reflection = object.reflection;
        t.smooth = object.shading == Shading::Phong || object.shading == Shading::Gouraud;
        t.transmission = material.transmission;
        t.ior = material.ior;
        t.absorption_color = material.absorption_color;
        t.absorption_distance = material.absorption_distance;
        traced.push_back(t);
    }
    const Room& room = scene.room;
    trace::TraceSettings settings;
    settings.room_ior = room.ior;
    settings.max_depth = scene.max_depth;
    settings.min_distance = detail::secondary_min_distance(room);
    settings.background = detail::background_light(scene.output);
    ray_tree = std::make_unique<trace::RayTree>(traced, lights, *accel, settings);
}

void Pipeline::refract_row(int y, int width, int begin, int end, BandScratch& s,
                           const SamplePass& pass) const {
    const std::size_t offset =
        static_cast<std::size_t>(y % band_height) * static_cast<std::size_t>(width);
    const RowRays rays = camera.row_rays(y, pass.position);
    const glm::vec3 eye = camera.eye;
    for (int x = begin; x < end; ++x) {
        const std::size_t i = offset + static_cast<std::size_t>(x);
        const ShadeTriangle* tri = s.visible[i];
        if (!tri) continue;
        const trace::TracedObject& glass = traced[tri->object];
        if (!(glass.transmission > 0.0f)) continue;
        const PreparedObject& object = objects[tri->object];
        const auto& corners = object.triangles[tri->source];
        const glm::vec3& p0 = object.positions[corners[0]];
        const glm::vec3& p1 = object.positions[corners[1]];
        const glm::vec3& p2 = object.positions[corners[2]];
        const glm::vec3 point = point_on_ray(rays, width, x, 1.0f / s.depth[i]);
        const glm::vec3& face = ray_tree->face(tri->object, tri->source);
        const glm::vec3 weights = barycentric(point, p0, p1, p2);
        glm::vec3 normal = face;  // N_s: flat and faceted
        if (glass.smooth) {
            const glm::vec3 mixed = weights.x * object.normals[corners[0]] +
                                    weights.y * object.normals[corners[1]] +
                                    weights.z * object.normals[corners[2]];
            const float length = glm::length(mixed);
            if (length > 0.0f) normal = mixed / length;
        }
        // The local part, by the object's shading model (§3).
        trace::RayTree::Local local{};
        switch (object.shading) {
            case Shading::Flat: {
                const glm::vec3 centroid = (p0 + p1 + p2) / 3.0f;
                local =
                    ray_tree->local(tri->object, centroid, face, glm::normalize(eye - centroid));
                break;
            }
            case Shading::Gouraud:
                for (int k = 0; k < 3; ++k) {
                    const glm::vec3& corner = object.positions[corners[k]];
                    const trace::RayTree::Local at =
                        ray_tree->local(tri->object, corner, object.normals[corners[k]],
                                        glm::normalize(eye - corner));
                    local.ambient_diffuse += weights[k] * at.ambient_diffuse;
                    local.all += weights[k] * at.all;
                }
                break;
            case Shading::Phong:
            case Shading::Faceted:
                local = ray_tree->local(tri->object, point, normal, glm::normalize(eye - point));
                break;
        }
        const glm::vec3 own = (1.0f - glass.transmission) * local.ambient_diffuse +
                              (local.all - local.ambient_diffuse);
        const glm::vec3 direction = glm::normalize(point - eye);
        const bool probing = y == probe_y && x == probe_x;
        std::vector<RayNode>* record = probing ? &probed.ray_tree : nullptr;
        if (record) record->clear();
        const glm::vec3 traced_light = ray_tree->first_hit(
            {tri->object, tri->source, point, direction, normal}, s.traced_rays, record);
        const glm::vec3 total = own + traced_light;
        if (record && !record->empty()) {
            RayNode& camera_ray = record->front();
            camera_ray.origin = eye;
            camera_ray.length = glm::length(point - eye);
            camera_ray.local = own;
            camera_ray.contribution = own;
            camera_ray.radiance = total;
        }
        s.r[static_cast<std::size_t>(x)] = total.x;
        s.g[static_cast<std::size_t>(x)] = total.y;
        s.b[static_cast<std::size_t>(x)] = total.z;
    }
}

}  // namespace litkit
