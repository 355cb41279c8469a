// SPDX-License-Identifier: MIT
// Wavefront OBJ mesh files (docs/spec.md §2, `type = "mesh"`), read with tinyobjloader.
#include <tiny_obj_loader.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <glm/vec3.hpp>
#include <limits>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "core/files.hpp"
#include "geometry/obj_numbers.hpp"
#include "litkit/error.hpp"
#include "litkit/shapes.hpp"

namespace litkit {

namespace {

// tinyobjloader ends its messages with "line N.)" or similar: the first
// number after "line " is where parsing stopped, or 0 if there is none.
std::uint32_t line_in_message(const std::string& message) {
    const std::size_t found = message.find("line ");
    if (found == std::string::npos) return 0;
    std::uint32_t line = 0;
    for (std::size_t at = found + 5;
         at < message.size() && std::isdigit(static_cast<unsigned char>(message[at])); ++at) {
        line = line * 10 + static_cast<std::uint32_t>(message[at] - '0');
    }
    return line;
}

std::string trimmed(std::string text) {
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
    std::size_t start = 0;
    while (start < text.size() && std::isspace(static_cast<unsigned char>(text[start]))) ++start;
    return text.substr(start);
}

}  // namespace

// The line of the `face_number`-th polygon (0-based, in file order, as
// tinyobjloader lists them: `f` lines with at least 3 corners), or 0 if the
// file cannot be read again. Only needed to place an error.
std::uint32_t line_of_face(const std::filesystem::path& path, std::size_t face_number) {
    std::string text;
    try {
        text = read_file_limited(path);
    } catch (const Error&) {
        return 0;
    }
    std::size_t faces_seen = 0;
    std::uint32_t line = 0;
    for (std::size_t at = 0; at < text.size();) {
        // Lines as tinyobjloader splits them (a lone "\r" ends one too).
        std::istringstream words{std::string(detail::next_obj_line(text, at))};
        ++line;
        std::string keyword;
        if (!(words >> keyword) || keyword != "f") continue;
        std::size_t corners = 0;
        for (std::string corner; words >> corner;) ++corners;
        if (corners < 3) continue;
        if (faces_seen == face_number) return line;
        ++faces_seen;
    }
    return 0;
}

Mesh load_obj(const std::filesystem::path& path) {
    const std::string name = path.string();

    std::error_code status_error;
    if (std::filesystem::is_directory(path, status_error)) {
        throw IoError(name, std::strerror(EISDIR));
    }
    // Bounded (docs/reliability.md), and every number checked first:
    // tinyobjloader reads "nan", "abc" or "0,5" as 0 without a word.
    // (The text apart from the stream, not file.view(): the C++ library of
    // the WebAssembly build, docs/web.md, has no istringstream::view.)
    const std::string text = read_file_limited(path);
    detail::check_obj_numbers(text, name);
    std::istringstream file(text);

    // Without tinyobjloader's triangulation: docs/spec.md §2 fixes the fan
    // (v0, vi, vi+1), made below. No material reader: materials play no part,
    // and a mesh file must not make us open other files.
    tinyobj::attrib_t attributes;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warnings;
    std::string errors;
    const bool parsed = tinyobj::LoadObj(&attributes, &shapes, &materials, &warnings, &errors,
                                         &file, /*readMatFn=*/nullptr, /*triangulate=*/false);
    if (file.bad()) throw IoError(name, errno != 0 ? std::strerror(errno) : "read error");
    if (!parsed) {
        const std::string reason = trimmed(errors);
        throw IoError(name, reason.empty() ? "not a valid OBJ file" : reason,
                      FileLoc{name, line_in_message(errors), 0});
    }

    Mesh mesh;
    const std::size_t vertex_count = attributes.vertices.size() / 3;
    if (vertex_count > std::numeric_limits<std::uint32_t>::max()) {
        throw IoError(name, "too many vertices (" + std::to_string(vertex_count) + ")");
    }
    mesh.positions.reserve(vertex_count);
    for (std::size_t vertex = 0; vertex < vertex_count; ++vertex) {
        const glm::vec3 position(attributes.vertices[3 * vertex],
                                 attributes.vertices[3 * vertex + 1],
                                 attributes.vertices[3 * vertex + 2]);
        if (!std::isfinite(position.x) || !std::isfinite(position.y) ||
            !std::isfinite(position.z)) {
            throw IoError(name, "vertex " + std::to_string(vertex + 1) +
                                    " has a coordinate that is not a finite number");
        }
        mesh.positions.push_back(position);
    }

    // docs/spec.md §9.2, normals = "file": the `vn` normals, checked only
    // when used (a face without them is fine for every other weighting).
    const std::size_t normal_count = attributes.normals.size() / 3;
    mesh.file_normals.reserve(normal_count);
    for (std::size_t normal = 0; normal < normal_count; ++normal) {
        mesh.file_normals.emplace_back(attributes.normals[3 * normal],
                                       attributes.normals[3 * normal + 1],
                                       attributes.normals[3 * normal + 2]);
    }

    std::size_t face_number = 0;  // across all shapes, in file order
    std::vector<std::uint32_t> corners;
    std::vector<std::uint32_t> corner_normals;
    for (const tinyobj::shape_t& shape : shapes) {
        std::size_t next_index = 0;
        for (const unsigned int corner_count : shape.mesh.num_face_vertices) {
            corners.clear();
            corner_normals.clear();
            for (unsigned int corner = 0; corner < corner_count; ++corner) {
                const int normal = shape.mesh.indices[next_index].normal_index;
                corner_normals.push_back(normal >= 0 &&
                                                 static_cast<std::size_t>(normal) < normal_count
                                             ? static_cast<std::uint32_t>(normal)
                                             : missing_file_normal);
                const int vertex = shape.mesh.indices[next_index++].vertex_index;
                if (vertex < 0 || static_cast<std::size_t>(vertex) >= vertex_count) {
                    // tinyobjloader only warns, and names the last line.
                    const std::string which = vertex < 0 ? "a vertex before the first one"
                                                         : "vertex " + std::to_string(vertex + 1);
                    throw IoError(name,
                                  "face " + std::to_string(face_number + 1) + " refers to " +
                                      which + ", but the file defines " +
                                      std::to_string(vertex_count) + " vertices",
                                  FileLoc{name, line_of_face(path, face_number), 0});
                }
                corners.push_back(static_cast<std::uint32_t>(vertex));
            }
            // docs/spec.md §2: the polygon (v0, v1, …, vk) becomes the fan (v0, vi, vi+1).
            for (std::size_t i = 1; i + 1 < corners.size(); ++i) {
                mesh.triangles.push_back({corners[0], corners[i], corners[i + 1]});
                mesh.triangle_file_normals.push_back(
                    {corner_normals[0], corner_normals[i], corner_normals[i + 1]});
                mesh.triangle_faces.push_back(static_cast<std::uint32_t>(face_number));
            }
            ++face_number;
        }
    }
    if (mesh.triangles.empty()) throw IoError(name, "the file has no faces");
    return mesh;
}

}  // namespace litkit
