// SPDX-License-Identifier: MIT
// What draws the viewer's picture: the renderer of the backend chosen
// (litkit/backend.hpp) behind one object, and the screen that shows an image
// in the window.
#pragma once

#include <variant>

#include "litkit/backend.hpp"
#include "litkit/gl_renderer.hpp"
#include "litkit/image.hpp"
#include "litkit/render.hpp"
#include "litkit/scene.hpp"

namespace litkit_cli {

// Shows an RGB image 1:1 in the window's framebuffer (on the current OpenGL
// context, which must outlive it).
class Screen {
  public:
    Screen();
    ~Screen();
    Screen(const Screen&) = delete;
    Screen& operator=(const Screen&) = delete;
    void show(const litkit::Image& image, int drawable_width, int drawable_height);

  private:
    unsigned texture_ = 0, framebuffer_ = 0;  // GLuint
    int width_ = 0, height_ = 0;
};

// litkit's own renderer: renders into an image that the screen shows.
class CpuDrawer {
  public:
    CpuDrawer(const litkit::Scene& scene, const litkit::RenderOptions& options)
        : renderer_(scene, options) {}
    void update(const litkit::Scene& scene) { renderer_.update(scene); }
    void render(litkit::Image& image) { renderer_.render_into(image); }
    void present(Screen& screen, const litkit::Image& image, int width, int height) {
        screen.show(image, width, height);
    }
    void snapshot(litkit::Image&) {}  // the image holds the last frame already

  private:
    litkit::Renderer renderer_;
};

// OpenGL: draws with the window's own context (the same shaders as `render
// --backend gl`) straight into the window.
class GlDrawer {
  public:
    GlDrawer(const litkit::Scene& scene, const litkit::RenderOptions& options)
        : renderer_(scene, options, litkit::GlRenderer::CurrentContext{}) {}
    void update(const litkit::Scene& scene) { renderer_.update(scene); }
    void render(litkit::Image&) {}  // it draws in present()
    void present(Screen& screen, const litkit::Image& image, int width, int height);
    void snapshot(litkit::Image& image) { renderer_.render_into(image); }

  private:
    litkit::GlRenderer renderer_;
};

// The renderer of the backend chosen. A new backend is a class with the
// functions above, one more alternative here and its case in drawer.cpp.
class Drawer {
  public:
    using Alternatives = std::variant<CpuDrawer, GlDrawer>;

    Drawer(litkit::Backend backend, const litkit::Scene& scene, int threads);
    // The scene changed (camera, models, an edit, a reload).
    void update(const litkit::Scene& scene) {
        std::visit([&](auto& drawer) { drawer.update(scene); }, drawer_);
    }
    // Renders the frame into `image` where the backend draws into memory.
    void render(litkit::Image& image) {
        std::visit([&](auto& drawer) { drawer.render(image); }, drawer_);
    }
    // Puts the frame into the window's framebuffer.
    void present(Screen& screen, const litkit::Image& image, int width, int height) {
        std::visit([&](auto& drawer) { drawer.present(screen, image, width, height); }, drawer_);
    }
    // The picture as it stands into `image` (for S).
    void snapshot(litkit::Image& image) {
        std::visit([&](auto& drawer) { drawer.snapshot(image); }, drawer_);
    }

  private:
    Alternatives drawer_;
};

}  // namespace litkit_cli
