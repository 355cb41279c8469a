// SPDX-License-Identifier: MIT
#include "litkit/lighting.hpp"

#include <glm/geometric.hpp>

#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "core/portable_math.hpp"
#include "core/scale_free.hpp"
#include "litkit/equations.hpp"
#include "litkit/error.hpp"

namespace litkit {

namespace {
// The family's one list (docs/spec.md §4 and §9.1), in the enumeration's order.
constexpr std::array<ReflectionModel, reflection_count> reflection_table{{
    {Reflection::Lambert, "lambert", "IM1: D = max(N.L, 0), S = 0."},
    {Reflection::HalfLambert, "half-lambert", "IM2: D = (0.5*(N.L) + 0.5)^2, S = 0."},
    {Reflection::Phong, "phong",
     "IM3: D = max(N.L, 0), S = max(R.V, 0)^shininess with R = 2(N.L)N - L;\n"
     "S = 0 where R.V <= 0 or N.L <= 0."},
    {Reflection::BlinnPhong, "blinn-phong",
     "IM4: D = max(N.L, 0), S = max(N.H, 0)^shininess with H = normalize(L + V);\n"
     "S = 0 where N.H <= 0 or N.L <= 0."},
    {Reflection::OrenNayar, "oren-nayar",
     "D = n_l*(A + B*max(0, L.V - n_l*n_v)/max(n_l, n_v)), A = 1 - 0.5s^2/(s^2 + 0.33),\n"
     "B = 0.45s^2/(s^2 + 0.09), s = sigma; S = 0."},
    {Reflection::CookTorrance, "cook-torrance",
     "D = n_l; S = pi*D_GGX*Vis*F*n_l (GGX distribution, height-correlated Smith\n"
     "visibility, Schlick Fresnel from f0; a = max(roughness, 0.045)^2)."},
    {Reflection::Toon, "toon",
     "D = min(floor(bands*n_l), bands - 1)/(bands - 1); S = 1 where n_h^shininess >= 0.5."},
    {Reflection::Minnaert, "minnaert",
     "D = n_l*b^(k - 1), b = n_l*n_v (at least 0.1 where k < 1); S = 0."},
    {Reflection::Gooch, "gooch",
     "diffuse colour t*warm + (1 - t)*cool, t = (1 + N.L)/2, cool = min(0.2*kd*C +\n"
     "(0, 0, 0.4), 1), warm = min(0.6*kd*C + (0.4, 0.4, 0), 1); S as phong."},
}};
}  // namespace

std::span<const ReflectionModel> reflection_models() { return reflection_table; }

std::string_view to_string(Reflection reflection) {
    for (const ReflectionModel& model : reflection_table)
        if (model.id == reflection) return model.name;
    return "?";
}

std::string_view to_string(Shading shading) {
    const auto index = static_cast<std::size_t>(shading);
    return index < shading_names.size() ? shading_names[index] : "?";
}

std::optional<Reflection> parse_reflection(std::string_view text) {
    for (const ReflectionModel& model : reflection_table)
        if (model.name == text) return model.id;
    return std::nullopt;
}

std::optional<Shading> parse_shading(std::string_view text) {
    for (std::size_t i = 0; i < shading_names.size(); ++i)
        if (shading_names[i] == text) return static_cast<Shading>(i);
    return std::nullopt;
}

std::optional<LightKind> parse_light_kind(std::string_view text) {
    std::optional<LightKind> kind;
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        ((light_kind_names[I] == text ? (void)kind.emplace(std::in_place_index<I>) : void()), ...);
    }
    (std::make_index_sequence<light_kind_names.size()>());
    return kind;
}

namespace equations {

float pow(float base, float exponent) { return power(base, exponent); }

PreparedLight prepare_light(const Light& light) {
    PreparedLight prepared;
    prepared.radiance = light.radiance();
    std::visit(
        [&](const auto& kind) {
            using Kind = std::decay_t<decltype(kind)>;
            if constexpr (std::is_same_v<Kind, AmbientLight>) {
                prepared.kind = PreparedLight::Kind::Ambient;
            } else if constexpr (std::is_same_v<Kind, DirectionalLight>) {
                prepared.kind = PreparedLight::Kind::Directional;
                prepared.direction = scale_free::unit(kind.direction);
            } else if constexpr (std::is_same_v<Kind, PointLight>) {
                prepared.kind = PreparedLight::Kind::Point;
                prepared.position = kind.position;
                prepared.attenuation = kind.attenuation;
            } else {
                static_assert(std::is_same_v<Kind, SpotLight>);
                prepared.kind = PreparedLight::Kind::Spot;
                prepared.position = kind.position;
                prepared.attenuation = kind.attenuation;
                prepared.direction = scale_free::unit(kind.direction);
                const double cutoff = kind.cutoff_degrees;
                prepared.cos_cutoff = static_cast<float>(cos_degrees(cutoff));
                // docs/spec.md §9.3: θi = θo·(1 − penumbra); penumbra 0 gives the hard edge.
                const double inner = cutoff * (1.0 - static_cast<double>(kind.penumbra));
                prepared.cos_inner = static_cast<float>(cos_degrees(inner));
                prepared.exponent = kind.exponent;
            }
        },
        light.kind);
    return prepared;
}

glm::vec3 shade_scalar(Reflection reflection, std::span<const PreparedLight> lights,
                       const MaterialT<float>& material, const glm::vec3& position,
                       const glm::vec3& normal, const glm::vec3& eye) {
    const Vec3<float> p = splat<float>(position);
    const Vec3<float> n = splat<float>(normal);
    const Vec3<float> v = normalize(splat<float>(eye) - p);
    const Vec3<float> color = with_reflection(reflection, [&](auto model) {
        return shade_point<decltype(model)::value>(lights, material, p, n, v);
    });
    return {color.x, color.y, color.z};
}

}  // namespace equations

namespace {

// shade()'s contract: a unit normal, and an eye that is not the point itself.
void check_point(const glm::vec3& position, const glm::vec3& normal, const glm::vec3& eye) {
    const float length = glm::length(normal);
    if (!(std::abs(length - 1.0f) <= 1e-3f)) {
        throw ArgumentError("shade: the normal must be a unit vector, but its length is " +
                            std::to_string(length) + " (normalise it first)");
    }
    if (eye == position) throw ArgumentError("shade: the eye is at the point being shaded");
}

}  // namespace

glm::vec3 shade(Reflection reflection, const Material& material, std::span<const Light> lights,
                const glm::vec3& position, const glm::vec3& normal, const glm::vec3& eye) {
    using namespace equations;
    check_point(position, normal, eye);
    std::vector<PreparedLight> prepared;
    prepared.reserve(lights.size());
    for (const Light& light : lights) prepared.push_back(prepare_light(light));

    return shade_scalar(reflection, prepared, splat<float>(material), position, normal, eye);
}

namespace {

// Records what shade_point reports, light by light.
struct TermsRecorder {
    ShadeTerms* terms;
    std::vector<std::pair<std::string, float>>* pending;

    void operator()(const char* name, float value) const { pending->emplace_back(name, value); }
    void model_terms(const equations::Terms<float>& terms) const {
        pending->emplace_back("D", terms.diffuse);
        pending->emplace_back("S", terms.specular);
    }
    void light(const equations::PreparedLight&, const equations::Vec3<float>& ambient) const {
        LightTerms& entry = terms->lights.emplace_back();
        entry.ambient = true;
        entry.contribution = {ambient.x, ambient.y, ambient.z};
    }
    void light(const equations::PreparedLight&, const equations::Vec3<float>& direct,
               const equations::Incidence<float>& incidence,
               const equations::Reflected<float>& reflected) const {
        LightTerms& entry = terms->lights.emplace_back();
        entry.to_light = {incidence.to_light.x, incidence.to_light.y, incidence.to_light.z};
        entry.factor = incidence.factor;
        entry.weight = reflected.diffuse;
        entry.color = {reflected.color.x, reflected.color.y, reflected.color.z};
        // D and S were recorded (as the last two values) by reflect.
        entry.specular = pending->back().second;
        pending->pop_back();
        entry.diffuse = pending->back().second;
        pending->pop_back();
        entry.intermediates = std::move(*pending);
        pending->clear();
        entry.contribution = {direct.x, direct.y, direct.z};
    }
};

}  // namespace

ShadeTerms shade_terms(Reflection reflection, const Material& material,
                       std::span<const Light> lights, const glm::vec3& position,
                       const glm::vec3& normal, const glm::vec3& eye) {
    using namespace equations;
    check_point(position, normal, eye);
    std::vector<PreparedLight> prepared;
    prepared.reserve(lights.size());
    for (const Light& light : lights) prepared.push_back(prepare_light(light));

    ShadeTerms terms;
    std::vector<std::pair<std::string, float>> pending;
    const TermsRecorder recorder{&terms, &pending};
    const Vec3<float> p = splat<float>(position);
    const Vec3<float> v = normalize(splat<float>(eye) - p);
    const Vec3<float> total = with_reflection(reflection, [&](auto model) {
        return shade_point<decltype(model)::value>(prepared, splat<float>(material), p,
                                                   splat<float>(normal), v, recorder);
    });
    terms.total = {total.x, total.y, total.z};
    return terms;
}

unsigned char to_pixel(float intensity, float gamma) {
    // NaN fails both comparisons and maps to 0 rather than to garbage.
    float clamped = intensity > 0.0f ? (intensity < 1.0f ? intensity : 1.0f) : 0.0f;
    float corrected = gamma == 1.0f ? clamped : power(clamped, 1.0f / gamma);
    return static_cast<unsigned char>(std::lround(255.0f * corrected));
}

}  // namespace litkit
