// The lighting-model family of docs/spec.md §3–§4: reflection models, shading models,
// lights and materials, and `shade`, which evaluates the colour at one
// surface point. Students and tests call `shade` directly; the renderers
// evaluate the very same equations (litkit/equations.hpp).
#pragma once

#include <glm/vec3.hpp>

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>

namespace litkit {

// docs/spec.md §4, IM1–IM4.
enum class Reflection { Lambert, HalfLambert, Phong, BlinnPhong };
// docs/spec.md §3, DD8–DD10, and §9.2's faceted: lit per pixel with the face normal.
enum class Shading { Flat, Gouraud, Phong, Faceted };

// Scene-file spelling: "lambert", "half-lambert", "phong", "blinn-phong".
std::string_view to_string(Reflection reflection);
// Scene-file spelling: "flat", "gouraud", "phong", "faceted".
std::string_view to_string(Shading shading);
std::optional<Reflection> parse_reflection(std::string_view text);
std::optional<Shading> parse_shading(std::string_view text);

// Surface coefficients. `color` is C of docs/spec.md §4: the material colour / 255,
// per channel in [0, 1].
struct Material {
    glm::vec3 color{1.0f, 1.0f, 1.0f};
    float ka = 0.1f;
    float kd = 0.7f;
    float ks = 0.5f;
    float shininess = 32.0f;
};

// Light kinds: a closed set behind one variant (docs/spec.md §4 table).
struct AmbientLight {};
struct DirectionalLight {
    glm::vec3 direction{0.0f, -1.0f, 0.0f};  // the way the light travels; need not be unit
};
struct PointLight {
    glm::vec3 position{0.0f};
    glm::vec3 attenuation{0.0f, 0.0f, 1.0f};  // k_c, k_l, k_q (DD7 by default)
};
struct SpotLight {
    glm::vec3 position{0.0f};
    glm::vec3 attenuation{0.0f, 0.0f, 1.0f};
    glm::vec3 direction{0.0f, -1.0f, 0.0f};  // axis of the cone; need not be unit
    float cutoff_degrees = 30.0f;            // half-angle of the cone
    float exponent = 0.0f;
};
using LightKind = std::variant<AmbientLight, DirectionalLight, PointLight, SpotLight>;

struct Light {
    LightKind kind;
    glm::vec3 color{1.0f, 1.0f, 1.0f};  // colour / 255
    float intensity = 1.0f;

    // I_L of docs/spec.md §4: intensity · colour / 255.
    glm::vec3 radiance() const { return intensity * color; }
};

// The colour I at surface point `position` with unit normal `normal`, seen
// from `eye`, before clamping and gamma (docs/spec.md §4):
//   I = Σ_ambient k_a·C·I_L + Σ_others f·I_L·(k_d·D·C + k_s·S).
// `normal` must be unit length; it is used as given (the shading model
// decides which normal that is).
glm::vec3 shade(Reflection reflection, const Material& material, std::span<const Light> lights,
                const glm::vec3& position, const glm::vec3& normal, const glm::vec3& eye);

// The pixel value of docs/spec.md §4 for one channel: round(255 · clamp(I, 0, 1)^(1/gamma)).
unsigned char to_pixel(float intensity, float gamma);

}  // namespace litkit
