// SPDX-License-Identifier: MIT
// The tracer's acceleration structure (src/trace/accel.hpp): single cases
// worked by hand (face rules, edge-on triangles, the open ends of (t_min,
// t_max), barycentrics, the tie rule), and the hierarchy against a brute-
// force reference (every triangle tested, kept here and not in the library)
// for random rays from outside and inside objects and for rays aimed exactly
// at closed meshes' shared edges and vertices.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cfenv>
#include <cmath>
#include <random>
#include <vector>

#include "litkit/shapes.hpp"
#include "trace/accel.hpp"
#include "trace/bvh_build.hpp"

namespace {

using litkit::trace::Accel;
using litkit::trace::Hit;
using litkit::trace::MeshView;
using litkit::trace::Ray;

// The reference: Woop, Benthin and Wald's watertight test (JCGT 2(1), 2013)
// written out once more, over every triangle, keeping the nearest hit and
// between equal distances the smaller (object, triangle).
struct Sheared {
    int kx, ky, kz;
    float sx, sy, sz;
    explicit Sheared(const glm::vec3& d) {
        const glm::vec3 m = glm::abs(d);
        kz = m.x > m.y ? (m.x > m.z ? 0 : 2) : (m.y > m.z ? 1 : 2);
        kx = (kz + 1) % 3, ky = (kx + 1) % 3;
        if (d[kz] < 0.0f) std::swap(kx, ky);
        sx = d[kx] / d[kz], sy = d[ky] / d[kz], sz = 1.0f / d[kz];
    }
};

void reference_test(const Ray& ray, const Sheared& s, const glm::vec3& p0, const glm::vec3& p1,
                    const glm::vec3& p2, bool front, std::uint32_t object, std::uint32_t triangle,
                    Hit& best) {
    const int kx = s.kx, ky = s.ky, kz = s.kz;
    const float sx = s.sx, sy = s.sy, sz = s.sz;
    // As arrays: glm's operator[] is a switch.
    const glm::vec3 a3 = p0 - ray.origin, b3 = p1 - ray.origin, c3 = p2 - ray.origin;
    const float a[3] = {a3.x, a3.y, a3.z}, b[3] = {b3.x, b3.y, b3.z}, c[3] = {c3.x, c3.y, c3.z};
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
    if (det == 0.0f || front != (det > 0.0f)) return;
    const float t = (u * (sz * a[kz]) + v * (sz * b[kz]) + w * (sz * c[kz])) / det;
    if (!(t > ray.t_min && t < ray.t_max)) return;
    if (t > best.t || (t == best.t && (object > best.object ||
                                       (object == best.object && triangle > best.triangle))))
        return;
    best = Hit{t, object, triangle, v / det, w / det};
}

Hit reference(const std::vector<MeshView>& objects, const Ray& ray, bool front,
              std::uint32_t only = litkit::trace::no_object) {
    Hit best;
    const Sheared sheared(ray.direction);
    for (std::uint32_t o = 0; o < objects.size(); ++o) {
        if (only != litkit::trace::no_object && o != only) continue;
        const MeshView& mesh = objects[o];
        for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
            const auto& tri = mesh.triangles[t];
            reference_test(ray, sheared, mesh.positions[tri[0]], mesh.positions[tri[1]],
                           mesh.positions[tri[2]], front, o, t, best);
        }
    }
    return best;
}

// Hits compared field by field, to the bit.
bool same(const Hit& a, const Hit& b) {
    if (a.object != b.object) return false;
    return !a.found() || (a.triangle == b.triangle && a.t == b.t && a.b1 == b.b1 && a.b2 == b.b2);
}

void expect_same(const Hit& got, const Hit& want, const Ray& ray) {
    if (same(got, want)) return;
    ADD_FAILURE() << "ray (" << ray.origin.x << ", " << ray.origin.y << ", " << ray.origin.z
                  << ") + t (" << ray.direction.x << ", " << ray.direction.y << ", "
                  << ray.direction.z << "), t in (" << ray.t_min << ", " << ray.t_max
                  << "): got object " << got.object << " triangle " << got.triangle << " t "
                  << got.t << " (" << got.b1 << ", " << got.b2 << "), want object " << want.object
                  << " triangle " << want.triangle << " t " << want.t << " (" << want.b1 << ", "
                  << want.b2 << ")";
}

struct Owned {
    std::vector<glm::vec3> positions;
    std::vector<std::array<std::uint32_t, 3>> triangles;
    MeshView view() const { return {positions, triangles}; }
};

Owned placed(const litkit::Mesh& mesh, glm::vec3 offset, float scale = 1.0f) {
    Owned out{{}, mesh.triangles};
    for (const glm::vec3& p : mesh.positions) out.positions.push_back(p * scale + offset);
    return out;
}

// The triangle (0,0,0), (1,0,0), (0,1,0): its normal (p1 − p0) × (p2 − p0)
// is +z, so rays going −z meet its front face.
Owned unit_triangle(float z = 0.0f) {
    return Owned{{{0, 0, z}, {1, 0, z}, {0, 1, z}}, {{{0, 1, 2}}}};
}

TEST(Accel, FrontFaceFromOutsideBackFaceFromInside) {
    const Owned tri = unit_triangle();
    const std::vector<MeshView> objects{tri.view()};
    const Accel accel(objects);
    // Down onto (0.5, 0.25): t = 1, corner 1's weight is x, corner 2's is y.
    const Ray down{{0.5f, 0.25f, 1.0f}, {0.0f, 0.0f, -1.0f}};
    const Hit hit = accel.nearest_front(down);
    ASSERT_TRUE(hit.found());
    EXPECT_EQ(hit.object, 0u);
    EXPECT_EQ(hit.triangle, 0u);
    EXPECT_EQ(hit.t, 1.0f);
    EXPECT_EQ(hit.b1, 0.5f);
    EXPECT_EQ(hit.b2, 0.25f);
    EXPECT_FALSE(accel.nearest_back(down, 0).found());  // d·N_g < 0: not a back face
    // Up from below, through the same point, twice as fast: t = 1/2.
    const Ray up{{0.5f, 0.25f, -1.0f}, {0.0f, 0.0f, 2.0f}};
    EXPECT_FALSE(accel.nearest_front(up).found());
    const Hit back = accel.nearest_back(up, 0);
    ASSERT_TRUE(back.found());
    EXPECT_EQ(back.t, 0.5f);
    EXPECT_EQ(back.b1, 0.5f);
    EXPECT_EQ(back.b2, 0.25f);
    // Outside the triangle (x + y > 1), and behind the origin.
    EXPECT_FALSE(accel.nearest_front({{0.75f, 0.5f, 1.0f}, {0.0f, 0.0f, -1.0f}}).found());
    EXPECT_FALSE(accel.nearest_front({{0.5f, 0.25f, -1.0f}, {0.0f, 0.0f, 1.0f}}).found());
    EXPECT_FALSE(accel.nearest_front({{0.5f, 0.25f, 1.0f}, {0.0f, 0.0f, 1.0f}}).found());
}

TEST(Accel, EdgeOnTriangleIsHitByNeither) {
    const Owned tri = unit_triangle();
    const std::vector<MeshView> objects{tri.view()};
    const Accel accel(objects);
    // In the triangle's plane, through its inside: d·N_g = 0.
    const Ray along{{-1.0f, 0.25f, 0.0f}, {1.0f, 0.0f, 0.0f}};
    EXPECT_FALSE(accel.nearest_front(along).found());
    EXPECT_FALSE(accel.nearest_back(along, 0).found());
}

TEST(Accel, TMinAndTMaxAreExcluded) {
    const Owned tri = unit_triangle();
    const std::vector<MeshView> objects{tri.view()};
    const Accel accel(objects);
    Ray ray{{0.25f, 0.25f, 1.0f}, {0.0f, 0.0f, -1.0f}};  // hits at t = 1 exactly
    ray.t_max = 1.0f;
    EXPECT_FALSE(accel.nearest_front(ray).found());
    ray.t_max = std::nextafter(1.0f, 2.0f);
    EXPECT_EQ(accel.nearest_front(ray).t, 1.0f);
    ray.t_min = 1.0f;
    EXPECT_FALSE(accel.nearest_front(ray).found());
    ray.t_min = std::nextafter(1.0f, 0.0f);
    EXPECT_EQ(accel.nearest_front(ray).t, 1.0f);
}

TEST(Accel, TiesGoToTheSmallerObjectThenTriangle) {
    // Object 0: a far triangle, then the near one (triangle 1). Object 1:
    // the near one twice (triangles 0 and 1). All three near ones are hit at
    // t = 1: (0, 1) wins, though object 1's come first in their object.
    Owned first{{{0, 0, -5}, {1, 0, -5}, {0, 1, -5}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
                {{{0, 1, 2}}, {{3, 4, 5}}}};
    Owned second{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{{0, 1, 2}}, {{0, 1, 2}}}};
    const Ray ray{{0.25f, 0.25f, 1.0f}, {0.0f, 0.0f, -1.0f}};
    {
        const std::vector<MeshView> objects{first.view(), second.view()};
        const Hit hit = Accel(objects).nearest_front(ray);
        EXPECT_EQ(hit.object, 0u);
        EXPECT_EQ(hit.triangle, 1u);
    }
    {
        const std::vector<MeshView> objects{second.view(), first.view()};
        const Hit hit = Accel(objects).nearest_front(ray);
        EXPECT_EQ(hit.object, 0u);
        EXPECT_EQ(hit.triangle, 0u);
    }
    // Many copies in many objects, which the hierarchy separates: the first.
    std::vector<Owned> copies;
    for (int i = 0; i < 200; ++i) copies.push_back(unit_triangle());
    std::vector<MeshView> objects;
    for (const Owned& c : copies) objects.push_back(c.view());
    objects.insert(objects.begin() + 37, MeshView{});  // and an empty object
    const Hit hit = Accel(objects).nearest_front(ray);
    EXPECT_EQ(hit.object, 0u);
    EXPECT_EQ(hit.t, 1.0f);
    EXPECT_EQ(Accel(objects).nearest_back({{0.25f, 0.25f, -1.0f}, {0, 0, 1}}, 150).object, 150u);
}

TEST(Accel, NoObjectsAndEmptyObjects) {
    const Ray ray{{0.25f, 0.25f, 1.0f}, {0.0f, 0.0f, -1.0f}};
    EXPECT_FALSE(Accel(std::vector<MeshView>{}).nearest_front(ray).found());
    const Owned tri = unit_triangle();
    const std::vector<MeshView> objects{MeshView{}, tri.view(), MeshView{}};
    const Accel accel(objects);
    const Hit hit = accel.nearest_front(ray);
    EXPECT_EQ(hit.object, 1u);
    EXPECT_EQ(hit.triangle, 0u);
    EXPECT_FALSE(accel.nearest_back(ray, 0).found());
    EXPECT_FALSE(accel.nearest_back({{0.25f, 0.25f, -1.0f}, {0, 0, 1}}, 2).found());
    EXPECT_EQ(accel.nearest_back({{0.25f, 0.25f, -1.0f}, {0, 0, 1}}, 1).object, 1u);
}

// The scene of the comparisons: a sphere, a torus, three cubes and a soup
// of random triangles (some of them long and thin, some crossing others).
struct Scene {
    std::vector<Owned> owned;
    std::vector<MeshView> objects;
    Scene() {
        owned.push_back(placed(litkit::make_sphere(1.0f, 12, 6), {0.0f, 0.0f, 0.0f}));
        owned.push_back(placed(litkit::make_torus(1.0f, 0.3f, 12, 6), {2.5f, 0.5f, -1.0f}));
        owned.push_back(placed(litkit::make_cube(1.0f), {-2.5f, 0.0f, 0.0f}));
        owned.push_back(placed(litkit::make_cube(0.5f), {0.0f, 2.0f, 0.5f}));
        owned.push_back(placed(litkit::make_cube(4.0f), {0.0f, -3.0f, 0.0f}));  // a floor
        std::mt19937 random(29);
        std::uniform_real_distribution<float> in(-3.0f, 3.0f), near(-0.6f, 0.6f);
        Owned soup;
        for (std::uint32_t i = 0; i < 60; ++i) {
            const glm::vec3 centre(in(random), in(random), in(random));
            const float stretch = i % 4 == 0 ? 4.0f : 1.0f;
            for (int k = 0; k < 3; ++k)
                soup.positions.push_back(
                    centre + glm::vec3(near(random) * stretch, near(random), near(random)));
            soup.triangles.push_back({3 * i, 3 * i + 1, 3 * i + 2});
        }
        owned.push_back(std::move(soup));
        for (const Owned& o : owned) objects.push_back(o.view());
    }
};

// Misses, axis-parallel rays (1/0 in the slab test), part-filled blocks of
// triangles and empty child slots raise neither an invalid operation (a
// NaN) nor a division by zero, which the renderers' callers may test for.
TEST(Accel, RaisesNoInvalidOperationOrDivisionByZero) {
    const Scene scene;
    const Accel accel(scene.objects);
    const std::vector<Ray> rays{
        {{0.1f, 0.2f, 9.0f}, {0.0f, 0.0f, -1.0f}},  {{9.0f, 0.1f, 0.2f}, {-1.0f, 0.0f, 0.0f}},
        {{0.3f, 9.0f, -0.2f}, {0.0f, -1.0f, 0.0f}}, {{9.0f, 9.0f, 9.0f}, {-1.0f, -1.0f, -1.0f}},
        {{9.0f, 9.0f, 9.0f}, {1.0f, 0.0f, 0.0f}},   {{0.0f, 0.0f, 0.0f}, {0.3f, 0.0f, 0.0f}}};
    std::feclearexcept(FE_ALL_EXCEPT);
    int found = 0;
    for (const Ray& ray : rays)
        found += accel.nearest_front(ray).found() + accel.nearest_back(ray, 0).found();
    EXPECT_FALSE(std::fetestexcept(FE_INVALID));
    EXPECT_FALSE(std::fetestexcept(FE_DIVBYZERO));
    EXPECT_GE(found, 5);
}

// The same for blocks of fewer than four triangles whatever their memory
// held before: the hierarchy's arrays are not zeroed before they are
// written (accel.cpp), so the spare lanes must be written too. The heap is
// first filled with NaN bit patterns and given back, where the next
// allocations find it.
TEST(Accel, PartFilledBlocksRaiseNothingWhateverTheHeapHeld) {
    {
        std::vector<std::vector<unsigned char>> poison;
        for (std::size_t size = 64; size <= (1u << 20); size *= 2)
            for (int copies = 0; copies < 4; ++copies) poison.emplace_back(size, 0xff);
    }
    Owned five;
    for (std::uint32_t i = 0; i < 5; ++i) {
        const float x = 2.0f * static_cast<float>(i);
        five.positions.insert(five.positions.end(), {{x, 0, 0}, {x + 1, 0, 0}, {x, 1, 0}});
        five.triangles.push_back({3 * i, 3 * i + 1, 3 * i + 2});
    }
    const std::vector<MeshView> objects{five.view()};
    const Accel accel(objects);
    std::feclearexcept(FE_ALL_EXCEPT);
    int found = 0;
    for (std::uint32_t i = 0; i < 5; ++i) {
        const Ray ray{{2.0f * static_cast<float>(i) + 0.25f, 0.25f, 1.0f}, {0.0f, 0.0f, -1.0f}};
        const Hit hit = accel.nearest_front(ray);
        found += hit.found() && hit.triangle == i;
    }
    EXPECT_FALSE(std::fetestexcept(FE_INVALID));
    EXPECT_FALSE(std::fetestexcept(FE_DIVBYZERO));
    EXPECT_EQ(found, 5);
}

// A large range is binned from a sample (bvh_build.cpp); when every
// sampled centroid falls into one bin, the others are binned too, so that
// a reference the sample missed still decides the split. 2,047 equal
// triangles and one far away at an odd index (binned every second): the
// far one is a leaf of its own under the root, not half of an index split.
TEST(BvhBuild, ASampleInOneBinIsBinnedWhole) {
    using litkit::trace::build::Box;
    std::vector<Box> boxes(2048, Box{{0.0f, 0.0f, 0.0f}, {0.001f, 0.001f, 0.001f}});
    boxes[1025] = Box{{100.0f, 100.0f, 100.0f}, {100.001f, 100.001f, 100.001f}};
    const litkit::trace::build::Tree tree = litkit::trace::build::build_tree(boxes, 4, {});
    const litkit::trace::build::Node& root = tree.nodes.at(0);
    ASSERT_EQ(root.count, 0u);
    int alone = 0;
    for (const std::uint32_t child : {root.a, root.b}) {
        const litkit::trace::build::Node& node = tree.nodes.at(child);
        alone += node.count == 1 && tree.order.at(node.a) == 1025;
    }
    EXPECT_EQ(alone, 1);
}

// Random rays in all, three quarters from anywhere and a quarter from
// inside objects: fewer where the reference is slow (the sanitizers' build
// compiles the tests at -O0, as does a Debug build).
#if defined(LITKIT_SANITIZED) || !defined(__OPTIMIZE__)
constexpr int random_rays = 20'000;
#else
constexpr int random_rays = 1'000'000;
#endif

TEST(Accel, MatchesBruteForceForRandomRays) {
    const Scene scene;
    std::mt19937 random(10);
    std::uniform_real_distribution<float> box(-5.0f, 5.0f), unit(-1.0f, 1.0f), ends(0.0f, 8.0f);
    // Built on one thread and on lent "threads" (jobs run in reverse).
    const litkit::ParallelFor reversed = [](std::size_t count, const litkit::ParallelJob& job) {
        for (std::size_t i = count; i-- > 0;) job(i);
    };
    const Accel accel(scene.objects), lent(scene.objects, reversed);
    int hits = 0;
    for (int i = 0; i < random_rays / 4 * 3; ++i) {
        Ray ray{{box(random), box(random), box(random)},
                {unit(random), unit(random), unit(random)}};
        if (i % 7 == 0) ray.direction[i % 3] = 0.0f;  // axis-parallel planes
        if (i % 11 == 0) ray.direction = {0.0f, 0.0f, 0.0f}, ray.direction[i % 3] = unit(random);
        if (i % 5 == 0) ray.t_min = ends(random), ray.t_max = ray.t_min + ends(random);
        const Hit want = reference(scene.objects, ray, true);
        hits += want.found();
        expect_same(accel.nearest_front(ray), want, ray);
        expect_same(lent.nearest_front(ray), want, ray);
        if (::testing::Test::HasFailure()) return;
    }
    EXPECT_GT(hits, random_rays /
                        20);  // a good part of them meets the scene  // the rays do meet the scene
}

TEST(Accel, MatchesBruteForceInsideObjects) {
    const Scene scene;
    const Accel accel(scene.objects);
    std::mt19937 random(11);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    // A point well inside each closed object.
    const std::vector<std::pair<std::uint32_t, std::pair<glm::vec3, float>>> insides{
        {0, {{0.0f, 0.0f, 0.0f}, 0.75f}},
        {1, {{3.5f, 0.5f, -1.0f}, 0.15f}},
        {2, {{-2.5f, 0.0f, 0.0f}, 0.45f}},
        {3, {{0.0f, 2.0f, 0.5f}, 0.2f}},
        {4, {{0.0f, -3.0f, 0.0f}, 1.9f}}};
    for (int i = 0; i < random_rays / 4; ++i) {
        const auto& [object, where] = insides[i % insides.size()];
        const float reach = where.second / std::sqrt(3.0f);
        const Ray ray{where.first + reach * glm::vec3(unit(random), unit(random), unit(random)),
                      {unit(random), unit(random), unit(random)}};
        const Hit want = reference(scene.objects, ray, false, object);
        ASSERT_TRUE(want.found());  // closed: every ray from inside leaves
        expect_same(accel.nearest_back(ray, object), want, ray);
        expect_same(accel.nearest_front(ray), reference(scene.objects, ray, true), ray);
        if (::testing::Test::HasFailure()) return;
    }
}

// An object of 18,432 triangles, whose hierarchy is collapsed in parts on
// the lent threads (accel.cpp: from 16,384 triangles), beside a small one:
// rays from outside and from inside, built on one thread and on lent
// "threads" that run their jobs in reverse.
TEST(Accel, MatchesBruteForceOnAnObjectCollapsedInParts) {
    const Owned big = placed(litkit::make_sphere(1.0f, 128, 72), {0.0f, 0.0f, 0.0f});
    ASSERT_GE(big.triangles.size(), 16384u);
    const Owned small = placed(litkit::make_cube(0.5f), {0.0f, 0.0f, 2.0f});
    const std::vector<MeshView> objects{small.view(), big.view()};
    const litkit::ParallelFor reversed = [](std::size_t count, const litkit::ParallelJob& job) {
        for (std::size_t i = count; i-- > 0;) job(i);
    };
    const Accel accel(objects), lent(objects, reversed);
    std::mt19937 random(12);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    const int rays = random_rays / 250;
    int hits = 0;
    for (int i = 0; i < rays; ++i) {
        const glm::vec3 target(0.9f * unit(random), 0.9f * unit(random), 0.9f * unit(random));
        const Ray outside{{3.0f * unit(random), 3.0f * unit(random), 3.0f}, {}};
        const Ray from{outside.origin, target - outside.origin};
        const Hit want = reference(objects, from, true);
        hits += want.object == 1;
        expect_same(accel.nearest_front(from), want, from);
        expect_same(lent.nearest_front(from), want, from);
        const Ray inside{0.5f * target, {unit(random), unit(random), unit(random)}};
        const Hit out = reference(objects, inside, false, 1);
        ASSERT_TRUE(out.found());
        expect_same(accel.nearest_back(inside, 1), out, inside);
        expect_same(lent.nearest_back(inside, 1), out, inside);
        if (::testing::Test::HasFailure()) return;
    }
    EXPECT_GT(hits, rays / 2);
}

// Rays through exactly a vertex or an edge's midpoint of a closed mesh,
// from inside it (back faces) and from outside where every triangle at that
// point faces the origin (front faces): at least one is hit, as brute force.
void aim_at_shared_points(const Owned& mesh, const std::vector<glm::vec3>& insides,
                          const std::vector<glm::vec3>& outsides) {
    const std::vector<MeshView> objects{mesh.view()};
    const Accel accel(objects);
    std::vector<glm::vec3> targets = mesh.positions;
    for (const auto& tri : mesh.triangles)
        for (int k = 0; k < 3; ++k)
            targets.push_back((mesh.positions[tri[k]] + mesh.positions[tri[(k + 1) % 3]]) * 0.5f);
    // Each triangle's normal and box in double, then the triangles touching
    // each target (within rounding), found once.
    struct Face {
        glm::dvec3 p0, n, lo, hi;
    };
    std::vector<Face> faces;
    for (const auto& tri : mesh.triangles) {
        const glm::dvec3 p0(mesh.positions[tri[0]]), p1(mesh.positions[tri[1]]),
            p2(mesh.positions[tri[2]]);
        faces.push_back({p0, glm::cross(p1 - p0, p2 - p0), glm::min(glm::min(p0, p1), p2),
                         glm::max(glm::max(p0, p1), p2)});
    }
    int front_checked = 0;
    for (const glm::vec3& target : targets) {
        const glm::dvec3 t(target);
        std::vector<const Face*> touching;
        for (const Face& f : faces)
            if (std::abs(glm::dot(f.n, t - f.p0)) <= 1e-6 * glm::length(f.n) &&
                glm::all(glm::lessThanEqual(f.lo - 1e-6, t)) &&
                glm::all(glm::lessThanEqual(t, f.hi + 1e-6)))
                touching.push_back(&f);
        for (const glm::vec3& origin : insides) {
            const Ray ray{origin, target - origin};
            const Hit hit = accel.nearest_back(ray, 0);
            ASSERT_TRUE(hit.found())
                << "from inside to " << target.x << ", " << target.y << ", " << target.z;
            expect_same(hit, reference(objects, ray, false), ray);
            EXPECT_NEAR(hit.t, 1.0f, 1e-5f);  // convex: it leaves at the target
        }
        for (const glm::vec3& origin : outsides) {
            // Every triangle touching the target must face the origin.
            if (std::any_of(touching.begin(), touching.end(), [&](const Face* f) {
                    return glm::dot(f->n, t - glm::dvec3(origin)) >= 0.0;
                }))
                continue;
            ++front_checked;
            const Ray ray{origin, target - origin};
            const Hit hit = accel.nearest_front(ray);
            ASSERT_TRUE(hit.found())
                << "from outside to " << target.x << ", " << target.y << ", " << target.z;
            expect_same(hit, reference(objects, ray, true), ray);
            EXPECT_NEAR(hit.t, 1.0f, 1e-5f);
        }
    }
    EXPECT_GT(front_checked, static_cast<int>(targets.size()) / 4);
}

TEST(Accel, RaysThroughSharedEdgesAndVerticesOfACube) {
    aim_at_shared_points(placed(litkit::make_cube(2.0f), {0.1f, 0.2f, 0.3f}),
                         {{0.1f, 0.2f, 0.3f}, {0.6f, -0.3f, 0.9f}, {-0.7f, 0.9f, 0.0f}},
                         {{3.1f, 4.2f, 5.3f}, {-4.0f, 1.0f, 0.5f}, {0.1f, 0.2f, -6.0f}});
}

TEST(Accel, RaysThroughSharedEdgesAndVerticesOfASphere) {
    aim_at_shared_points(placed(litkit::make_sphere(1.5f, 24, 12), {0.0f, 0.5f, 0.0f}),
                         {{0.0f, 0.5f, 0.0f}, {0.3f, 0.2f, -0.4f}},
                         {{4.0f, 3.0f, 5.0f}, {-6.0f, 0.5f, 0.1f}, {0.0f, -5.0f, 0.0f}});
}

}  // namespace
