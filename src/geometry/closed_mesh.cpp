// SPDX-License-Identifier: MIT
// docs/spec.md §10.1's closed-mesh rule (closed_mesh.hpp).
#include "geometry/closed_mesh.hpp"

#include <algorithm>
#include <utility>
#include <vector>

#include "geometry/weld.hpp"

namespace litkit::detail {

namespace {

std::uint64_t edge_key(std::uint32_t from, std::uint32_t to) {
    return std::uint64_t{from} << 32 | to;
}

}  // namespace

std::optional<UnclosedEdge> find_unclosed_edge(const Mesh& mesh) {
    const std::vector<std::uint32_t> vertex = weld(mesh.positions);
    // The triangles that take part (DD9's rule, as vertex_normals applies it).
    std::vector<std::size_t> usable;
    usable.reserve(mesh.triangles.size());
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& triangle = mesh.triangles[t];
        const std::uint32_t a = vertex[triangle[0]], b = vertex[triangle[1]],
                            c = vertex[triangle[2]];
        if (a == b || b == c || c == a) continue;
        if (face_normal(mesh.positions[triangle[0]], mesh.positions[triangle[1]],
                        mesh.positions[triangle[2]]) == glm::vec3(0.0f))
            continue;
        usable.push_back(t);
    }
    // Every directed edge of those triangles, between welded vertices.
    std::vector<std::uint64_t> edges;
    edges.reserve(usable.size() * 3);
    for (const std::size_t t : usable)
        for (int k = 0; k < 3; ++k)
            edges.push_back(
                edge_key(vertex[mesh.triangles[t][k]], vertex[mesh.triangles[t][(k + 1) % 3]]));
    std::sort(edges.begin(), edges.end());
    const auto count = [&](std::uint64_t key) {
        const auto [first, last] = std::equal_range(edges.begin(), edges.end(), key);
        return static_cast<std::size_t>(last - first);
    };
    for (const std::size_t t : usable) {
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t from = mesh.triangles[t][k], to = mesh.triangles[t][(k + 1) % 3];
            const std::size_t forward = count(edge_key(vertex[from], vertex[to]));
            const std::size_t backward = count(edge_key(vertex[to], vertex[from]));
            if (forward != 1 || backward != 1) return UnclosedEdge{t, from, to, forward, backward};
        }
    }
    return std::nullopt;
}

}  // namespace litkit::detail
