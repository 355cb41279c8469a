// SPDX-License-Identifier: MIT
#include "codegen/gl_glass.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "codegen/glsl_glass.hpp"
#include "litkit/mesh.hpp"
#include "scene/transparency.hpp"
#include "trace/bvh_build.hpp"

namespace litkit::detail {

namespace {

// The deepest hierarchy the shaders' walk can hold (its stack, glsl_glass.cpp).
constexpr int deepest_walk = 64;

struct Corner {
    glm::vec3 position;
    glm::vec3 normal;
};

// Triangle `t` of an object as OpenGL draws it (gl_scene.cpp's layouts).
std::array<Corner, 3> corners(const GlObject& object, std::size_t t) {
    std::array<Corner, 3> c;
    const float* v = object.vertices.data();
    for (std::size_t k = 0; k < 3; ++k) {
        if (object.indices.empty()) {
            const float* at = v + (3 * t + k) * 9;
            c[k] = {{at[0], at[1], at[2]}, {at[3], at[4], at[5]}};
        } else {
            const float* at = v + std::size_t{object.indices[3 * t + k]} * 6;
            c[k] = {{at[0], at[1], at[2]}, {at[3], at[4], at[5]}};
        }
    }
    return c;
}

void put(std::vector<float>& texels, const glm::vec3& v, float w) {
    texels.insert(texels.end(), {v.x, v.y, v.z, w});
}

float bits(std::uint32_t value) { return std::bit_cast<float>(value); }

// A box widened a little (as the CPU's hierarchy pads its boxes), so that a
// ray grazing a face still enters the box around it.
trace::build::Box padded(const trace::build::Box& box) {
    trace::build::Box wide = box;
    for (int a = 0; a < 3; ++a) {
        const float margin = std::max(std::fabs(box.lo[a]), std::fabs(box.hi[a])) * 1e-6f + 1e-30f;
        wide.lo[a] -= margin;
        wide.hi[a] += margin;
    }
    return wide;
}

struct Flattener {
    const trace::build::Tree& tree;
    std::vector<float>& nodes;
    int deepest = 0;

    // Node `n` and its subtree, depth first: an inner node's first child
    // right after it. Returns the node's place.
    std::uint32_t emit(std::uint32_t n, int depth) {
        deepest = std::max(deepest, depth);
        const trace::build::Node& node = tree.nodes[n];
        const std::uint32_t place = static_cast<std::uint32_t>(nodes.size() / 8);
        const trace::build::Box box = padded(node.box);
        nodes.insert(nodes.end(), 8, 0.0f);
        float* at = nodes.data() + std::size_t{place} * 8;
        for (int a = 0; a < 3; ++a) {
            at[a] = box.lo[a];
            at[4 + a] = box.hi[a];
        }
        if (node.count > 0) {
            at[3] = bits(node.a);  // leaf: its first triangle in leaf order
            at[7] = bits(node.count);
            return place;
        }
        emit(node.a, depth + 1);
        const std::uint32_t second = emit(node.b, depth + 1);
        at = nodes.data() + std::size_t{place} * 8;  // the vector may have moved
        at[3] = bits(second);
        at[7] = bits(0);
        return place;
    }
};

void put_objects(GlassData& data, std::span<const GlObject> objects) {
    data.objects.clear();
    const int texels = glsl::object_texels();
    for (const GlObject& object : objects) {
        const Material& m = object.material;
        const auto model = std::find(data.models.begin(), data.models.end(), object.reflection);
        const bool smooth = object.shading == Shading::Phong || object.shading == Shading::Gouraud;
        const bool clear = m.absorption_color == glm::vec3(1.0f);
        const std::size_t start = data.objects.size();
        put(data.objects, m.color, m.ka);
        data.objects.insert(data.objects.end(), {m.kd, m.ks, m.shininess, m.transmission});
        put(data.objects, m.absorption_color, m.absorption_distance);
        data.objects.insert(data.objects.end(),
                            {m.ior, static_cast<float>(model - data.models.begin()),
                             smooth ? 1.0f : 0.0f, clear ? 1.0f : 0.0f});
        data.objects.resize(start + static_cast<std::size_t>(texels) * 4, 0.0f);
        std::size_t parameter = start + 16;
        for_each_model_parameter(
            [&](const ModelParameter&, const float& value) { data.objects[parameter++] = value; },
            m);
    }
}

void put_settings(GlassData& data, const Scene& scene) {
    const Room& room = scene.room;
    data.room_ior = room.ior;
    data.max_depth = scene.max_depth;
    data.min_distance = secondary_min_distance(room);
    data.background_light = background_light(scene.output);
}

}  // namespace

bool has_glass(const Scene& scene) { return first_transparent_object(scene).has_value(); }

std::vector<Reflection> scene_models(std::span<const GlObject> objects) {
    std::vector<Reflection> models;
    for (const GlObject& object : objects)
        if (std::find(models.begin(), models.end(), object.reflection) == models.end())
            models.push_back(object.reflection);
    return models;
}

GlassData glass_data(const Scene& scene, std::span<const GlObject> objects) {
    GlassData data;
    data.models = scene_models(objects);
    // Every triangle, in drawing order: its corners, N_g and boxes.
    struct Triangle {
        std::array<Corner, 3> corners;
        glm::vec3 face;
        std::uint32_t object, index;
    };
    std::vector<Triangle> triangles;
    std::vector<trace::build::Box> boxes;
    for (std::size_t o = 0; o < objects.size(); ++o) {
        data.face_base.push_back(static_cast<int>(triangles.size()));
        for (std::size_t t = 0; t < objects[o].triangles; ++t) {
            const std::array<Corner, 3> c = corners(objects[o], t);
            const glm::vec3 face = face_normal(c[0].position, c[1].position, c[2].position);
            triangles.push_back(
                {c, face, static_cast<std::uint32_t>(o), static_cast<std::uint32_t>(t)});
            put(data.faces, face, 0.0f);
            trace::build::Box box;
            for (const Corner& corner : c)
                for (int a = 0; a < 3; ++a) {
                    box.lo[a] = std::min(box.lo[a], corner.position[a]);
                    box.hi[a] = std::max(box.hi[a], corner.position[a]);
                }
            boxes.push_back(box);
        }
    }
    const trace::build::Tree tree = trace::build::build_tree(boxes, 4, ParallelFor{});
    for (const std::uint32_t k : tree.order) {
        const Triangle& t = triangles[k];
        put(data.triangles, t.corners[0].position, static_cast<float>(t.object));
        put(data.triangles, t.corners[1].position, static_cast<float>(t.index));
        put(data.triangles, t.corners[2].position, 0.0f);
        put(data.triangles, t.face, 0.0f);
        for (const Corner& corner : t.corners) put(data.triangles, corner.normal, 0.0f);
    }
    if (!tree.nodes.empty()) {
        Flattener flat{tree, data.nodes};
        flat.emit(0, 1);
        if (flat.deepest > deepest_walk)
            throw std::runtime_error(
                "the scene's triangles make a hierarchy " + std::to_string(flat.deepest) +
                " levels deep; the shaders walk at most " + std::to_string(deepest_walk));
    }
    data.node_count = static_cast<int>(data.nodes.size() / 8);
    put_objects(data, objects);
    put_settings(data, scene);
    return data;
}

void update_glass_data(GlassData& data, const Scene& scene, std::span<const GlObject> objects) {
    put_objects(data, objects);
    put_settings(data, scene);
}

}  // namespace litkit::detail
