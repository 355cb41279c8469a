// SPDX-License-Identifier: MIT
// The tracer's acceleration structure (accel.hpp): a four-wide bounding-
// volume hierarchy per object and one over the objects, in one array of
// nodes. The top hierarchy's leaf for an object is that object's root, so
// that nearest_front walks the whole scene in one loop (no second stack, no
// per-object set-up) while nearest_back(o) starts at o's root and sees o's
// triangles alone; one hierarchy per object also keeps objects apart that
// one over all triangles would mix (a glass sphere inside a room's walls).
//
// Each hierarchy is collapsed from a binary SAH tree (bvh_build.cpp) by
// opening, at each node, the child of largest area until it has four: a
// node holds its children's boxes as four lanes per plane (one SIMD test
// for all four, simd.hpp), and a leaf is one block of up to four triangles'
// corners, also as lanes, tested at once. The traversal enters children
// nearest first and stops at the best hit so far.
//
// Exactly the answers of testing every triangle: boxes are tested
// conservatively (padded, entry and exit distances widened by a relative
// margin far above the rounding of the slab test and of the triangle
// test's shear), a subtree is skipped only when its entry lies beyond the
// best hit so far (a tie at the same distance may still win by its smaller
// index), and the four-wide triangle test repeats the operations of the
// scalar watertight test below exactly, so its hits are the scalar test's
// (lanes with an edge function of 0, which the scalar test recomputes in
// double, go to the scalar test itself).
#include "trace/accel.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <new>
#include <utility>
#include <vector>

#include "trace/bvh_build.hpp"
#include "trace/simd.hpp"

namespace litkit::trace {

namespace {

enum class Facing { Front, Back };

constexpr float margin = 0x1p-19f;  // relative widening of boxes and box distances

// What the triangle test and the box test need of a ray, computed once.
struct Prepared {
    float origin[3], inverse[3];
    int kx, ky, kz;
    float sx, sy, sz;
    float t_min, t_max;
    // Broadcast: the box planes' origin and inverse direction per axis, and
    // which plane of each axis the ray meets first (the node's row).
    simd::Floats o[3], inv[3];
    int near_row[3], far_row[3];
    simd::Floats o_k[3], s_k[3];  // origin along kx, ky, kz; sx, sy, sz

    explicit Prepared(const Ray& ray) : t_min(ray.t_min), t_max(ray.t_max) {
        const glm::vec3& d = ray.direction;
        const glm::vec3 a_abs = glm::abs(d);
        kz = a_abs.x > a_abs.y ? (a_abs.x > a_abs.z ? 0 : 2) : (a_abs.y > a_abs.z ? 1 : 2);
        kx = (kz + 1) % 3, ky = (kx + 1) % 3;
        if (d[kz] < 0.0f) std::swap(kx, ky);
        sx = d[kx] / d[kz], sy = d[ky] / d[kz], sz = 1.0f / d[kz];
        for (int a = 0; a < 3; ++a) {
            origin[a] = ray.origin[a];
            // 1/0 (and 1/x overflowing) as the largest float: (b − o) · inverse
            // is then never 0 · ∞, and no division by zero is raised.
            const float i = d[a] != 0.0f ? 1.0f / d[a] : 0.0f;
            inverse[a] = d[a] != 0.0f && std::isfinite(i)
                             ? i
                             : std::copysign(std::numeric_limits<float>::max(), d[a]);
            o[a] = simd::Floats(origin[a]), inv[a] = simd::Floats(inverse[a]);
            const bool negative = std::signbit(inverse[a]);
            near_row[a] = 2 * a + (negative ? 1 : 0), far_row[a] = 2 * a + (negative ? 0 : 1);
        }
        const int k[3] = {kx, ky, kz};
        const float s[3] = {sx, sy, sz};
        for (int i = 0; i < 3; ++i)
            o_k[i] = simd::Floats(origin[k[i]]), s_k[i] = simd::Floats(s[i]);
    }
};

// Woop, Benthin and Wald's watertight test of one triangle; updates `best`
// when the triangle is hit closer (or as close, by a smaller index) with the
// facing asked for.
void intersect(const Prepared& ray, const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2,
               Facing facing, std::uint32_t object, std::uint32_t triangle, Hit& best) {
    const int kx = ray.kx, ky = ray.ky, kz = ray.kz;
    const float sx = ray.sx, sy = ray.sy, sz = ray.sz;
    const float a[3] = {p0.x - ray.origin[0], p0.y - ray.origin[1], p0.z - ray.origin[2]};
    const float b[3] = {p1.x - ray.origin[0], p1.y - ray.origin[1], p1.z - ray.origin[2]};
    const float c[3] = {p2.x - ray.origin[0], p2.y - ray.origin[1], p2.z - ray.origin[2]};
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

// Four children: their boxes as lanes, row 2a the lower and 2a + 1 the
// upper planes of axis a; a child is a node's index, or leaf_bit | a
// block's index, or `empty` (an empty box, which no ray enters).
struct alignas(64) Node4 {
    float box[6][4];
    std::uint32_t child[4];
};
constexpr std::uint32_t leaf_bit = 0x80000000u, empty = ~0u;

// Up to four triangles of one object: corner v's coordinate a in row 3v + a.
struct alignas(16) Block {
    float corner[9][4];
    std::uint32_t triangle[4];
    std::uint32_t object, count;
};

// An allocator whose vectors leave new elements of a resize unset (every
// node and block is written whole after it): zeroing the 15 MB of a large
// mesh's hierarchy first would be one more pass, on one thread.
template <class T>
struct Unset : std::allocator<T> {
    template <class U>
    struct rebind {
        using other = Unset<U>;
    };
    Unset() = default;
    template <class U>
    explicit Unset(const Unset<U>&) noexcept {}
    template <class U>
    void construct(U* at) noexcept {
        ::new (static_cast<void*>(at)) U;
    }
    template <class U, class... Args>
    void construct(U* at, Args&&... args) {
        ::new (static_cast<void*>(at)) U(std::forward<Args>(args)...);
    }
};

}  // namespace

struct Accel::Impl {
    std::vector<MeshView> objects;
    std::vector<Node4, Unset<Node4>> nodes;
    std::vector<Block, Unset<Block>> blocks;
    std::vector<std::uint32_t> roots;  // per object: its root (a child), or empty
    std::uint32_t top = empty;

    // The children binary node `node` opens into (see the top of the file):
    // the child of largest area opened until there are four or only leaves.
    static int open_children(const build::Tree& tree, const build::Node& node,
                             std::uint32_t open[4]) {
        open[0] = node.a, open[1] = node.b;
        int size = 2;
        while (size < 4) {
            int widest = -1;
            float widest_area = -1.0f;
            for (int i = 0; i < size; ++i) {
                const build::Node& c = tree.nodes[open[i]];
                if (c.count > 0) continue;
                float d[3];
                for (int a = 0; a < 3; ++a) d[a] = c.box.hi[a] - c.box.lo[a];
                const float area = d[0] * d[1] + d[1] * d[2] + d[2] * d[0];
                if (area > widest_area) widest = i, widest_area = area;
            }
            if (widest < 0) break;
            const build::Node& c = tree.nodes[open[widest]];
            open[widest] = c.a, open[size++] = c.b;
        }
        return size;
    }

    // A node of the children `open` (their boxes padded), children to be
    // filled in; lanes past `size` are empty.
    static Node4 node_of(const build::Tree& tree, const std::uint32_t open[4], int size) {
        Node4 out;
        for (int i = 0; i < 4; ++i) {
            out.child[i] = empty;
            build::Box box;  // empty: lo = ∞, hi = −∞
            if (i < size) box = padded(tree.nodes[open[i]].box);
            for (int a = 0; a < 3; ++a)
                out.box[2 * a][i] = box.lo[a], out.box[2 * a + 1][i] = box.hi[a];
        }
        return out;
    }

    // Collapses binary node `at` of `tree` into `nodes`; a binary leaf
    // becomes leaf(node). (The hierarchy over the objects.)
    template <class Leaf>
    std::uint32_t collapse(const build::Tree& tree, std::uint32_t at, const Leaf& leaf) {
        const build::Node& node = tree.nodes[at];
        if (node.count > 0) return leaf(node);
        std::uint32_t open[4];
        const int size = open_children(tree, node, open);
        const auto index = static_cast<std::uint32_t>(nodes.size());
        nodes.emplace_back();
        Node4 out = node_of(tree, open, size);
        for (int i = 0; i < size; ++i) out.child[i] = collapse(tree, open[i], leaf);
        nodes[index] = out;
        return index;
    }

    // A child that stands for binary node holes[h] until that is collapsed.
    static constexpr std::uint32_t hole_bit = 0x40000000u;

    // How many four-wide nodes collapsing binary node `at` makes, down to
    // `cut` levels (an inner node there is appended to `holes` instead; a
    // negative `cut`: all levels).
    static std::uint32_t count(const build::Tree& tree, std::uint32_t at, int cut,
                               std::vector<std::uint32_t>* holes) {
        const build::Node& node = tree.nodes[at];
        if (node.count > 0) return 0;
        if (cut == 0) {
            holes->push_back(at);
            return 0;
        }
        std::uint32_t open[4];
        const int size = open_children(tree, node, open);
        std::uint32_t sum = 1;
        for (int i = 0; i < size; ++i) sum += count(tree, open[i], cut - 1, holes);
        return sum;
    }

    // Collapses binary node `at` into the nodes from `next` on, in the order
    // count() counts them, and returns it; down to `cut` levels, where the
    // h-th inner node becomes hole_bit | h. A binary leaf starting at
    // tree.order[a] is block block_index[a].
    std::uint32_t fill(const build::Tree& tree, std::uint32_t at,
                       const std::vector<std::uint32_t>& block_index, int cut, std::uint32_t& next,
                       std::uint32_t& holes) {
        const build::Node& node = tree.nodes[at];
        if (node.count > 0) return leaf_bit | block_index[node.a];
        if (cut == 0) return hole_bit | holes++;
        std::uint32_t open[4];
        const int size = open_children(tree, node, open);
        const std::uint32_t index = next++;
        Node4 out = node_of(tree, open, size);
        for (int i = 0; i < size; ++i)
            out.child[i] = fill(tree, open[i], block_index, cut - 1, next, holes);
        nodes[index] = out;
        return index;
    }

    // Collapses object `object`'s binary tree and returns its root, on the
    // lent threads: its blocks first, one per binary leaf in the order of
    // their triangles in tree.order (a flat pass, fetching the triangles
    // ahead: the triangles of neighbouring leaves lie anywhere in the mesh,
    // and waiting on them was most of the collapse's time); then the nodes,
    // the top three levels and each subtree below them, counted first so
    // that each is written in place.
    std::uint32_t collapse_object(const build::Tree& tree, const MeshView& mesh,
                                  std::uint32_t object, const ParallelFor& parallel) {
        const std::span<const std::uint32_t> order = tree.order;
        std::vector<std::uint32_t> block_index(order.size(), 0), starts;
        for (const build::Node& node : tree.nodes)
            if (node.count > 0) block_index[node.a] = 1;
        for (std::uint32_t a = 0; a < order.size(); ++a)
            if (block_index[a]) {
                block_index[a] = static_cast<std::uint32_t>(blocks.size() + starts.size());
                starts.push_back(a);
            }
        starts.push_back(static_cast<std::uint32_t>(order.size()));
        const std::size_t first = blocks.size(), leaves = starts.size() - 1;
        blocks.resize(first + leaves);
        parallel_chunks(parallel, leaves, 1024, [&](std::size_t b) {
            constexpr std::size_t ahead = 8;
            if (b + 2 * ahead < leaves)
                __builtin_prefetch(&mesh.triangles[order[starts[b + 2 * ahead]]]);
            if (b + ahead < leaves)
                for (const std::uint32_t v : mesh.triangles[order[starts[b + ahead]]])
                    __builtin_prefetch(&mesh.positions[v]);
            fill_block(blocks[first + b], mesh, object,
                       order.subspan(starts[b], starts[b + 1] - starts[b]));
        });

        constexpr std::size_t parted = 16384;  // triangles; fewer are collapsed at once
        const int cut = order.size() < parted ? -1 : 3;
        std::vector<std::uint32_t> holes;
        const std::uint32_t top = count(tree, 0, cut, &holes);
        std::vector<std::uint32_t> at(holes.size());
        run_parallel(parallel, holes.size(),
                     [&](std::size_t h) { at[h] = count(tree, holes[h], -1, nullptr); });
        auto end = static_cast<std::uint32_t>(nodes.size()) + top;
        for (std::uint32_t& start : at) {
            const std::uint32_t size = start;
            start = end, end += size;
        }
        auto next = static_cast<std::uint32_t>(nodes.size());
        nodes.resize(end);
        std::uint32_t hole = 0;
        const std::uint32_t root = fill(tree, 0, block_index, cut, next, hole);
        std::vector<std::uint32_t> roots(holes.size());
        run_parallel(parallel, holes.size(), [&](std::size_t h) {
            std::uint32_t none = 0;
            roots[h] = fill(tree, holes[h], block_index, -1, at[h], none);
        });
        // The top's children that stand for holes (a hole is never the root,
        // and the top's nodes are fewer than hole_bit).
        for (std::uint32_t i = next - top; i < next; ++i)
            for (std::uint32_t& child : nodes[i].child)
                if (child != empty && !(child & leaf_bit) && (child & hole_bit))
                    child = roots[child & ~hole_bit];
        return root;
    }

    // `block` holding `triangles` of object `object`, whole: its lanes
    // past them 0 (the four-wide test computes on every lane, and what an
    // allocation held before could be a NaN; Accel.RaisesNoInvalid...).
    static void fill_block(Block& block, const MeshView& mesh, std::uint32_t object,
                           std::span<const std::uint32_t> triangles) {
        block.object = object;
        block.count = static_cast<std::uint32_t>(triangles.size());
        for (std::uint32_t l = 0; l < 4; ++l) {
            const bool used = l < block.count;
            block.triangle[l] = used ? triangles[l] : 0;
            for (int v = 0; v < 3; ++v) {
                const glm::vec3 p =
                    used ? mesh.positions[mesh.triangles[triangles[l]][v]] : glm::vec3(0.0f);
                block.corner[3 * v][l] = p.x, block.corner[3 * v + 1][l] = p.y,
                                 block.corner[3 * v + 2][l] = p.z;
            }
        }
    }

    void prefetch(std::uint32_t child) const {
        const char* at = child & leaf_bit
                             ? reinterpret_cast<const char*>(&blocks[child & ~leaf_bit])
                             : reinterpret_cast<const char*>(&nodes[child]);
        for (std::size_t line = 0; line < (child & leaf_bit ? sizeof(Block) : sizeof(Node4));
             line += 64)
            __builtin_prefetch(at + line);
    }

    [[gnu::always_inline]] void test_block(const Prepared& ray, const Block& block, Facing facing,
                                           Hit& best) const {
        using simd::Floats;
        const int k[3] = {ray.kx, ray.ky, ray.kz};
        // Corner v relative to the origin along kz, and sheared along kx, ky.
        Floats z[3], x[3], y[3];
        for (int v = 0; v < 3; ++v) {
            z[v] = Floats::load_aligned(block.corner[3 * v + k[2]]) - ray.o_k[2];
            x[v] =
                (Floats::load_aligned(block.corner[3 * v + k[0]]) - ray.o_k[0]) - ray.s_k[0] * z[v];
            y[v] =
                (Floats::load_aligned(block.corner[3 * v + k[1]]) - ray.o_k[1]) - ray.s_k[1] * z[v];
        }
        const Floats u = x[2] * y[1] - y[2] * x[1];
        const Floats v = x[0] * y[2] - y[0] * x[2];
        const Floats w = x[1] * y[0] - y[1] * x[0];
        const Floats zero(0.0f);
        const simd::Mask any_zero = (u == zero) | (v == zero) | (w == zero);
        const simd::Mask mixed =
            ((u < zero) | (v < zero) | (w < zero)) & ((u > zero) | (v > zero) | (w > zero));
        const Floats det = u + v + w;
        const simd::Mask facing_ok = facing == Facing::Front ? det > zero : det < zero;
        const Floats t_scaled =
            u * (ray.s_k[2] * z[0]) + v * (ray.s_k[2] * z[1]) + w * (ray.s_k[2] * z[2]);
        // Lanes with det = 0 (empty ones too) divide by 1: no NaN, no flag.
        const Floats t = t_scaled / xsimd::select(det == zero, Floats(1.0f), det);
        const float limit = std::min(best.t, ray.t_max);
        const simd::Mask in_range = (t > Floats(ray.t_min)) & (t <= Floats(limit));
        const unsigned lanes = (1u << block.count) - 1u;
        // Lanes with an edge function of 0: the scalar test, which redoes
        // them in double.
        unsigned retest = simd::bits(any_zero) & lanes;
        // The others: the four-wide test's u, v, w, det and t are the scalar
        // test's, operation for operation, so its verdict stands; only the
        // tie rule and t < t_max are left.
        unsigned hits = simd::bits(~any_zero & ~mixed & facing_ok & in_range) & lanes;
        if (hits) {
            alignas(16) float t_lane[4], v_lane[4], w_lane[4], det_lane[4];
            t.store_aligned(t_lane), v.store_aligned(v_lane), w.store_aligned(w_lane);
            det.store_aligned(det_lane);
            do {
                const int l = __builtin_ctz(hits);
                hits &= hits - 1;
                const float tl = t_lane[l];
                const std::uint32_t triangle = block.triangle[l];
                if (!(tl < ray.t_max) || tl > best.t ||
                    (tl == best.t && (block.object > best.object ||
                                      (block.object == best.object && triangle > best.triangle))))
                    continue;
                best = Hit{tl, block.object, triangle, v_lane[l] / det_lane[l],
                           w_lane[l] / det_lane[l]};
            } while (hits);
        }
        while (retest) {
            const int l = __builtin_ctz(retest);
            retest &= retest - 1;
            const auto corner = [&](int c) {
                return glm::vec3(block.corner[3 * c][l], block.corner[3 * c + 1][l],
                                 block.corner[3 * c + 2][l]);
            };
            intersect(ray, corner(0), corner(1), corner(2), facing, block.object, block.triangle[l],
                      best);
        }
    }

    // Forward: rays with t_min >= 0 (every ray of the ray tree) take a
    // cheaper box test. Its tests, with w = 1 + 2·margin and k = 1 + 4·margin,
    //   max(t_near, t_min / w) <= min(k · t_far, w · limit),
    // accept every child the general test below accepts (whose conditions,
    // t_near widened <= t_far widened, <= limit, t_far widened >= t_min,
    // imply these for t_min >= 0 and limit > 0; for limit <= t_min no
    // triangle can be hit at all), so it enters at least the same children.
    template <bool Forward>
    Hit traverse(const Prepared& ray, std::uint32_t root, Facing facing) const {
        using simd::Floats;
        Hit best;
        if (root == empty) return best;
        struct Entry {
            std::uint32_t child;
            float entry;
        };
        // Three entries a level at most, and a binary tree's depth is at most
        // 64 + 32 (bvh_build.cpp), in the top hierarchy and in an object's.
        Entry stack[3 * 2 * 96 + 1];
        int size = 0;
        stack[size++] = {root, -std::numeric_limits<float>::infinity()};
        const Floats t_min(ray.t_min), zero(0.0f), lower(1.0f - margin), upper(1.0f + margin);
        constexpr float w = 1.0f + 2.0f * margin;
        const Floats t_min_w(ray.t_min / w), k(1.0f + 4.0f * margin);
        // The distance beyond which no subtree is entered: the best hit so
        // far or t_max, widened by w in the forward test.
        const auto reach = [&] {
            const float limit = std::min(best.t, ray.t_max);
            return Forward ? limit * w : limit;
        };
        while (size > 0) {
            const Entry e = stack[--size];
            if (e.entry > reach()) continue;
            std::uint32_t child = e.child;
            while (true) {
                if (child & leaf_bit) {
                    test_block(ray, blocks[child & ~leaf_bit], facing, best);
                    break;
                }
                const Node4& node = nodes[child];
                const Floats limit(reach());
                Floats t_near[3], t_far[3];
                for (int a = 0; a < 3; ++a) {
                    t_near[a] =
                        (Floats::load_aligned(node.box[ray.near_row[a]]) - ray.o[a]) * ray.inv[a];
                    t_far[a] =
                        (Floats::load_aligned(node.box[ray.far_row[a]]) - ray.o[a]) * ray.inv[a];
                }
                const Floats tf = xsimd::min(xsimd::min(t_far[0], t_far[1]), t_far[2]);
                unsigned hit;
                Floats entries;
                if constexpr (Forward) {
                    entries = xsimd::max(xsimd::max(t_near[0], t_near[1]),
                                         xsimd::max(t_near[2], t_min_w));
                    hit = simd::bits((entries <= tf * k) & (entries <= limit));
                } else {
                    const Floats tn = xsimd::max(xsimd::max(t_near[0], t_near[1]), t_near[2]);
                    // Widened by `margin` of their size (products, not sums, so
                    // that an empty child's ∞ stays ∞ rather than ∞ − ∞).
                    const Floats tn_c = xsimd::select(tn > zero, tn * lower, tn * upper);
                    const Floats tf_c = xsimd::select(tf > zero, tf * upper, tf * lower);
                    hit = simd::bits((tn_c <= tf_c) & (tn_c <= limit) & (tf_c >= t_min));
                    entries = xsimd::max(tn_c, t_min);
                }
                if (!hit) break;
                if ((hit & (hit - 1)) == 0) {  // one child
                    child = node.child[__builtin_ctz(hit)];
                    continue;
                }
                // Fetch the children entered while they are sorted (rays in a
                // hierarchy larger than the caches wait on memory more than on
                // arithmetic; one child is read at once, with no time to win).
                for (unsigned h = hit; h; h &= h - 1) prefetch(node.child[__builtin_ctz(h)]);
                alignas(16) float entry[4];
                entries.store_aligned(entry);
                // Nearest first: the others go on the stack, farthest deepest.
                Entry order[4];
                int n = 0;
                for (; hit; hit &= hit - 1) {
                    const int i = __builtin_ctz(hit);
                    Entry c{node.child[i], entry[i]};
                    int j = n++;
                    for (; j > 0 && order[j - 1].entry < c.entry; --j) order[j] = order[j - 1];
                    order[j] = c;
                }
                for (int i = 0; i < n - 1; ++i) stack[size++] = order[i];
                child = order[n - 1].child;
            }
        }
        return best;
    }
};

Accel::Accel(std::span<const MeshView> objects, const ParallelFor& parallel)
    : impl_(std::make_unique<Impl>()) {
    Impl& m = *impl_;
    m.objects.assign(objects.begin(), objects.end());
    m.roots.assign(objects.size(), empty);
    std::vector<build::Box> object_boxes;
    std::vector<std::uint32_t> placed;  // the objects with triangles
    for (std::uint32_t o = 0; o < objects.size(); ++o) {
        const MeshView& mesh = objects[o];
        if (mesh.triangles.empty()) continue;
        const build::Tree tree =
            build::build_triangles(mesh.positions, mesh.triangles, 4, parallel);
        m.roots[o] = m.collapse_object(tree, mesh, o, parallel);
        object_boxes.push_back(tree.nodes[0].box);
        placed.push_back(o);
    }
    if (placed.empty()) return;
    const build::Tree top = build::build_tree(object_boxes, 1, parallel);
    m.top = m.collapse(top, 0, [&](const build::Node& leaf) {  // an object's root in its place
        return m.roots[placed[top.order[leaf.a]]];
    });
}
Accel::~Accel() = default;
Accel::Accel(Accel&&) noexcept = default;
Accel& Accel::operator=(Accel&&) noexcept = default;

Hit Accel::nearest_front(const Ray& ray) const {
    const Prepared prepared(ray);
    return ray.t_min >= 0.0f ? impl_->traverse<true>(prepared, impl_->top, Facing::Front)
                             : impl_->traverse<false>(prepared, impl_->top, Facing::Front);
}

Hit Accel::nearest_back(const Ray& ray, std::uint32_t object) const {
    if (object >= impl_->roots.size()) return Hit{};
    const Prepared prepared(ray);
    const std::uint32_t root = impl_->roots[object];
    return ray.t_min >= 0.0f ? impl_->traverse<true>(prepared, root, Facing::Back)
                             : impl_->traverse<false>(prepared, root, Facing::Back);
}

}  // namespace litkit::trace
