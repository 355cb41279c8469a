// SPDX-License-Identifier: MIT
#include "viewer/drawer.hpp"

#include <epoxy/gl.h>

#include <stdexcept>
#include <string>

namespace litkit_cli {

namespace {

Drawer::Alternatives create(litkit::Backend backend, const litkit::Scene& scene, int threads) {
    litkit::RenderOptions options;
    options.threads = threads;
    switch (backend) {
        case litkit::Backend::Cpu:
            return Drawer::Alternatives(std::in_place_type<CpuDrawer>, scene, options);
        case litkit::Backend::Gl:
            return Drawer::Alternatives(std::in_place_type<GlDrawer>, scene, options);
    }
    throw std::logic_error("no drawer for backend " + std::string(litkit::to_string(backend)));
}

}  // namespace

Screen::Screen() {
    glGenTextures(1, &texture_);
    glGenFramebuffers(1, &framebuffer_);
}

Screen::~Screen() {
    glDeleteFramebuffers(1, &framebuffer_);
    glDeleteTextures(1, &texture_);
}

void Screen::show(const litkit::Image& image, int drawable_width, int drawable_height) {
    glBindTexture(GL_TEXTURE_2D, texture_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    if (image.width != width_ || image.height != height_) {
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, image.width, image.height, 0, GL_RGB,
                     GL_UNSIGNED_BYTE, image.rgb.data());
        width_ = image.width;
        height_ = image.height;
    } else {
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, image.width, image.height, GL_RGB, GL_UNSIGNED_BYTE,
                        image.rgb.data());
    }
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
    glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture_, 0);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glViewport(0, 0, drawable_width, drawable_height);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    // Row 0 of the image is the top (docs/spec.md §1); OpenGL's is the
    // bottom: flip while copying, pixel for pixel.
    glBlitFramebuffer(0, 0, image.width, image.height, 0, drawable_height, image.width,
                      drawable_height - image.height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
}

void GlDrawer::present(Screen&, const litkit::Image&, int width, int height) {
    glViewport(0, 0, width, height);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    renderer_.draw_to(0);
}

Drawer::Drawer(litkit::Backend backend, const litkit::Scene& scene, int threads)
    : drawer_(create(backend, scene, threads)) {}

}  // namespace litkit_cli
