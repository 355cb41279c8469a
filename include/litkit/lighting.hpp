// SPDX-License-Identifier: MIT
/// \file
/// The lighting-model family of docs/spec.md §3–§4: reflection models, shading models,
/// lights and materials, and `shade`, which evaluates the colour at one
/// surface point. Students and tests call `shade` directly; the renderers
/// evaluate the very same equations (litkit/equations.hpp).
#pragma once

#include <glm/vec3.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace litkit {

/// An 8-bit colour, 0–255 per channel (red, green, blue): a scene file's
/// colour or a pixel's.
///
/// One convention across the API: every colour of a scene
/// (Material::color, Light::color, OutputSettings::background) is a
/// glm::vec3 of linear values, 0–1 per channel (1 = full). Scene files
/// write colours as 0–255 integers (or "#rrggbb"), and images hold 8-bit
/// pixels; from_rgb8 and to_rgb8 convert between the two, and are exact for
/// the 256 byte values: to_rgb8(from_rgb8(b)) == b for every b.
using Rgb8 = std::array<std::uint8_t, 3>;
/// An 8-bit colour as a 0–1 colour: each byte / 255 (so 255 → 1.0f).
/// The inverse of to_rgb8 for every byte value. Never throws.
inline glm::vec3 from_rgb8(const Rgb8& rgb) { return glm::vec3(rgb[0], rgb[1], rgb[2]) / 255.0f; }
/// A 0–1 colour as 8 bits per channel: each channel clamped to [0, 1]
/// (NaN → 0), × 255, rounded half up. Never throws.
inline Rgb8 to_rgb8(const glm::vec3& color) {
    auto byte = [](float c) {
        const float clamped = c > 0.0f ? (c < 1.0f ? c : 1.0f) : 0.0f;  // NaN fails c > 0
        return static_cast<std::uint8_t>(std::floor(clamped * 255.0f + 0.5f));
    };
    return {byte(color.x), byte(color.y), byte(color.z)};
}

/// The reflection models of docs/spec.md §4 (IM1–IM4) and §9.1 (LC2): how
/// much light a surface point sends to the eye (each equation, with its
/// source, in litkit/equations.hpp). The order is the spec's, and that of
/// every list users see (validation's names, `litkit view`'s keys 1–9).
///
/// Adding a model (the one recipe):
/// 1. its enumerator here, last (and reflection_count below counted from it);
/// 2. its row in reflection_models() (src/lighting/lighting.cpp): the
///    scene-file name and a one-line summary;
/// 3. its branch in equations::reflection_terms (D and S), or in
///    equations::reflect where it changes the diffuse colour, as gooch does;
/// 4. a parameter of its own, if any: a field of Material and of
///    equations::MaterialT and a line in for_each_model_parameter;
/// 5. its rows in docs/spec.md §9.1 and docs/scene-format.md (tests/test_spec.cpp
///    checks the names against reflection_models()) and its tests in
///    tests/test_lighting.cpp.
/// Every path follows from these: the scalar and SIMD evaluators and the GLSL
/// generator (through equations::with_reflection), the exported program,
/// `explain`, validation, the command line, the Python binding, the
/// playground and the starting file of `litkit init` (through
/// reflection_models(); tests/test_spec.cpp checks the lists in the docs).
enum class Reflection {
    Lambert,       ///< "lambert": diffuse only, D = max(N·L, 0).
    HalfLambert,   ///< "half-lambert": Valve's wrapped diffuse, D = (0.5·N·L + 0.5)².
    Phong,         ///< "phong": Lambert plus the mirror highlight max(R·V, 0)^α.
    BlinnPhong,    ///< "blinn-phong": Lambert plus the half-vector highlight max(N·H, 0)^α.
    OrenNayar,     ///< "oren-nayar": rough diffuse, roughness `sigma` (§9.1).
    CookTorrance,  ///< "cook-torrance": GGX microfacets, `roughness` and `f0` (§9.1).
    Toon,          ///< "toon": diffuse in `bands` flat steps, a highlight on or off (§9.1).
    Minnaert,      ///< "minnaert": limb darkening, exponent `minnaert_k` (§9.1).
    Gooch,         ///< "gooch": cool-to-warm technical illustration (§9.1).
};
/// How many Reflection values there are (for arrays indexed by model).
inline constexpr int reflection_count = static_cast<int>(Reflection::Gooch) + 1;

/// One reflection model as users see it: its scene-file name and a one-line
/// summary of its equations (printed into generated shaders).
struct ReflectionModel {
    /// The model.
    Reflection id;
    /// Its scene-file spelling, as to_string(Reflection) gives it.
    std::string_view name;
    /// Its equations in one line.
    std::string_view summary;
};
/// Every model, in the order of the enumeration.
std::span<const ReflectionModel> reflection_models();
/// Where the lighting is evaluated, and with which normal (docs/spec.md §3,
/// DD8–DD10, and §9.2). Gouraud shading is H. Gouraud's, "Continuous Shading
/// of Curved Surfaces", IEEE Transactions on Computers C-20(6), 1971; Phong
/// shading (normals interpolated) is B. T. Phong's of 1975 (equations.hpp).
enum class Shading {
    Flat,     ///< "flat": once per triangle, at its centroid with the face normal.
    Gouraud,  ///< "gouraud": at the vertices, colours interpolated across the triangle.
    Phong,    ///< "phong": per pixel, with interpolated and renormalised vertex normals.
    Faceted   ///< "faceted": per pixel, with the face normal (§9.2).
};
/// How many Shading values there are.
inline constexpr int shading_count = static_cast<int>(Shading::Faceted) + 1;
/// The shading models' scene-file names, in the enumeration's order: the one
/// list that to_string, parse_shading, the scene reader's "did you mean", the
/// command line, the Python binding, the playground and the docs' tables
/// (checked by tests/test_spec.cpp) all take.
inline constexpr std::array<std::string_view, shading_count> shading_names{"flat", "gouraud",
                                                                           "phong", "faceted"};

/// Scene-file spelling: the model's name in reflection_models().
std::string_view to_string(Reflection reflection);
/// Scene-file spelling: the model's name in shading_names.
std::string_view to_string(Shading shading);
/// The model a scene-file spelling names (exact, lower case), or nothing.
std::optional<Reflection> parse_reflection(std::string_view text);
/// The shading model a scene-file spelling names (exact, lower case), or nothing.
std::optional<Shading> parse_shading(std::string_view text);

/// The surface coefficients of docs/spec.md §4 (C, k_a, k_d, k_s, α). The
/// parameters of docs/spec.md §9.1 are here whatever the model, so that
/// switching models keeps them; a model ignores those it does not use.
struct Material {
    /// C: the surface colour, linear, 0–1 per channel (a scene file's 0–255 /
    /// 255: from_rgb8). A scene built in code is only checked to be finite.
    glm::vec3 color{1.0f, 1.0f, 1.0f};
    /// k_a, ambient coefficient in [0, 1].
    float ka = 0.1f;
    /// k_d, diffuse coefficient in [0, 1].
    float kd = 0.7f;
    /// k_s, specular coefficient in [0, 1].
    float ks = 0.5f;
    /// α, the specular exponent (≥ 0) of the models with a highlight.
    float shininess = 32.0f;
    float sigma = 30.0f;      ///< oren-nayar: surface roughness σ in degrees
    float roughness = 0.5f;   ///< cook-torrance: perceptual roughness r
    float f0 = 0.04f;         ///< cook-torrance: reflectance at normal incidence
    float bands = 3.0f;       ///< toon: how many diffuse levels (a whole number)
    float minnaert_k = 1.5f;  ///< minnaert: limb darkening k
    // Refraction (docs/spec.md §10.1): accepted on every object, whatever its
    // model, and without effect while transmission is 0.
    /// t, in [0, 1]: the share of the surface's ambient and diffuse light
    /// replaced by refraction and mirror reflection (docs/spec.md §10.2 item
    /// 8); 0 (the default) is opaque. Above 0 the object must be a closed mesh.
    float transmission = 0.0f;
    /// n_o, in [1, 3]: the refractive index of the object's interior (water
    /// 1.33, glass 1.5, diamond 2.42).
    float ior = 1.5f;
    /// a: the colour white light turns into after absorption_distance inside
    /// the object (Beer–Lambert, docs/spec.md §10.2 item 7), linear, 0–1 per
    /// channel like `color` (a scene file's 0–255 / 255: from_rgb8); white,
    /// the default, absorbs nothing.
    glm::vec3 absorption_color{1.0f, 1.0f, 1.0f};
    /// D (> 0, finite): the distance, in scene units, after which white light
    /// inside the object has turned into absorption_color.
    float absorption_distance = 1.0f;
};

/// One parameter of the models of docs/spec.md §9.1 as scene files name and
/// bound it: its key (also its name in the generated GLSL), its closed range,
/// and whether it is a whole number.
struct ModelParameter {
    /// The scene-file key and GLSL name ("sigma").
    std::string_view key;
    /// The smallest value allowed.
    float low;
    /// The largest value allowed.
    float high;
    /// Whether only whole numbers are allowed.
    bool whole;
};

/// The one list of those parameters: calls f(parameter, field...) for each,
/// with that field of every material given (Material and
/// equations::MaterialT<T> name their fields alike). The scene reader,
/// validation, the OpenGL upload and the code generators all follow it, so a
/// model's new parameter is a field of Material and MaterialT and a line here.
template <class F, class... Materials>
void for_each_model_parameter(F&& f, Materials&&... materials) {
    f(ModelParameter{"sigma", 0.0f, 90.0f, false}, materials.sigma...);
    f(ModelParameter{"roughness", 0.0f, 1.0f, false}, materials.roughness...);
    f(ModelParameter{"f0", 0.0f, 1.0f, false}, materials.f0...);
    f(ModelParameter{"bands", 2.0f, 16.0f, true}, materials.bands...);
    f(ModelParameter{"minnaert_k", 0.0f, 4.0f, false}, materials.minnaert_k...);
}

// Light kinds: a closed set behind one variant (docs/spec.md §4 table).
/// An ambient light: it lights every point equally, from no direction.
struct AmbientLight {};
/// A light infinitely far away: parallel rays, no attenuation.
struct DirectionalLight {
    glm::vec3 direction{0.0f, -1.0f, 0.0f};  ///< the way the light travels; need not be unit
};
/// A light at a point, shining every way, attenuated with distance d by
/// 1 / (k_c + k_l·d + k_q·d²).
struct PointLight {
    /// Where the light is, in world coordinates.
    glm::vec3 position{0.0f};
    glm::vec3 attenuation{0.0f, 0.0f, 1.0f};  ///< k_c, k_l, k_q (DD7 by default)
};
/// A point light limited to a cone: inside it the light is scaled by
/// c^exponent, c the cosine of the angle from the axis (docs/spec.md §4.2).
struct SpotLight {
    /// Where the light is, in world coordinates.
    glm::vec3 position{0.0f};
    /// k_c, k_l, k_q as for PointLight.
    glm::vec3 attenuation{0.0f, 0.0f, 1.0f};
    glm::vec3 direction{0.0f, -1.0f, 0.0f};  ///< axis of the cone; need not be unit
    float cutoff_degrees = 30.0f;            ///< half-angle of the cone, in (0, 90]
    /// The spot exponent (≥ 0): how fast light falls off from the axis.
    float exponent = 0.0f;
    float penumbra = 0.0f;  ///< docs/spec.md §9.3: the soft fraction of the cone, 0–1
};
/// Any one of the light kinds: a closed set behind one variant (docs/spec.md §4 table).
using LightKind = std::variant<AmbientLight, DirectionalLight, PointLight, SpotLight>;
/// The light kinds' scene-file names (a [[lights]] entry's `type`), in the
/// variant's order: the one list that the scene reader, the GLSL generator's
/// comments, `explain`, the Python binding and the docs' tables take.
inline constexpr std::array<std::string_view, std::variant_size_v<LightKind>> light_kind_names{
    "ambient", "directional", "point", "spot"};
/// The scene-file name of `kind`'s alternative ("spot" for a SpotLight). Never throws.
inline std::string_view light_kind_name(const LightKind& kind) {
    return light_kind_names[kind.index()];
}
/// The kind a scene-file name gives (exact, lower case), with the kind's
/// defaults, or nothing.
std::optional<LightKind> parse_light_kind(std::string_view text);

/// A light: its kind (with the kind's geometry), colour and intensity.
struct Light {
    /// Which kind, with its position, direction and cone.
    LightKind kind;
    /// The light's colour, linear, 0–1 per channel (a scene file's 0–255 /
    /// 255: from_rgb8). A scene built in code is only checked to be finite.
    glm::vec3 color{1.0f, 1.0f, 1.0f};
    /// The scale of the colour (≥ 0, finite): I_L = intensity · color.
    float intensity = 1.0f;

    /// I_L of docs/spec.md §4: intensity · color.
    glm::vec3 radiance() const { return intensity * color; }
};

/// The colour I at surface point `position` with unit normal `normal`, seen
/// from `eye`, before clamping and gamma (docs/spec.md §4):
///   I = Σ_ambient k_a·C·I_L + Σ_others f·I_L·(k_d·D·C + k_s·S).
/// `normal` must be unit length (within 1e-3: the shading model decides which
/// normal that is, and a normal of another length would scale D and S);
/// throws ArgumentError otherwise, and for an eye at `position`. Light
/// directions need not be unit: they are normalised. Positions are in world
/// coordinates; the result is per channel, ≥ 0, unbounded above.
glm::vec3 shade(Reflection reflection, const Material& material, std::span<const Light> lights,
                const glm::vec3& position, const glm::vec3& normal, const glm::vec3& eye);

/// One light's part in shade(), with the values of docs/spec.md §4 and §9 that
/// gave it, for showing the arithmetic (a student checking a hand calculation,
/// `litkit explain`).
struct LightTerms {
    /// Whether the light is ambient (then only `contribution` matters).
    bool ambient = false;
    glm::vec3 to_light{0.0f};  ///< L (zero for an ambient light)
    float factor = 1.0f;       ///< f: attenuation × spot factor (1 for directional)
    float diffuse = 0.0f;      ///< D
    float specular = 0.0f;     ///< S
    /// What f·I_L multiplies: weight·color + k_s·S per channel; weight = k_d·D
    /// and color = C for every model but gooch (weight 1, its cool-to-warm wash).
    float weight = 0.0f;
    /// The colour that `weight` multiplies (see `weight`).
    glm::vec3 color{0.0f};
    /// The model's named intermediate values: A, B, s, t (oren-nayar); D_GGX,
    /// Vis, F (cook-torrance); band (toon); t, cool.r…, warm.b (gooch).
    std::vector<std::pair<std::string, float>> intermediates;
    glm::vec3 contribution{0.0f};  ///< this light's part of I
};

/// The working of shade() at one point: every light's terms and the sum.
struct ShadeTerms {
    std::vector<LightTerms> lights;  ///< in the order given
    glm::vec3 total{0.0f};           ///< I, exactly what shade() returns
};

/// shade() with its working: each light's terms and the model's intermediate
/// values. `total` is shade()'s result, bit for bit (the same evaluation).
/// Throws as shade() does.
ShadeTerms shade_terms(Reflection reflection, const Material& material,
                       std::span<const Light> lights, const glm::vec3& position,
                       const glm::vec3& normal, const glm::vec3& eye);

/// The pixel value of docs/spec.md §4 for one channel: round(255 · clamp(I, 0, 1)^(1/gamma)).
/// `gamma` > 0.
unsigned char to_pixel(float intensity, float gamma);

}  // namespace litkit
