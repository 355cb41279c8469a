// SPDX-License-Identifier: MIT
#include "backend_renderer.hpp"

#include <stdexcept>

#include "crossing.hpp"
#include "modules.hpp"
#include "usage_error.hpp"

namespace litkit_cli {

namespace {

BackendRenderer::Alternatives create(litkit::Backend backend, const litkit::Scene& scene,
                                     const litkit::RenderOptions& options) {
    using Alternatives = BackendRenderer::Alternatives;
    switch (backend) {
        case litkit::Backend::Cpu:
            return Alternatives(std::in_place_type<CpuBackend>, scene, options);
        case litkit::Backend::Gl:
            return Alternatives(std::in_place_type<GlModuleBackend>, scene, options);
    }
    throw std::logic_error("no renderer for backend " + std::string(litkit::to_string(backend)));
}

}  // namespace

CpuBackend::CpuBackend(const litkit::Scene& scene, const litkit::RenderOptions& options)
    : renderer_(scene, options) {}

std::string CpuBackend::description() const {
    return "CPU backend: " + std::to_string(renderer_.thread_count()) + " threads, " +
           renderer_.kernel_set() + " kernels";
}

GlModuleBackend::GlModuleBackend(const litkit::Scene& scene, const litkit::RenderOptions& options) {
    CaughtError error;
    renderer_ = open_module<GlModule, litkit::RenderOptions>("litkit-gl.so", "litkit_gl_module",
                                                             "--backend gl")
                    .create(scene, options, error);
    // An argument the backend cannot take (a scene with glass, which OpenGL
    // does not draw yet) is a usage problem: exit status 2, as for export.
    if (!renderer_ && error.kind == CaughtError::Kind::Argument) throw UsageError{error.what};
    if (!renderer_) throw_again(error);
}

void GlModuleBackend::render_into(litkit::Image& image) {
    CaughtError error;
    if (!renderer_->render_into(image, error)) throw_again(error);
}

BackendRenderer::BackendRenderer(litkit::Backend backend, const litkit::Scene& scene,
                                 const litkit::RenderOptions& options)
    : renderer_(create(backend, scene, options)) {}

std::string threads_not_applicable(litkit::Backend backend) {
    switch (backend) {
        case litkit::Backend::Cpu:
            return "";
        case litkit::Backend::Gl:
            // OpenGL decides its own parallelism (a GPU's cores, or llvmpipe's
            // LP_NUM_THREADS): say so rather than ignore the option.
            return "--threads applies to the CPU backend; with --backend gl the driver chooses "
                   "(for Mesa's llvmpipe, set LP_NUM_THREADS)";
    }
    return "";
}

}  // namespace litkit_cli
