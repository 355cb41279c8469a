// SPDX-License-Identifier: MIT
// Scenes: loading them (files, text, the built-in default), checking them,
// and the parts a notebook changes between pictures (observer, room, output,
// models). Lights and objects are changed through dictionaries
// (Scene.to_dict() and litkit.loads(dict), in litkit/__init__.py).
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "convert.hpp"

namespace litkit_python {

namespace {

// Scene.normals' docstring, naming the weightings from the library's list.
const char* normals_doc() {
    static const std::string doc = [] {
        std::string names;
        for (std::string_view name : litkit::normals_names)
            names += (names.empty() ? "" : ", ") + std::string(name);
        return "How vertex normals weight faces (" + names + "), or None";
    }();
    return doc.c_str();
}

const char* severity_name(litkit::Severity severity) {
    return severity == litkit::Severity::Error ? "error" : "warning";
}

py::object optional_name(const auto& model) {
    return model ? py::object(py::str(std::string(litkit::to_string(*model)))) : py::none();
}

void bind_diagnostic(py::module_& module) {
    py::class_<litkit::Diagnostic>(module, "Diagnostic",
                                   "One problem found in a scene, located in its file.")
        .def_property_readonly("file",
                               [](const litkit::Diagnostic& d) -> py::object {
                                   if (d.location.file.empty()) return py::none();
                                   return py::str(d.location.file);
                               })
        .def_property_readonly("line",
                               [](const litkit::Diagnostic& d) -> py::object {
                                   if (d.location.line == 0) return py::none();
                                   return py::int_(d.location.line);
                               })
        .def_property_readonly("column",
                               [](const litkit::Diagnostic& d) -> py::object {
                                   if (d.location.column == 0) return py::none();
                                   return py::int_(d.location.column);
                               })
        .def_property_readonly(
            "severity", [](const litkit::Diagnostic& d) { return severity_name(d.severity); })
        .def_readonly("message", &litkit::Diagnostic::message)
        .def("__str__", &litkit::Diagnostic::to_string)
        .def("__repr__", [](const litkit::Diagnostic& d) {
            return "<litkit.Diagnostic " + py::repr(py::str(d.to_string())).cast<std::string>() +
                   ">";
        });
}

void bind_parts(py::module_& module) {
    py::class_<litkit::Room>(module, "Room", "The box around the scene, centred at the origin.")
        .def_readwrite("width", &litkit::Room::width)
        .def_readwrite("height", &litkit::Room::height)
        .def_readwrite("depth", &litkit::Room::depth)
        .def_readwrite("ior", &litkit::Room::ior,
                       "Refractive index of the medium filling the room, 1-3");
    py::class_<litkit::Observer>(module, "Observer", "The perspective camera.")
        .def_readwrite("position", &litkit::Observer::position)
        .def_readwrite("look_at", &litkit::Observer::look_at)
        .def_readwrite("up", &litkit::Observer::up)
        .def_readwrite("fov", &litkit::Observer::fov_degrees, "Vertical field of view, degrees")
        .def_readwrite("near", &litkit::Observer::near)
        .def_readwrite("far", &litkit::Observer::far);
    py::class_<litkit::OutputSettings>(module, "Output",
                                       "The picture's size, background and gamma.")
        .def_readwrite("width", &litkit::OutputSettings::width)
        .def_readwrite("height", &litkit::OutputSettings::height)
        .def_readwrite("background", &litkit::OutputSettings::background)
        .def_readwrite("gamma", &litkit::OutputSettings::gamma)
        .def_readwrite("samples", &litkit::OutputSettings::samples,
                       "Samples per pixel, 1, 4, 8 or 16 (anti-aliasing)");
}

litkit::Scene load_files(const std::vector<std::filesystem::path>& files, std::uint64_t budget) {
    if (files.empty()) throw litkit::ArgumentError("load: no scene file given");
    py::gil_scoped_release unlocked;  // reading files and meshes
    return litkit::load_scene(files, {.max_triangles = budget});
}

}  // namespace

void bind_scene(py::module_& module) {
    bind_diagnostic(module);
    bind_parts(module);

    py::class_<litkit::Scene>(module, "Scene",
                              "A loaded, checked scene. Change observer, room, output, reflection "
                              "and shading in place; render() checks the scene again.")
        .def_readwrite("room", &litkit::Scene::room)
        .def_readwrite("observer", &litkit::Scene::observer)
        .def_readwrite("output", &litkit::Scene::output)
        .def_property(
            "reflection", [](const litkit::Scene& s) { return optional_name(s.reflection); },
            [](litkit::Scene& s, std::optional<std::string> name) {
                s.reflection = name ? std::optional(reflection_from(*name)) : std::nullopt;
            },
            "The scene's reflection model, or None where [lighting] leaves it out")
        .def_property(
            "shading", [](const litkit::Scene& s) { return optional_name(s.shading); },
            [](litkit::Scene& s, std::optional<std::string> name) {
                s.shading = name ? std::optional(shading_from(*name)) : std::nullopt;
            },
            "The scene's shading model, or None where [lighting] leaves it out")
        .def_property(
            "normals", [](const litkit::Scene& s) { return optional_name(s.normals); },
            [](litkit::Scene& s, std::optional<std::string> name) {
                s.normals = name ? std::optional(normals_from(*name)) : std::nullopt;
            },
            normals_doc())
        .def_readwrite("crease_angle", &litkit::Scene::crease_angle_degrees)
        .def_readwrite("max_depth", &litkit::Scene::max_depth,
                       "Surface interactions along one ray path through glass, 1-16")
        .def_property_readonly("light_count",
                               [](const litkit::Scene& s) { return s.lights.size(); })
        .def_property_readonly("object_count",
                               [](const litkit::Scene& s) { return s.objects.size(); })
        .def_readonly("warnings", &litkit::Scene::warnings, "What loading found surely unintended")
        .def(
            "to_toml",
            [](const litkit::Scene& s, const std::string& written_as) {
                return litkit::scene_to_toml(s, written_as);
            },
            py::arg("written_as") = "",
            "The scene as one TOML file (mesh paths relative to written_as's folder)")
        .def(
            "add_mesh",
            [](litkit::Scene& s, const py::handle& vertices, const py::handle& faces,
               const std::string& name, glm::vec3 position, glm::vec3 rotation, float scale,
               std::optional<litkit::Material> material) {
                litkit::SceneObject object;
                object.name = name;
                object.shape = litkit::MeshDataShape(mesh_from_arrays(vertices, faces));
                object.position = position;
                object.rotation_degrees = rotation;
                object.scale = scale;
                if (material) object.material = *material;
                // Checked with the scene it joins (a name already taken, a
                // scale of 0, an object outside the room) before it joins it.
                litkit::Scene with = s;
                with.objects.push_back(std::move(object));
                {
                    py::gil_scoped_release unlocked;
                    validate_or_throw(with);
                }
                s = std::move(with);
                return s.objects.size() - 1;
            },
            py::arg("vertices"), py::arg("faces"), py::kw_only(), py::arg("name") = "",
            py::arg("position") = glm::vec3(0.0f), py::arg("rotation") = glm::vec3(0.0f),
            py::arg("scale") = 1.0f, py::arg("material") = py::none(),
            "Adds a mesh given as arrays, vertices (N, 3) numbers and faces (M, 3) integer "
            "indices into them, counter-clockwise seen from outside, as an object placed like a "
            "scene file's (position, rotation in degrees x then y then z, scale, material). "
            "Checked as a mesh file is (shapes, finite coordinates, indices in range) and with "
            "the scene; raises litkit.Error and leaves the scene as it was. Returns the object's "
            "index. A scene holding one has no TOML (to_toml and to_dict raise ArgumentError).")
        .def(py::pickle(
            // A scene pickles as its TOML text (mesh files by absolute path),
            // read back as litkit.loads reads text: another process, a
            // Dask worker, gets the same scene where it can read the same files.
            [](const litkit::Scene& s) { return py::make_tuple(litkit::scene_to_toml(s)); },
            [](const py::tuple& state) {
                if (state.size() != 1 || !py::isinstance<py::str>(state[0]))
                    throw litkit::ArgumentError("Scene: a pickled scene is one TOML text");
                const std::string text = state[0].cast<std::string>();
                py::gil_scoped_release unlocked;  // may read mesh files
                return litkit::parse_scene(text, "pickled scene");
            }))
        .def("copy", [](const litkit::Scene& s) { return litkit::Scene(s); })
        .def("__copy__", [](const litkit::Scene& s) { return litkit::Scene(s); })
        .def("__deepcopy__", [](const litkit::Scene& s, py::dict) { return litkit::Scene(s); })
        .def("__repr__", [](const litkit::Scene& s) {
            auto model = [](const auto& m) {
                return m ? std::string(litkit::to_string(*m)) : std::string("default");
            };
            return "<litkit.Scene " + std::to_string(s.lights.size()) + " lights, " +
                   std::to_string(s.objects.size()) + " objects, " +
                   std::to_string(s.output.width) + "x" + std::to_string(s.output.height) + ", " +
                   model(s.reflection) + "/" + model(s.shading) + ">";
        });

    module.def("_load", &load_files, py::arg("files"),
               py::arg("max_triangles") = litkit::default_triangle_budget);
    module.def(
        "_loads",
        [](const std::string& text, const std::filesystem::path& name) {
            py::gil_scoped_release unlocked;  // may read mesh files
            return litkit::parse_scene(text, name);
        },
        py::arg("text"), py::arg("name"));
    module.def("default_scene", &litkit::default_scene,
               "The built-in default scene: one cube, one point light, Phong and Phong.");
    module.def("default_scene_toml", [] { return std::string(litkit::default_scene_toml()); });
    module.def(
        "_check_scene",
        [](const litkit::Scene& scene) {
            const litkit::Scene copy = scene;  // another thread may change `scene`
            py::gil_scoped_release unlocked;
            return validate_or_throw(copy);
        },
        py::arg("scene"));
}

}  // namespace litkit_python
