// Mesh file formats by file-name extension: the one table that says which
// reader reads a mesh file (a scene's `type = "mesh"` object). A new format
// is one entry in mesh_formats.cpp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string_view>

#include "litkit/mesh.hpp"

namespace litkit::detail {

struct MeshFormat {
    // The extensions it is chosen by, lower case with the dot (".obj");
    // matched without regard to case.
    std::string_view extension;
    // Reads a file: throws IoError, located where reading stopped, for one
    // that cannot be read or parsed.
    Mesh (*read)(const std::filesystem::path& path);
    // The line of the file where its `face_number`-th face (as
    // Mesh::triangle_faces numbers them) is written, or 0 where that is
    // unknown; for placing errors.
    std::uint32_t (*line_of_face)(const std::filesystem::path& path, std::size_t face_number);
};

// The format of the file at `path`, by its extension; Wavefront OBJ for an
// extension no entry names (or none).
const MeshFormat& mesh_format(const std::filesystem::path& path);

}  // namespace litkit::detail
