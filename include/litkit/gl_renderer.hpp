// SPDX-License-Identifier: MIT
/// \file
/// The OpenGL backend (`litkit render --backend gl`): the picture of docs/spec.md §1–§4
/// drawn by OpenGL 3.3 core on a headless EGL context (a GPU's driver where
/// there is one, Mesa's llvmpipe otherwise), with shaders from litkit/glsl.hpp.
/// Part of the separate library litkit::gl, so that the core library does not
/// depend on OpenGL.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>

#include "litkit/error.hpp"
#include "litkit/image.hpp"
#include "litkit/render.hpp"
#include "litkit/scene.hpp"

namespace litkit {

/// No OpenGL could be had (no EGL library, no display, no 3.3 context), or it
/// failed (a shader the driver rejects, an incomplete framebuffer); what()
/// says which and why.
class GlError : public Error {
  public:
    /// `what` is the whole message, saying which step failed and why.
    explicit GlError(const std::string& what) : Error(what) {}
};

/// Draws a scene with OpenGL: the same picture as Renderer (docs/spec.md
/// §1–§4), through the shaders of litkit/glsl.hpp. Keeps the programs and
/// the uploaded meshes so that several frames cost only the drawing. With
/// several samples per pixel (`output.samples`, docs/spec.md §11) a frame is
/// one pass per sample, averaged in linear light on the CPU as Renderer
/// averages; the samples can change in update() without new programs.
class GlRenderer {
  public:
    /// Creates the context, compiles the programs and uploads every object's
    /// world-space vertices. Throws GlError, or IoError for an unreadable
    /// mesh file. `options.threads` and `options.kernels` do not apply.
    /// Refraction (docs/spec.md §10) is not drawn yet: a scene where some
    /// object's transmission is above 0 is refused with ArgumentError, here
    /// and in update() (the CPU renderer draws it).
    explicit GlRenderer(const Scene& scene, RenderOptions options = {});
    /// Draws with the OpenGL (3.3 core or later) context current on this
    /// thread, such as a window's (litkit view), instead of a headless one of
    /// its own. That context must stay current while the renderer is used.
    struct CurrentContext {};
    /// A renderer on the caller's current context (see CurrentContext).
    GlRenderer(const Scene& scene, RenderOptions options, CurrentContext);
    /// Frees the GL objects, and the context when it is its own.
    ~GlRenderer();
    /// Not copyable: it owns GL objects and perhaps a context.
    GlRenderer(const GlRenderer&) = delete;
    /// Not copyable either.
    GlRenderer& operator=(const GlRenderer&) = delete;

    /// The scene to draw from now on: a new camera, size, lights' values,
    /// materials or gamma keep the programs and the uploaded meshes; other
    /// changes build them again. The programs are written for the lights'
    /// number and kinds and for a gamma of 1 or not (glsl::generate_for_scene),
    /// so a light of another kind, a light more or less, or gamma leaving or
    /// reaching 1 builds them again.
    void update(const Scene& scene);

    /// Draws one frame at the scene's output size and reads it back.
    Image render();
    /// As render(), into `image`, reusing its storage (resized if needed).
    void render_into(Image& image);
    /// Draws one frame and copies it, pixel for pixel, to the bottom-left
    /// corner of `framebuffer` (0: the window's) of the current context.
    void draw_to(unsigned framebuffer);

    /// The triangles of every object together, as uploaded.
    std::size_t triangle_count() const;
    /// GL_RENDERER and GL_VERSION, e.g. "llvmpipe (LLVM 15.0.6, 256 bits), 4.5 (Core Profile)
    /// Mesa 22.3.6".
    std::string description() const;

    /// The backend's state (src/gl/); public only so that the backend's own
    /// source files can name it.
    struct Impl;

  private:
    GlRenderer(const Scene& scene, RenderOptions options, CurrentContext, bool headless);
    std::unique_ptr<Impl> impl_;
};

}  // namespace litkit
