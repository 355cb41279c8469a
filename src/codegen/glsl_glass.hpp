// SPDX-License-Identifier: MIT
// The programs that draw glass through OpenGL (docs/spec.md §10): the
// usual raster program of an object's reflection × shading model, whose
// fragments on an object with t > 0 also trace the ray tree of §10.2 in the
// shader, against the scene's triangles and hierarchy held in texture
// buffers (gl_glass.hpp fills them; docs/design.md, "Glass through OpenGL").
#pragma once

#include <span>

#include "litkit/glsl.hpp"
#include "litkit/lighting.hpp"

namespace litkit::glsl {

// The texture buffers' layouts, RGBA32F texels (gl_glass.cpp writes them,
// the shaders read them):
// - u_triangles, 7 texels a triangle, in the hierarchy's leaf order:
//   (p0, object), (p1, triangle within the object), (p2, 0), (N_g, 0), then
//   the corners' vertex normals (n0, 0), (n1, 0), (n2, 0);
// - u_nodes, 4 texels a node, two for each of its two children: (lower
//   corner, bits of the child's node or of its first triangle), (upper
//   corner, bits of its triangle count: 0 for a node, −1.0 for an empty
//   slot). Node 0 is the root of the tree over the objects, node 1 + o the
//   root of object o's tree over its own triangles (a two-level hierarchy,
//   as src/trace/accel.cpp's);
// - u_objects, object_texels() a scene object: (C, k_a), (k_d, k_s, α, t),
//   (absorption colour, D), (n_o, model, smooth, clear), then the models'
//   parameters (litkit::for_each_model_parameter's order), four a texel;
// - u_faces, 1 texel a triangle in drawing order: (N_g, 0).
inline constexpr int triangle_texels = 7;
inline constexpr int node_texels = 4;
int object_texels();

// What a glass program is made for: its object's models, every reflection
// model of the scene's objects (the rays reach any of them; `models[k]` is
// model number k of u_objects), and the lights, gamma and output as for
// generate_for_scene.
struct GlassProgram {
    Reflection reflection = Reflection::Phong;
    Shading shading = Shading::Phong;
    std::span<const Reflection> models;
    std::span<const Light> lights;
    float gamma = 1.0f;
    // The pixel, or one sample's light for anti-aliasing's passes.
    FragmentOutput output = FragmentOutput::Pixel;
};

Shaders generate_glass(const GlassProgram& program);

}  // namespace litkit::glsl
