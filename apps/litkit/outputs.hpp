// SPDX-License-Identifier: MIT
// Where the commands write: the default names of their outputs, standard
// output, and the rule that an output is never one of the inputs.
#pragma once

#include <filesystem>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include "litkit/image.hpp"
#include "litkit/scene.hpp"

namespace litkit_cli {

// `-o -`: the picture goes to standard output, so every message goes to
// standard error.
// Also any name of this process's standard output (/dev/stdout,
// /proc/self/fd/1, a file that standard output is redirected to).
bool is_standard_output(const std::filesystem::path& output);

// The image as PNG into `output`, or onto standard output (is_standard_output).
void write_png_output(const litkit::Image& image, const std::filesystem::path& output);

// A picture's name must say what the file holds: `output` must end in one
// of `extensions` (".png", compared case-insensitively) unless it is
// standard output (is_standard_output), a folder's name ("DIR/", reported
// by the writer) or something that exists and is no regular file
// (/dev/null, a pipe, a folder). Else a UsageError naming what `command`
// writes, before anything is drawn: a .jpg or .gif holding PNG bytes would
// be refused or misread by whatever opens it later.
void require_picture_name(const std::filesystem::path& output,
                          std::initializer_list<std::string_view> extensions,
                          std::string_view command, std::string_view writes);

// `render`'s output: "scene.toml" → "scene.png"; the default scene →
// "default.png"; a scene from standard input → "stdin.png".
std::filesystem::path default_output(const std::vector<std::string>& scenes);

// A scene file's stem with a suffix: "scene.toml" → "scene-compare.png".
std::filesystem::path output_beside(const std::vector<std::string>& scenes,
                                    const std::string& suffix);

// The output must not be one of the inputs, the scene `files` or the mesh
// files they name (docs/spec.md §6): a UsageError if it is.
void refuse_to_overwrite_inputs(const litkit::Scene& scene, const std::vector<std::string>& files,
                                const std::filesystem::path& output);

}  // namespace litkit_cli
