// SPDX-License-Identifier: MIT
// A Scene's objects placed in the world (docs/spec.md §2): their transforms, meshes and
// world-space vertices and normals, as every backend draws them; the meshes
// validation built, kept for the renderers (BuiltMeshes).
#include "litkit/scene.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat3x3.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "core/portable_math.hpp"
#include "geometry/creased_normals.hpp"
#include "geometry/mesh_formats.hpp"
#include "litkit/shapes.hpp"
#include "scene/validate_internal.hpp"
#include "scene/world_mesh.hpp"

namespace litkit {

std::string_view shape_type_name(const Shape& shape) {
    struct Name {
        std::string_view operator()(const CubeShape&) const { return "cube"; }
        std::string_view operator()(const SphereShape&) const { return "sphere"; }
        std::string_view operator()(const TorusShape&) const { return "torus"; }
        std::string_view operator()(const TeapotShape&) const { return "teapot"; }
        std::string_view operator()(const MeshFileShape&) const { return "mesh"; }
        std::string_view operator()(const MeshDataShape&) const { return "mesh data"; }
    };
    return std::visit(Name{}, shape);
}

FileLoc Scene::location_of(std::string_view path) const {
    auto found = locations.find(path);
    return found == locations.end() ? FileLoc{} : found->second;
}

namespace {

// The same shape with the same parameters (a mesh in memory: the same one,
// or equal positions and triangles).
bool same_shape(const Shape& a, const Shape& b) {
    if (a.index() != b.index()) return false;
    return std::visit(
        [&](const auto& shape) {
            using S = std::decay_t<decltype(shape)>;
            const S& other = std::get<S>(b);
            if constexpr (std::is_same_v<S, CubeShape>)
                return shape.size == other.size;
            else if constexpr (std::is_same_v<S, SphereShape>)
                return shape.radius == other.radius && shape.segments == other.segments &&
                       shape.rings == other.rings;
            else if constexpr (std::is_same_v<S, TorusShape>)
                return shape.major_radius == other.major_radius &&
                       shape.minor_radius == other.minor_radius &&
                       shape.segments == other.segments && shape.sides == other.sides;
            else if constexpr (std::is_same_v<S, TeapotShape>)
                return shape.size == other.size && shape.subdivisions == other.subdivisions;
            else if constexpr (std::is_same_v<S, MeshFileShape>)
                return shape.file == other.file;
            else
                return shape.mesh == other.mesh ||
                       (shape.mesh && other.mesh &&
                        shape.mesh->positions == other.mesh->positions &&
                        shape.mesh->triangles == other.mesh->triangles);
        },
        a);
}

}  // namespace

bool same_geometry(const SceneObject& a, const SceneObject& b) {
    if (a.position != b.position || a.rotation_degrees != b.rotation_degrees || a.scale != b.scale)
        return false;
    return same_shape(a.shape, b.shape);
}

glm::mat4 object_to_world(const SceneObject& object) {
    // docs/spec.md §2: world = T(position) · Rz · Ry · Rx · S(scale); each glm call
    // multiplies on the right, so the calls read in the formula's order.
    // Each rotation's sine and cosine from the angle in degrees, in double,
    // rounded once to float (core/portable_math.hpp): the same bits in every
    // build, exact for whole turns (10000° is 280°) and right angles.
    const auto rotation = [](float degrees, int axis) {
        const SineCosine angle = sin_cos_degrees(degrees);
        const auto s = static_cast<float>(angle.sine), c = static_cast<float>(angle.cosine);
        const int next = (axis + 1) % 3, after = (axis + 2) % 3;  // right-handed: x→y→z→x
        glm::mat4 turn(1.0f);                                     // column-major: turn[column][row]
        turn[next][next] = c;
        turn[next][after] = s;
        turn[after][next] = -s;
        turn[after][after] = c;
        return turn;
    };
    glm::mat4 transform = glm::translate(glm::mat4(1.0f), object.position);
    transform = transform * rotation(object.rotation_degrees.z, 2);
    transform = transform * rotation(object.rotation_degrees.y, 1);
    transform = transform * rotation(object.rotation_degrees.x, 0);
    return glm::scale(transform, glm::vec3(object.scale));
}

Mesh object_mesh(const SceneObject& object) {
    struct Build {
        Mesh operator()(const CubeShape& cube) const { return make_cube(cube.size); }
        Mesh operator()(const SphereShape& sphere) const {
            return make_sphere(sphere.radius, sphere.segments, sphere.rings);
        }
        Mesh operator()(const TorusShape& torus) const {
            return make_torus(torus.major_radius, torus.minor_radius, torus.segments, torus.sides);
        }
        Mesh operator()(const TeapotShape& teapot) const {
            return make_teapot(teapot.size, teapot.subdivisions);
        }
        Mesh operator()(const MeshFileShape& mesh) const {
            return detail::mesh_format(mesh.file, mesh.format).read(mesh.file);
        }
        Mesh operator()(const MeshDataShape& data) const {
            if (!data.mesh) throw ArgumentError("an in-memory mesh (MeshDataShape) holds no mesh");
            if (std::string problem = check_mesh_data(*data.mesh); !problem.empty())
                throw ArgumentError("in-memory mesh: " + problem);
            Mesh mesh;
            mesh.positions = data.mesh->positions;
            mesh.triangles = data.mesh->triangles;
            return mesh;
        }
    };
    return std::visit(Build{}, object.shape);
}

void BuiltMeshes::keep(const Shape& shape, Mesh mesh) {
    if (std::holds_alternative<MeshFileShape>(shape) ||
        std::holds_alternative<MeshDataShape>(shape))
        return;
    const std::lock_guard lock(mutex_);
    entries_.emplace_front(shape, std::move(mesh));
    if (entries_.size() > capacity) entries_.pop_back();
}

std::optional<Mesh> BuiltMeshes::take(const Shape& shape) {
    const std::lock_guard lock(mutex_);
    for (auto entry = entries_.begin(); entry != entries_.end(); ++entry) {
        if (!same_shape(entry->first, shape)) continue;
        Mesh mesh = std::move(entry->second);
        entries_.erase(entry);
        return mesh;
    }
    return std::nullopt;
}

Mesh object_mesh(const SceneObject& object, BuiltMeshes* built) {
    if (built) {
        if (std::optional<Mesh> kept = built->take(object.shape)) return std::move(*kept);
    }
    return object_mesh(object);
}

namespace {

// docs/spec.md §9.2: a position once per distinct normal at it. A position's
// first normal keeps the position's own index, so that where nothing splits
// (a sphere under a crease) the mesh is exactly the unsplit one.
class CornerSplitter {
  public:
    // `normals` has one entry per position of `mesh` and grows with it.
    CornerSplitter(Mesh& mesh, std::vector<glm::vec3>& normals)
        : mesh_(mesh),
          normals_(normals),
          assigned_(mesh.positions.size(), false),
          next_copy_(mesh.positions.size(), none) {}

    // Points `corner` (an index into the positions) at a position with `normal`.
    void assign(std::uint32_t& corner, const glm::vec3& normal) {
        if (!assigned_[corner]) {
            assigned_[corner] = true;
            normals_[corner] = normal;
            return;
        }
        std::uint32_t copy = corner;
        std::uint32_t last = corner;
        while (copy != none && normals_[copy] != normal) {
            last = copy;
            copy = next_copy_[copy];
        }
        if (copy == none) {
            copy = static_cast<std::uint32_t>(mesh_.positions.size());
            mesh_.positions.push_back(mesh_.positions[corner]);
            normals_.push_back(normal);
            next_copy_.push_back(none);
            next_copy_[last] = copy;
        }
        corner = copy;
    }

  private:
    static constexpr std::uint32_t none = 0xffffffffu;
    Mesh& mesh_;
    std::vector<glm::vec3>& normals_;
    std::vector<bool> assigned_;
    std::vector<std::uint32_t> next_copy_;  // more copies of a position
};

void split_by_corner_normals(Mesh& mesh, const std::vector<glm::vec3>& normals_of_corners,
                             std::vector<glm::vec3>& normals) {
    normals.assign(mesh.positions.size(), glm::vec3(0.0f));
    CornerSplitter splitter(mesh, normals);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k)
            splitter.assign(mesh.triangles[t][k], normals_of_corners[3 * t + k]);
}

// split_by_corner_normals for crease normals, touching only the corners at
// vertices where faces may part: every other position keeps its index and
// its vertex normal, as split_by_corner_normals would keep them, so the
// result is the same mesh (docs/performance.md: a sphere under a crease
// costs one pass more than without).
void split_at_creases(Mesh& mesh, const CreasedNormals& creased, std::vector<glm::vec3>& normals) {
    normals.assign(mesh.positions.size(), glm::vec3(0.0f));
    if (creased.split_corners.empty()) {
        // No vertex may split (creased_normals lists a corner of each that
        // may): every used position takes its vertex's normal, and no
        // splitter (two arrays over the positions) is needed.
        const std::uint32_t* vertex_of = creased.vertex_of_position.data();
        const glm::vec3* vertex_normal = creased.vertex_normals.data();
        glm::vec3* out = normals.data();
        for (const auto& triangle : mesh.triangles)  // positions no triangle uses stay zero
            for (const std::uint32_t corner : triangle)
                out[corner] = vertex_normal[vertex_of[corner]];
        return;
    }
    for (const auto& triangle : mesh.triangles)  // positions no triangle uses stay zero
        for (const std::uint32_t corner : triangle)
            if (!creased.position_may_split(corner))
                normals[corner] = creased.position_normal(corner);
    CornerSplitter splitter(mesh, normals);
    for (std::size_t at = 0; at < creased.split_corners.size(); ++at) {
        const std::uint32_t corner = creased.split_corners[at];
        splitter.assign(mesh.triangles[corner / 3][corner % 3], creased.split_normals[at]);
    }
}

// docs/spec.md §9.2 "file": each corner's normal as the mesh file gives it.
std::vector<glm::vec3> file_corner_normals(const Mesh& mesh, const SceneObject& object) {
    const auto* file = std::get_if<MeshFileShape>(&object.shape);
    if (!file || mesh.triangle_file_normals.size() != mesh.triangles.size()) {
        throw ArgumentError("world_mesh: normals = \"file\" needs a mesh object");
    }
    std::vector<glm::vec3> normals(mesh.triangles.size() * 3);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t index = mesh.triangle_file_normals[t][k];
            if (index == missing_file_normal) {
                throw SceneError({missing_file_normal_error(*file, mesh, t)});
            }
            normals[3 * t + k] = mesh.file_normals[index];
        }
    }
    return normals;
}

}  // namespace

Diagnostic missing_file_normal_error(const MeshFileShape& file, const Mesh& mesh,
                                     std::size_t triangle) {
    const std::uint32_t face = mesh.triangle_faces[triangle];
    const detail::MeshFormat& format = detail::mesh_format(file.file, file.format);
    const std::uint32_t line = format.line_of_face(file.file, face);
    return Diagnostic{FileLoc{file.file.string(), line, 0}, Severity::Error,
                      "face " + std::to_string(face + 1) + " has a corner without a normal (" +
                          std::string(format.normals_hint) + "), which normals = \"file\" needs"};
}

std::optional<Diagnostic> check_file_normals(const MeshFileShape& file, const Mesh& mesh) {
    for (std::size_t t = 0; t < mesh.triangle_file_normals.size(); ++t) {
        for (const std::uint32_t normal : mesh.triangle_file_normals[t]) {
            if (normal == missing_file_normal) return missing_file_normal_error(file, mesh, t);
        }
    }
    return std::nullopt;
}

NormalOptions normal_options(const Scene& scene, const SceneObject& object) {
    NormalOptions options;
    if (object.normals) {
        options.normals = *object.normals;
    } else if (scene.normals) {
        const bool from_file = std::holds_alternative<MeshFileShape>(object.shape);
        options.normals =
            *scene.normals == Normals::File && !from_file ? Normals::Mean : *scene.normals;
    }
    options.crease_angle_degrees =
        object.crease_angle_degrees ? object.crease_angle_degrees : scene.crease_angle_degrees;
    return options;
}

WorldMesh world_mesh(const SceneObject& object) { return world_mesh(object, NormalOptions{}); }

WorldMesh world_mesh(const SceneObject& object, const NormalOptions& options) {
    return world_mesh(object, options, ParallelFor{});
}

WorldMesh world_mesh(const SceneObject& object, const NormalOptions& options,
                     const ParallelFor& parallel, BuiltMeshes* built) {
    Mesh mesh = object_mesh(object, built);
    std::vector<glm::vec3> local_normals;
    const bool creased = options.crease_angle_degrees && *options.crease_angle_degrees < 180.0f;
    if (options.normals == Normals::File) {
        // docs/spec.md §9.2: with the file's normals the crease angle is ignored.
        split_by_corner_normals(mesh, file_corner_normals(mesh, object), local_normals);
    } else if (creased) {
        split_at_creases(mesh,
                         creased_normals(mesh, options.normals, *options.crease_angle_degrees),
                         local_normals);
    } else {
        local_normals = vertex_normals(mesh, options.normals, parallel);
    }
    const glm::mat4 model = object_to_world(object);
    const glm::mat3 rotation = glm::mat3(model) * (1.0f / object.scale);

    WorldMesh world;
    world.positions.resize(mesh.positions.size());
    world.normals.resize(mesh.positions.size());
    parallel_chunks(parallel, mesh.positions.size(), 16384, [&](std::size_t i) {
        world.positions[i] = glm::vec3(model * glm::vec4(mesh.positions[i], 1.0f));
        const glm::vec3 n = rotation * local_normals[i];
        const float length = glm::length(n);
        world.normals[i] = length > 0.0f ? n / length : n;
    });
    world.triangles = std::move(mesh.triangles);
    return world;
}

}  // namespace litkit
