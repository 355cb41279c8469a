/// \file
/// Built-in shapes and mesh files (docs/spec.md §2), in local coordinates. Built-in
/// meshes are closed where the shape is and wind counter-clockwise seen from
/// outside. The make_ functions throw ArgumentError for arguments out
/// of range (sizes not positive, segments or sides below 3, rings below 2,
/// subdivisions below 1, a torus's minor radius not below its major radius).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>

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

}  // namespace litkit
