// SPDX-License-Identifier: MIT
// What the binding's files share: glm::vec3 as a Python sequence of three
// numbers, model names as strings, images as NumPy arrays, and the
// argument checks that turn a bad Python argument into litkit.ArgumentError.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <glm/vec3.hpp>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "litkit/litkit.hpp"

namespace pybind11::detail {

// glm::vec3 <-> any sequence of three numbers (tuple, list, NumPy array);
// returned to Python as a tuple of three floats.
template <>
struct type_caster<glm::vec3> {
    PYBIND11_TYPE_CASTER(glm::vec3, const_name("tuple[float, float, float]"));

    bool load(handle source, bool convert) {
        if (!source || isinstance<str>(source) || isinstance<bytes>(source) ||
            !PySequence_Check(source.ptr()))
            return false;
        const auto sequence = reinterpret_borrow<pybind11::sequence>(source);
        if (sequence.size() != 3) return false;
        for (std::size_t i = 0; i < 3; ++i) {
            make_caster<float> component;
            if (!component.load(sequence[i], convert)) return false;
            value[static_cast<glm::length_t>(i)] = cast_op<float>(component);
        }
        return true;
    }

    static handle cast(const glm::vec3& v, return_value_policy, handle) {
        return pybind11::make_tuple(v.x, v.y, v.z).release();
    }
};

}  // namespace pybind11::detail

namespace litkit_python {

namespace py = pybind11;

// "phong" -> Reflection::Phong; an unknown name throws litkit::ArgumentError
// listing the known ones.
litkit::Reflection reflection_from(const std::string& name);
litkit::Shading shading_from(const std::string& name);
litkit::Normals normals_from(const std::string& name);
// Throws litkit::ArgumentError: "unknown reflection model 'fong'; expected one
// of: lambert, half-lambert, ..." (`known`: the library's list of names).
[[noreturn]] void unknown(const std::string& what, const std::string& name,
                          std::span<const std::string_view> known);

// The replacements render() takes for the scene's own values; each checked
// as the command line checks its options (sizes 1-max_image_side, threads
// 0-max_render_threads).
struct Overrides {
    std::optional<std::string> reflection;
    std::optional<std::string> shading;
    std::optional<int> width;
    std::optional<int> height;
    std::optional<int> max_depth;
    std::optional<int> samples;  // docs/spec.md §11: 1, 4, 8 or 16
    // Throws litkit::ArgumentError for an unknown name, a size, a max_depth
    // out of range or a count of samples not allowed.
    void apply_to(litkit::Scene& scene) const;
};
int checked_threads(int threads);

// The image as a C-contiguous uint8 array of shape (height, width, 3) that
// owns the pixels (moved, not copied).
py::array image_array(litkit::Image&& image);

// Throws litkit::SceneError when `scene` breaks a rule of docs/spec.md §6;
// returns the warnings otherwise. Call without the GIL (it may read meshes).
std::vector<litkit::Diagnostic> validate_or_throw(const litkit::Scene& scene);

// Scene.add_mesh's mesh: vertices (N, 3) numbers and faces (M, 3) integers,
// checked (shapes, dtypes, finite coordinates, indices below N); raises
// litkit::ArgumentError naming the first bad entry (mesh.cpp).
litkit::Mesh mesh_from_arrays(const py::handle& vertices, const py::handle& faces);

void bind_errors(py::module_& module);
void bind_scene(py::module_& module);
void bind_lighting(py::module_& module);
void bind_render(py::module_& module);
void bind_explain(py::module_& module);

}  // namespace litkit_python
