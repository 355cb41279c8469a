// SPDX-License-Identifier: MIT
// Scene files (docs/spec.md §5): reading them, parsing TOML, merging several files
// into one Scene, and validating it (docs/spec.md §6). Problems are collected, never
// thrown one at a time, so that a run reports all of them.
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <system_error>

#include "core/files.hpp"
#include "litkit/validate.hpp"
#include "scene/nesting.hpp"
#include "scene/reader.hpp"
#include "scene/world_mesh.hpp"

namespace litkit {

namespace {

namespace fs = std::filesystem;
using detail::ParsedFile;
using detail::SceneReader;

// Parses TOML text; a syntax error or invalid UTF-8 makes the file one that
// cannot be read (docs/spec.md §6), located where parsing stopped.
toml::table parse_toml(std::string_view text, const std::string& name) {
    detail::check_nesting(text, name);  // toml++ recurses once per level
    try {
        return toml::parse(text, std::string_view(name));
    } catch (const toml::parse_error& failure) {
        const toml::source_position& where = failure.source().begin;
        throw IoError(name, std::string(failure.description()),
                      FileLoc{name, where.line, where.column});
    }
}

std::string read_bytes(const fs::path& path) { return read_file_limited(path); }

// A direction whose squared length is not a normal float (1e-30 squared is
// 0 in float, 1e20 squared is infinite) would normalise to NaN wherever the
// renderers normalise it: such directions are made unit length here, in
// double. Every other direction is left exactly as written.
glm::vec3 unit_if_needed(const glm::vec3& direction) {
    const float squared = glm::dot(direction, direction);
    if (squared >= std::numeric_limits<float>::min() &&
        squared <= std::numeric_limits<float>::max())
        return direction;
    const glm::dvec3 d(direction);
    const double largest = std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)});
    if (largest == 0.0) return direction;  // the zero vector: refused by validation
    return glm::vec3(glm::normalize(d / largest));
}

void normalise_tiny_and_huge_directions(Scene& scene) {
    for (SceneLight& light : scene.lights) {
        if (auto* directional = std::get_if<DirectionalLight>(&light.light.kind))
            directional->direction = unit_if_needed(directional->direction);
        if (auto* spot = std::get_if<SpotLight>(&light.light.kind))
            spot->direction = unit_if_needed(spot->direction);
    }
    scene.observer.up = unit_if_needed(scene.observer.up);
}

Scene build_scene(std::span<const ParsedFile> files,
                  std::uint64_t triangle_budget = default_triangle_budget) {
    Scene scene;
    // Validation keeps the meshes it builds here, for the renderer.
    scene.built_meshes = std::make_shared<BuiltMeshes>();
    SceneReader reader(scene);
    for (const ParsedFile& file : files) reader.read_file(file);
    reader.check_required_tables(files);
    std::vector<Diagnostic> diagnostics = reader.take_diagnostics();

    // The value and geometry rules (validate.hpp) run too, so that one run
    // reports every problem; entities with shape errors hold defaults in
    // place of their bad values and are left out of the geometric checks.
    for (Diagnostic& diagnostic :
         validate_scene(scene, reader.broken_entities(), triangle_budget)) {
        if (diagnostic.severity == Severity::Warning)
            scene.warnings.push_back(std::move(diagnostic));
        else
            diagnostics.push_back(std::move(diagnostic));
    }
    // A failed load still carries its warnings, for the caller to show.
    if (!diagnostics.empty()) throw SceneError(std::move(diagnostics), std::move(scene.warnings));
    normalise_tiny_and_huge_directions(scene);
    return scene;
}

}  // namespace

Scene load_scene(std::span<const std::filesystem::path> files) { return load_scene(files, {}); }

Scene load_scene(std::span<const std::filesystem::path> files, const LoadOptions& options) {
    std::vector<ParsedFile> parsed;
    parsed.reserve(files.size());
    for (const fs::path& path : files) {
        std::string name = path.string();
        toml::table root = parse_toml(read_bytes(path), name);
        parsed.push_back(ParsedFile{std::move(name), path.parent_path(), std::move(root)});
    }
    return build_scene(parsed, options.max_triangles);
}

Scene parse_scene(std::string_view toml_text, const std::filesystem::path& source_name) {
    std::string name = source_name.string();
    ParsedFile file{name, source_name.parent_path(), parse_toml(toml_text, name)};
    return build_scene(std::span(&file, 1));
}

}  // namespace litkit
