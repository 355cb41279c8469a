// SPDX-License-Identifier: MIT
// `--backend gl` as the CLI uses it: litkit::GlRenderer (library litkit::gl)
// behind a small interface, in the module litkit-gl.so, so that libepoxy
// (3,500 relocations of its own) loads only in the runs that draw with
// OpenGL (modules.hpp, docs/design.md "Modules").
#pragma once

#include <cstddef>
#include <memory>
#include <string>

#include "crossing.hpp"
#include "litkit/image.hpp"
#include "litkit/render.hpp"
#include "litkit/scene.hpp"
#include "modules.hpp"

namespace litkit_cli {

// What the CLI asks of the OpenGL backend (litkit::GlRenderer's functions
// of the same names). Nothing is thrown across the module's boundary
// (crossing.hpp): what the renderer throws comes back in `error`.
class GlBackend {
  public:
    virtual ~GlBackend() = default;
    // False when it threw (`error` says what).
    virtual bool render_into(litkit::Image& image, CaughtError& error) noexcept = 0;
    virtual std::size_t triangle_count() const noexcept = 0;
    virtual std::string description() const noexcept = 0;
};

// What the module's entry function returns.
struct GlModule {
    ModuleStamp stamp;  // module_stamp<GlModule, litkit::RenderOptions>()
    // A renderer on a headless context of its own; null when GlRenderer's
    // constructor threw (litkit::GlError, or IoError for an unreadable mesh
    // file), which `error` then holds.
    std::unique_ptr<GlBackend> (*create)(const litkit::Scene& scene,
                                         const litkit::RenderOptions& options,
                                         CaughtError& error) noexcept;
};

}  // namespace litkit_cli

// The OpenGL module's entry, by a C name for dlsym.
extern "C" const litkit_cli::GlModule* litkit_gl_module();
