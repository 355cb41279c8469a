// SPDX-License-Identifier: MIT
#include "geometry/mesh_formats.hpp"

#include <array>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <string>

#include "core/files.hpp"
#include "litkit/error.hpp"
#include "litkit/shapes.hpp"

namespace litkit {

namespace detail {

namespace {

std::uint32_t no_lines(const std::filesystem::path&, std::size_t) { return 0; }

constexpr std::array<std::string_view, 1> obj_extensions{".obj"};
constexpr std::array<std::string_view, 1> ply_extensions{".ply"};
constexpr std::array<std::string_view, 1> stl_extensions{".stl"};
constexpr std::array<std::string_view, 2> gltf_extensions{".gltf", ".glb"};

// In MeshFileFormat's order; the first is also the format of a file whose
// extension none names.
constexpr std::array formats = {
    MeshFormat{MeshFileFormat::Obj, obj_extensions, load_obj, line_of_face, "v/vt/vn or v//vn"},
    MeshFormat{MeshFileFormat::Ply, ply_extensions, load_ply, ply_line_of_face,
               "the vertex element's nx, ny, nz"},
    MeshFormat{MeshFileFormat::Stl, stl_extensions, load_stl, stl_line_of_face,
               "STL files give none: their facet normals are not read"},
    MeshFormat{MeshFileFormat::Gltf, gltf_extensions, load_gltf, no_lines,
               "the primitive's NORMAL attribute"},
};
static_assert(formats.size() == mesh_file_format_names.size());

bool same_extension(std::string_view written, std::string_view lower_case) {
    if (written.size() != lower_case.size()) return false;
    for (std::size_t i = 0; i < written.size(); ++i) {
        if (std::tolower(static_cast<unsigned char>(written[i])) != lower_case[i]) return false;
    }
    return true;
}

}  // namespace

const MeshFormat& mesh_format(const std::filesystem::path& path,
                              std::optional<MeshFileFormat> format) {
    if (format) return formats[static_cast<std::size_t>(*format)];
    const std::string extension = path.extension().string();
    for (const MeshFormat& entry : formats) {
        for (const std::string_view written : entry.extensions)
            if (same_extension(extension, written)) return entry;
    }
    return formats.front();
}

std::string read_mesh_file(const std::filesystem::path& path) {
    std::error_code status_error;
    if (std::filesystem::is_directory(path, status_error))
        throw IoError(path.string(), std::strerror(EISDIR));
    return read_file_limited(path);
}

}  // namespace detail

std::string_view to_string(MeshFileFormat format) {
    return mesh_file_format_names[static_cast<std::size_t>(format)];
}

std::optional<MeshFileFormat> parse_mesh_file_format(std::string_view text) {
    for (std::size_t i = 0; i < mesh_file_format_names.size(); ++i)
        if (text == mesh_file_format_names[i]) return static_cast<MeshFileFormat>(i);
    return std::nullopt;
}

MeshFileFormat mesh_file_format(const std::filesystem::path& path) {
    return detail::mesh_format(path).format;
}

Mesh load_mesh_file(const std::filesystem::path& path, std::optional<MeshFileFormat> format) {
    return detail::mesh_format(path, format).read(path);
}

Mesh load_ply(const std::filesystem::path& path) {
    return detail::parse_ply(detail::read_mesh_file(path), path.string());
}

Mesh load_stl(const std::filesystem::path& path) {
    return detail::parse_stl(detail::read_mesh_file(path), path.string());
}

Mesh load_gltf(const std::filesystem::path& path) {
    return detail::parse_gltf(detail::read_mesh_file(path), path);
}

namespace detail {

std::uint32_t ply_line_of_face(const std::filesystem::path& path, std::size_t face_number) {
    std::vector<std::uint32_t> lines;
    try {
        parse_ply(read_mesh_file(path), path.string(), &lines);
    } catch (const Error&) {
        return 0;
    }
    return face_number < lines.size() ? lines[face_number] : 0;
}

std::uint32_t stl_line_of_face(const std::filesystem::path& path, std::size_t face_number) {
    std::vector<std::uint32_t> lines;
    try {
        parse_stl(read_mesh_file(path), path.string(), &lines);
    } catch (const Error&) {
        return 0;
    }
    return face_number < lines.size() ? lines[face_number] : 0;
}

}  // namespace detail

}  // namespace litkit
