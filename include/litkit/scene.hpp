// SPDX-License-Identifier: MIT
/// \file
/// A scene as docs/spec.md §5 describes it, and its loading from TOML files.
/// Units: lengths in the scene's world units, angles in degrees, material and
/// light colours and the background 0–1 per channel (the scene file's 0–255
/// / 255: from_rgb8).
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "litkit/error.hpp"
#include "litkit/lighting.hpp"
#include "litkit/limits.hpp"
#include "litkit/mesh.hpp"
#include "litkit/samples.hpp"
#include "litkit/shapes.hpp"

namespace litkit {

/// The axis-aligned box centred at the origin that bounds the scene (docs/spec.md §1).
struct Room {
    /// Extent along x (> 0).
    float width = 10.0f;
    /// Extent along y (> 0).
    float height = 10.0f;
    /// Extent along z (> 0).
    float depth = 10.0f;
    /// n_r, in [1, 3]: the refractive index of the medium that fills the room
    /// (docs/spec.md §10.1; 1, the default, is air or vacuum).
    float ior = 1.0f;
};

/// The narrowest field of view allowed, in degrees (docs/reliability.md):
/// below about 1e-7 degrees a float's positions are coarser than the pixels
/// and the picture gets holes; 0.01 keeps a margin of 1000 at the largest image.
inline constexpr float smallest_fov_degrees = 0.01f;

/// The single perspective camera (docs/spec.md §1, AB3). Positions in world
/// coordinates, distances in world units.
struct Observer {
    /// The eye, in world coordinates; inside the room, not inside an object.
    glm::vec3 position{0.0f, 0.0f, 5.0f};
    /// The point at the centre of the picture; not at `position`.
    glm::vec3 look_at{0.0f};
    /// Which way is up in the picture; not parallel to the view direction.
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    /// The vertical field of view in degrees, in [smallest_fov_degrees, 180).
    float fov_degrees = 45.0f;
    /// The near clipping distance (> 0, below far).
    float near = 0.05f;
    /// The far clipping distance (> near).
    float far = 1000.0f;
};

/// The picture: its size, background and gamma (the `[output]` table).
struct OutputSettings {
    /// Width in pixels, 1–max_image_side (16384, litkit/limits.hpp).
    int width = 800;
    /// Height in pixels, 1–max_image_side.
    int height = 600;
    /// The colour of every pixel no object covers, linear 0–1 per channel
    /// like every colour of the API (Rgb8); such a pixel is
    /// to_rgb8(background), without gamma. A scene file's [r, g, b] of 0–255
    /// is from_rgb8 of it, and comes back out unchanged. Beware:
    /// `background = {10, 20, 30}` compiles (as 10.0f, ...); renderers refuse
    /// it ("background must be 0–1 per channel"): write from_rgb8({10, 20, 30}).
    glm::vec3 background{0.0f, 0.0f, 0.0f};
    /// The gamma of docs/spec.md §4.5 (> 0; 1: no correction): a covered
    /// pixel is round(255 · clamp(I, 0, 1)^(1/gamma)) per channel.
    float gamma = 1.0f;
    /// Samples per pixel (docs/spec.md §11, anti-aliasing): 1, 4, 8 or 16
    /// (litkit/samples.hpp). Each sample is shaded as a pixel centre would
    /// be; the pixel is the mean of the samples' clamped intensities, then
    /// gamma. 1 (the default) is one sample at the pixel's centre.
    int samples = 1;
};

/// A cube centred at its origin (make_cube).
struct CubeShape {
    /// Edge length (> 0).
    float size = 1.0f;
};
/// A UV sphere centred at its origin, poles on ±y (make_sphere).
struct SphereShape {
    /// Radius (> 0).
    float radius = 1.0f;
    /// Divisions around y, 3–4096.
    int segments = 64;
    /// Latitude bands from pole to pole, 2–2048.
    int rings = 32;
};
/// A torus in the xz-plane around the y axis (make_torus).
struct TorusShape {
    /// Distance from the centre to the middle of the tube (> 0).
    float major_radius = 1.0f;
    /// Radius of the tube (> 0, below major_radius).
    float minor_radius = 0.25f;
    /// Divisions around y, 3–4096.
    int segments = 64;
    /// Divisions around the tube, 3–4096.
    int sides = 32;
};
/// The Utah teapot, upright on +y (make_teapot).
struct TeapotShape {
    /// Height (> 0).
    float size = 1.0f;
    /// Steps along each edge of a Bézier patch, 1–64.
    int subdivisions = 10;
};
/// A mesh file (load_mesh_file): OBJ, PLY, STL or glTF.
struct MeshFileShape {
    std::filesystem::path file;  ///< already resolved against the scene file's folder
    /// The file's format; nothing: by the file's extension (mesh_file_format).
    std::optional<MeshFileFormat> format = std::nullopt;
};
/// A mesh given in memory, for scenes built in code: positions and triangles
/// (counter-clockwise seen from outside), in the object's local coordinates
/// like a mesh file's. Validated like a mesh file (validate_scene and every
/// renderer, with check_mesh_data): every position finite, every index below
/// positions.size(), at least one triangle; file_normals are not used
/// (normals = "file" needs a mesh file). Held by a shared pointer to const,
/// so that copying a scene (Renderer::update keeps one) does not copy the
/// mesh; build it once:
///
///     litkit::Mesh mesh;  mesh.positions = {...};  mesh.triangles = {...};
///     object.shape = litkit::MeshDataShape(std::move(mesh));
///
/// A scene file cannot hold one: scene_to_toml refuses it (ArgumentError).
struct MeshDataShape {
    /// The mesh, shared and immutable. Null only in a default-constructed
    /// MeshDataShape, which validation refuses ("the MeshDataShape holds no mesh").
    std::shared_ptr<const Mesh> mesh;
    /// No mesh (null): give one before the scene is validated or drawn.
    MeshDataShape() = default;
    /// Takes `data` over (move it in to avoid a copy); it is checked later,
    /// with the scene, not here.
    explicit MeshDataShape(Mesh data) : mesh(std::make_shared<const Mesh>(std::move(data))) {}
};
/// What an object is made of: one of the built-in shapes, a mesh file or a
/// mesh in memory.
using Shape =
    std::variant<CubeShape, SphereShape, TorusShape, TeapotShape, MeshFileShape, MeshDataShape>;

/// The scene-file name of a shape type: "cube", "sphere", "torus", "teapot",
/// "mesh"; "mesh data" for a MeshDataShape (which no scene file holds).
std::string_view shape_type_name(const Shape& shape);

/// A light of the scene with its name.
struct SceneLight {
    std::string name;  ///< may be empty
    /// The light itself.
    Light light;
};

/// An object of the scene: a shape placed in the world, with its material
/// and the models that override the scene's.
struct SceneObject {
    std::string name;  ///< may be empty
    /// What the object is made of before it is placed.
    Shape shape;
    /// Where its local origin goes, in world coordinates.
    glm::vec3 position{0.0f};
    glm::vec3 rotation_degrees{0.0f};  ///< applied x, then y, then z
    /// Uniform scale (> 0).
    float scale = 1.0f;
    /// Its surface.
    Material material;
    std::optional<Reflection> reflection;  ///< overrides Scene::reflection
    std::optional<Shading> shading;        ///< overrides Scene::shading
    /// docs/spec.md §9.2; each overrides its Scene:: namesake.
    std::optional<Normals> normals;
    /// The crease angle in degrees, (0, 180]; overrides Scene::crease_angle_degrees.
    std::optional<float> crease_angle_degrees;
};

class BuiltMeshes;

/// The default of Scene::max_depth (docs/spec.md §10.1).
inline constexpr int default_max_depth = 8;
/// The smallest Scene::max_depth allowed: the first hit alone.
inline constexpr int min_max_depth = 1;
/// The largest Scene::max_depth allowed.
inline constexpr int max_max_depth = 16;

/// A whole scene, as loaded (load_scene, parse_scene) or built in code. A
/// renderer draws it only after validate_scene finds no error.
struct Scene {
    /// The box that bounds everything.
    Room room;
    /// The camera.
    Observer observer;
    /// The picture's size, background and gamma.
    OutputSettings output;
    /// From [lighting]; missing means "not given" (R11: the caller decides
    /// whether the defaults apply).
    std::optional<Reflection> reflection;
    /// From [lighting], as `reflection`.
    std::optional<Shading> shading;
    /// docs/spec.md §9.2, for every object; not given means mean and no crease.
    std::optional<Normals> normals;
    /// The crease angle in degrees, (0, 180], for every object; not given: no crease.
    std::optional<float> crease_angle_degrees;
    /// docs/spec.md §10.2 item 9: the most surface interactions along one
    /// ray path, the first hit included, min_max_depth–max_max_depth
    /// (`[lighting] max_depth`, `--max-depth`). Matters only where some
    /// object's transmission is above 0.
    int max_depth = default_max_depth;
    /// The lights, in file order.
    std::vector<SceneLight> lights;
    /// The objects, in file order.
    std::vector<SceneObject> objects;

    /// Where each value came from, keyed by its path in the scene
    /// ("observer.position", "lights[0].position", "objects[2]"), so that
    /// later checks can point at the offending value.
    std::map<std::string, FileLoc, std::less<>> locations;
    /// The place of the value at `path` (as in `locations`); an empty FileLoc
    /// when the value was not read from a file.
    FileLoc location_of(std::string_view path) const;

    /// Problems that do not stop rendering but are surely unintended (no
    /// lights, an object outside the view), found while loading.
    std::vector<Diagnostic> warnings;

    /// The meshes of built-in shapes that validating this scene built, kept
    /// for its renderers to take instead of building them again (each is
    /// taken once; the last four built are kept). load_scene and
    /// parse_scene set it, and validate_scene and every renderer use it
    /// when it is set; copies of the scene share it. Null for a scene built
    /// in code: then every renderer builds its meshes itself. Set it to null
    /// to free what was not taken.
    std::shared_ptr<BuiltMeshes> built_meshes;
};

/// The default reflection model of R10: Phong.
inline constexpr Reflection default_reflection = Reflection::Phong;
/// The default shading model of R10: Phong.
inline constexpr Shading default_shading = Shading::Phong;

/// Reads and merges scene files (docs/spec.md §5): `lights` and `objects` arrays are
/// concatenated in the order given; every other table may appear in one file
/// only. Throws IoError for a file that cannot be read (missing, not UTF-8,
/// not TOML) and SceneError listing every problem found in the input.
Scene load_scene(std::span<const std::filesystem::path> files);

/// The scene-wide triangle budget (docs/reliability.md): the objects' shapes
/// may need at most this many triangles together, counted from their
/// parameters before any mesh is built (about 3.5 GB to render on the CPU, so
/// that the 24 GiB machines litkit is tested on never run out of memory).
inline constexpr std::uint64_t default_triangle_budget = 64'000'000;

/// Limits that load_scene applies.
struct LoadOptions {
    /// The most triangles the objects may make together (SceneError beyond).
    std::uint64_t max_triangles = default_triangle_budget;
};
/// load_scene with limits other than the defaults.
Scene load_scene(std::span<const std::filesystem::path> files, const LoadOptions& options);

/// Parses one scene from text. `source_name` is used in messages and its
/// folder resolves relative mesh paths. Throws as load_scene does.
Scene parse_scene(std::string_view toml_text, const std::filesystem::path& source_name);

/// The scene as one TOML file that `load_scene` reads back as the same scene
/// (every value, colours as their 0-255 integers, every key written out).
/// Mesh paths are written relative to the folder of `written_as` where they
/// can be, else absolute. Comments of the original files are not kept.
/// Throws ArgumentError for an object with a MeshDataShape: a scene file
/// names its meshes by file, so write the mesh as an OBJ file (mesh_to_obj)
/// and use a MeshFileShape.
std::string scene_to_toml(const Scene& scene, const std::filesystem::path& written_as = {});

/// The built-in default scene of docs/spec.md §7 (R12): one cube, one point light at
/// the centre of the room, Phong shading, Phong reflection. As TOML text,
/// with comments (what `litkit init` writes and the playground starts
/// with); its comments list every reflection model, shading model, normals
/// weighting and light type, taken from the library's lists.
std::string_view default_scene_toml();
/// The built-in default scene, loaded.
Scene default_scene();

/// True when the two objects have the same mesh in the same place: the same
/// shape with the same parameters, position, rotation and scale (what a
/// renderer's update can keep). Two MeshDataShapes are the same when they
/// share one Mesh or hold equal positions and triangles.
bool same_geometry(const SceneObject& a, const SceneObject& b);

/// world = T(position) · Rz · Ry · Rx · S(scale) (docs/spec.md §2).
glm::mat4 object_to_world(const SceneObject& object);

/// The object's mesh in local coordinates (builds the shape, reads the file
/// or copies the in-memory mesh's positions and triangles). Throws as
/// load_obj does for a mesh file, and ArgumentError for a MeshDataShape that
/// holds no mesh or one that check_mesh_data refuses.
Mesh object_mesh(const SceneObject& object);

/// An object's triangles in world space, as every backend draws them:
/// positions placed by object_to_world, and DD9 vertex normals (found in local
/// coordinates, where docs/spec.md §2 welds positions, then rotated: the scale is
/// uniform and positive, so that is the same direction).
struct WorldMesh {
    /// The vertices, in world coordinates.
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;  ///< unit, or zero where no triangle counts
    /// Three indices into `positions` per triangle, counter-clockwise seen from outside.
    std::vector<std::array<std::uint32_t, 3>> triangles;
};
/// The object in world space with DD9 (mean) normals.
WorldMesh world_mesh(const SceneObject& object);

/// How an object's vertex normals are found (docs/spec.md §9.2).
struct NormalOptions {
    /// The weighting, or the file's own normals.
    Normals normals = Normals::Mean;
    std::optional<float> crease_angle_degrees;  ///< absent or 180: nothing splits
    /// Equal when both fields are.
    bool operator==(const NormalOptions&) const = default;
};

/// The object's own `normals` and `crease_angle`, else the scene's; "file"
/// from the scene applies to mesh objects only, the others use mean.
NormalOptions normal_options(const Scene& scene, const SceneObject& object);

/// world_mesh with the normals of docs/spec.md §9.2. Where normals differ per
/// corner (a crease, or a mesh file's normals), a position appears once per
/// distinct normal at it, so every backend gets per-corner normals as plain
/// vertices. Throws SceneError, located at the face's line in the mesh file,
/// for "file" normals on a mesh that lacks a normal at some face corner, and
/// ArgumentError for "file" normals on an object that is not a mesh file.
WorldMesh world_mesh(const SceneObject& object, const NormalOptions& options);

}  // namespace litkit
