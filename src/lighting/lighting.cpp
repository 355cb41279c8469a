#include "litkit/lighting.hpp"

#include <glm/geometric.hpp>

#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "litkit/equations.hpp"

namespace litkit {

namespace {
constexpr std::array<std::pair<Reflection, std::string_view>, 4> reflection_names{{
    {Reflection::Lambert, "lambert"},
    {Reflection::HalfLambert, "half-lambert"},
    {Reflection::Phong, "phong"},
    {Reflection::BlinnPhong, "blinn-phong"},
}};
constexpr std::array<std::pair<Shading, std::string_view>, 4> shading_names{{
    {Shading::Flat, "flat"},
    {Shading::Gouraud, "gouraud"},
    {Shading::Phong, "phong"},
    {Shading::Faceted, "faceted"},
}};
}  // namespace

std::string_view to_string(Reflection reflection) {
    for (const auto& [value, name] : reflection_names)
        if (value == reflection) return name;
    return "?";
}

std::string_view to_string(Shading shading) {
    for (const auto& [value, name] : shading_names)
        if (value == shading) return name;
    return "?";
}

std::optional<Reflection> parse_reflection(std::string_view text) {
    for (const auto& [value, name] : reflection_names)
        if (name == text) return value;
    return std::nullopt;
}

std::optional<Shading> parse_shading(std::string_view text) {
    for (const auto& [value, name] : shading_names)
        if (name == text) return value;
    return std::nullopt;
}

namespace equations {

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
                prepared.direction = glm::normalize(kind.direction);
            } else if constexpr (std::is_same_v<Kind, PointLight>) {
                prepared.kind = PreparedLight::Kind::Point;
                prepared.position = kind.position;
                prepared.attenuation = kind.attenuation;
            } else {
                static_assert(std::is_same_v<Kind, SpotLight>);
                prepared.kind = PreparedLight::Kind::Spot;
                prepared.position = kind.position;
                prepared.attenuation = kind.attenuation;
                prepared.direction = glm::normalize(kind.direction);
                double radians = static_cast<double>(kind.cutoff_degrees) * (M_PI / 180.0);
                prepared.cos_cutoff = static_cast<float>(std::cos(radians)) - spot_boundary_slack;
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

glm::vec3 shade(Reflection reflection, const Material& material, std::span<const Light> lights,
                const glm::vec3& position, const glm::vec3& normal, const glm::vec3& eye) {
    using namespace equations;
    std::vector<PreparedLight> prepared;
    prepared.reserve(lights.size());
    for (const Light& light : lights) prepared.push_back(prepare_light(light));

    return shade_scalar(reflection, prepared, splat<float>(material), position, normal, eye);
}

unsigned char to_pixel(float intensity, float gamma) {
    // NaN fails both comparisons and maps to 0 rather than to garbage.
    float clamped = intensity > 0.0f ? (intensity < 1.0f ? intensity : 1.0f) : 0.0f;
    float corrected = gamma == 1.0f ? clamped : std::pow(clamped, 1.0f / gamma);
    return static_cast<unsigned char>(std::lround(255.0f * corrected));
}

}  // namespace litkit
