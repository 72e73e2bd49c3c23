// How the module fails: jtracer.SceneError holding jtracer.Diagnostic objects
// (the scene language's findings as `jtracer-cli --check` prints them, one
// object each), and OSError for what the core reports as an I/O error.

#include "bindings.hpp"

#include "jtracer/source_files.hpp"

#include <pybind11/operators.h>

#include <utility>

namespace jt::python {

namespace {

// One finding with the file it is about. line and column are 0 for a finding
// about the file as a whole, as in the core.
struct PythonDiagnostic {
    std::string file;
    int line = 0;
    int column = 0;
    std::string severity;  // "error", "warning" or "note"
    std::string message;
    bool operator==(const PythonDiagnostic&) const = default;
};

// "scene.jts:3:12: error: MESSAGE": the first line --check prints for it.
std::string header_line(const PythonDiagnostic& d) {
    const Severity severity = d.severity == "error"     ? Severity::error
                              : d.severity == "warning" ? Severity::warning
                                                        : Severity::note;
    const Diagnostic core{severity, {d.line, d.column}, d.message};
    const std::string text = format_diagnostic(core, d.file, {});
    return text.substr(0, text.find('\n'));
}

// The exception class, made once by bind_errors and kept for the life of
// the process (a module's types are never unloaded).
PyObject* scene_error_type = nullptr;

// A path is bytes, not always UTF-8 (a folder named in Latin-1), and the
// messages quote paths: pybind11's strict decoding would turn a scene's
// errors into a UnicodeDecodeError. A file name decodes as os.fsdecode does
// (surrogateescape), so that it names the file Python opened; a message with
// U+FFFD for such a byte, so that it prints.
py::str decoded(const std::string& text, const char* errors) {
    PyObject* str = PyUnicode_DecodeUTF8(text.data(), static_cast<Py_ssize_t>(text.size()), errors);
    if (!str) throw py::error_already_set();
    return py::reinterpret_steal<py::str>(str);
}
py::str file_str(const std::string& file) {
    return decoded(file, "surrogateescape");
}
py::str message_str(const std::string& message) {
    return decoded(message, "replace");
}

}  // namespace

py::list diagnostic_list(const std::vector<Diagnostic>& diagnostics, const LoadedScene& loaded) {
    py::list list;
    for (const Diagnostic& d : diagnostics)
        list.append(PythonDiagnostic{
            std::string(file_name(loaded.parsed.source.files, loaded.path, d.pos.file)), d.pos.line,
            d.pos.column,
            d.severity == Severity::error     ? "error"
            : d.severity == Severity::warning ? "warning"
                                              : "note",
            d.message});
    return list;
}

void raise_scene_error(const std::string& message, const std::vector<Diagnostic>& diagnostics,
                       const LoadedScene& loaded) {
    std::string text = message;
    if (!text.empty() && text.back() == '\n') text.pop_back();
    py::object error = py::reinterpret_borrow<py::object>(scene_error_type)(message_str(text));
    error.attr("diagnostics") = diagnostic_list(diagnostics, loaded);
    PyErr_SetObject(scene_error_type, error.ptr());
    throw py::error_already_set();
}

void raise_os_error(const std::string& message) {
    PyErr_SetObject(PyExc_OSError, message_str(message).ptr());
    throw py::error_already_set();
}

void bind_errors(py::module_& m) {
    py::class_<PythonDiagnostic>(m, "Diagnostic",
                                 "A finding in a scene file: where, how bad, and what.")
        .def(py::init([](std::string file, int line, int column, std::string severity,
                         std::string message) {
                 if (severity != "error" && severity != "warning" && severity != "note")
                     throw py::value_error("severity: \"error\", \"warning\" or \"note\", not \"" +
                                           severity + "\"");
                 return PythonDiagnostic{std::move(file), line, column, std::move(severity),
                                         std::move(message)};
             }),
             py::arg("file"), py::arg("line"), py::arg("column"), py::arg("severity"),
             py::arg("message"))
        .def_property_readonly(
            "file", [](const PythonDiagnostic& d) { return file_str(d.file); },
            "The file as it was given")
        .def_readonly("line", &PythonDiagnostic::line, "1-based; 0 when about the whole file")
        .def_readonly("column", &PythonDiagnostic::column, "1-based, in bytes; 0 with line 0")
        .def_readonly("severity", &PythonDiagnostic::severity,
                      "\"error\", \"warning\" or \"note\" (a --define that replaces a "
                      "definition)")
        .def_property_readonly("message",
                               [](const PythonDiagnostic& d) { return message_str(d.message); })
        .def("__str__", [](const PythonDiagnostic& d) { return message_str(header_line(d)); })
        .def("__repr__",
             [](const PythonDiagnostic& d) {
                 return "Diagnostic(file=" + py::repr(file_str(d.file)).cast<std::string>() +
                        ", line=" + std::to_string(d.line) +
                        ", column=" + std::to_string(d.column) +
                        ", severity=" + py::repr(py::str(d.severity)).cast<std::string>() +
                        ", message=" + py::repr(message_str(d.message)).cast<std::string>() + ")";
             })
        .def(py::self == py::self)
        .def("__hash__", [](const PythonDiagnostic& d) {
            return py::hash(py::make_tuple(file_str(d.file), d.line, d.column, d.severity,
                                           message_str(d.message)));
        });

    scene_error_type = PyErr_NewExceptionWithDoc(
        "jtracer.SceneError",
        "A scene with errors. str() is what `jtracer-cli --check` prints; .diagnostics "
        "lists them (warnings included) as Diagnostic objects.",
        PyExc_Exception, nullptr);
    if (!scene_error_type) throw py::error_already_set();
    m.add_object("SceneError", py::reinterpret_borrow<py::object>(scene_error_type));
}

}  // namespace jt::python
