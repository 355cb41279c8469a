// The tracer's acceleration structure (accel.hpp). For now every query
// tests every triangle of the objects it may hit; the hierarchy replaces
// this loop, with the same answers.
#include "trace/accel.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <utility>
#include <vector>

namespace litkit::trace {

namespace {

enum class Facing { Front, Back };

// Woop, Benthin and Wald's watertight test of one triangle; updates `best`
// when the triangle is hit closer (or as close, by a smaller index) with the
// facing asked for.
void intersect(const Ray& ray, const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2,
               Facing facing, std::uint32_t object, std::uint32_t triangle, Hit& best) {
    const glm::vec3& d = ray.direction;
    const glm::vec3 a_abs = glm::abs(d);
    int kz = a_abs.x > a_abs.y ? (a_abs.x > a_abs.z ? 0 : 2) : (a_abs.y > a_abs.z ? 1 : 2);
    int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
    if (d[kz] < 0.0f) std::swap(kx, ky);
    const float sx = d[kx] / d[kz], sy = d[ky] / d[kz], sz = 1.0f / d[kz];
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

}  // namespace

struct Accel::Impl {
    std::vector<MeshView> objects;
};

Accel::Accel(std::span<const MeshView> objects, const ParallelFor&)
    : impl_(std::make_unique<Impl>(Impl{{objects.begin(), objects.end()}})) {}
Accel::~Accel() = default;
Accel::Accel(Accel&&) noexcept = default;
Accel& Accel::operator=(Accel&&) noexcept = default;

Hit Accel::nearest_front(const Ray& ray) const {
    Hit best;
    for (std::uint32_t o = 0; o < impl_->objects.size(); ++o) {
        const MeshView& mesh = impl_->objects[o];
        for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
            const auto& tri = mesh.triangles[t];
            intersect(ray, mesh.positions[tri[0]], mesh.positions[tri[1]], mesh.positions[tri[2]],
                      Facing::Front, o, t, best);
        }
    }
    return best;
}

Hit Accel::nearest_back(const Ray& ray, std::uint32_t object) const {
    Hit best;
    const MeshView& mesh = impl_->objects[object];
    for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& tri = mesh.triangles[t];
        intersect(ray, mesh.positions[tri[0]], mesh.positions[tri[1]], mesh.positions[tri[2]],
                  Facing::Back, object, t, best);
    }
    return best;
}

}  // namespace litkit::trace
