// SPDX-License-Identifier: MIT
/// \file
/// The one home of the lighting equations (docs/spec.md §4). Every path evaluates
/// these templates: the scalar `shade` and the CPU renderer's per-vertex and
/// per-triangle stages with T = float, its per-pixel kernels with SIMD batches,
/// and the GLSL generator and `explain` with their own T. Each equation cites
/// its source where it has one. Adding a reflection model: see the recipe at
/// litkit::Reflection (lighting.hpp).
///
/// A T must provide + - * /, comparisons yielding a mask, and, found by
/// argument-dependent lookup (or declared below for float): sqrt, pow, max,
/// min, floor, select(mask, if_true, if_false). Branches on values are written as select so
/// that the same text works for one point or for a batch of points.
#pragma once

#include "litkit/lighting.hpp"

#include <glm/vec3.hpp>

#include <cmath>
#include <span>
#include <type_traits>
#include <utility>

namespace xsimd {
template <class T, class A>
class batch;
}

/// The lighting equations as templates on the scalar type T (float, a SIMD
/// batch, a GLSL expression): one text for every path (see equations.hpp).
namespace litkit::equations {

/// \name Scalar primitives
/// Scalar versions of the primitive operations, so float works like a batch.
//@{
/// mask ? if_true : if_false, the float form of a batch's blend.
inline float select(bool mask, float if_true, float if_false) { return mask ? if_true : if_false; }
/// The larger of a and b.
inline float max(float a, float b) { return a > b ? a : b; }
/// The smaller of a and b.
inline float min(float a, float b) { return a < b ? a : b; }
using std::floor;
using std::sqrt;
/// base^exponent with C's powf's special cases (0^0 = 1, a negative base
/// only with a whole exponent), but the same bits in every build: C
/// libraries' powf differ in the last bit (glibc's and the WebAssembly
/// build's), which could move a pixel between `litkit render` and the
/// playground. Computed in double with IEEE arithmetic only and rounded once
/// (src/core/portable_math.cpp); correctly rounded but for rare ties.
float pow(float base, float exponent);
//@}

/// pow of SIMD batches of floats (the CPU kernels' T): for a whole exponent
/// from 0 to 64 in every lane (shininess 32, a spot's exponent 2), the
/// power by repeated squaring (within n · 2^-24, relative); otherwise exactly
/// xsimd::pow's result, but where no lane's base is negative (as max(base,
/// 0) makes it for every use but toon's) without the work xsimd::pow does
/// for negative bases. A zero base gives 0, but 0^0 = 1 (docs/spec.md).
/// Declared here so that the
/// templates below find it before xsimd's own pow; defined in
/// src/cpu/shade_kernel_impl.hpp, where the kernels are compiled.
template <class Arch>
xsimd::batch<float, Arch> pow(const xsimd::batch<float, Arch>& base,
                              const xsimd::batch<float, Arch>& exponent);

/// A 3-vector of T: a point, direction or RGB colour, one per lane of a batch.
template <class T>
struct Vec3 {
    /// \name Components
    //@{
    /// The components: a point's or direction's x, y, z; a colour's r, g, b.
    T x, y, z;
    //@}
};

/// \name Vector arithmetic
/// Component-wise, as GLSL's vec3 (products by a scalar and per channel).
//@{
/// The same vector in every lane: each component converted to T.
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
//@}

/// Material with coefficients of type T (docs/spec.md §4 symbols C, k_a, k_d,
/// k_s, α, and the parameters of §9.1, named as in Material so that
/// for_each_model_parameter visits both).
template <class T>
struct MaterialT {
    /// C, per channel in [0, 1], as Material::color.
    Vec3<T> color;
    /// \name Coefficients of §4
    //@{
    /// k_a, k_d, k_s and α, as the Material fields of the same names.
    T ka, kd, ks, shininess;
    //@}
    /// \name Parameters of §9.1
    //@{
    /// The parameters of §9.1, as the Material fields of the same names.
    T sigma{}, roughness{}, f0{}, bands{}, minnaert_k{};
    //@}
};
/// The material in every lane: each coefficient converted to T.
template <class T>
MaterialT<T> splat(const Material& m) {
    MaterialT<T> result{splat<T>(m.color), T(m.ka), T(m.kd), T(m.ks), T(m.shininess)};
    for_each_model_parameter([](const ModelParameter&, T& to, const float& from) { to = T(from); },
                             result, m);
    return result;
}

// ---- Light directions and factors (docs/spec.md §4, first table) ----

/// Where a light comes from at a surface point: L (unit, towards the light)
/// and the factor f.
template <class T>
struct Incidence {
    /// L: unit, from the point towards the light.
    Vec3<T> to_light;
    /// f: the attenuation times the spot factor; 1 for a directional light.
    T factor;
};

/// DD7 generalised: f = 1 / (k_c + k_l·d + k_q·d²), the attenuation of
/// OpenGL's fixed-function lights; `coefficients` is
/// (k_c, k_l, k_q), `distance` is d in world units.
template <class T>
T distance_attenuation(const Vec3<T>& coefficients, const T& distance) {
    return T(1) /
           (coefficients.x + coefficients.y * distance + coefficients.z * distance * distance);
}

/// Directional light: L = −normalize(direction), f = 1. `travel_unit` is the
/// normalised direction the light travels.
template <class T>
Incidence<T> directional_incidence(const Vec3<T>& travel_unit) {
    return {-travel_unit, T(1)};
}

/// Point light: L = normalize(position − p), f = attenuation at distance d.
template <class T>
Incidence<T> point_incidence(const Vec3<T>& light_position, const Vec3<T>& attenuation,
                             const Vec3<T>& p) {
    Vec3<T> to_light = light_position - p;
    T distance = length(to_light);
    return {(T(1) / distance) * to_light, distance_attenuation(attenuation, distance)};
}

/// The spot boundary is inclusive (c ≥ cos(cutoff)); this much slack in the
/// cosine keeps a point exactly on the cone inside despite float rounding. It
/// applies to the comparisons only, not to the soft edge's interpolation.
inline constexpr float spot_boundary_slack = 1e-6f;

/// Spot cone: c = −L·axis; s = c^exponent · w where c ≥ cos θo (0^0 = 1), else
/// 0, with the soft edge of docs/spec.md §9.3: w = 1 where c ≥ cos θi, else
/// t²(3 − 2t), t = (c − cos θo)/(cos θi − cos θo). With penumbra 0, θi = θo and
/// w = 1 throughout the cone. `axis_unit` is the normalised spot direction.
template <class T>
T spot_factor(const Vec3<T>& to_light, const Vec3<T>& axis_unit, const T& cos_cutoff,
              const T& cos_inner, const T& exponent) {
    T c = -dot(to_light, axis_unit);
    T width = cos_inner - cos_cutoff;
    T t = (c - cos_cutoff) / select(width > T(0), width, T(1));
    T w = select(c >= cos_inner - T(spot_boundary_slack), T(1), t * t * (T(3) - T(2) * t));
    return select(c >= cos_cutoff - T(spot_boundary_slack), pow(max(c, T(0)), exponent) * w, T(0));
}

// ---- Reflection models (docs/spec.md §4, second table; IM1–IM4) ----

/// A model's two terms for one light (docs/spec.md §4.3).
template <class T>
struct Terms {
    T diffuse;   ///< D
    T specular;  ///< S
};

/// max(base, 0)^α, and exactly 0 wherever base ≤ 0 whatever α (never 0^0).
template <class T>
T specular_power(const T& base, const T& shininess) {
    return select(base > T(0), pow(max(base, T(0)), shininess), T(0));
}

/// Where a model's named intermediate values go (A and B of Oren–Nayar, D_GGX,
/// Vis and F of Cook–Torrance, ...): nowhere by default, at no cost; a caller
/// that wants to show the arithmetic (litkit::shade_terms) passes a recorder.
struct NoTrace {
    /// One named intermediate value ("A", 0.87): ignored.
    template <class T>
    void operator()(const char*, const T&) const {}
    /// reflect and shade_point also report D and S and each light's part
    /// (litkit::shade_terms). The model's Terms: ignored.
    template <class... Parts>
    void model_terms(const Parts&...) const {}
    /// One light's part of I, with its incidence and reflection: ignored.
    template <class... Parts>
    void light(const Parts&...) const {}
};

/// D and S for a model of the diffuse + specular form at unit normal N, unit
/// L, unit V (docs/spec.md §4, second table, and §9.1). Sources, model by model:
/// - lambert: J. H. Lambert, Photometria (1760), the cosine law.
/// - half-lambert: Valve's wrapped diffuse, J. Mitchell, G. McTaggart and
///   C. Green, "Shading in Valve's Source Engine", SIGGRAPH 2006 course.
/// - phong: B. T. Phong, "Illumination for Computer Generated Pictures",
///   Communications of the ACM 18(6), 1975.
/// - blinn-phong: J. F. Blinn, "Models of Light Reflection for Computer
///   Synthesized Pictures", SIGGRAPH 1977 (the half vector).
/// - oren-nayar: M. Oren and S. K. Nayar, "Generalization of Lambert's
///   Reflectance Model", SIGGRAPH 1994 (the qualitative model, A and B).
/// - cook-torrance: R. L. Cook and K. E. Torrance, "A Reflectance Model for
///   Computer Graphics", ACM TOG 1(1), 1982, with the GGX distribution of
///   B. Walter, S. R. Marschner, H. Li and K. E. Torrance, "Microfacet Models
///   for Refraction through Rough Surfaces", EGSR 2007; the height-correlated
///   Smith visibility of E. Heitz, "Understanding the Masking-Shadowing
///   Function in Microfacet-Based BRDFs", JCGT 3(2), 2014; the Fresnel
///   approximation of C. Schlick, "An Inexpensive BRDF Model for
///   Physically-based Rendering", Computer Graphics Forum 13(3), 1994; and
///   a = roughness² of B. Burley, "Physically-Based Shading at Disney",
///   SIGGRAPH 2012 course.
/// - toon: cel shading's quantised diffuse and on-or-off highlight, with no
///   one source.
/// - minnaert: M. Minnaert, "The Reciprocity Principle in Lunar Photometry",
///   Astrophysical Journal 93, 1941 (D = n_l^k · n_v^(k−1)).
/// - gooch (reflect below): A. Gooch, B. Gooch, P. Shirley and E. Cohen, "A
///   Non-Photorealistic Lighting Model for Automatic Technical
///   Illustration", SIGGRAPH 1998.
template <Reflection R, class T, class Trace = NoTrace>
Terms<T> reflection_terms(const Vec3<T>& normal, const Vec3<T>& to_light, const Vec3<T>& to_eye,
                          const MaterialT<T>& material, const Trace& trace = {}) {
    T n_dot_l = dot(normal, to_light);
    const auto lit = [&](const T& value) { return select(n_dot_l > T(0), value, T(0)); };
    if constexpr (R == Reflection::Lambert) {
        return {max(n_dot_l, T(0)), T(0)};
    } else if constexpr (R == Reflection::HalfLambert) {
        T wrapped = T(0.5f) * n_dot_l + T(0.5f);
        return {wrapped * wrapped, T(0)};
    } else if constexpr (R == Reflection::Phong || R == Reflection::Gooch) {
        Vec3<T> reflected = (T(2) * n_dot_l) * normal - to_light;  // R = 2(N·L)N − L
        T specular = specular_power(dot(reflected, to_eye), material.shininess);
        return {max(n_dot_l, T(0)), lit(specular)};
    } else if constexpr (R == Reflection::BlinnPhong) {
        Vec3<T> halfway = normalize(to_light + to_eye);  // H = normalize(L + V)
        T specular = specular_power(dot(normal, halfway), material.shininess);
        return {max(n_dot_l, T(0)), lit(specular)};
    } else if constexpr (R == Reflection::OrenNayar) {
        // D = n_l·(A + B·max(0, s)/t), s = L·V − n_l·n_v, t = max(n_l, n_v).
        T sigma = material.sigma * T(0.0174532925f);  // σ in radians
        T sigma2 = sigma * sigma;
        T a = T(1) - T(0.5f) * sigma2 / (sigma2 + T(0.33f));
        T b = T(0.45f) * sigma2 / (sigma2 + T(0.09f));
        T n_dot_v = max(dot(normal, to_eye), T(0));
        T s = dot(to_light, to_eye) - n_dot_l * n_dot_v;
        T t = max(n_dot_l, n_dot_v);
        T ratio = max(T(0), s) / select(t > T(0), t, T(1));
        trace("A", a);
        trace("B", b);
        trace("s", s);
        trace("t", t);
        return {lit(n_dot_l * (a + b * ratio)), T(0)};
    } else if constexpr (R == Reflection::CookTorrance) {
        // D = n_l; S = π·D_GGX·Vis·F·n_l (GGX, height-correlated Smith, Schlick).
        constexpr float pi = 3.14159265358979323846f;
        T r = max(material.roughness, T(0.045f));
        T a = r * r;
        T a2 = a * a;
        T m = max(dot(normal, to_eye), T(1e-4f));
        Vec3<T> halfway = normalize(to_light + to_eye);
        T n_dot_h = max(dot(normal, halfway), T(0));
        // n_h²·(a² − 1) + 1, summed as (1 − n_h²) + n_h²·a²: the same value, but
        // exact at the peak (n_h = 1), where the spec's order loses most of a²
        // to cancellation in float when the roughness is small.
        T n_h2 = n_dot_h * n_dot_h;
        T d_denominator = (T(1) - n_h2) + n_h2 * a2;
        T d_ggx = a2 / (T(pi) * (d_denominator * d_denominator));
        T vis = T(0.5f) / (n_dot_l * sqrt(m * m * (T(1) - a2) + a2) +
                           m * sqrt(n_dot_l * n_dot_l * (T(1) - a2) + a2));
        T one_minus_v_dot_h = T(1) - max(dot(to_eye, halfway), T(0));
        T fifth = one_minus_v_dot_h * one_minus_v_dot_h;
        fifth = fifth * fifth * one_minus_v_dot_h;
        T fresnel = material.f0 + (T(1) - material.f0) * fifth;
        trace("D_GGX", d_ggx);
        trace("Vis", vis);
        trace("F", fresnel);
        return {max(n_dot_l, T(0)), lit(T(pi) * d_ggx * vis * fresnel * n_dot_l)};
    } else if constexpr (R == Reflection::Toon) {
        // D = min(⌊bands·n_l⌋, bands − 1)/(bands − 1); S = 1 where n_h^α ≥ 0.5.
        T level = min(floor(material.bands * n_dot_l), material.bands - T(1));
        Vec3<T> halfway = normalize(to_light + to_eye);
        T n_dot_h = max(dot(normal, halfway), T(0));
        T highlight = select(pow(n_dot_h, material.shininess) >= T(0.5f), T(1), T(0));
        trace("band", level);
        return {lit(level / (material.bands - T(1))), lit(highlight)};
    } else {
        static_assert(R == Reflection::Minnaert);
        // D = n_l·b^(k − 1), b = n_l·n_v, at least 0.1 where k < 1.
        T n_dot_v = max(dot(normal, to_eye), T(0));
        T base = n_dot_l * n_dot_v;
        base = select(material.minnaert_k < T(1), max(base, T(0.1f)), base);
        return {lit(n_dot_l * pow(max(base, T(0)), material.minnaert_k - T(1))), T(0)};
    }
}

/// What multiplies f·I_L for one light: the diffuse colour, as a weight
/// times a colour (k_d·D and C for most models), and the specular S (which
/// takes the light's colour, times k_s).
template <class T>
struct Reflected {
    /// The diffuse weight: k_d·D (1 for gooch).
    T diffuse;
    /// The colour the weight multiplies: C (gooch: its wash).
    Vec3<T> color;
    /// S, before k_s.
    T specular;
};

/// The reflection of model R: k_d·D·C and S for the diffuse + specular
/// models; for `gooch` (docs/spec.md §9.1; Gooch et al. 1998, above) the
/// cool-to-warm wash t·warm + (1 − t)·cool, t = (1 + N·L)/2, and the phong S.
template <Reflection R, class T, class Trace = NoTrace>
Reflected<T> reflect(const Vec3<T>& normal, const Vec3<T>& to_light, const Vec3<T>& to_eye,
                     const MaterialT<T>& material, const Trace& trace = {}) {
    Terms<T> terms = reflection_terms<R>(normal, to_light, to_eye, material, trace);
    if constexpr (R == Reflection::Gooch) {
        T t = (T(1) + dot(normal, to_light)) * T(0.5f);
        Vec3<T> tinted = material.kd * material.color;
        Vec3<T> cool{min(T(0.2f) * tinted.x, T(1)), min(T(0.2f) * tinted.y, T(1)),
                     min(T(0.2f) * tinted.z + T(0.4f), T(1))};
        Vec3<T> warm{min(T(0.6f) * tinted.x + T(0.4f), T(1)),
                     min(T(0.6f) * tinted.y + T(0.4f), T(1)), min(T(0.6f) * tinted.z, T(1))};
        trace("t", t);
        trace("cool.r", cool.x);
        trace("cool.g", cool.y);
        trace("cool.b", cool.z);
        trace("warm.r", warm.x);
        trace("warm.g", warm.y);
        trace("warm.b", warm.z);
        trace.model_terms(terms);
        return {T(1), t * warm + (T(1) - t) * cool, terms.specular};
    } else {
        trace.model_terms(terms);
        return {material.kd * terms.diffuse, material.color, terms.specular};
    }
}

// ---- Colour (docs/spec.md §4, DD3–DD6) ----

/// k_a · C · I_L for an ambient light.
template <class T>
Vec3<T> ambient_term(const Vec3<T>& radiance, const MaterialT<T>& material) {
    return material.ka * (material.color * radiance);
}

/// f · I_L · (k_d · D · C + k_s · S): specular takes the light's colour.
template <class T>
Vec3<T> direct_term(const Vec3<T>& radiance, const T& factor, const Reflected<T>& reflected,
                    const MaterialT<T>& material) {
    T diffuse = reflected.diffuse;
    T specular = material.ks * reflected.specular;
    Vec3<T> reflectance{diffuse * reflected.color.x + specular,
                        diffuse * reflected.color.y + specular,
                        diffuse * reflected.color.z + specular};
    return factor * (radiance * reflectance);
}

/// A light reduced to plain numbers, ready for any T: directions normalised,
/// cos(cutoff) computed once. Built by `prepare_light`.
struct PreparedLight {
    /// Which kind of Light it came from (the alternatives of LightKind).
    enum class Kind {
        Ambient,      ///< AmbientLight
        Directional,  ///< DirectionalLight
        Point,        ///< PointLight
        Spot          ///< SpotLight
    };
    /// The kind; it says which fields below are used.
    Kind kind = Kind::Ambient;
    glm::vec3 radiance{0.0f};     ///< I_L
    glm::vec3 position{0.0f};     ///< point, spot
    glm::vec3 direction{0.0f};    ///< unit; directional: travel direction; spot: axis
    glm::vec3 attenuation{0.0f};  ///< point, spot
    float cos_cutoff = 0.0f;      ///< spot: cos θo
    float cos_inner = 0.0f;       ///< spot: cos θi (docs/spec.md §9.3)
    float exponent = 0.0f;        ///< spot
};

/// `light` as plain numbers: its radiance, its direction normalised, its
/// cone's cosines.
PreparedLight prepare_light(const Light& light);

/// The one place a run-time Reflection becomes a template argument: calls
/// f(std::integral_constant<Reflection, R>{}) for the model chosen, for every
/// model from 0 to reflection_count − 1: a new model needs nothing here.
template <int I = 0, class F>
decltype(auto) with_reflection(Reflection reflection, F&& f) {
    constexpr auto model = static_cast<Reflection>(I);
    if constexpr (I + 1 < reflection_count) {
        if (reflection != model) return with_reflection<I + 1>(reflection, std::forward<F>(f));
    }
    return f(std::integral_constant<Reflection, model>{});
}

/// shade_point for one point with plain floats: the scalar path that
/// litkit::shade and the renderer's per-vertex and per-triangle stages share.
/// `normal` unit length; V is normalize(eye − position). Does not check its
/// arguments (litkit::shade does).
glm::vec3 shade_scalar(Reflection reflection, std::span<const PreparedLight> lights,
                       const MaterialT<float>& material, const glm::vec3& position,
                       const glm::vec3& normal, const glm::vec3& eye);

/// I = Σ_ambient k_a·C·I_L + Σ_others f·I_L·(k_d·D·C + k_s·S) at point p with
/// unit normal N and unit V (docs/spec.md §4). Unclamped.
template <Reflection R, class T, class Trace = NoTrace>
Vec3<T> shade_point(std::span<const PreparedLight> lights, const MaterialT<T>& material,
                    const Vec3<T>& p, const Vec3<T>& normal, const Vec3<T>& to_eye,
                    const Trace& trace = {}) {
    Vec3<T> total{T(0), T(0), T(0)};
    for (const PreparedLight& light : lights) {
        Vec3<T> radiance = splat<T>(light.radiance);
        Incidence<T> incidence;
        switch (light.kind) {
            case PreparedLight::Kind::Ambient: {
                const Vec3<T> ambient = ambient_term(radiance, material);
                trace.light(light, ambient);
                total = total + ambient;
                continue;
            }
            case PreparedLight::Kind::Directional:
                incidence = directional_incidence(splat<T>(light.direction));
                break;
            case PreparedLight::Kind::Point:
                incidence =
                    point_incidence(splat<T>(light.position), splat<T>(light.attenuation), p);
                break;
            case PreparedLight::Kind::Spot:
                incidence =
                    point_incidence(splat<T>(light.position), splat<T>(light.attenuation), p);
                incidence.factor =
                    incidence.factor * spot_factor(incidence.to_light, splat<T>(light.direction),
                                                   T(light.cos_cutoff), T(light.cos_inner),
                                                   T(light.exponent));
                break;
        }
        Reflected<T> reflected = reflect<R>(normal, incidence.to_light, to_eye, material, trace);
        const Vec3<T> direct = direct_term(radiance, incidence.factor, reflected, material);
        trace.light(light, direct, incidence, reflected);
        total = total + direct;
    }
    return total;
}

}  // namespace litkit::equations
