// SPDX-License-Identifier: MIT
// The renderer a command draws with: whichever backend --backend chose
// (litkit/backend.hpp), behind one object. Every backend draws the picture of
// docs/spec.md §1-§4.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>

#include "gl_module.hpp"
#include "litkit/backend.hpp"
#include "litkit/image.hpp"
#include "litkit/render.hpp"
#include "litkit/scene.hpp"

namespace litkit_cli {

// litkit's own renderer, litkit::Renderer.
class CpuBackend {
  public:
    CpuBackend(const litkit::Scene& scene, const litkit::RenderOptions& options);
    void render_into(litkit::Image& image) { renderer_.render_into(image); }
    std::size_t triangle_count() const { return renderer_.triangle_count(); }
    std::string description() const;
    std::string_view setup_steps() const { return "meshes, normals, world space"; }
    std::optional<std::size_t> shaded_pixel_count() const { return renderer_.shaded_pixel_count(); }
    std::uint64_t traced_ray_count() const { return renderer_.traced_ray_count(); }

  private:
    litkit::Renderer renderer_;
};

// OpenGL: litkit::GlRenderer on a headless context, from the module
// litkit-gl.so (gl_module.hpp), which the CLI loads only for this backend.
class GlModuleBackend {
  public:
    GlModuleBackend(const litkit::Scene& scene, const litkit::RenderOptions& options);
    void render_into(litkit::Image& image);
    std::size_t triangle_count() const { return renderer_->triangle_count(); }
    std::string description() const { return "OpenGL backend: " + renderer_->description(); }
    std::string_view setup_steps() const {
        return "meshes, normals, world space, context, shaders, upload";
    }
    std::optional<std::size_t> shaded_pixel_count() const { return std::nullopt; }
    std::uint64_t traced_ray_count() const { return 0; }

  private:
    std::unique_ptr<GlBackend> renderer_;
};

// The renderer of the backend chosen. A new backend is a class with the
// functions above, one more alternative here and its case in
// backend_renderer.cpp's two switches.
class BackendRenderer {
  public:
    using Alternatives = std::variant<CpuBackend, GlModuleBackend>;

    BackendRenderer(litkit::Backend backend, const litkit::Scene& scene,
                    const litkit::RenderOptions& options);
    void render_into(litkit::Image& image) {
        std::visit([&](auto& renderer) { renderer.render_into(image); }, renderer_);
    }
    std::size_t triangle_count() const {
        return std::visit([](const auto& renderer) { return renderer.triangle_count(); },
                          renderer_);
    }
    // "CPU backend: 8 threads, avx2 kernels", "OpenGL backend: ...".
    std::string description() const {
        return std::visit([](const auto& renderer) { return renderer.description(); }, renderer_);
    }
    // What setting the renderer up did (for `bench`).
    std::string_view setup_steps() const {
        return std::visit([](const auto& renderer) { return renderer.setup_steps(); }, renderer_);
    }
    // Pixels shaded in the last frame, where the backend counts them.
    std::optional<std::size_t> shaded_pixel_count() const {
        return std::visit([](const auto& renderer) { return renderer.shaded_pixel_count(); },
                          renderer_);
    }

    // Rays cast from glass in the last frame (0 without glass).
    std::uint64_t traced_ray_count() const {
        return std::visit([](const auto& renderer) { return renderer.traced_ray_count(); },
                          renderer_);
    }

  private:
    Alternatives renderer_;
};

// Why --threads does not apply to `backend` (a usage error's message), or ""
// where it does.
std::string threads_not_applicable(litkit::Backend backend);

}  // namespace litkit_cli
