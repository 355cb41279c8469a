// SPDX-License-Identifier: MIT
// The viewer panel's per-object and per-light controls (panel.hpp).
#include "viewer/panel.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <type_traits>
#include <variant>

#include "litkit/lighting.hpp"

namespace litkit_cli {

bool inside_room(const litkit::Room& room, const glm::vec3& p) {
    return std::abs(p.x) <= room.width / 2 && std::abs(p.y) <= room.height / 2 &&
           std::abs(p.z) <= room.depth / 2;
}

bool material_controls(litkit::Material& m) {
    bool edited = false;
    edited |= ImGui::ColorEdit3("color", &m.color.x);
    edited |= ImGui::SliderFloat("ka", &m.ka, 0.0f, 1.0f);
    edited |= ImGui::SliderFloat("kd", &m.kd, 0.0f, 1.0f);
    edited |= ImGui::SliderFloat("ks", &m.ks, 0.0f, 1.0f);
    edited |= ImGui::SliderFloat("shininess", &m.shininess, 0.0f, 256.0f);
    // Glass (docs/spec.md §10.1), clamped to the ranges a scene file allows
    // even where a value is typed (ctrl+click).
    constexpr ImGuiSliderFlags clamp = ImGuiSliderFlags_AlwaysClamp;
    edited |= ImGui::SliderFloat("transmission", &m.transmission, 0.0f, 1.0f, "%.3f", clamp);
    edited |= ImGui::SliderFloat("ior", &m.ior, 1.0f, 3.0f, "%.3f", clamp);
    edited |= ImGui::ColorEdit3("absorption color", &m.absorption_color.x);
    edited |= ImGui::SliderFloat("absorption distance", &m.absorption_distance, 0.01f, 100.0f,
                                 "%.3f", clamp | ImGuiSliderFlags_Logarithmic);
    litkit::for_each_model_parameter(
        [&](const litkit::ModelParameter& parameter, float& value) {
            const std::string name(parameter.key);
            if (parameter.whole) {
                int whole = static_cast<int>(value);
                if (ImGui::SliderInt(name.c_str(), &whole, static_cast<int>(parameter.low),
                                     static_cast<int>(parameter.high))) {
                    value = static_cast<float>(whole);
                    edited = true;
                }
            } else {
                edited |= ImGui::SliderFloat(name.c_str(), &value, parameter.low, parameter.high);
            }
        },
        m);
    return edited;
}

bool light_controls(litkit::SceneLight& light, const litkit::Room& room) {
    bool edited = false;
    edited |= ImGui::SliderFloat("intensity", &light.light.intensity, 0.0f, 100.0f);
    edited |= ImGui::ColorEdit3("color", &light.light.color.x);
    std::visit(
        [&](auto& kind) {
            using K = std::decay_t<decltype(kind)>;
            const float half = std::max({room.width, room.height, room.depth}) / 2;
            if constexpr (std::is_same_v<K, litkit::DirectionalLight>) {
                edited |= ImGui::DragFloat3("direction", &kind.direction.x, 0.01f);
            } else if constexpr (std::is_same_v<K, litkit::PointLight> ||
                                 std::is_same_v<K, litkit::SpotLight>) {
                glm::vec3 position = kind.position;
                if (ImGui::DragFloat3("position", &position.x, 0.02f, -half, half) &&
                    inside_room(room, position)) {
                    kind.position = position;
                    edited = true;
                }
                edited |= ImGui::DragFloat3("attenuation", &kind.attenuation.x, 0.01f, 0.0f, 10.0f);
                if constexpr (std::is_same_v<K, litkit::SpotLight>) {
                    edited |= ImGui::DragFloat3("direction", &kind.direction.x, 0.01f);
                    edited |= ImGui::SliderFloat("cutoff", &kind.cutoff_degrees, 0.5f, 90.0f);
                    edited |= ImGui::SliderFloat("exponent", &kind.exponent, 0.0f, 128.0f);
                    edited |= ImGui::SliderFloat("penumbra", &kind.penumbra, 0.0f, 1.0f);
                }
            }
        },
        light.light.kind);
    return edited;
}

}  // namespace litkit_cli
