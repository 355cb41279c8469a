// The tracer's acceleration structure (accel.hpp): one binary SAH tree per
// object (bvh_build.cpp) and one over the objects' boxes, in one array of
// nodes where the top tree's leaf for an object is a copy of that object's
// root, so that nearest_front walks the whole scene in one loop and
// nearest_back(o) starts at o's root and sees o's triangles alone.
//
// Exactly the answers of testing every triangle: boxes are tested
// conservatively (padded, entry and exit distances widened by a relative
// margin far above the rounding of the slab test and of the triangle
// test's shear), a subtree is skipped only when its entry lies beyond the
// best hit so far (a tie at the same distance may still win by its smaller
// index), and every triangle is tested by the one watertight test below.
#include "trace/accel.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "trace/bvh_build.hpp"

namespace litkit::trace {

namespace {

enum class Facing { Front, Back };

constexpr float margin = 0x1p-19f;  // relative widening of boxes and box distances

// What the triangle test and the box test need of a ray, computed once.
struct Prepared {
    glm::vec3 origin, inverse;
    int kx, ky, kz;
    float sx, sy, sz;
    float t_min, t_max;

    explicit Prepared(const Ray& ray) : origin(ray.origin), t_min(ray.t_min), t_max(ray.t_max) {
        const glm::vec3& d = ray.direction;
        const glm::vec3 a_abs = glm::abs(d);
        kz = a_abs.x > a_abs.y ? (a_abs.x > a_abs.z ? 0 : 2) : (a_abs.y > a_abs.z ? 1 : 2);
        kx = (kz + 1) % 3, ky = (kx + 1) % 3;
        if (d[kz] < 0.0f) std::swap(kx, ky);
        sx = d[kx] / d[kz], sy = d[ky] / d[kz], sz = 1.0f / d[kz];
        for (int a = 0; a < 3; ++a) {
            // 1/0 (and 1/x overflowing) as the largest float: (b − o) · inverse
            // is then never 0 · ∞.
            const float inv = 1.0f / d[a];
            inverse[a] =
                std::isfinite(inv) ? inv : std::copysign(std::numeric_limits<float>::max(), d[a]);
        }
    }
};

// Woop, Benthin and Wald's watertight test of one triangle; updates `best`
// when the triangle is hit closer (or as close, by a smaller index) with the
// facing asked for.
void intersect(const Prepared& ray, const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2,
               Facing facing, std::uint32_t object, std::uint32_t triangle, Hit& best) {
    const int kx = ray.kx, ky = ray.ky, kz = ray.kz;
    const float sx = ray.sx, sy = ray.sy, sz = ray.sz;
    const glm::vec3 a = p0 - ray.origin, b = p1 - ray.origin, c = p2 - ray.origin;
    const float ax = a[kx] - sx * a[kz], ay = a[ky] - sy * a[kz];
    const float bx = b[kx] - sx * b[kz], by = b[ky] - sy * b[kz];
    const float cx = c[kx] - sx * c[kz], cy = c[ky] - sy * c[kz];
    float u = cx * by - cy * bx, v = ax * cy - ay * cx, w = bx * ay - by * ax;
    if (u == 0.0f || v == 0.0f || w == 0.0f) {
        u = static_cast<float>(double(cx) * by - double(cy) * bx);
        v = static_cast<float>(double(ax) * cy - double(ay) * cx);
        w = static_cast<float>(double(bx) * ay - double(by) * ax);
    }
    if ((u < 0.0f || v < 0.0f || w < 0.0f) && (u > 0.0f || v > 0.0f || w > 0.0f)) return;
    const float det = u + v + w;
    if (det == 0.0f) return;
    // det > 0: the triangle winds counter-clockwise seen from the ray's
    // origin side, so d·N_g < 0 (a front face).
    if ((facing == Facing::Front) != (det > 0.0f)) return;
    const float t_scaled = u * (sz * a[kz]) + v * (sz * b[kz]) + w * (sz * c[kz]);
    const float t = t_scaled / det;
    if (!(t > ray.t_min && t < ray.t_max)) return;
    if (t > best.t || (t == best.t && (object > best.object ||
                                       (object == best.object && triangle > best.triangle))))
        return;
    best = Hit{t, object, triangle, v / det, w / det};
}

// A box widened by `margin` of its largest coordinate (and by the smallest
// normal float, for a box at the origin).
build::Box padded(const build::Box& box) {
    float largest = 0.0f;
    for (int a = 0; a < 3; ++a)
        largest = std::max({largest, std::abs(box.lo[a]), std::abs(box.hi[a])});
    const float pad = largest * margin + std::numeric_limits<float>::min();
    build::Box out = box;
    for (int a = 0; a < 3; ++a) out.lo[a] -= pad, out.hi[a] += pad;
    return out;
}

struct BNode {
    build::Box box;  // padded
    std::uint32_t a = 0, b = 0, count = 0, object = 0;
};

}  // namespace

struct Accel::Impl {
    std::vector<MeshView> objects;
    std::vector<BNode> nodes;
    std::vector<std::uint32_t> slots;  // leaves' triangles
    std::vector<std::uint32_t> roots;  // per object: its root node, or none
    std::uint32_t top = no_object;

    // The entry distance of `node`'s box along `ray` (conservative), or
    // none when the ray misses it before `limit`.
    static bool enters(const Prepared& ray, const BNode& node, float limit, float& entry) {
        float near = -std::numeric_limits<float>::infinity();
        float far = std::numeric_limits<float>::infinity();
        for (int a = 0; a < 3; ++a) {
            const float t0 = (node.box.lo[a] - ray.origin[a]) * ray.inverse[a];
            const float t1 = (node.box.hi[a] - ray.origin[a]) * ray.inverse[a];
            near = std::max(near, std::min(t0, t1));
            far = std::min(far, std::max(t0, t1));
        }
        near -= std::abs(near) * margin;
        far += std::abs(far) * margin;
        entry = std::max(near, ray.t_min);
        return near <= far && near <= limit && far >= ray.t_min;
    }

    Hit traverse(const Prepared& ray, std::uint32_t root, Facing facing) const {
        Hit best;
        if (root == no_object) return best;
        struct Entry {
            std::uint32_t node;
            float entry;
        };
        Entry stack[256];
        int size = 0;
        stack[size++] = {root, -std::numeric_limits<float>::infinity()};
        while (size > 0) {
            const Entry e = stack[--size];
            const float limit = std::min(best.t, ray.t_max);
            if (e.entry > limit) continue;
            const BNode& node = nodes[e.node];
            float entry = 0.0f;
            if (!enters(ray, node, limit, entry)) continue;
            if (node.count > 0) {
                const MeshView& mesh = objects[node.object];
                for (std::uint32_t i = node.a; i < node.a + node.count; ++i) {
                    const auto& tri = mesh.triangles[slots[i]];
                    intersect(ray, mesh.positions[tri[0]], mesh.positions[tri[1]],
                              mesh.positions[tri[2]], facing, node.object, slots[i], best);
                }
                continue;
            }
            stack[size++] = {node.b, entry};
            stack[size++] = {node.a, entry};
        }
        return best;
    }
};

Accel::Accel(std::span<const MeshView> objects, const ParallelFor& parallel)
    : impl_(std::make_unique<Impl>()) {
    Impl& m = *impl_;
    m.objects.assign(objects.begin(), objects.end());
    m.roots.assign(objects.size(), no_object);
    std::vector<build::Box> object_boxes;
    std::vector<std::uint32_t> placed;  // the objects with triangles
    for (std::uint32_t o = 0; o < objects.size(); ++o) {
        const MeshView& mesh = objects[o];
        if (mesh.triangles.empty()) continue;
        std::vector<build::Box> boxes(mesh.triangles.size());
        parallel_chunks(parallel, boxes.size(), 4096, [&](std::size_t i) {
            build::Box& box = boxes[i];
            for (const std::uint32_t v : mesh.triangles[i])
                for (int a = 0; a < 3; ++a) {
                    box.lo[a] = std::min(box.lo[a], mesh.positions[v][a]);
                    box.hi[a] = std::max(box.hi[a], mesh.positions[v][a]);
                }
        });
        const build::Tree tree = build::build_tree(boxes, 4, parallel);
        const auto node_offset = static_cast<std::uint32_t>(m.nodes.size());
        const auto slot_offset = static_cast<std::uint32_t>(m.slots.size());
        for (const build::Node& n : tree.nodes) {
            if (n.count > 0)
                m.nodes.push_back({padded(n.box), n.a + slot_offset, 0, n.count, o});
            else
                m.nodes.push_back({padded(n.box), n.a + node_offset, n.b + node_offset, 0, o});
        }
        m.slots.insert(m.slots.end(), tree.order.begin(), tree.order.end());
        m.roots[o] = node_offset;
        object_boxes.push_back(tree.nodes[0].box);
        placed.push_back(o);
    }
    if (placed.empty()) return;
    const build::Tree top = build::build_tree(object_boxes, 1, parallel);
    const auto offset = static_cast<std::uint32_t>(m.nodes.size());
    for (const build::Node& n : top.nodes) {
        if (n.count > 0)  // the object's root in its place
            m.nodes.push_back(m.nodes[m.roots[placed[top.order[n.a]]]]);
        else
            m.nodes.push_back({padded(n.box), n.a + offset, n.b + offset, 0, 0});
    }
    m.top = offset;
}
Accel::~Accel() = default;
Accel::Accel(Accel&&) noexcept = default;
Accel& Accel::operator=(Accel&&) noexcept = default;

Hit Accel::nearest_front(const Ray& ray) const {
    return impl_->traverse(Prepared(ray), impl_->top, Facing::Front);
}

Hit Accel::nearest_back(const Ray& ray, std::uint32_t object) const {
    if (object >= impl_->roots.size()) return Hit{};
    return impl_->traverse(Prepared(ray), impl_->roots[object], Facing::Back);
}

}  // namespace litkit::trace
