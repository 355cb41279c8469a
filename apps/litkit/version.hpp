// SPDX-License-Identifier: MIT
// `litkit --version`: the version, then what this build was made with.
#pragma once

#include <string>

namespace litkit_cli {

// "litkit 0.1.0", a blank line, and one line per feature of the build: the
// SIMD kernel sets (and the one this CPU runs), the OpenGL and viewer
// modules, the Python module, the PNG deflater and Adler-32.
std::string version_text();

}  // namespace litkit_cli
