// SPDX-License-Identifier: MIT
/// \file
/// The renderers that draw a scene, by name: one list that the command
/// line's `--backend`, its help text and the viewer take their choices from.
#pragma once

#include <optional>
#include <span>
#include <string_view>

namespace litkit {

/// A renderer of the picture of docs/spec.md §1–§4. Every backend draws the
/// same scene; they differ in where the work runs. A new backend is one
/// value here, one entry in backends() and one case wherever a program
/// creates a renderer for a Backend.
enum class Backend {
    Cpu,  ///< "cpu": litkit's own rasterizer, litkit::Renderer (render.hpp).
    Gl,   ///< "gl": OpenGL 3.3, litkit::GlRenderer (gl_renderer.hpp, library litkit::gl).
};

/// The backend used where none is chosen.
inline constexpr Backend default_backend = Backend::Cpu;

/// A backend with its name, as backends() lists it.
struct BackendInfo {
    /// The backend.
    Backend id;
    /// Its spelling on the command line, as to_string(Backend) gives it.
    std::string_view name;
    /// What it is, in a few words for a help text.
    std::string_view summary;
};
/// Every backend, in the order of the enumeration.
std::span<const BackendInfo> backends();

/// The backend's name: "cpu" or "gl".
std::string_view to_string(Backend backend);
/// The backend a name spells (exact, lower case), or nothing.
std::optional<Backend> parse_backend(std::string_view text);

}  // namespace litkit
