// A Scene's objects placed in the world (docs/spec.md §2): their transforms, meshes and
// world-space vertices and normals, as every backend draws them.
#include "litkit/scene.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat3x3.hpp>

#include <type_traits>
#include <variant>

#include "litkit/shapes.hpp"

namespace litkit {

std::string_view shape_type_name(const Shape& shape) {
    struct Name {
        std::string_view operator()(const CubeShape&) const { return "cube"; }
        std::string_view operator()(const SphereShape&) const { return "sphere"; }
        std::string_view operator()(const TorusShape&) const { return "torus"; }
        std::string_view operator()(const TeapotShape&) const { return "teapot"; }
        std::string_view operator()(const MeshFileShape&) const { return "mesh"; }
    };
    return std::visit(Name{}, shape);
}

FileLoc Scene::location_of(std::string_view path) const {
    auto found = locations.find(path);
    return found == locations.end() ? FileLoc{} : found->second;
}

bool same_geometry(const SceneObject& a, const SceneObject& b) {
    if (a.position != b.position || a.rotation_degrees != b.rotation_degrees || a.scale != b.scale)
        return false;
    if (a.shape.index() != b.shape.index()) return false;
    return std::visit(
        [&](const auto& shape) {
            using S = std::decay_t<decltype(shape)>;
            const S& other = std::get<S>(b.shape);
            if constexpr (std::is_same_v<S, CubeShape>) return shape.size == other.size;
            else if constexpr (std::is_same_v<S, SphereShape>)
                return shape.radius == other.radius && shape.segments == other.segments &&
                       shape.rings == other.rings;
            else if constexpr (std::is_same_v<S, TorusShape>)
                return shape.major_radius == other.major_radius &&
                       shape.minor_radius == other.minor_radius && shape.segments == other.segments &&
                       shape.sides == other.sides;
            else if constexpr (std::is_same_v<S, TeapotShape>)
                return shape.size == other.size && shape.subdivisions == other.subdivisions;
            else
                return shape.file == other.file;
        },
        a.shape);
}

glm::mat4 object_to_world(const SceneObject& object) {
    // docs/spec.md §2: world = T(position) · Rz · Ry · Rx · S(scale); each glm call
    // multiplies on the right, so the calls read in the formula's order.
    glm::mat4 transform = glm::translate(glm::mat4(1.0f), object.position);
    transform = glm::rotate(transform, glm::radians(object.rotation_degrees.z), {0.0f, 0.0f, 1.0f});
    transform = glm::rotate(transform, glm::radians(object.rotation_degrees.y), {0.0f, 1.0f, 0.0f});
    transform = glm::rotate(transform, glm::radians(object.rotation_degrees.x), {1.0f, 0.0f, 0.0f});
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
        Mesh operator()(const MeshFileShape& mesh) const { return load_obj(mesh.file); }
    };
    return std::visit(Build{}, object.shape);
}

WorldMesh world_mesh(const SceneObject& object) {
    Mesh mesh = object_mesh(object);
    const std::vector<glm::vec3> local_normals = vertex_normals(mesh);
    const glm::mat4 model = object_to_world(object);
    const glm::mat3 rotation = glm::mat3(model) * (1.0f / object.scale);

    WorldMesh world;
    world.positions.reserve(mesh.positions.size());
    world.normals.reserve(mesh.positions.size());
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        world.positions.push_back(glm::vec3(model * glm::vec4(mesh.positions[i], 1.0f)));
        const glm::vec3 n = rotation * local_normals[i];
        const float length = glm::length(n);
        world.normals.push_back(length > 0.0f ? n / length : n);
    }
    world.triangles = std::move(mesh.triangles);
    return world;
}

}  // namespace litkit
