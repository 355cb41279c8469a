// SPDX-License-Identifier: MIT
// The module litkit-gl.so: litkit::GlRenderer for the CLI's `--backend gl`.
#include "gl_module.hpp"

#include "litkit/gl_renderer.hpp"

namespace litkit_cli {

namespace {

class GlRendererBackend final : public GlBackend {
  public:
    GlRendererBackend(const litkit::Scene& scene, const litkit::RenderOptions& options)
        : renderer_(scene, options) {}
    bool render_into(litkit::Image& image, CaughtError& error) noexcept override {
        return call_catching([&] { renderer_.render_into(image); }, error);
    }
    std::size_t triangle_count() const noexcept override { return renderer_.triangle_count(); }
    std::string description() const noexcept override { return renderer_.description(); }

  private:
    litkit::GlRenderer renderer_;
};

std::unique_ptr<GlBackend> create(const litkit::Scene& scene, const litkit::RenderOptions& options,
                                  CaughtError& error) noexcept {
    std::unique_ptr<GlBackend> backend;
    call_catching([&] { backend = std::make_unique<GlRendererBackend>(scene, options); }, error);
    return backend;
}

}  // namespace

}  // namespace litkit_cli

extern "C" __attribute__((visibility("default"))) const litkit_cli::GlModule* litkit_gl_module() {
    static constexpr litkit_cli::GlModule module{
        litkit_cli::module_stamp<litkit_cli::GlModule, litkit::RenderOptions>(),
        litkit_cli::create};
    return &module;
}
