// SPDX-License-Identifier: MIT
// glTF 2.0 mesh files (docs/scene-format.md, "Mesh files"): the JSON, the
// GLB container and data: URIs parsed by tinygltf (tinygltf.cpp), every
// number litkit draws then checked here, where each error can be named by
// its place in the file ("meshes[0].primitives[1].indices: …").
#include "geometry/tinygltf.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <new>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "core/files.hpp"
#include "geometry/mesh_formats.hpp"
#include "litkit/error.hpp"

namespace litkit::detail {

namespace {

namespace fs = std::filesystem;

constexpr std::uint64_t max_triangles = max_mesh_file_triangles;

// Deeper JSON is refused before it is parsed: tinygltf reads `extras` and
// `extensions` values recursively, one stack frame per level. glTF's own
// members nest 6 levels deep.
constexpr int max_json_depth = 64;

// The first place where the JSON text nests deeper than max_json_depth, or
// npos.
std::size_t too_deep(std::string_view json) {
    int depth = 0;
    bool in_string = false;
    for (std::size_t at = 0; at < json.size(); ++at) {
        const char c = json[at];
        if (in_string) {
            if (c == '\\')
                ++at;
            else if (c == '"')
                in_string = false;
        } else if (c == '"') {
            in_string = true;
        } else if (c == '[' || c == '{') {
            if (++depth > max_json_depth) return at;
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
    return std::string_view::npos;
}

// Buffer files, read through tinygltf's file-system callbacks: only from
// the glTF file's folder and below, within the read limit in all.
struct BufferFiles {
    fs::path folder;
    std::uint64_t bytes_read = 0;
    std::string refused;  // why the last file was not read, in our words
};

bool file_exists(const std::string&, void*) { return true; }  // read_buffer says why not
std::string expand_path(const std::string& path, void*) { return path; }
bool write_nothing(std::string* error, const std::string&, const std::vector<unsigned char>&,
                   void*) {
    if (error) *error = "litkit writes no glTF files";
    return false;
}

bool read_buffer(std::vector<unsigned char>* out, std::string* error, const std::string& joined,
                 void* user_data) {
    auto& files = *static_cast<BufferFiles*>(user_data);
    // tinygltf joins the folder and the URI (already %-decoded).
    const fs::path path = fs::path(joined).lexically_normal();
    const fs::path relative = path.lexically_relative(files.folder);
    const std::string uri = relative.empty() ? joined : relative.generic_string();
    if (relative.empty() || *relative.begin() == "..") {
        files.refused = "buffer file '" + uri +
                        "' is outside the glTF file's folder (buffers are read from its folder "
                        "and the folders below it only)";
        *error = files.refused;
        return false;
    }
    try {
        const std::string bytes = read_file_limited(
            path, max_input_file_bytes - std::min(files.bytes_read, max_input_file_bytes));
        files.bytes_read += bytes.size();
        out->assign(bytes.begin(), bytes.end());
        return true;
    } catch (const IoError& failure) {
        files.refused = "buffer file '" + uri + "': " + failure.reason() +
                        (failure.reason().find("larger") != std::string::npos
                             ? " (the limit holds for the glTF file's buffers together)"
                             : "");
        *error = files.refused;
        return false;
    }
}

// Images are never decoded: their bytes are not even looked at.
bool skip_image(tinygltf::Image*, const int, std::string*, std::string*, int, int,
                const unsigned char*, int, void*) {
    return true;
}

std::string first_lines(const std::string& text) {
    std::string result;
    for (std::size_t at = 0; at < text.size() && result.size() < 300;) {
        std::size_t end = text.find('\n', at);
        if (end == std::string::npos) end = text.size();
        if (end > at) result += (result.empty() ? "" : "; ") + text.substr(at, end - at);
        at = end + 1;
    }
    return result;
}

std::string indexed(std::string_view list, std::size_t index) {
    return std::string(list) + "[" + std::to_string(index) + "]";
}

class Extractor {
  public:
    Extractor(const tinygltf::Model& model, const std::string& name) : model_(model), name_(name) {}

    Mesh extract() {
        for (const std::string& extension : model_.extensionsRequired)
            if (extension == "KHR_draco_mesh_compression" || extension == "EXT_meshopt_compression")
                fail("extensionsRequired",
                     "'" + extension +
                         "' compresses the meshes, which litkit does not read: export the file "
                         "without mesh compression");
        if (model_.scenes.empty())
            fail("scenes", "the file has no scene (litkit draws the meshes of its default scene)");
        std::size_t scene = 0;
        if (model_.defaultScene >= 0) {
            scene = static_cast<std::size_t>(model_.defaultScene);
            if (scene >= model_.scenes.size())
                fail("scene", "scene " + std::to_string(scene) + " does not exist (the file has " +
                                  std::to_string(model_.scenes.size()) + ")");
        }
        visited_.assign(model_.nodes.size(), false);
        const std::vector<int>& roots = model_.scenes[scene].nodes;
        for (std::size_t i = 0; i < roots.size(); ++i)
            visit(roots[i], indexed(indexed("scenes", scene) + ".nodes", i));
        if (mesh_.triangles.empty())
            fail(indexed("scenes", scene),
                 skipped_ ? "the scene has no triangles (only points or lines, which litkit does "
                            "not draw)"
                          : "the scene has no triangles");
        if (!has_normals_) mesh_.file_normals.clear();
        return std::move(mesh_);
    }

  private:
    [[noreturn]] void fail(const std::string& where, const std::string& reason) const {
        throw IoError(name_, where + ": " + reason, FileLoc{name_});
    }

    // Depth first, without recursion (a file may nest nodes deeply); each
    // node once: glTF's nodes form trees, and a node met twice (a cycle, or
    // two parents) would repeat, or never end.
    void visit(int root, const std::string& where) {
        struct Pending {
            int node;
            glm::dmat4 parent;
            std::string where;
        };
        std::vector<Pending> pending{{root, glm::dmat4(1.0), where}};
        while (!pending.empty()) {
            Pending next = std::move(pending.back());
            pending.pop_back();
            if (next.node < 0 || static_cast<std::size_t>(next.node) >= model_.nodes.size())
                fail(next.where, "node " + std::to_string(next.node) +
                                     " does not exist (the file has " +
                                     std::to_string(model_.nodes.size()) + ")");
            const auto index = static_cast<std::size_t>(next.node);
            const std::string here = indexed("nodes", index);
            if (visited_[index])
                fail(next.where, here +
                                     " is met a second time (glTF nodes form trees: a node "
                                     "has one parent at most, and no cycles)");
            visited_[index] = true;
            const tinygltf::Node& node = model_.nodes[index];
            const glm::dmat4 world = next.parent * local_matrix(node, here);
            if (node.mesh >= 0) add_mesh(node.mesh, world, here);
            for (std::size_t i = 0; i < node.children.size(); ++i)
                pending.push_back({node.children[i], world, here + indexed(".children", i)});
        }
    }

    glm::dmat4 local_matrix(const tinygltf::Node& node, const std::string& where) const {
        auto check = [&](const std::vector<double>& values, const char* key,
                         std::initializer_list<std::size_t> sizes) {
            bool size_ok = false;
            for (std::size_t size : sizes) size_ok = size_ok || values.size() == size;
            if (!size_ok)
                fail(where + "." + key, "has " + std::to_string(values.size()) + " numbers");
            for (double value : values)
                if (!std::isfinite(value))
                    fail(where + "." + key, "holds a number that is not finite");
        };
        check(node.matrix, "matrix", {0, 16});
        check(node.translation, "translation", {0, 3});
        check(node.rotation, "rotation", {0, 4});
        check(node.scale, "scale", {0, 3});
        glm::dmat4 matrix(1.0);
        if (!node.matrix.empty()) {
            for (int column = 0; column < 4; ++column)
                for (int row = 0; row < 4; ++row)
                    matrix[column][row] = node.matrix[4 * column + row];
            return matrix;
        }
        // glTF: T · R · S, the rotation a unit quaternion (x, y, z, w).
        if (!node.translation.empty())
            matrix[3] =
                glm::dvec4(node.translation[0], node.translation[1], node.translation[2], 1);
        if (!node.rotation.empty()) {
            glm::dquat rotation(node.rotation[3], node.rotation[0], node.rotation[1],
                                node.rotation[2]);
            const double length = glm::length(rotation);
            if (!(length > 0.5 && length < 2.0))
                fail(where + ".rotation", "is not a unit quaternion");
            matrix = matrix * glm::mat4_cast(rotation / length);
        }
        if (!node.scale.empty())
            matrix =
                matrix * glm::dmat4(glm::dvec4(node.scale[0], 0, 0, 0),
                                    glm::dvec4(0, node.scale[1], 0, 0),
                                    glm::dvec4(0, 0, node.scale[2], 0), glm::dvec4(0, 0, 0, 1));
        return matrix;
    }

    // An accessor's elements, `components` per element, as floats (or, for
    // indices, 32-bit integers: no wider than their data): checked against
    // its buffer view and buffer, normalised integers mapped to [-1, 1] or
    // [0, 1] (glTF 2.0 §3.11), sparse values applied.
    template <typename T>
    std::vector<T> read_accessor(int accessor_index, const std::string& where, int type) const {
        constexpr bool integers = std::is_same_v<T, std::uint32_t>;
        if (accessor_index < 0 ||
            static_cast<std::size_t>(accessor_index) >= model_.accessors.size())
            fail(where, "accessor " + std::to_string(accessor_index) +
                            " does not exist (the file has " +
                            std::to_string(model_.accessors.size()) + ")");
        const tinygltf::Accessor& accessor =
            model_.accessors[static_cast<std::size_t>(accessor_index)];
        const std::string place = where + " (" + indexed("accessors", accessor_index) + ")";
        const auto components = static_cast<std::size_t>(tinygltf::GetNumComponentsInType(type));
        if (accessor.type != type)
            fail(place,
                 type == TINYGLTF_TYPE_VEC3 ? "must be of type VEC3" : "must be of type SCALAR");
        const int component_type = accessor.componentType;
        const bool floats = component_type == TINYGLTF_COMPONENT_TYPE_FLOAT;
        const bool index_type = component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
                                component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
        const bool small_integer = component_type == TINYGLTF_COMPONENT_TYPE_BYTE ||
                                   component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                   component_type == TINYGLTF_COMPONENT_TYPE_SHORT ||
                                   component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
        if (integers ? !index_type : !(floats || small_integer))
            fail(place, "component type " + std::to_string(component_type) +
                            (integers ? " is not one of indices (5121, 5123, 5125)"
                                      : " is not float (5126) or a byte or short (5120–5123)"));
        const auto component_size = static_cast<std::size_t>(
            tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(component_type)));
        const std::size_t element_size = component_size * components;
        const std::uint64_t count = accessor.count;
        if (count > max_input_file_bytes / element_size)
            fail(place, "its count " + std::to_string(count) +
                            " is beyond what litkit reads (the files' read limit)");
        std::vector<T> values(count * components, T{});
        auto read_from = [&](int view_index, std::uint64_t offset, std::uint64_t elements,
                             std::size_t size, const std::string& what,
                             bool stride_allowed) -> std::pair<const unsigned char*, std::size_t> {
            if (view_index < 0 || static_cast<std::size_t>(view_index) >= model_.bufferViews.size())
                fail(what, "buffer view " + std::to_string(view_index) + " does not exist");
            const tinygltf::BufferView& view =
                model_.bufferViews[static_cast<std::size_t>(view_index)];
            const std::string view_place = indexed("bufferViews", view_index);
            if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model_.buffers.size())
                fail(view_place, "buffer " + std::to_string(view.buffer) + " does not exist");
            const std::vector<unsigned char>& data =
                model_.buffers[static_cast<std::size_t>(view.buffer)].data;
            if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset)
                fail(view_place, "bytes " + std::to_string(view.byteOffset) + " to " +
                                     std::to_string(view.byteOffset + view.byteLength) +
                                     " lie beyond its buffer's " + std::to_string(data.size()));
            const std::size_t stride =
                stride_allowed && view.byteStride != 0 ? view.byteStride : size;
            if (stride < size)
                fail(view_place, "its byteStride " + std::to_string(stride) +
                                     " is shorter than an element (" + std::to_string(size) +
                                     " bytes)");
            if (elements > 0 &&
                (offset > view.byteLength || (elements - 1) > (view.byteLength - offset) / stride ||
                 (elements - 1) * stride + size > view.byteLength - offset))
                fail(what, std::to_string(elements) + " elements of " + std::to_string(size) +
                               " bytes from byte " + std::to_string(offset) + " do not fit in " +
                               view_place + " (" + std::to_string(view.byteLength) + " bytes)");
            return {data.data() + view.byteOffset + offset, stride};
        };
        auto component = [&](const unsigned char* at, int of_type, bool normalized) {
            double value = 0;
            switch (of_type) {
                case TINYGLTF_COMPONENT_TYPE_BYTE: {
                    std::int8_t raw;
                    std::memcpy(&raw, at, 1);
                    value = normalized ? std::max(raw / 127.0, -1.0) : raw;
                    break;
                }
                case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
                    value = normalized ? *at / 255.0 : *at;
                    break;
                case TINYGLTF_COMPONENT_TYPE_SHORT: {
                    std::int16_t raw;
                    std::memcpy(&raw, at, 2);
                    value = normalized ? std::max(raw / 32767.0, -1.0) : raw;
                    break;
                }
                case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
                    std::uint16_t raw;
                    std::memcpy(&raw, at, 2);
                    value = normalized ? raw / 65535.0 : raw;
                    break;
                }
                case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
                    std::uint32_t raw;
                    std::memcpy(&raw, at, 4);
                    value = raw;
                    break;
                }
                default: {
                    float raw;
                    std::memcpy(&raw, at, 4);
                    value = raw;
                }
            }
            return value;
        };
        const bool normalized = accessor.normalized && !floats && !integers;
        if (accessor.bufferView >= 0) {
            const auto [start, stride] = read_from(accessor.bufferView, accessor.byteOffset, count,
                                                   element_size, place, /*stride_allowed=*/true);
            for (std::size_t e = 0; e < count; ++e)
                for (std::size_t c = 0; c < components; ++c)
                    values[e * components + c] = static_cast<T>(component(
                        start + e * stride + c * component_size, component_type, normalized));
        }
        if (accessor.sparse.isSparse) {
            const auto& sparse = accessor.sparse;
            const std::string sparse_place = place + ".sparse";
            if (sparse.count < 1 || static_cast<std::uint64_t>(sparse.count) > count)
                fail(sparse_place, "its count " + std::to_string(sparse.count) +
                                       " is not between 1 and the accessor's " +
                                       std::to_string(count));
            const int index_component = sparse.indices.componentType;
            if (index_component != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
                index_component != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
                index_component != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
                fail(sparse_place + ".indices", "component type " +
                                                    std::to_string(index_component) +
                                                    " is not one of 5121, 5123, 5125");
            if (sparse.indices.byteOffset < 0 || sparse.values.byteOffset < 0)
                fail(sparse_place, "a byteOffset is negative");
            const auto index_size = static_cast<std::size_t>(
                tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(index_component)));
            const auto sparse_count = static_cast<std::uint64_t>(sparse.count);
            const auto [indices, index_stride] = read_from(
                sparse.indices.bufferView, static_cast<std::uint64_t>(sparse.indices.byteOffset),
                sparse_count, index_size, sparse_place + ".indices", false);
            const auto [replacements, value_stride] = read_from(
                sparse.values.bufferView, static_cast<std::uint64_t>(sparse.values.byteOffset),
                sparse_count, element_size, sparse_place + ".values", false);
            for (std::size_t s = 0; s < sparse_count; ++s) {
                const double target = component(indices + s * index_stride, index_component, false);
                if (target >= static_cast<double>(count))
                    fail(sparse_place + ".indices",
                         "index " + std::to_string(static_cast<std::uint64_t>(target)) +
                             " is beyond the accessor's " + std::to_string(count) + " elements");
                const auto element = static_cast<std::size_t>(target);
                for (std::size_t c = 0; c < components; ++c)
                    values[element * components + c] = static_cast<T>(
                        component(replacements + s * value_stride + c * component_size,
                                  component_type, normalized));
            }
        }
        if constexpr (!integers)
            for (std::size_t i = 0; i < values.size(); ++i)
                if (!std::isfinite(values[i]))
                    fail(place, "element " + std::to_string(i / components) +
                                    " has a coordinate that is not a finite number");
        return values;
    }

    void add_mesh(int mesh_index, const glm::dmat4& world, const std::string& node_place) {
        if (static_cast<std::size_t>(mesh_index) >= model_.meshes.size())
            fail(node_place + ".mesh", "mesh " + std::to_string(mesh_index) +
                                           " does not exist (the file has " +
                                           std::to_string(model_.meshes.size()) + ")");
        const tinygltf::Mesh& mesh = model_.meshes[static_cast<std::size_t>(mesh_index)];
        const glm::dmat3 linear(world);
        const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(linear));
        // A mirroring placement turns counter-clockwise faces clockwise (glTF 2.0 §3.7.4).
        const bool mirrored = glm::determinant(linear) < 0;
        for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
            const tinygltf::Primitive& primitive = mesh.primitives[p];
            const std::string where = indexed(indexed("meshes", mesh_index) + ".primitives", p);
            const int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
            if (mode < TINYGLTF_MODE_TRIANGLES) {  // points, lines, line loops and strips
                skipped_ = true;
                continue;
            }
            if (mode > TINYGLTF_MODE_TRIANGLE_FAN)
                fail(where + ".mode", std::to_string(mode) + " is not a glTF primitive mode (0–6)");
            const auto position_attribute = primitive.attributes.find("POSITION");
            if (position_attribute == primitive.attributes.end())
                fail(where + ".attributes", "has no POSITION");
            // The triangle budget, from the counts, before anything is read.
            const int counted =
                primitive.indices >= 0 ? primitive.indices : position_attribute->second;
            if (counted >= 0 && static_cast<std::size_t>(counted) < model_.accessors.size())
                check_budget(model_.accessors[static_cast<std::size_t>(counted)].count, mode,
                             where);
            const std::vector<float> positions = read_accessor<float>(
                position_attribute->second, where + ".attributes.POSITION", TINYGLTF_TYPE_VEC3);
            const std::size_t vertex_count = positions.size() / 3;
            std::vector<float> normals;
            if (const auto found = primitive.attributes.find("NORMAL");
                found != primitive.attributes.end()) {
                normals = read_accessor<float>(found->second, where + ".attributes.NORMAL",
                                               TINYGLTF_TYPE_VEC3);
                if (normals.size() != positions.size())
                    fail(where + ".attributes.NORMAL", "has " + std::to_string(normals.size() / 3) +
                                                           " elements, POSITION " +
                                                           std::to_string(vertex_count));
            }
            std::vector<std::uint32_t> order;
            if (primitive.indices >= 0) {
                const std::vector<std::uint32_t> indices = read_accessor<std::uint32_t>(
                    primitive.indices, where + ".indices", TINYGLTF_TYPE_SCALAR);
                order.reserve(indices.size());
                for (std::size_t i = 0; i < indices.size(); ++i) {
                    if (indices[i] >= vertex_count)
                        fail(where + ".indices",
                             "index " + std::to_string(indices[i]) + " (element " +
                                 std::to_string(i) + ") is beyond the " +
                                 std::to_string(vertex_count) + " vertices of its POSITION");
                    order.push_back(indices[i]);
                }
            } else {
                order.resize(vertex_count);
                for (std::size_t i = 0; i < vertex_count; ++i)
                    order[i] = static_cast<std::uint32_t>(i);
            }
            add_primitive(positions, normals, order, mode, world, normal_matrix, mirrored, where);
        }
    }

    void check_budget(std::uint64_t count, int mode, const std::string& where) const {
        const std::uint64_t triangles = mode == TINYGLTF_MODE_TRIANGLES ? count / 3
                                        : count >= 3                    ? count - 2
                                                                        : 0;
        if (mesh_.triangles.size() + triangles > max_triangles)
            fail(where, "the file's meshes, placed by its nodes, make more than " +
                            std::to_string(max_triangles) + " triangles");
    }

    void add_primitive(const std::vector<float>& positions, const std::vector<float>& normals,
                       const std::vector<std::uint32_t>& order, int mode, const glm::dmat4& world,
                       const glm::dmat3& normal_matrix, bool mirrored, const std::string& where) {
        const std::size_t count = order.size();
        check_budget(count, mode, where);
        const std::size_t triangles = mode == TINYGLTF_MODE_TRIANGLES ? count / 3
                                      : count >= 3                    ? count - 2
                                                                      : 0;
        if (mesh_.positions.size() + positions.size() / 3 >
            std::numeric_limits<std::uint32_t>::max())
            fail(where, "the file's meshes have too many vertices");
        const auto base = static_cast<std::uint32_t>(mesh_.positions.size());
        for (std::size_t v = 0; v < positions.size() / 3; ++v) {
            const glm::dvec4 placed = world * glm::dvec4(positions[3 * v], positions[3 * v + 1],
                                                         positions[3 * v + 2], 1.0);
            const glm::vec3 position(placed);
            if (!std::isfinite(position.x) || !std::isfinite(position.y) ||
                !std::isfinite(position.z))
                fail(where + ".attributes.POSITION",
                     "element " + std::to_string(v) +
                         ", placed by its node, is beyond the range of "
                         "numbers litkit draws");
            mesh_.positions.push_back(position);
            glm::dvec3 normal(0.0);
            if (!normals.empty()) {
                normal = normal_matrix *
                         glm::dvec3(normals[3 * v], normals[3 * v + 1], normals[3 * v + 2]);
                if (glm::length(normal) > 0) normal = glm::normalize(normal);
            }
            mesh_.file_normals.emplace_back(normal);
        }
        has_normals_ = has_normals_ || !normals.empty();
        for (std::size_t t = 0; t < triangles; ++t) {
            std::array<std::uint32_t, 3> corners;
            if (mode == TINYGLTF_MODE_TRIANGLES) {
                corners = {order[3 * t], order[3 * t + 1], order[3 * t + 2]};
            } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {  // glTF 2.0 §3.7.2.1
                corners = t % 2 == 0 ? std::array{order[t], order[t + 1], order[t + 2]}
                                     : std::array{order[t], order[t + 2], order[t + 1]};
            } else {  // a fan around the first vertex
                corners = {order[0], order[t + 1], order[t + 2]};
            }
            if (mirrored) std::swap(corners[1], corners[2]);
            for (std::uint32_t& corner : corners) corner += base;
            mesh_.triangles.push_back(corners);
            mesh_.triangle_file_normals.push_back(
                normals.empty()
                    ? std::array{missing_file_normal, missing_file_normal, missing_file_normal}
                    : corners);
            mesh_.triangle_faces.push_back(static_cast<std::uint32_t>(mesh_.triangle_faces.size()));
        }
    }

    const tinygltf::Model& model_;
    const std::string& name_;
    std::vector<bool> visited_;
    bool skipped_ = false;
    bool has_normals_ = false;
    Mesh mesh_;
};

}  // namespace

Mesh parse_gltf(std::string_view bytes, const fs::path& path) {
    const std::string name = path.string();
    BufferFiles files;
    files.folder =
        path.parent_path().empty() ? fs::path(".") : path.parent_path().lexically_normal();
    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks({file_exists, expand_path, read_buffer, write_nothing, &files});
    loader.SetImageLoader(skip_image, nullptr);
    tinygltf::Model model;
    std::string errors;
    std::string warnings;
    bool loaded = false;
    const bool binary = bytes.substr(0, 4) == "glTF";
    // GLB: the JSON chunk's length at byte 12, its text from byte 20.
    std::string_view json = bytes;
    if (binary) {
        std::uint32_t length = 0;
        if (bytes.size() >= 16) std::memcpy(&length, bytes.data() + 12, 4);
        json = bytes.size() >= 20 ? bytes.substr(20, length) : std::string_view();
    }
    if (const std::size_t deep = too_deep(json); deep != std::string_view::npos)
        throw IoError(name,
                      "the JSON nests deeper than " + std::to_string(max_json_depth) +
                          " levels (byte " + std::to_string(deep + (binary ? 20 : 0)) + ")",
                      FileLoc{name});
    try {
        const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
        const auto size = static_cast<unsigned int>(bytes.size());  // ≤ the read limit
        loaded = binary ? loader.LoadBinaryFromMemory(&model, &errors, &warnings, data, size,
                                                      files.folder.string())
                        : loader.LoadASCIIFromString(&model, &errors, &warnings, bytes.data(), size,
                                                     files.folder.string());
    } catch (const std::bad_alloc&) {
        throw;
    } catch (const std::exception& failure) {
        // tinygltf lets some of its JSON library's and the standard
        // library's exceptions through (an empty data: URI, a number of
        // the wrong kind).
        errors = failure.what();
    }
    if (!files.refused.empty()) throw IoError(name, files.refused, FileLoc{name});
    if (!loaded) {
        const std::string reason = first_lines(errors);
        throw IoError(name,
                      std::string(binary ? "not a valid GLB file" : "not a valid glTF file") +
                          (reason.empty() ? "" : ": " + reason),
                      FileLoc{name});
    }
    return Extractor(model, name).extract();
}

}  // namespace litkit::detail
