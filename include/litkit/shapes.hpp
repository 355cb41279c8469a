// SPDX-License-Identifier: MIT
/// \file
/// Built-in shapes and mesh files (docs/spec.md §2), in local coordinates. Built-in
/// meshes are closed where the shape is and wind counter-clockwise seen from
/// outside. The make_ functions throw ArgumentError for arguments out
/// of range (sizes not positive, segments or sides below 3, rings below 2,
/// subdivisions below 1, a torus's minor radius not below its major radius).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string_view>

#include "litkit/mesh.hpp"

namespace litkit {

/// A cube of edge `size`, corners (±s/2, ±s/2, ±s/2). Each face's diagonal is chosen so
/// that every corner touches the same number of triangles on each of its three
/// faces: its DD9 normal is then exactly normalize(±1, ±1, ±1).
Mesh make_cube(float size);

/// UV sphere, poles on ±y: `segments` divisions around y, `rings` latitude
/// bands from pole to pole.
Mesh make_sphere(float radius, int segments, int rings);

/// Torus: a ring in the xz-plane around the y axis: `segments` divisions around y,
/// `sides` divisions around the tube.
Mesh make_torus(float major_radius, float minor_radius, int segments, int sides);

/// The Utah teapot (Newell's 32 bicubic Bézier patches), upright on +y, height
/// `size`, centred on its bounding box; `subdivisions` steps along each edge
/// of a patch.
Mesh make_teapot(float size, int subdivisions);

/// A Wavefront OBJ file, coordinates as they are. A polygon (v0, v1, …, vk)
/// becomes the fan (v0, vi, vi+1). Throws IoError if the file cannot be read
/// or parsed, has no faces, or a face refers to a vertex it does not define,
/// with the line where parsing stopped when known.
/// Also keeps the file's `vn` normals (Mesh::file_normals) for docs/spec.md
/// §9.2; a corner without one, or with an index beyond them, has
/// missing_file_normal.
Mesh load_obj(const std::filesystem::path& path);

/// The line of an OBJ file's `face_number`-th face (0-based, in file order,
/// as Mesh::triangle_faces numbers them), or 0 if the file cannot be read
/// again. For placing errors.
std::uint32_t line_of_face(const std::filesystem::path& path, std::size_t face_number);

/// The mesh file formats (docs/scene-format.md, "Mesh files"): Wavefront
/// OBJ, PLY (ASCII and binary), STL (ASCII and binary) and glTF 2.0 (.gltf
/// and .glb).
enum class MeshFileFormat {
    Obj,  ///< "obj": load_obj
    Ply,  ///< "ply": load_ply
    Stl,  ///< "stl": load_stl
    Gltf  ///< "gltf": load_gltf, for .gltf and .glb alike
};
/// The formats' scene-file names (an object's `format` key), in the
/// enumeration's order.
inline constexpr std::array<std::string_view, 4> mesh_file_format_names{"obj", "ply", "stl",
                                                                        "gltf"};
/// Scene-file spelling: the format's name in mesh_file_format_names.
std::string_view to_string(MeshFileFormat format);
/// The format a scene-file spelling names (exact, lower case), or nothing.
std::optional<MeshFileFormat> parse_mesh_file_format(std::string_view text);
/// The format of a file by its extension, without regard to case: .obj,
/// .ply, .stl, .gltf and .glb; OBJ for any other extension, or none.
MeshFileFormat mesh_file_format(const std::filesystem::path& path);
/// Reads a mesh file in `format`, or in the format its extension names.
/// Throws IoError as the format's reader does.
Mesh load_mesh_file(const std::filesystem::path& path,
                    std::optional<MeshFileFormat> format = std::nullopt);

/// A PLY file (ASCII, binary little or big endian): the `vertex` element's
/// x, y, z (and nx, ny, nz when all three are there, for normals = "file"),
/// the `face` element's `vertex_indices` (or `vertex_index`) lists, each a
/// polygon made a fan as OBJ's are. Other elements and properties are read
/// past. Throws IoError, located at line:column (ASCII) or with the byte
/// (binary), for a file that cannot be read, a header it does not
/// understand, counts the data do not hold, a coordinate that is not finite,
/// an index beyond the vertices, or no faces.
Mesh load_ply(const std::filesystem::path& path);

/// An STL file, ASCII or binary (binary when its size is that of the
/// triangle count at byte 80, else ASCII when it starts with "solid"): each
/// facet a triangle, its three corners positions of their own; the facet
/// normals are not read. Throws IoError as load_ply does.
Mesh load_stl(const std::filesystem::path& path);

/// A glTF 2.0 file (.gltf, with buffers in data: URIs or in files beside it,
/// or .glb): every triangle primitive (triangles, strips, fans) of every
/// mesh of the default scene (else the first), placed by its nodes'
/// matrices or translation, rotation and scale, as one mesh; the NORMAL
/// attribute (for normals = "file"). Images, materials and animations are
/// not read. Throws IoError naming the place in the file
/// ("meshes[0].primitives[1].indices: ...") for a file that cannot be read,
/// a buffer outside the file's folder, an accessor beyond its data, a
/// coordinate that is not finite, an index beyond the vertices, or no
/// triangles.
Mesh load_gltf(const std::filesystem::path& path);

}  // namespace litkit
