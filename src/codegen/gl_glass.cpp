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

// A child as its parent node holds it: its box and either a node (count 0)
// or a leaf's triangles (the first, in u_triangles, and count > 0). An
// empty slot (count < 0) holds −1.0 for its count, whose bits are a
// negative integer (not a NaN, which a driver might not keep bit for bit).
struct Child {
    trace::build::Box box;
    std::uint32_t ref = 0;
    std::int32_t count = -1;
};

// The two-level hierarchy of src/trace/accel.cpp in u_nodes: node 0 is the
// root of the tree over the objects, node 1 + o the root of object o's tree
// over its triangles (where a ray inside o starts), the rest in any order.
// Each node holds its two children's boxes, so that a step of the walk
// tests both from four texels.
struct Flattener {
    std::vector<float>& nodes;
    int deepest = 0;

    std::uint32_t allocate() {
        const auto place = static_cast<std::uint32_t>(nodes.size() / (4 * glsl::node_texels));
        nodes.insert(nodes.end(), std::size_t{4} * glsl::node_texels, 0.0f);
        return place;
    }

    void fill(std::uint32_t place, const Child& a, const Child& b) {
        // The walk tests two sibling leaves in one loop.
        if (a.count > 0 && b.count > 0 && b.ref != a.ref + static_cast<std::uint32_t>(a.count))
            throw std::logic_error("glass buffers: sibling leaves whose triangles are apart");
        float* at = nodes.data() + std::size_t{place} * 4 * glsl::node_texels;
        for (const Child* child : {&a, &b}) {
            if (child->count < 0) {
                std::fill(at, at + 8, 0.0f);
                at[7] = -1.0f;
            } else {
                const trace::build::Box box = padded(child->box);
                for (int k = 0; k < 3; ++k) {
                    at[k] = box.lo[k];
                    at[4 + k] = box.hi[k];
                }
                at[3] = bits(child->ref);
                at[7] = bits(static_cast<std::uint32_t>(child->count));
            }
            at += 8;
        }
    }

    // Node n of `tree` as a child: a leaf's triangles (triangle_base + its
    // place in the tree's order), or a node of its own, filled, whose
    // leaves `leaf` makes.
    template <typename Leaf>
    Child child(const trace::build::Tree& tree, std::uint32_t n, int depth, const Leaf& leaf) {
        const trace::build::Node& node = tree.nodes[n];
        if (node.count > 0) return leaf(node);
        const std::uint32_t place = allocate();
        fill_from(place, tree, n, depth, leaf);
        return {node.box, place, 0};
    }

    // `place` holds node n's two children (a leaf root: itself and nothing).
    template <typename Leaf>
    void fill_from(std::uint32_t place, const trace::build::Tree& tree, std::uint32_t n, int depth,
                   const Leaf& leaf) {
        deepest = std::max(deepest, depth);
        const trace::build::Node& node = tree.nodes[n];
        if (node.count > 0) {
            fill(place, leaf(node), Child{});
            return;
        }
        const Child a = child(tree, node.a, depth + 1, leaf);
        const Child b = child(tree, node.b, depth + 1, leaf);
        fill(place, a, b);
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
    Flattener flat{data.nodes};
    for (std::size_t o = 0; o <= objects.size(); ++o) flat.allocate();  // the roots' places
    // Each object's triangles, in drawing order: their corners, N_g and
    // boxes; then in its tree's leaf order into u_triangles.
    std::vector<trace::build::Box> object_boxes;
    std::vector<std::uint32_t> placed;  // the objects with triangles
    int deepest_object = 0;
    for (std::size_t o = 0; o < objects.size(); ++o) {
        data.face_base.push_back(static_cast<int>(data.faces.size() / 4));
        std::vector<std::array<Corner, 3>> triangles;
        std::vector<trace::build::Box> boxes;
        for (std::size_t t = 0; t < objects[o].triangles; ++t) {
            const std::array<Corner, 3>& c = triangles.emplace_back(corners(objects[o], t));
            put(data.faces, face_normal(c[0].position, c[1].position, c[2].position), 0.0f);
            trace::build::Box& box = boxes.emplace_back();
            for (const Corner& corner : c)
                for (int a = 0; a < 3; ++a) {
                    box.lo[a] = std::min(box.lo[a], corner.position[a]);
                    box.hi[a] = std::max(box.hi[a], corner.position[a]);
                }
        }
        const auto root = static_cast<std::uint32_t>(1 + o);
        if (triangles.empty()) {
            flat.fill(root, Child{}, Child{});
            continue;
        }
        const auto base =
            static_cast<std::uint32_t>(data.triangles.size() / 4 / glsl::triangle_texels);
        const trace::build::Tree tree = trace::build::build_tree(boxes, 4, ParallelFor{});
        for (const std::uint32_t k : tree.order) {
            const std::array<Corner, 3>& c = triangles[k];
            const glm::vec3 face = face_normal(c[0].position, c[1].position, c[2].position);
            put(data.triangles, c[0].position, static_cast<float>(o));
            put(data.triangles, c[1].position, static_cast<float>(k));
            put(data.triangles, c[2].position, 0.0f);
            put(data.triangles, face, 0.0f);
            for (const Corner& corner : c) put(data.triangles, corner.normal, 0.0f);
        }
        flat.deepest = 0;
        flat.fill_from(root, tree, 0, 1, [base](const trace::build::Node& leaf) {
            return Child{leaf.box, base + leaf.a, static_cast<std::int32_t>(leaf.count)};
        });
        deepest_object = std::max(deepest_object, flat.deepest);
        object_boxes.push_back(tree.nodes[0].box);
        placed.push_back(static_cast<std::uint32_t>(o));
    }
    int deepest = deepest_object;
    if (placed.empty()) {
        flat.fill(0, Child{}, Child{});
    } else {
        // A leaf of the objects' tree holds one object: its root's place.
        const trace::build::Tree top = trace::build::build_tree(object_boxes, 1, ParallelFor{});
        flat.deepest = 0;
        flat.fill_from(0, top, 0, 1, [&](const trace::build::Node& leaf) {
            return Child{leaf.box, 1 + placed[top.order[leaf.a]], 0};
        });
        deepest += flat.deepest;
    }
    if (deepest > deepest_walk)
        throw std::runtime_error(
            "the scene's triangles make a hierarchy " + std::to_string(deepest) +
            " levels deep; the shaders walk at most " + std::to_string(deepest_walk));
    data.node_count = static_cast<int>(data.nodes.size() / (4 * glsl::node_texels));
    put_objects(data, objects);
    put_settings(data, scene);
    return data;
}

void update_glass_data(GlassData& data, const Scene& scene, std::span<const GlObject> objects) {
    put_objects(data, objects);
    put_settings(data, scene);
}

}  // namespace litkit::detail
