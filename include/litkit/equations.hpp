// The one home of the lighting equations (docs/spec.md §4). Every path evaluates
// these templates: the scalar `shade` with T = float, the renderer's
// per-vertex and per-pixel stages, and later SIMD batches and the GLSL
// generator, each with its own T.
//
// A T must provide + - * /, comparisons yielding a mask, and, found by
// argument-dependent lookup (or declared below for float): sqrt, pow, max,
// select(mask, if_true, if_false). Branches on values are written as select so
// that the same text works for one point or for a batch of points.
#pragma once

#include "litkit/lighting.hpp"

#include <glm/vec3.hpp>

#include <cmath>
#include <span>
#include <type_traits>

namespace litkit::equations {

// Scalar versions of the primitive operations, so float works like a batch.
inline float select(bool mask, float if_true, float if_false) { return mask ? if_true : if_false; }
inline float max(float a, float b) { return a > b ? a : b; }
using std::pow;
using std::sqrt;

template <class T>
struct Vec3 {
    T x, y, z;
};

template <class T>
Vec3<T> splat(const glm::vec3& v) {
    return {T(v.x), T(v.y), T(v.z)};
}
template <class T>
Vec3<T> operator+(const Vec3<T>& a, const Vec3<T>& b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
template <class T>
Vec3<T> operator-(const Vec3<T>& a, const Vec3<T>& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
template <class T>
Vec3<T> operator-(const Vec3<T>& a) {
    return {-a.x, -a.y, -a.z};
}
template <class T>
Vec3<T> operator*(const T& s, const Vec3<T>& a) {
    return {s * a.x, s * a.y, s * a.z};
}
// Per-channel product (colours).
template <class T>
Vec3<T> operator*(const Vec3<T>& a, const Vec3<T>& b) {
    return {a.x * b.x, a.y * b.y, a.z * b.z};
}
template <class T>
T dot(const Vec3<T>& a, const Vec3<T>& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <class T>
T length(const Vec3<T>& a) {
    return sqrt(dot(a, a));
}
template <class T>
Vec3<T> normalize(const Vec3<T>& a) {
    return (T(1) / length(a)) * a;
}

// Material with coefficients of type T (docs/spec.md §4 symbols C, k_a, k_d, k_s, α).
template <class T>
struct MaterialT {
    Vec3<T> color;
    T ka, kd, ks, shininess;
};
template <class T>
MaterialT<T> splat(const Material& m) {
    return {splat<T>(m.color), T(m.ka), T(m.kd), T(m.ks), T(m.shininess)};
}

// ---- Light directions and factors (docs/spec.md §4, first table) ----

// Where a light comes from at a surface point: L (unit, towards the light)
// and the factor f.
template <class T>
struct Incidence {
    Vec3<T> to_light;
    T factor;
};

// DD7 generalised: f = 1 / (k_c + k_l·d + k_q·d²).
template <class T>
T distance_attenuation(const Vec3<T>& coefficients, const T& distance) {
    return T(1) / (coefficients.x + coefficients.y * distance + coefficients.z * distance * distance);
}

// Directional light: L = −normalize(direction), f = 1. `travel_unit` is the
// normalised direction the light travels.
template <class T>
Incidence<T> directional_incidence(const Vec3<T>& travel_unit) {
    return {-travel_unit, T(1)};
}

// Point light: L = normalize(position − p), f = attenuation at distance d.
template <class T>
Incidence<T> point_incidence(const Vec3<T>& light_position, const Vec3<T>& attenuation,
                             const Vec3<T>& p) {
    Vec3<T> to_light = light_position - p;
    T distance = length(to_light);
    return {(T(1) / distance) * to_light, distance_attenuation(attenuation, distance)};
}

// Spot cone: c = −L·axis; s = c^exponent where c ≥ cos(cutoff) (0^0 = 1), else 0.
// `axis_unit` is the normalised spot direction.
template <class T>
T spot_factor(const Vec3<T>& to_light, const Vec3<T>& axis_unit, const T& cos_cutoff,
              const T& exponent) {
    T c = -dot(to_light, axis_unit);
    return select(c >= cos_cutoff, pow(max(c, T(0)), exponent), T(0));
}

// ---- Reflection models (docs/spec.md §4, second table; IM1–IM4) ----

template <class T>
struct Terms {
    T diffuse;   // D
    T specular;  // S
};

// max(base, 0)^α, and exactly 0 wherever base ≤ 0 whatever α (never 0^0).
template <class T>
T specular_power(const T& base, const T& shininess) {
    return select(base > T(0), pow(max(base, T(0)), shininess), T(0));
}

// D and S for reflection model R at unit normal N, unit L, unit V.
template <Reflection R, class T>
Terms<T> reflection_terms(const Vec3<T>& normal, const Vec3<T>& to_light, const Vec3<T>& to_eye,
                          const T& shininess) {
    T n_dot_l = dot(normal, to_light);
    if constexpr (R == Reflection::Lambert) {
        return {max(n_dot_l, T(0)), T(0)};
    } else if constexpr (R == Reflection::HalfLambert) {
        T wrapped = T(0.5f) * n_dot_l + T(0.5f);
        return {wrapped * wrapped, T(0)};
    } else if constexpr (R == Reflection::Phong) {
        Vec3<T> reflected = (T(2) * n_dot_l) * normal - to_light;  // R = 2(N·L)N − L
        T specular = specular_power(dot(reflected, to_eye), shininess);
        return {max(n_dot_l, T(0)), select(n_dot_l > T(0), specular, T(0))};
    } else {
        static_assert(R == Reflection::BlinnPhong);
        Vec3<T> halfway = normalize(to_light + to_eye);  // H = normalize(L + V)
        T specular = specular_power(dot(normal, halfway), shininess);
        return {max(n_dot_l, T(0)), select(n_dot_l > T(0), specular, T(0))};
    }
}

// ---- Colour (docs/spec.md §4, DD3–DD6) ----

// k_a · C · I_L for an ambient light.
template <class T>
Vec3<T> ambient_term(const Vec3<T>& radiance, const MaterialT<T>& material) {
    return material.ka * (material.color * radiance);
}

// f · I_L · (k_d · D · C + k_s · S): specular takes the light's colour.
template <class T>
Vec3<T> direct_term(const Vec3<T>& radiance, const T& factor, const Terms<T>& terms,
                    const MaterialT<T>& material) {
    T diffuse = material.kd * terms.diffuse;
    T specular = material.ks * terms.specular;
    Vec3<T> reflectance{diffuse * material.color.x + specular, diffuse * material.color.y + specular,
                        diffuse * material.color.z + specular};
    return factor * (radiance * reflectance);
}

// A light reduced to plain numbers, ready for any T: directions normalised,
// cos(cutoff) computed once. Built by `prepare_lights`.
struct PreparedLight {
    enum class Kind { Ambient, Directional, Point, Spot };
    Kind kind = Kind::Ambient;
    glm::vec3 radiance{0.0f};     // I_L
    glm::vec3 position{0.0f};     // point, spot
    glm::vec3 direction{0.0f};    // unit; directional: travel direction; spot: axis
    glm::vec3 attenuation{0.0f};  // point, spot
    float cos_cutoff = 0.0f;      // spot
    float exponent = 0.0f;        // spot
};

// The spot boundary is inclusive (c ≥ cos(cutoff)); this much slack in the
// cosine keeps a point exactly on the cone inside despite float rounding.
inline constexpr float spot_boundary_slack = 1e-6f;

PreparedLight prepare_light(const Light& light);

// The one place a run-time Reflection becomes a template argument: calls
// f(std::integral_constant<Reflection, R>{}) for the model chosen. Adding a
// reflection model adds its case here and its branch in reflection_terms.
template <class F>
decltype(auto) with_reflection(Reflection reflection, F&& f) {
    switch (reflection) {
        case Reflection::Lambert:
            return f(std::integral_constant<Reflection, Reflection::Lambert>{});
        case Reflection::HalfLambert:
            return f(std::integral_constant<Reflection, Reflection::HalfLambert>{});
        case Reflection::Phong:
            break;
        case Reflection::BlinnPhong:
            return f(std::integral_constant<Reflection, Reflection::BlinnPhong>{});
    }
    return f(std::integral_constant<Reflection, Reflection::Phong>{});
}

// shade_point for one point with plain floats: the scalar path that
// litkit::shade and the renderer's per-vertex and per-triangle stages share.
// `normal` unit length; V is normalize(eye − position).
glm::vec3 shade_scalar(Reflection reflection, std::span<const PreparedLight> lights,
                       const MaterialT<float>& material, const glm::vec3& position,
                       const glm::vec3& normal, const glm::vec3& eye);

// I = Σ_ambient k_a·C·I_L + Σ_others f·I_L·(k_d·D·C + k_s·S) at point p with
// unit normal N and unit V (docs/spec.md §4). Unclamped.
template <Reflection R, class T>
Vec3<T> shade_point(std::span<const PreparedLight> lights, const MaterialT<T>& material,
                    const Vec3<T>& p, const Vec3<T>& normal, const Vec3<T>& to_eye) {
    Vec3<T> total{T(0), T(0), T(0)};
    for (const PreparedLight& light : lights) {
        Vec3<T> radiance = splat<T>(light.radiance);
        Incidence<T> incidence;
        switch (light.kind) {
            case PreparedLight::Kind::Ambient:
                total = total + ambient_term(radiance, material);
                continue;
            case PreparedLight::Kind::Directional:
                incidence = directional_incidence(splat<T>(light.direction));
                break;
            case PreparedLight::Kind::Point:
                incidence = point_incidence(splat<T>(light.position), splat<T>(light.attenuation), p);
                break;
            case PreparedLight::Kind::Spot:
                incidence = point_incidence(splat<T>(light.position), splat<T>(light.attenuation), p);
                incidence.factor =
                    incidence.factor * spot_factor(incidence.to_light, splat<T>(light.direction),
                                                   T(light.cos_cutoff), T(light.exponent));
                break;
        }
        Terms<T> terms =
            reflection_terms<R>(normal, incidence.to_light, to_eye, material.shininess);
        total = total + direct_term(radiance, incidence.factor, terms, material);
    }
    return total;
}

}  // namespace litkit::equations
