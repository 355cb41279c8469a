// SPDX-License-Identifier: MIT
// The viewer panel's controls of one object's material and of one light
// (Dear ImGui widgets, drawn inside the caller's tree node).
#pragma once

#include <glm/vec3.hpp>

#include "litkit/scene.hpp"

namespace litkit_cli {

bool inside_room(const litkit::Room& room, const glm::vec3& p);

// Sliders for the material's colour, coefficients, model parameters and
// glass (docs/spec.md §10.1: t, ior, absorption colour and distance, each
// kept in its range). True where the user changed something.
bool material_controls(litkit::Material& material);

// The light's intensity, colour and what its type has (position inside the
// room, direction, attenuation, cone). True where the user changed something.
bool light_controls(litkit::SceneLight& light, const litkit::Room& room);

}  // namespace litkit_cli
