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
///   output: the pixel value of docs/spec.md §4, already rounded to a multiple of 1/255.
/// \endverbatim
#pragma once

#include <string>

#include "litkit/lighting.hpp"

/// GLSL generated from litkit/equations.hpp (see glsl.hpp).
namespace litkit::glsl {

/// The source of one shader program.
struct Shaders {
    std::string vertex;    ///< GLSL 3.30 core
    std::string fragment;  ///< GLSL 3.30 core
};

/// The program drawing objects with this reflection × shading model under at
/// most `light_capacity` (≥ 1) lights.
Shaders generate(Reflection reflection, Shading shading, int light_capacity);

}  // namespace litkit::glsl
