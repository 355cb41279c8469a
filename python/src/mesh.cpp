// SPDX-License-Identifier: MIT
// Meshes from NumPy arrays as objects of a scene (Scene.add_mesh): vertices
// N x 3, faces M x 3, checked as a mesh file is checked (shapes, types,
// finite coordinates, indices in range) before the scene holds them.
#include <pybind11/numpy.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>

#include "convert.hpp"

namespace litkit_python {

namespace {

[[noreturn]] void refuse(const std::string& message) {
    throw litkit::ArgumentError("Scene.add_mesh: " + message);
}

std::string shape_of(const py::array& array) {
    std::string text = "(";
    for (py::ssize_t axis = 0; axis < array.ndim(); ++axis)
        text += (axis ? ", " : "") + std::to_string(array.shape(axis));
    return text + (array.ndim() == 1 ? ",)" : ")");
}

// `value` as an array of shape (rows >= 1, 3) whose dtype is of one of `kinds`
// (NumPy's dtype.kind letters), or an ArgumentError naming `name`.
py::array checked_array(const py::handle& value, const char* name, const std::string& kinds,
                        const char* what) {
    const py::array array = py::module_::import("numpy").attr("asarray")(value);
    const char kind = array.dtype().kind();
    if (kinds.find(kind) == std::string::npos) {
        refuse(std::string(name) + " must hold " + what + ", not " +
               py::str(array.dtype()).cast<std::string>());
    }
    if (array.ndim() != 2 || array.shape(1) != 3 || array.shape(0) < 1) {
        refuse(std::string(name) + " must have the shape (" + (name[0] == 'v' ? "N" : "M") +
               ", 3) with at least one row, not " + shape_of(array));
    }
    return array;
}

}  // namespace

litkit::Mesh mesh_from_arrays(const py::handle& vertices, const py::handle& faces) {
    const py::array given_vertices = checked_array(vertices, "vertices", "fiu", "numbers");
    const py::array given_faces = checked_array(faces, "faces", "iu", "integers");
    const auto positions =
        py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(given_vertices);
    const auto indices =
        py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(given_faces);
    if (!positions || !indices) refuse("vertices or faces cannot be read as numbers");
    const auto count = static_cast<std::uint64_t>(positions.shape(0));
    if (count > std::numeric_limits<std::uint32_t>::max())
        refuse("more vertices than 32-bit indices reach");

    litkit::Mesh mesh;
    mesh.positions.resize(count);
    const auto p = positions.unchecked<2>();
    for (py::ssize_t row = 0; row < positions.shape(0); ++row) {
        for (py::ssize_t axis = 0; axis < 3; ++axis) {
            const auto single = static_cast<float>(p(row, axis));
            if (!std::isfinite(single)) {
                refuse("vertices[" + std::to_string(row) + "][" + std::to_string(axis) + "] is " +
                       py::repr(py::float_(p(row, axis))).cast<std::string>() +
                       ", not a finite 32-bit float");
            }
            mesh.positions[static_cast<std::size_t>(row)][static_cast<int>(axis)] = single;
        }
    }
    mesh.triangles.resize(static_cast<std::size_t>(indices.shape(0)));
    const auto f = indices.unchecked<2>();
    for (py::ssize_t row = 0; row < indices.shape(0); ++row) {
        for (py::ssize_t corner = 0; corner < 3; ++corner) {
            const std::int64_t index = f(row, corner);
            if (index < 0 || static_cast<std::uint64_t>(index) >= count) {
                refuse("faces[" + std::to_string(row) + "][" + std::to_string(corner) + "] is " +
                       std::to_string(index) + ", not an index of vertices (0 to " +
                       std::to_string(count - 1) + ")");
            }
            mesh.triangles[static_cast<std::size_t>(row)][static_cast<std::size_t>(corner)] =
                static_cast<std::uint32_t>(index);
        }
    }
    // What the library checks of every mesh given in memory (the same rules).
    if (const std::string problem = litkit::check_mesh_data(mesh); !problem.empty())
        refuse(problem);
    return mesh;
}

}  // namespace litkit_python
