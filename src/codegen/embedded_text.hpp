// SPDX-License-Identifier: MIT
// Source files the exporter writes out, compiled into the library as text
// (src/CMakeLists.txt embeds them at build time).
#pragma once

namespace litkit::detail {

extern const char* const opengl_core_text;       // src/gl/opengl_core.inc
extern const char* const opengl_samples_text;    // src/gl/opengl_samples.inc
extern const char* const program_template_text;  // src/codegen/program.cpp.in

}  // namespace litkit::detail
