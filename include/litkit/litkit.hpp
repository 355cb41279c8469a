// SPDX-License-Identifier: MIT
/// \file
/// litkit's public API in one include: scenes and their files, the lighting
/// models and the per-point evaluator, meshes and shapes, the list of
/// backends, the CPU renderer, images, the teaching tools (compare, explain,
/// turntable) and the GLSL and C++ exporters. The OpenGL backend, in the
/// separate library litkit::gl, has its own header: litkit/gl_renderer.hpp.
#pragma once

#include "litkit/backend.hpp"
#include "litkit/compare.hpp"
#include "litkit/equations.hpp"
#include "litkit/error.hpp"
#include "litkit/explain.hpp"
#include "litkit/export.hpp"
#include "litkit/glsl.hpp"
#include "litkit/image.hpp"
#include "litkit/lighting.hpp"
#include "litkit/limits.hpp"
#include "litkit/mesh.hpp"
#include "litkit/ray_tree.hpp"
#include "litkit/refraction.hpp"
#include "litkit/render.hpp"
#include "litkit/samples.hpp"
#include "litkit/scene.hpp"
#include "litkit/shapes.hpp"
#include "litkit/turntable.hpp"
#include "litkit/validate.hpp"
