// SPDX-License-Identifier: MIT
/// \file
/// The equations of refraction (docs/spec.md §10.2, items 1–7 and 10): what
/// happens to a ray at the interface between two media, and how much light
/// survives a stretch inside an object. Written once, as templates on the
/// scalar type T in the manner of equations.hpp, so that float, a SIMD batch
/// and a GLSL expression all evaluate the same text; branches on values are
/// select. Nothing calls them yet: the scene keys of §10.1 are not read, and
/// the ray tree that will use these (T. Whitted, "An Improved Illumination
/// Model for Shaded Display", Communications of the ACM 23(6), 1980) is to
/// come.
///
/// Besides what equations.hpp asks of a T, the comparison `a <= b` must give
/// a mask type that select takes (bool, a batch_bool, glsl::Mask).
#pragma once

#include "litkit/equations.hpp"

#include <utility>

namespace litkit::equations {

/// The mask type that comparisons of T give: bool for float, a batch_bool
/// for a SIMD batch, glsl::Mask for a GLSL expression.
template <class T>
using MaskOf = decltype(std::declval<const T&>() <= std::declval<const T&>());

/// What happens to a ray at one interface (docs/spec.md §10.2, items 2–5),
/// every field for every lane, total internal reflection or not.
template <class T>
struct Interface {
    /// c₁ = −d·n = cos θ₁, the cosine of the angle of incidence.
    T cos_incident;
    /// k = 1 − η²(1 − c₁²) = cos² θ₂ where there is a refracted ray.
    T k;
    /// c₂ = √max(k, 0) = cos θ₂, the cosine of the angle of refraction (0
    /// under total internal reflection).
    T cos_refracted;
    /// F, the share of the light reflected (exact, unpolarised); 1 under
    /// total internal reflection, so 1 − F is the share refracted.
    T fresnel;
    /// T = η·d + (η·c₁ − c₂)·n, unit; under total internal reflection,
    /// where there is no refracted ray, the mirror direction (so that it is
    /// never NaN; its weight 1 − F is 0 there).
    Vec3<T> refracted;
    /// R = d + 2c₁·n, the mirror direction, unit.
    Vec3<T> reflected;
    /// Total internal reflection: k ≤ 0.
    MaskOf<T> total_internal_reflection;
};

/// The ray of unit direction `direction` (d) meets the interface from the
/// medium of index n₁ into that of index n₂, with `eta` = η = n₁/n₂ and
/// `normal` (n) the unit normal on the ray's side (c₁ = −d·n ≥ 0; docs/spec.md
/// §10.2 item 2 says what to do where it is not). Sources:
/// - Snell's law in vector form: P. S. Heckbert, "Writing a Ray Tracer", in
///   A. S. Glassner (ed.), An Introduction to Ray Tracing, Academic Press,
///   1989; and B. de Greve, "Reflections and Refractions in Ray Tracing",
///   2006. k = 1 − η²(1 − c₁²); total internal reflection iff k ≤ 0; else
///   c₂ = √k and T = η·d + (η·c₁ − c₂)·n, so that n₁ sin θ₁ = n₂ sin θ₂.
/// - The mirror direction: R = d + 2c₁·n (the angle of reflection equals the
///   angle of incidence).
/// - The Fresnel equations, for unpolarised light: M. Born and E. Wolf,
///   Principles of Optics, §1.5.2, with the amplitude ratios
///   r_s = (η c₁ − c₂)/(η c₁ + c₂) and r_p = (c₁ − η c₂)/(c₁ + η c₂), and
///   F = (r_s² + r_p²)/2; F = 1 under total internal reflection. Not
///   Schlick's approximation, which is 5.7/255 wrong at 80° from air and far
///   worse inside glass.
///
/// Every division is guarded, so that a lane under total internal reflection
/// (where η c₁ + c₂ can be 0 at grazing incidence) computes no NaN or
/// infinity that select would then have to discard.
template <class T>
Interface<T> refract_interface(const Vec3<T>& direction, const Vec3<T>& normal, const T& eta) {
    T c1 = -dot(direction, normal);
    T k = T(1) - eta * eta * (T(1) - c1 * c1);
    MaskOf<T> tir = k <= T(0);
    T c2 = sqrt(max(k, T(0)));
    Vec3<T> reflected = direction + (T(2) * c1) * normal;
    Vec3<T> through = eta * direction + (eta * c1 - c2) * normal;
    Vec3<T> refracted{select(tir, reflected.x, through.x), select(tir, reflected.y, through.y),
                      select(tir, reflected.z, through.z)};
    // Both denominators are positive wherever there is a refracted ray and
    // c₁ ≥ 0; 0 only at grazing incidence under total internal reflection.
    T s_denominator = eta * c1 + c2;
    T p_denominator = c1 + eta * c2;
    T r_s = (eta * c1 - c2) / select(s_denominator > T(0), s_denominator, T(1));
    T r_p = (c1 - eta * c2) / select(p_denominator > T(0), p_denominator, T(1));
    T fresnel = select(tir, T(1), T(0.5f) * (r_s * r_s + r_p * r_p));
    return {c1, k, c2, fresnel, refracted, reflected, tir};
}

/// The Beer–Lambert law for one channel (docs/spec.md §10.2 item 7): the
/// share of light left after a stretch of length ℓ inside an object whose
/// white light turns into `color` (a/255, in [0, 1], as Material::color)
/// after `distance` D (> 0): A = (a/255)^(ℓ/D). A = 1 at ℓ = 0, whatever a;
/// 0^x = 0 for x > 0 (A. Beer, "Bestimmung der Absorption des rothen Lichts
/// in farbigen Flüssigkeiten", Annalen der Physik 86, 1852; J. H. Lambert,
/// Photometria, 1760).
template <class T>
T absorption(const T& color, const T& length, const T& distance) {
    T exponent = length / distance;
    T power = select(color > T(0), pow(max(color, T(0)), exponent), T(0));
    return select(exponent > T(0), power, T(1));
}

/// absorption per channel: A = (a/255)^(ℓ/D) for r, g and b.
template <class T>
Vec3<T> absorption(const Vec3<T>& color, const T& length, const T& distance) {
    return {absorption(color.x, length, distance), absorption(color.y, length, distance),
            absorption(color.z, length, distance)};
}

}  // namespace litkit::equations
