// SPDX-License-Identifier: MIT
/// \file
/// Code generation (R7): the scene as shaders a user pastes into an OpenGL
/// program, or as a whole program a user builds and runs. Both draw what
/// `litkit render --backend gl` draws.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "litkit/lighting.hpp"
#include "litkit/scene.hpp"

namespace litkit {

/// The most numbers of vertex data export_cpp writes into main.cpp by
/// default (ExportOptions::max_source_numbers): about 45 MB of source, which
/// g++ 12 builds at -O2 in about a minute with about 1.3 GB of memory.
inline constexpr std::uint64_t default_max_source_numbers = 4'000'000;

/// How export_glsl and export_cpp write.
struct ExportOptions {
    /// Used where the scene leaves [lighting] out (as RenderOptions).
    Reflection fallback_reflection = default_reflection;
    /// The shading model used where the scene leaves it out (as fallback_reflection).
    Shading fallback_shading = default_shading;
    /// Off: a file that would be written and already exists stops the export
    /// (IoError with reason "already exists") before anything is written.
    bool replace_existing = false;
    /// Files the export reads (the scene files; the scene's mesh files are
    /// added by the export itself): an export never writes over one of them,
    /// --force or not (ArgumentError).
    std::vector<std::filesystem::path> inputs;
    /// export_cpp: the most numbers of vertex data (positions, normals,
    /// centroids, indices: 27 a triangle drawn flat, 6 a vertex and 3 a
    /// triangle otherwise) that main.cpp may hold, all objects together. Past
    /// it the export writes nothing and throws SceneError located at the
    /// object that crosses it, naming the limit; built-in shapes are sized
    /// from their parameters before any mesh is built (docs/reliability.md).
    std::uint64_t max_source_numbers = default_max_source_numbers;
};

/// Writes, into `directory` (created if missing), a vertex and a fragment
/// shader for each reflection × shading pair the scene's objects use:
/// "<reflection>-<shading>.vert" and ".frag" (GLSL 3.30 core, the uniforms
/// they expect documented at their top), sized for the scene's lights. The
/// folder's files are written all or none (write_folder_atomically). Returns the paths written;
/// throws IoError, and ArgumentError for a scene where some object's
/// transmission is above 0 (refraction, docs/spec.md §10, is not exported yet).
std::vector<std::filesystem::path> export_glsl(const Scene& scene,
                                               const std::filesystem::path& directory,
                                               const ExportOptions& options = {});

/// Writes, into `directory`, "main.cpp" and "CMakeLists.txt": a standalone
/// program named `program_name` (a C identifier) that draws the scene with
/// OpenGL 3.3 on a headless EGL context and writes a PNG, or shows it in a
/// window with --window (built where SDL2 is found). `scene_label` names the
/// scene in the program's comments. Returns the paths written; throws IoError
/// (also for an unreadable mesh file), ArgumentError for a bad
/// program name or a scene where some object's transmission is above 0
/// (refraction, docs/spec.md §10, is not exported yet), and SceneError when
/// the objects' vertex data would exceed options.max_source_numbers.
std::vector<std::filesystem::path> export_cpp(const Scene& scene,
                                              const std::filesystem::path& directory,
                                              const std::string& program_name,
                                              const std::string& scene_label,
                                              const ExportOptions& options = {});

/// The commands that build and run what export_cpp wrote into `directory`.
std::string export_cpp_instructions(const std::filesystem::path& directory,
                                    const std::string& program_name);

}  // namespace litkit
