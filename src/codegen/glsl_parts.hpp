// SPDX-License-Identifier: MIT
// The pieces the shaders are assembled from (glsl.cpp), shared with the
// glass programs (glsl_glass.cpp), which add the ray tree to them.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "litkit/glsl.hpp"
#include "litkit/lighting.hpp"

namespace litkit::glsl {

// The comment at the top of every shader: what made it and its interface.
std::string header(Reflection reflection, Shading shading, std::string_view stage,
                   FragmentOutput output);

// The structs, uniforms and generated lighting functions of one reflection
// model, ending with shade(p, normal, to_eye) for the material u_material.
// `lights`: the scene's lights, for a program specialised to them; none: the
// general program, a loop over u_light_count lights of any kind.
std::string lighting_declarations(Reflection reflection, int light_capacity,
                                  std::optional<std::span<const Light>> lights);

// shade(p, normal, to_eye) alone, as lighting_declarations ends.
std::string shade_text(std::optional<std::span<const Light>> lights);

// to_pixel(I): the pixel value of docs/spec.md §4 over 255.
std::string to_pixel_function(bool gamma_one);

// sample_light(I): one sample's clamped linear light (docs/spec.md §11).
std::string sample_light_function();

}  // namespace litkit::glsl
