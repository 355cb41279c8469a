// SPDX-License-Identifier: MIT
// Meshes given in memory (scene.hpp's MeshDataShape): their checks, OBJ
// text, the orientation tests behind the inside-out warning, and bounds.
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "litkit/mesh.hpp"

namespace litkit {

namespace {

std::string float_text(float value) {
    char buffer[32];
    const auto result =
        std::to_chars(buffer, buffer + sizeof buffer, value);  // shortest round-trip
    return std::string(buffer, result.ptr);
}

// Each position's index among the distinct coordinates (equal coordinates,
// bit for bit after -0 → 0, share one).
std::vector<std::uint32_t> welded_indices(const Mesh& mesh) {
    std::map<std::tuple<float, float, float>, std::uint32_t> first;
    std::vector<std::uint32_t> index(mesh.positions.size());
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        const glm::vec3& p = mesh.positions[i];
        const auto key = std::make_tuple(p.x + 0.0f, p.y + 0.0f, p.z + 0.0f);
        index[i] = first.emplace(key, static_cast<std::uint32_t>(first.size())).first->second;
    }
    return index;
}

}  // namespace

std::string check_mesh_data(const Mesh& mesh) {
    if (mesh.triangles.empty()) return "the mesh has no triangles";
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        const glm::vec3& p = mesh.positions[i];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            return "position " + std::to_string(i) + " is not finite (" + float_text(p.x) + ", " +
                   float_text(p.y) + ", " + float_text(p.z) + ")";
    }
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        for (const std::uint32_t corner : mesh.triangles[t]) {
            if (corner >= mesh.positions.size())
                return "triangle " + std::to_string(t) + " refers to position " +
                       std::to_string(corner) + ", but the mesh has " +
                       std::to_string(mesh.positions.size()) + " positions";
        }
    }
    return {};
}

std::string mesh_to_obj(const Mesh& mesh) {
    std::string text = "# written by litkit\n";
    for (const glm::vec3& p : mesh.positions)
        text += "v " + float_text(p.x) + " " + float_text(p.y) + " " + float_text(p.z) + "\n";
    for (const auto& t : mesh.triangles)
        text += "f " + std::to_string(t[0] + 1) + " " + std::to_string(t[1] + 1) + " " +
                std::to_string(t[2] + 1) + "\n";
    return text;
}

double signed_volume(const Mesh& mesh) {
    double volume = 0.0;
    for (const auto& t : mesh.triangles) {
        const glm::dvec3 a(mesh.positions[t[0]]), b(mesh.positions[t[1]]), c(mesh.positions[t[2]]);
        volume += glm::dot(a, glm::cross(b, c));
    }
    return volume / 6.0;
}

bool is_closed(const Mesh& mesh) {
    if (mesh.triangles.empty()) return false;
    const std::vector<std::uint32_t> weld = welded_indices(mesh);
    std::vector<std::uint64_t> edges;  // directed, from << 32 | to
    edges.reserve(mesh.triangles.size() * 3);
    for (const auto& t : mesh.triangles) {
        for (int k = 0; k < 3; ++k) {
            const std::uint64_t from = weld[t[k]], to = weld[t[(k + 1) % 3]];
            if (from == to) return false;  // a degenerate edge: not a clean surface
            edges.push_back(from << 32 | to);
        }
    }
    std::sort(edges.begin(), edges.end());
    for (std::size_t i = 0; i < edges.size(); ++i) {
        if (i + 1 < edges.size() && edges[i + 1] == edges[i]) return false;  // used twice one way
        const std::uint64_t reverse = (edges[i] & 0xffffffffu) << 32 | edges[i] >> 32;
        if (!std::binary_search(edges.begin(), edges.end(), reverse)) return false;
    }
    return true;
}

Bounds bounds(const Mesh& mesh) {
    if (mesh.positions.empty()) return {};
    Bounds box{mesh.positions.front(), mesh.positions.front()};
    for (const glm::vec3& position : mesh.positions) {
        box.min = glm::min(box.min, position);
        box.max = glm::max(box.max, position);
    }
    return box;
}

}  // namespace litkit
