// SPDX-License-Identifier: MIT
// Anti-aliasing in the exports (docs/spec.md §11): the C++ program's sample
// pattern, and what the GLSL export's hosts do with the passes.
#pragma once

#include <string>

#include "litkit/scene.hpp"

namespace litkit::detail {

// The rows of the program's sample_pattern: the scene's samples per pixel.
std::string samples_source(const Scene& scene);

// `--format glsl` with several samples per pixel: what the host does with
// the programs' passes, for the fragment shader's heading comment.
std::string host_samples_comment(const Scene& scene);

}  // namespace litkit::detail
