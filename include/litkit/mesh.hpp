// SPDX-License-Identifier: MIT
/// \file
/// Triangle meshes (AB4) and their normals (docs/spec.md §2, DD8, DD9).
#pragma once

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace litkit {

/// An indexed triangle mesh. Triangles wind counter-clockwise seen from
/// outside. Positions that coincide may appear more than once (a sphere's
/// seam, a cube's face corners); normals treat them as one vertex.
struct Mesh {
    /// The vertices, in the mesh's own (local) coordinates.
    std::vector<glm::vec3> positions;
    /// Three indices into `positions` per triangle, counter-clockwise seen from outside.
    std::vector<std::array<std::uint32_t, 3>> triangles;

    /// The normals a mesh file gives (OBJ `vn`), for normals = "file"
    /// (docs/spec.md §9.2); empty for built-in shapes.
    std::vector<glm::vec3> file_normals;
    /// For each triangle, the index into file_normals of each corner's normal
    /// (missing_file_normal where the face gave none); empty for built-in shapes.
    std::vector<std::array<std::uint32_t, 3>> triangle_file_normals;
    /// For each triangle, the number of the file's face (0-based, in file
    /// order) that it came from; empty for built-in shapes.
    std::vector<std::uint32_t> triangle_faces;
};
/// The index Mesh::triangle_file_normals holds for a corner without a file normal.
inline constexpr std::uint32_t missing_file_normal = 0xffffffffu;

/// docs/spec.md §9.2: how a vertex normal weights the faces that share the
/// vertex, or the mesh file's own normals. The mean is Gouraud's (1971); the
/// angle weights are G. Thürmer and C. A. Wüthrich's, "Computing Vertex
/// Normals from Polygonal Facets", Journal of Graphics Tools 3(1), 1998;
/// "max" is N. Max's, "Weights for Computing Vertex Normals from Facet
/// Normals", Journal of Graphics Tools 4(2), 1999.
enum class Normals {
    Mean,   ///< "mean": each face's unit normal counts once (DD9, the default).
    Area,   ///< "area": weighted by the face's area (e1 × e2).
    Angle,  ///< "angle": weighted by the face's angle at the vertex.
    Max,    ///< "max": Max's weighting, e1 × e2 over the product of the edges' squared lengths.
    File    ///< "file": the mesh file's own `vn` normals.
};
/// How many Normals values there are.
inline constexpr int normals_count = static_cast<int>(Normals::File) + 1;
/// The weightings' scene-file names, in the enumeration's order: the one list
/// that the scene reader's "did you mean", the command line, the Python
/// binding and the docs' tables (checked by tests/test_spec.cpp) take.
inline constexpr std::array<std::string_view, normals_count> normals_names{"mean", "area", "angle",
                                                                           "max", "file"};
/// Scene-file spelling: the weighting's name in normals_names.
std::string_view to_string(Normals normals);
/// The weighting a scene-file spelling names (exact, lower case), or nothing.
std::optional<Normals> parse_normals(std::string_view text);

/// DD8: normalize((b − a) × (c − a)); the zero vector for a zero-area triangle.
glm::vec3 face_normal(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c);

/// DD9: for each entry of mesh.positions, the normalised plain mean of the face
/// normals of every triangle touching that position, where positions within
/// 1e-6 × the bounding-box diagonal count as one (transitively: a chain of such
/// positions is one vertex). Zero-area triangles take no part, nor do
/// triangles two of whose corners count as one. A position touched by no
/// usable triangle gets the zero vector. O(n log n); throws ArgumentError
/// for a triangle index beyond the positions (or more positions than 32-bit
/// indices reach).
std::vector<glm::vec3> vertex_normals(const Mesh& mesh);

/// docs/spec.md §9.2: vertex normals with each usable triangle f at vertex v
/// weighted as `weighting` says (e1, e2: f's edges leaving v in winding
/// order, n̂_f its DD8 normal): Mean n̂_f (exactly vertex_normals(mesh)),
/// Area e1 × e2, Angle θ_f·n̂_f with θ_f = atan2(‖e1 × e2‖, e1·e2), Max
/// (e1 × e2)/(‖e1‖²·‖e2‖²). Welding and zero-area rules as vertex_normals;
/// a triangle with a zero-length edge takes no part. File is not a
/// weighting: it throws ArgumentError (as for a triangle index beyond the
/// positions).
std::vector<glm::vec3> vertex_normals(const Mesh& mesh, Normals weighting);

/// docs/spec.md §9.2 crease: the normal of each triangle corner (entry
/// 3·t + k for corner k of triangle t), summing with `weighting` only the
/// triangles g at the corner's vertex whose unit normals satisfy
/// n̂_f·n̂_g > cos(crease_angle_degrees), f itself always. A corner whose
/// every neighbour counts gets exactly its vertex normal. Unusable triangles
/// get the zero vector. Throws ArgumentError for File, an angle outside
/// (0, 180] or a triangle index beyond the positions.
std::vector<glm::vec3> corner_normals(const Mesh& mesh, Normals weighting,
                                      float crease_angle_degrees);

/// What is wrong with a mesh given in memory (scene.hpp's MeshDataShape),
/// checked as load_obj checks a file: no triangles, a position that is not
/// finite, or a triangle index beyond the positions. One message, for the
/// first problem found; empty when the mesh is usable. Never throws;
/// O(positions + triangles).
std::string check_mesh_data(const Mesh& mesh);

/// The mesh as Wavefront OBJ text (`v` lines, then `f` lines, 1-based), which
/// load_obj reads back as the same positions and triangles (each float
/// written with enough digits to round-trip). Normals are not written.
std::string mesh_to_obj(const Mesh& mesh);

/// Signed volume enclosed by the triangles, (1/6) Σ a · (b × c) over the
/// triangles (a, b, c), in double precision, in cubic units of the mesh's
/// coordinates: positive for a closed mesh wound counter-clockwise seen from
/// outside, negative for one turned inside out (its faces wind clockwise).
/// Meaningful for closed meshes only (is_closed). Every index must be below
/// positions.size() (check_mesh_data): they are not checked here.
double signed_volume(const Mesh& mesh);

/// True when every edge of the mesh is shared by exactly two triangles that
/// traverse it in opposite directions (positions compared by index after
/// welding exactly equal coordinates): a closed, consistently wound surface,
/// for which signed_volume gives the inside's volume. False for a mesh
/// without triangles or with a degenerate edge. Every index must be below
/// positions.size() (check_mesh_data): they are not checked here.
bool is_closed(const Mesh& mesh);

/// Axis-aligned bounding box of a mesh's positions (both corners zero for a
/// mesh without positions).
struct Bounds {
    /// The smallest x, y and z.
    glm::vec3 min{0.0f};
    /// The largest x, y and z.
    glm::vec3 max{0.0f};
};
/// The axis-aligned bounding box of `mesh.positions`.
Bounds bounds(const Mesh& mesh);

}  // namespace litkit
