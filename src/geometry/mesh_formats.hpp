// SPDX-License-Identifier: MIT
// Mesh file formats: the one table that says which reader reads a mesh
// file (a scene's `type = "mesh"` object), chosen by the file's extension
// or by the object's `format` key. A new format is one entry in
// mesh_formats.cpp and a file of its own (obj.cpp, ply.cpp, stl.cpp,
// gltf.cpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "litkit/mesh.hpp"
#include "litkit/shapes.hpp"

namespace litkit::detail {

struct MeshFormat {
    MeshFileFormat format;
    // The extensions it is chosen by, lower case with the dot (".obj");
    // matched without regard to case.
    std::span<const std::string_view> extensions;
    // Reads a file: throws IoError, located where reading stopped, for one
    // that cannot be read or parsed.
    Mesh (*read)(const std::filesystem::path& path);
    // The line of the file where its `face_number`-th face (as
    // Mesh::triangle_faces numbers them) is written, or 0 where that is
    // unknown (binary files); for placing errors.
    std::uint32_t (*line_of_face)(const std::filesystem::path& path, std::size_t face_number);
    // Where the format keeps the normals that normals = "file" uses, for
    // the error about a face corner without one.
    std::string_view normals_hint;
};

// The format of the file at `path`: `format` where it is given, else by the
// file's extension; Wavefront OBJ for an extension no entry names (or none).
const MeshFormat& mesh_format(const std::filesystem::path& path,
                              std::optional<MeshFileFormat> format = std::nullopt);

// The most triangles one PLY or glTF file may make (a PLY face of 255
// corners makes 253 from 256 bytes; a glTF mesh may be placed by many
// nodes): the scene's default triangle budget (scene.hpp's
// default_triangle_budget, which counts no mesh file's triangles before
// reading it), so that a small file cannot exhaust memory.
inline constexpr std::uint64_t max_mesh_file_triangles = 64'000'000;

// The readers over bytes already read, for the fuzz targets and the tests;
// `name` is the file's name in messages. `face_lines`, when given, receives
// the line of each face of a text file (nothing for a binary one).
Mesh parse_ply(std::string_view bytes, const std::string& name,
               std::vector<std::uint32_t>* face_lines = nullptr);
Mesh parse_stl(std::string_view bytes, const std::string& name,
               std::vector<std::uint32_t>* face_lines = nullptr);
// glTF: `path` names the file (in messages) and its folder, where its
// buffer files are looked for.
Mesh parse_gltf(std::string_view bytes, const std::filesystem::path& path);

std::uint32_t ply_line_of_face(const std::filesystem::path& path, std::size_t face_number);
std::uint32_t stl_line_of_face(const std::filesystem::path& path, std::size_t face_number);

// Throws IoError (EISDIR) for a folder, then reads the file within the
// read limit (core/files.hpp): what every reader starts with.
std::string read_mesh_file(const std::filesystem::path& path);

}  // namespace litkit::detail
