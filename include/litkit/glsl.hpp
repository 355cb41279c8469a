// SPDX-License-Identifier: MIT
/// \file
/// GLSL generated from the lighting equations (docs/spec.md §4): the OpenGL backend's
/// shaders and what `litkit export --format glsl` writes. The function bodies
/// come from instantiating litkit/equations.hpp with a scalar type that prints
/// GLSL instead of computing, so the GPU evaluates the very text the CPU does.
///
/// The interface every generated program shares (documented again at the top
/// of each shader):
/// \verbatim
///   vertex inputs, world space:
///     location 0  vec3 a_position
///     location 1  vec3 a_normal     flat: the face normal (DD8), else the vertex normal (DD9)
///     location 2  vec3 a_centroid   flat only: the triangle's centroid
///   uniforms:
///     mat4 u_view_projection        world → clip
///     vec3 u_eye                    the observer's position
///     Material u_material           {vec3 color; float ka, kd, ks, shininess}
///     int u_light_count             ≤ the program's light capacity
///     Light u_lights[capacity]      {int kind; vec3 radiance, position, direction,
///                                    attenuation; float cos_cutoff, exponent}
///                                   kind: 0 ambient, 1 directional, 2 point, 3 spot;
///                                   the fields of equations::PreparedLight
///     float u_inv_gamma             1 / gamma
///   output: the pixel value of docs/spec.md §4, already rounded to a multiple of 1/255
///           (FragmentOutput::Pixel), or one sample's clamped linear light
///           (FragmentOutput::SampleLight).
/// \endverbatim
#pragma once

#include <cstddef>
#include <span>
#include <string>

#include "litkit/lighting.hpp"

/// GLSL generated from litkit/equations.hpp (see glsl.hpp).
namespace litkit::glsl {

/// The source of one shader program.
struct Shaders {
    std::string vertex;    ///< GLSL 3.30 core
    std::string fragment;  ///< GLSL 3.30 core
};

/// What a program's fragment shader writes (its frag_color's rgb; alpha is 1).
enum class FragmentOutput {
    /// The pixel value of docs/spec.md §4: round(255 · clamp(I, 0, 1)^(1/γ)) / 255,
    /// exact in an RGBA8 target. One sample per pixel.
    Pixel,
    /// One sample's L_k = clamp(I, 0, 1) (docs/spec.md §11): linear light,
    /// neither gamma nor rounding, for a float target whose passes the host
    /// averages (anti-aliasing). u_inv_gamma is not declared.
    SampleLight,
};

/// The program drawing objects with this reflection × shading model under at
/// most `light_capacity` (≥ 1) lights.
Shaders generate(Reflection reflection, Shading shading, int light_capacity,
                 FragmentOutput output = FragmentOutput::Pixel);

/// The program drawing objects with this reflection × shading model under
/// exactly these lights, as the OpenGL backend draws: shade() has one block
/// per light, of its kind, in the given order, instead of a loop over
/// u_light_count lights of any kind (which it does not read). The uniforms
/// are the same, so the lights' values (radiance, position, direction, ...)
/// can change without a new program; their number and kinds cannot. Light
/// values given here are not used. Likewise `gamma`: only whether it is 1
/// matters; a program for gamma 1 leaves the power out (u_inv_gamma unused).
Shaders generate(Reflection reflection, Shading shading, std::span<const Light> lights, float gamma,
                 FragmentOutput output = FragmentOutput::Pixel);

/// What the OpenGL backend and the program of `litkit export --format cpp`
/// draw with: the program specialised to the lights up to this many lights,
/// the general one (sized for them) beyond, where one block per light would
/// make a long shader to compile for little gain.
inline constexpr std::size_t max_specialised_lights = 16;
/// generate(reflection, shading, lights, gamma) for up to
/// max_specialised_lights lights, else the general program sized for them.
Shaders generate_for_scene(Reflection reflection, Shading shading, std::span<const Light> lights,
                           float gamma, FragmentOutput output = FragmentOutput::Pixel);

}  // namespace litkit::glsl
