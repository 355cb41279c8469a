// The OpenGL backend (`litkit render --backend gl`): the picture of docs/spec.md §1–§4
// drawn by OpenGL 3.3 core on a headless EGL context (a GPU's driver where
// there is one, Mesa's llvmpipe otherwise), with shaders from litkit/glsl.hpp.
// Part of the separate library litkit::gl, so that the core library does not
// depend on OpenGL.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>

#include "litkit/error.hpp"
#include "litkit/image.hpp"
#include "litkit/render.hpp"
#include "litkit/scene.hpp"

namespace litkit {

// No OpenGL could be had (no EGL library, no display, no 3.3 context), or it
// failed (a shader the driver rejects, an incomplete framebuffer); what()
// says which and why.
class GlError : public Error {
public:
    explicit GlError(const std::string& what) : Error(what) {}
};

class GlRenderer {
public:
    // Creates the context, compiles the programs and uploads every object's
    // world-space vertices. Throws GlError, or IoError for an unreadable
    // mesh file. `options.threads` and `options.kernels` do not apply.
    explicit GlRenderer(const Scene& scene, RenderOptions options = {});
    // Draws with the OpenGL (3.3 core or later) context current on this
    // thread, such as a window's (litkit view), instead of a headless one of
    // its own. That context must stay current while the renderer is used.
    struct CurrentContext {};
    GlRenderer(const Scene& scene, RenderOptions options, CurrentContext);
    ~GlRenderer();
    GlRenderer(const GlRenderer&) = delete;
    GlRenderer& operator=(const GlRenderer&) = delete;

    // The scene to draw from now on: a new camera, size, lights' values,
    // materials or gamma keep the programs and the uploaded meshes; other
    // changes build them again. The programs are written for the lights'
    // number and kinds and for a gamma of 1 or not (glsl::generate_for_scene),
    // so a light of another kind, a light more or less, or gamma leaving or
    // reaching 1 builds them again.
    void update(const Scene& scene);

    // Draws one frame at the scene's output size and reads it back.
    Image render();
    void render_into(Image& image);
    // Draws one frame and copies it, pixel for pixel, to the bottom-left
    // corner of `framebuffer` (0: the window's) of the current context.
    void draw_to(unsigned framebuffer);

    std::size_t triangle_count() const;
    // GL_RENDERER and GL_VERSION, e.g. "llvmpipe (LLVM 15.0.6, 256 bits), 4.5 (Core Profile) Mesa 22.3.6".
    std::string description() const;

    struct Impl;

private:
    GlRenderer(const Scene& scene, RenderOptions options, CurrentContext, bool headless);
    std::unique_ptr<Impl> impl_;
};

}  // namespace litkit
