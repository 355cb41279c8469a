// The module litkit-gl.so: litkit::GlRenderer for the CLI's `--backend gl`.
#include "gl_module.hpp"

#include "litkit/gl_renderer.hpp"

namespace litkit_cli {

namespace {

class GlRendererBackend final : public GlBackend {
public:
    GlRendererBackend(const litkit::Scene& scene, const litkit::RenderOptions& options)
        : renderer_(scene, options) {}
    void render_into(litkit::Image& image) override { renderer_.render_into(image); }
    std::size_t triangle_count() const override { return renderer_.triangle_count(); }
    std::string description() const override { return renderer_.description(); }

private:
    litkit::GlRenderer renderer_;
};

std::unique_ptr<GlBackend> create(const litkit::Scene& scene, const litkit::RenderOptions& options) {
    return std::make_unique<GlRendererBackend>(scene, options);
}

}  // namespace

}  // namespace litkit_cli

extern "C" __attribute__((visibility("default"))) const litkit_cli::GlModule* litkit_gl_module() {
    static constexpr litkit_cli::GlModule module{
        litkit_cli::module_stamp<litkit_cli::GlModule, litkit::RenderOptions>(), litkit_cli::create};
    return &module;
}
