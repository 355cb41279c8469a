// SPDX-License-Identifier: MIT
// litkit's errors as Python exceptions: litkit.Error, the base of
// litkit.SceneError, litkit.IoError and litkit.ArgumentError, as in C++
// (litkit/error.hpp). str(error) is what() — the one-line diagnostic
// `litkit check` prints, one line per problem for a SceneError — and the
// instance carries file, line, column (None where unknown) and message.
#include <pybind11/stl.h>

#include "convert.hpp"

namespace litkit_python {

namespace {

// The exception classes, created once and kept for the life of the process
// (never destroyed: the interpreter may be gone when statics are).
PyObject* error_type = nullptr;
PyObject* scene_error_type = nullptr;
PyObject* io_error_type = nullptr;
PyObject* argument_error_type = nullptr;

// what() without its place and "error: ": "scene.toml:3:9: error: x" -> "x".
std::string message_of(const litkit::Error& error) {
    std::string text = error.what();
    const std::string place = error.location().to_string() + ": ";
    if (!error.location().file.empty() && text.starts_with(place)) text.erase(0, place.size());
    if (text.starts_with("error: ")) text.erase(0, 7);
    return text;
}

py::object or_none(std::uint32_t number) {
    return number > 0 ? py::object(py::int_(number)) : py::object(py::none());
}

void raise(PyObject* type, const litkit::Error& error,
           const std::vector<litkit::Diagnostic>& diagnostics,
           const std::vector<litkit::Diagnostic>& warnings) {
    py::object instance = py::reinterpret_borrow<py::object>(type)(error.what());
    const litkit::FileLoc& place = error.location();
    instance.attr("file") = place.file.empty() ? py::object(py::none()) : py::str(place.file);
    if (const auto* io = dynamic_cast<const litkit::IoError*>(&error); io && place.file.empty())
        instance.attr("file") = io->path();  // the file that could not be read
    instance.attr("line") = or_none(place.line);
    instance.attr("column") = or_none(place.column);
    instance.attr("message") =
        diagnostics.empty() ? message_of(error) : diagnostics.front().message;
    instance.attr("diagnostics") = py::cast(diagnostics);
    instance.attr("warnings") = py::cast(warnings);
    PyErr_SetObject(type, instance.ptr());
}

PyObject* new_type(py::module_& module, const char* name, PyObject* base, const char* doc) {
    PyObject* type =
        PyErr_NewExceptionWithDoc((std::string("litkit.") + name).c_str(), doc, base, nullptr);
    if (!type) throw py::error_already_set();
    module.add_object(name, py::handle(type));  // add_object takes a new reference
    Py_INCREF(type);                            // and this one is ours, for good
    return type;
}

}  // namespace

void bind_errors(py::module_& module) {
    error_type = new_type(module, "Error", PyExc_Exception,
                          "Every error litkit raises. str(error) is the diagnostic `litkit check` "
                          "prints; file, line, column (None where unknown) and message say "
                          "where and what; diagnostics lists every problem of a scene.");
    scene_error_type = new_type(module, "SceneError", error_type,
                                "The scene breaks rules of the scene format (all of them are "
                                "listed in diagnostics).");
    io_error_type = new_type(module, "IoError", error_type,
                             "A file could not be read (missing, not UTF-8, not TOML).");
    argument_error_type = new_type(module, "ArgumentError", error_type,
                                   "A function was called with an argument outside its contract "
                                   "(an unknown model name, a size of 0, a normal that is not "
                                   "unit length).");
    py::register_exception_translator([](std::exception_ptr thrown) {
        try {
            if (thrown) std::rethrow_exception(thrown);
        } catch (const litkit::SceneError& error) {
            raise(scene_error_type, error, error.diagnostics(), error.warnings());
        } catch (const litkit::IoError& error) {
            raise(io_error_type, error, {}, {});
        } catch (const litkit::ArgumentError& error) {
            raise(argument_error_type, error, {}, {});
        } catch (const litkit::Error& error) {
            raise(error_type, error, {}, {});
        }
    });
}

}  // namespace litkit_python
