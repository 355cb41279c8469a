// SPDX-License-Identifier: MIT
// litkit_gl_peer: the plain OpenGL program bench/compare.sh measures litkit
// against. See main.cpp for what it is and why.
#pragma once

#include <glm/vec3.hpp>

#include <string>
#include <vector>

#include "litkit/lighting.hpp"

namespace peer {

// One light as the shaders use it, worked out by the peer itself from the
// scene's litkit::Light (docs/spec.md §4's table).
struct PeerLight {
    enum Kind { Ambient, Directional, Point, Spot } kind = Ambient;
    glm::vec3 radiance{0.0f};     // intensity · colour / 255
    glm::vec3 position{0.0f};     // point, spot
    glm::vec3 direction{0.0f};    // unit: the way a directional light travels; a spot's axis
    glm::vec3 attenuation{0.0f};  // k_c, k_l, k_q
    float cos_cutoff = 0.0f, cos_inner = 0.0f, exponent = 0.0f;  // spot
};

std::vector<PeerLight> peer_lights(const std::vector<litkit::Light>& lights);

struct ShaderSources {
    std::string vertex, fragment;
};

// The program for one reflection × shading model under exactly these
// lights: one block of code per light, of its kind, with the light's values
// as uniforms u_light<i>_*; the ambient lights summed into u_ambient.
// `gamma`: whether the picture's gamma is other than 1 (u_inv_gamma).
// Throws std::runtime_error for a reflection model it does not write
// (only the four classic ones: lambert, half-lambert, phong, blinn-phong).
ShaderSources shaders_for(litkit::Reflection reflection, litkit::Shading shading,
                          const std::vector<PeerLight>& lights, bool gamma);

}  // namespace peer
