// SPDX-License-Identifier: MIT
// The binned SAH build (bvh_build.hpp). Each node's primitives are a range
// of one array of references, partitioned in place; the bounds of each
// side are gathered while partitioning, so a node's one pass of its own is
// its binning. The root's binning runs in chunks on the lent threads, the
// next levels split their nodes side by side, and the tree's lower parts,
// once the ranges are small enough, are built as independent jobs and
// appended in a fixed order. Minima, maxima and counts merge exactly in any
// order, so the tree is the same on any number of threads. Ranges of up to
// 16 primitives split at their median instead of by bins.
#include "trace/bvh_build.hpp"

#include <algorithm>
#include <array>
#include <cstring>

#include <glm/common.hpp>

#include "trace/simd.hpp"

namespace litkit::trace::build {

namespace {

using simd::Floats;

constexpr int bin_count = 16;            // at most; 8 for nodes of up to 64 primitives
constexpr std::uint32_t chunk = 4096;    // references per job of a chunked pass
constexpr std::uint32_t max_depth = 64;  // deeper, ranges are halved (bounds the stacks)
constexpr std::uint32_t sampled = 512;   // references binned at least, of larger ranges
constexpr std::uint32_t max_stride = 16;
constexpr std::uint32_t small = 16;  // ranges split at their median, not binned

// A primitive's box; lane 3 of `lo` holds its index (as bits), of `hi` zero.
struct alignas(16) Ref {
    float lo[4];
    float hi[4];
};

std::uint32_t id_of(const Ref& ref) {
    std::uint32_t id;
    std::memcpy(&id, &ref.lo[3], sizeof id);
    return id;
}

// Box and centroid bounds (centroids doubled: lo + hi) of refs [begin, end).
struct Bounds {
    static constexpr float inf = std::numeric_limits<float>::infinity();
    Floats lo = Floats(inf), hi = Floats(-inf), c_lo = Floats(inf), c_hi = Floats(-inf);
    void merge(const Bounds& other) {
        lo = xsimd::min(lo, other.lo), hi = xsimd::max(hi, other.hi);
        c_lo = xsimd::min(c_lo, other.c_lo), c_hi = xsimd::max(c_hi, other.c_hi);
    }
};

const Floats& xyz_mask() {
    alignas(16) static const std::uint32_t bits[4] = {~0u, ~0u, ~0u, 0u};
    static const Floats mask =
        xsimd::bitwise_cast<Floats>(xsimd::batch<std::uint32_t, simd::Arch>::load_aligned(bits));
    return mask;
}

Bounds bounds_of(const Ref* refs, std::uint32_t begin, std::uint32_t end) {
    Bounds b;
    const Floats keep = xyz_mask();
    for (std::uint32_t i = begin; i < end; ++i) {
        const Floats lo = Floats::load_aligned(refs[i].lo) & keep;
        const Floats hi = Floats::load_aligned(refs[i].hi);
        const Floats c = lo + hi;
        b.lo = xsimd::min(b.lo, lo), b.hi = xsimd::max(b.hi, hi);
        b.c_lo = xsimd::min(b.c_lo, c), b.c_hi = xsimd::max(b.c_hi, c);
    }
    return b;
}

Box box_of(const Bounds& b) {
    alignas(16) float lo[4], hi[4];
    b.lo.store_aligned(lo), b.hi.store_aligned(hi);
    Box box;
    std::copy(lo, lo + 3, box.lo), std::copy(hi, hi + 3, box.hi);
    return box;
}

struct Bins {
    std::array<std::array<Floats, bin_count>, 3> lo, hi;
    std::array<std::array<std::uint32_t, bin_count>, 3> count{};
    int used = 0;
    Bins() = default;
    explicit Bins(int bins) : used(bins) {
        for (int a = 0; a < 3; ++a)
            for (int k = 0; k < used; ++k) {
                lo[a][k] = Floats(std::numeric_limits<float>::infinity());
                hi[a][k] = Floats(-std::numeric_limits<float>::infinity());
            }
    }
    void merge(const Bins& other) {
        for (int a = 0; a < 3; ++a)
            for (int k = 0; k < used; ++k) {
                lo[a][k] = xsimd::min(lo[a][k], other.lo[a][k]);
                hi[a][k] = xsimd::max(hi[a][k], other.hi[a][k]);
                count[a][k] += other.count[a][k];
            }
    }
};

// The bin of a doubled centroid c along each axis: (c − c_lo) · scale,
// truncated, at most bins − 1. The partition computes the same in
// scalars (the same operations, so the same bins).
struct Binner {
    int bins;
    Floats c_lo, scale;
    float c_lo_s[4], scale_s[4];
    Binner(const Bounds& b, int bins) : bins(bins), c_lo(b.c_lo) {
        alignas(16) float lo[4], hi[4], s[4];
        b.c_lo.store_aligned(lo), b.c_hi.store_aligned(hi);
        for (int a = 0; a < 4; ++a) {
            const float extent = hi[a] - lo[a];
            s[a] = a < 3 && extent > 0.0f ? float(bins) * (1.0f - 1e-6f) / extent : 0.0f;
            c_lo_s[a] = lo[a], scale_s[a] = s[a];
        }
        scale = Floats::load_aligned(s);
    }
    int bin(const Ref& ref, int axis) const {
        const float c = ref.lo[axis] + ref.hi[axis];
        const float f = std::min((c - c_lo_s[axis]) * scale_s[axis], float(bins - 1));
        return static_cast<int>(f);
    }
};

// Two sets of bins, alternate references into each: neighbouring
// references (neighbouring triangles) often fall into the same bins, and
// with one set each update would wait on the one before it.
Bins bin_refs(const Ref* refs, std::uint32_t begin, std::uint32_t end, std::uint32_t stride,
              const Binner& binner) {
    Bins bins(binner.bins);
    const Floats keep = xyz_mask(), last(float(binner.bins - 1));
    const auto add = [&](Bins& into, const Ref& ref) {
        alignas(16) std::int32_t k[4];
        const Floats lo = Floats::load_aligned(ref.lo) & keep;
        const Floats hi = Floats::load_aligned(ref.hi);
        const Floats f = xsimd::min((lo + hi - binner.c_lo) * binner.scale, last);
        xsimd::to_int(f).store_aligned(k);
        for (int a = 0; a < 3; ++a) {
            into.lo[a][k[a]] = xsimd::min(into.lo[a][k[a]], lo);
            into.hi[a][k[a]] = xsimd::max(into.hi[a][k[a]], hi);
            ++into.count[a][k[a]];
        }
    };
    std::uint32_t i = begin;
    if (end - begin >= 64 * stride) {
        Bins odd(binner.bins);
        for (; i + stride < end; i += 2 * stride) add(bins, refs[i]), add(odd, refs[i + stride]);
        bins.merge(odd);
    }
    for (; i < end; i += stride) add(bins, refs[i]);
    return bins;
}

float half_area(const Floats& lo, const Floats& hi) {
    alignas(16) float d[4];
    (hi - lo).store_aligned(d);
    if (!(d[0] >= 0.0f)) return 0.0f;  // empty
    return d[0] * d[1] + d[1] * d[2] + d[2] * d[0];
}

std::uint32_t blocks(std::uint32_t n) { return (n + 3) / 4; }

// Runs `pass` over [begin, end) in chunks (on the lent threads when the
// range is large), merging the chunks' results in order.
template <class Result, class Pass>
Result chunked(const ParallelFor* parallel, std::uint32_t begin, std::uint32_t end, Pass pass) {
    const std::uint32_t n = end - begin;
    if (!parallel || n < 2 * chunk) return pass(begin, end);
    const std::uint32_t jobs = (n + chunk - 1) / chunk;
    std::vector<Result> parts(jobs);
    run_parallel(*parallel, jobs, [&](std::size_t j) {
        const std::uint32_t b = begin + static_cast<std::uint32_t>(j) * chunk;
        parts[j] = pass(b, std::min(end, b + chunk));
    });
    for (std::uint32_t j = 1; j < jobs; ++j) parts[0].merge(parts[j]);
    return parts[0];
}

struct Builder {
    std::vector<Ref> refs;
    std::uint32_t max_leaf;

    // Decides node [begin, end) with bounds `b`: a leaf (returns false), or
    // the split point `mid` after partitioning the range, and the bounds of
    // both sides.
    bool split(std::uint32_t begin, std::uint32_t end, std::uint32_t depth, const Bounds& b,
               std::uint32_t& mid, Bounds& left, Bounds& right, const ParallelFor* parallel) {
        Ref* r = refs.data();
        const std::uint32_t n = end - begin;
        // A leaf of one block costs no more than any split (which adds a
        // node to the blocks).
        if (n <= 1 || (n <= max_leaf && max_leaf <= 4)) return false;
        const auto halve = [&] {
            mid = begin + n / 2;
            left = bounds_of(r, begin, mid), right = bounds_of(r, mid, end);
            return true;
        };
        if (depth >= max_depth) return n > max_leaf && halve();  // whatever the heuristic says
        if (n <= small) {
            // Few primitives: split at the median along the centroids'
            // longest axis (cheaper than binning, and as good this close to
            // the leaves), a whole number of blocks on the left.
            alignas(16) float extent[4];
            (b.c_hi - b.c_lo).store_aligned(extent);
            const int axis = extent[0] >= extent[1] ? (extent[0] >= extent[2] ? 0 : 2)
                                                    : (extent[1] >= extent[2] ? 1 : 2);
            const std::uint32_t blocks_left = (n / 2 + 3) / 4;
            mid = begin + std::min(4 * blocks_left, n - 1);
            std::nth_element(r + begin, r + mid, r + end, [axis](const Ref& p, const Ref& q) {
                return p.lo[axis] + p.hi[axis] < q.lo[axis] + q.hi[axis];
            });
            left = bounds_of(r, begin, mid), right = bounds_of(r, mid, end);
            return true;
        }
        const Binner binner(b, n <= 64 ? 8 : bin_count);
        std::uint32_t stride = 1;
        while (stride < max_stride && n >= 2 * stride * sampled) stride *= 2;
        const int used = binner.bins;
        // Binned from a sample, every sampled centroid may fall in one bin
        // while the others spread: then they are binned all.
        Bins bins;
        float best_cost = 0.0f;
        int best_axis = -1, best_k = 0;
        while (true) {
            bins = chunked<Bins>(parallel, begin, end, [&](std::uint32_t s, std::uint32_t e) {
                return bin_refs(r, s, e, stride, binner);
            });
            std::uint32_t binned = 0;
            for (int k = 0; k < used; ++k) binned += bins.count[0][k];
            // Sweep each axis: cost of splitting before bin k.
            best_cost = std::numeric_limits<float>::infinity(), best_axis = -1, best_k = 0;
            for (int a = 0; a < 3; ++a) {
                std::array<float, bin_count> right_cost{};
                Floats rlo(std::numeric_limits<float>::infinity()),
                    rhi(-std::numeric_limits<float>::infinity());
                std::uint32_t rn = 0;
                for (int k = used - 1; k > 0; --k) {
                    rlo = xsimd::min(rlo, bins.lo[a][k]), rhi = xsimd::max(rhi, bins.hi[a][k]);
                    rn += bins.count[a][k];
                    right_cost[k] = rn ? half_area(rlo, rhi) * float(blocks(rn)) : -1.0f;
                }
                Floats llo(std::numeric_limits<float>::infinity()),
                    lhi(-std::numeric_limits<float>::infinity());
                std::uint32_t ln = 0;
                for (int k = 1; k < used; ++k) {
                    llo = xsimd::min(llo, bins.lo[a][k - 1]),
                    lhi = xsimd::max(lhi, bins.hi[a][k - 1]);
                    ln += bins.count[a][k - 1];
                    if (ln == 0 || ln == binned) continue;
                    const float cost = half_area(llo, lhi) * float(blocks(ln)) + right_cost[k];
                    if (cost < best_cost) best_cost = cost, best_axis = a, best_k = k;
                }
            }
            if (best_axis >= 0 || stride == 1) break;
            stride = 1;
        }
        const float area = half_area(b.lo, b.hi);
        // Traversing a node costs as much as testing one block.
        const float leaf_cost = area * float(blocks(n));
        if (n <= max_leaf && (best_axis < 0 || leaf_cost <= area + best_cost)) return false;
        if (best_axis < 0) return halve();  // every centroid in one bin
        // Hoare's partition, each reference classified once, its bounds
        // added to its side's as it is.
        left = right = Bounds{};
        const Floats keep = xyz_mask();
        const auto add = [&](Bounds& side, const Ref& ref) {
            const Floats lo = Floats::load_aligned(ref.lo) & keep;
            const Floats hi = Floats::load_aligned(ref.hi);
            side.lo = xsimd::min(side.lo, lo), side.hi = xsimd::max(side.hi, hi);
            side.c_lo = xsimd::min(side.c_lo, lo + hi), side.c_hi = xsimd::max(side.c_hi, lo + hi);
        };
        const auto goes_left = [&](const Ref& ref) { return binner.bin(ref, best_axis) < best_k; };
        std::uint32_t i = begin, j = end;
        while (true) {
            while (i < j && goes_left(r[i])) add(left, r[i++]);
            while (i < j && !goes_left(r[j - 1])) add(right, r[--j]);
            if (i >= j) break;
            add(right, r[i]), add(left, r[j - 1]);
            std::swap(r[i++], r[--j]);
        }
        mid = i;
        return true;
    }

    // Builds the subtree of [begin, end) (bounds `b`) into `nodes`, its
    // root at `at`.
    void subtree(std::vector<Node>& nodes, std::uint32_t at, std::uint32_t begin, std::uint32_t end,
                 std::uint32_t depth, const Bounds& b) {
        std::uint32_t mid = 0;
        Bounds left_b, right_b;
        if (!split(begin, end, depth, b, mid, left_b, right_b, nullptr)) {
            nodes[at] = Node{box_of(b), begin, 0, end - begin};
            return;
        }
        const auto left = static_cast<std::uint32_t>(nodes.size());
        nodes.resize(nodes.size() + 2);
        nodes[at] = Node{box_of(b), left, left + 1, 0};
        subtree(nodes, left, begin, mid, depth + 1, left_b);
        subtree(nodes, left + 1, mid, end, depth + 1, right_b);
    }
};

// The tree over `builder`'s references (build_tree, build_triangles).
Tree build(Builder& builder, const ParallelFor& parallel) {
    Tree tree;
    const auto n = static_cast<std::uint32_t>(builder.refs.size());
    if (n == 0) return tree;
    const ParallelFor* lent = parallel ? &parallel : nullptr;

    // The upper part, a level at a time, until the ranges are small enough
    // to be jobs of their own: a level of one node splits with its passes in
    // chunks, a level of several splits its nodes side by side. Nodes are
    // numbered in level order, with or without threads.
    struct Pending {
        std::uint32_t node, begin, end, depth;
        Bounds bounds;
    };
    struct Split {
        std::uint32_t mid = 0;
        bool inner = false;
        Bounds left, right;
    };
    const std::uint32_t job_size = std::max<std::uint32_t>(2048, n / 32);
    std::vector<Node>& nodes = tree.nodes;
    nodes.resize(1);
    Ref* r = builder.refs.data();
    const Bounds all = chunked<Bounds>(
        lent, 0, n, [&](std::uint32_t s, std::uint32_t e) { return bounds_of(r, s, e); });
    std::vector<Pending> level{{0, 0, n, 0, all}}, jobs;
    while (!level.empty()) {
        std::vector<Pending> splitting, next;
        for (const Pending& p : level)
            (p.end - p.begin <= job_size ? jobs : splitting).push_back(p);
        std::vector<Split> splits(splitting.size());
        const auto one = [&](std::size_t i, const ParallelFor* chunks) {
            const Pending& p = splitting[i];
            Split& out = splits[i];
            out.inner = builder.split(p.begin, p.end, p.depth, p.bounds, out.mid, out.left,
                                      out.right, chunks);
        };
        if (splitting.size() == 1)
            one(0, lent);
        else
            run_parallel(parallel, splitting.size(), [&](std::size_t i) { one(i, nullptr); });
        for (std::size_t i = 0; i < splitting.size(); ++i) {
            const Pending& p = splitting[i];
            const Split& done = splits[i];
            if (!done.inner) {
                nodes[p.node] = Node{box_of(p.bounds), p.begin, 0, p.end - p.begin};
                continue;
            }
            const auto left = static_cast<std::uint32_t>(nodes.size());
            nodes.resize(nodes.size() + 2);
            nodes[p.node] = Node{box_of(p.bounds), left, left + 1, 0};
            next.push_back({left, p.begin, done.mid, p.depth + 1, done.left});
            next.push_back({left + 1, done.mid, p.end, p.depth + 1, done.right});
        }
        level = std::move(next);
    }
    // The jobs, each into a tree of its own (its root first), then appended
    // in the order they were found.
    std::vector<std::vector<Node>> parts(jobs.size());
    run_parallel(parallel, jobs.size(), [&](std::size_t j) {
        parts[j].resize(1);
        builder.subtree(parts[j], 0, jobs[j].begin, jobs[j].end, jobs[j].depth, jobs[j].bounds);
    });
    // Each part's nodes after the last's, its root in its job's node (a
    // part's node i > 0 is node at[j] + i − 1), moved in on the lent threads.
    std::vector<std::uint32_t> at(jobs.size());
    auto size = static_cast<std::uint32_t>(nodes.size());
    for (std::size_t j = 0; j < jobs.size(); ++j)
        at[j] = size, size += static_cast<std::uint32_t>(parts[j].size()) - 1;
    nodes.resize(size);
    run_parallel(parallel, jobs.size(), [&](std::size_t j) {
        const std::uint32_t offset = at[j] - 1;  // part's 1 → at[j]
        auto remap = [&](Node node) {
            if (node.count == 0) node.a += offset, node.b += offset;
            return node;
        };
        nodes[jobs[j].node] = remap(parts[j][0]);
        for (std::size_t i = 1; i < parts[j].size(); ++i) nodes[offset + i] = remap(parts[j][i]);
    });
    tree.order.resize(n);
    parallel_chunks(parallel, n, chunk,
                    [&](std::size_t i) { tree.order[i] = id_of(builder.refs[i]); });
    return tree;
}

// Reference i: box `lo`, `hi`, index i.
void set_ref(Ref& ref, std::size_t i, const float* lo, const float* hi) {
    const auto id = static_cast<std::uint32_t>(i);
    std::copy(lo, lo + 3, ref.lo), std::copy(hi, hi + 3, ref.hi);
    std::memcpy(&ref.lo[3], &id, sizeof id);
    ref.hi[3] = 0.0f;
}

}  // namespace

Tree build_tree(std::span<const Box> boxes, std::uint32_t max_leaf, const ParallelFor& parallel) {
    Builder builder{std::vector<Ref>(boxes.size()), max_leaf};
    parallel_chunks(parallel, boxes.size(), chunk,
                    [&](std::size_t i) { set_ref(builder.refs[i], i, boxes[i].lo, boxes[i].hi); });
    return build(builder, parallel);
}

Tree build_triangles(std::span<const glm::vec3> positions,
                     std::span<const std::array<std::uint32_t, 3>> triangles,
                     std::uint32_t max_leaf, const ParallelFor& parallel) {
    Builder builder{std::vector<Ref>(triangles.size()), max_leaf};
    parallel_chunks(parallel, triangles.size(), chunk, [&](std::size_t i) {
        const auto& [i0, i1, i2] = triangles[i];
        const glm::vec3 &p0 = positions[i0], &p1 = positions[i1], &p2 = positions[i2];
        const glm::vec3 lo = glm::min(glm::min(p0, p1), p2), hi = glm::max(glm::max(p0, p1), p2);
        const float l[3] = {lo.x, lo.y, lo.z}, h[3] = {hi.x, hi.y, hi.z};
        set_ref(builder.refs[i], i, l, h);
    });
    return build(builder, parallel);
}

}  // namespace litkit::trace::build
