// SPDX-License-Identifier: MIT
#include "version.hpp"

#include "litkit/render.hpp"

namespace litkit_cli {

std::string version_text() {
    using Kernels = litkit::RenderOptions::Kernels;
    const char* running = litkit::kernel_set_available(Kernels::Avx512) ? "avx512"
                          : litkit::kernel_set_available(Kernels::Avx2) ? "avx2"
                                                                        : "portable";
    // The build's choices come from CMake (apps/litkit/CMakeLists.txt).
    return std::string("litkit ") + LITKIT_VERSION +
           "\n\n"
           "SIMD kernels: avx512, avx2, portable (this CPU runs " +
           running +
           ")\n"
           "OpenGL backend: module " LITKIT_FEATURE_GL_MODULE
           " (--backend gl)\n"
           "viewer: module " LITKIT_FEATURE_VIEW_MODULE
           " (litkit view)\n"
           "Python module: " LITKIT_FEATURE_PYTHON
           "\n"
           "PNG deflater: " LITKIT_FEATURE_DEFLATE "; Adler-32: " LITKIT_FEATURE_ADLER "\n";
}

}  // namespace litkit_cli
