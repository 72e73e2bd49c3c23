// jtracer.load, parse and check, and the Scene they return with its read-only
// views. A view's attributes are the schema's properties (schema.hpp), named
// and converted from the table, so that a property added there shows here.

#include "bindings.hpp"

#include "jtracer/frontend/render_flags.hpp"
#include "jtracer/parallel_chunks.hpp"
#include "jtracer/schema.hpp"
#include "jtracer/source_serializer.hpp"

#include <pybind11/operators.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <new>
#include <optional>

namespace jt::python {

namespace {

// A property's value as Python holds it: int, float, str, a tuple of three
// floats for vectors and colours.
py::object to_python(int value) {
    return py::int_(value);
}
py::object to_python(double value) {
    return py::float_(value);
}
py::object to_python(const std::string& value) {
    return py::str(value);
}
py::object to_python(const Vec3& value) {
    return py::make_tuple(value.x, value.y, value.z);
}
// An unset value (a focus distance that follows look_at, no smooth_angle) is None.
template <class T>
py::object to_python(const std::optional<T>& value) {
    return value ? to_python(*value) : py::none();
}

// A class whose attributes are the block's schema properties, read-only, with
// a repr listing them and to_dict().
template <class Block>
void bind_view(py::module_& m, const char* name, const char* doc) {
    py::class_<Block> view(m, name, doc);
    for (const PropertySpec<Block>& property : schema_of<Block>().properties) {
        const PropertySpec<Block>* spec = &property;  // the tables are static
        view.def_property_readonly(std::string(property.name).c_str(), [spec](const Block& b) {
            return with_member(*spec, b, [](const auto& v) { return to_python(v); });
        });
    }
    view.def(
        "to_dict",
        [](const Block& b) {
            py::dict values;
            for (const PropertySpec<Block>& p : schema_of<Block>().properties)
                values[py::str(std::string(p.name))] =
                    with_member(p, b, [](const auto& v) { return to_python(v); });
            return values;
        },
        "The properties by their names in the scene language");
    view.def("__repr__", [name](const Block& b) {
        std::string text = std::string(name) + "(";
        bool first = true;
        for (const PropertySpec<Block>& p : schema_of<Block>().properties) {
            const py::object value = with_member(p, b, [](const auto& v) { return to_python(v); });
            text += (first ? "" : ", ") + std::string(p.name) + "=" +
                    py::repr(value).cast<std::string>();
            first = false;
        }
        return text + ")";
    });
    view.def(py::self == py::self);
}

// What `jtracer-cli --check` reports for a loaded scene, one just read or
// parsed (so the checks may take its primitives as parsed).
// Without the GIL: checking reads every model and picture the scene names,
// which for a large one takes seconds that other Python threads may use.
std::vector<Diagnostic> findings(const LoadedScene& loaded) {
    py::gil_scoped_release unlocked;
    std::vector<Diagnostic> diagnostics = check_scene(
        loaded, {.validation = {.run_chunks = parallel_chunks(), .primitives_as_parsed = true}});
    frontend::name_setting_flags(diagnostics, python_names);
    return diagnostics;
}

// A width or height of 0 is an error of the frame, not of the scene:
// render(width=, height=) may still set it, as --width/--height do for a file
// without them, and render() reports it when it does not.
std::shared_ptr<PythonScene> checked_scene(LoadedScene loaded) {
    std::vector<Diagnostic> diagnostics = findings(loaded);
    if (std::any_of(diagnostics.begin(), diagnostics.end(), [](const Diagnostic& d) {
            return d.severity == Severity::error && !asks_for_frame_size(d);
        }))
        raise_scene_error(format_diagnostics(diagnostics, loaded), diagnostics, loaded);
    std::erase_if(diagnostics, asks_for_frame_size);
    auto scene = std::make_shared<PythonScene>();
    scene->loaded = std::move(loaded);
    scene->warnings = std::move(diagnostics);
    return scene;
}

// The `defines` argument of load() and parse() as ParseOptions, as
// jtracer-cli's --define NAME=VALUE: a number (int or float), three numbers
// (a vector), or a str holding the value as a file writes it ('"out.png"' for a
// string, "2 * pi" for an expression). Raises TypeError or ValueError.
// `clock` is --clock's value: any finite number (docs/language.md §15.4).
ParseOptions options_with(const py::handle& defines_object, const py::handle& clock_object) {
    const std::optional<py::dict> defines = optional_dict_argument(defines_object, "defines");
    const double clock = number_argument(clock_object, "clock");
    ParseOptions options;
    options.source_map = false;
    if (!std::isfinite(clock))
        throw py::value_error("clock: a finite number, not " +
                              py::repr(py::float_(clock)).cast<std::string>());
    options.clock = clock;
    options.value_names = python_names.values;
    if (!defines) return options;
    for (const auto& [key, value] : *defines) {
        if (!py::isinstance<py::str>(key)) throw py::type_error("defines: the names must be str");
        const std::string name = text_argument(key, "defines");
        auto number_text = [&](py::handle v) -> std::string {
            if (py::isinstance<py::bool_>(v) ||
                !(py::isinstance<py::int_>(v) || py::isinstance<py::float_>(v)))
                throw py::type_error("defines['" + name +
                                     "']: expected a number, three numbers or a str");
            // A nan, an inf or an int past the doubles would otherwise reach
            // the scene language as its repr: "unknown name 'nan' at column 1".
            const double number = PyFloat_AsDouble(v.ptr());
            if (number == -1.0 && PyErr_Occurred()) {
                PyErr_Clear();
                throw py::value_error("defines['" + name +
                                      "']: a finite number, not one too large for a double");
            }
            if (!std::isfinite(number))
                throw py::value_error("defines['" + name + "']: a finite number, not " +
                                      py::repr(v).cast<std::string>());
            return py::repr(v).cast<std::string>();
        };
        std::string text;
        if (py::isinstance<py::str>(value)) {
            text = text_argument(value, "defines['" + name + "']");
        } else if (py::isinstance<py::sequence>(value)) {
            const py::sequence items = value.cast<py::sequence>();
            if (items.size() != 3)
                throw py::value_error("defines['" + name + "']: a vector takes three numbers");
            text = "<" + number_text(items[0]) + ", " + number_text(items[1]) + ", " +
                   number_text(items[2]) + ">";
        } else {
            text = number_text(value);
        }
        Expected<Define> define = parse_define(name + "=" + text, python_names.values);
        if (!define)
            throw py::value_error(python_names.values.define(name) + ": " + define.error().message);
        options.defines.push_back(std::move(*define));
    }
    return options;
}

// The scene's text, keeping its file's names: the file was read without the
// source map (as jtracer-cli reads it), so it is parsed again with it.
std::string scene_text(const PythonScene& s) {
    ParseOptions options = s.loaded.options;
    options.source_map = true;
    const ParseResult parsed = parse_scene(s.loaded.text, options);
    return serialize_scene(s.loaded.parsed.scene, {s.loaded.text, parsed, options.defines});
}

// As jtracer-cli reads a file: without the source map, which check_scene
// builds only when there is something to locate.
LoadedScene read_file(const std::filesystem::path& path, const ParseOptions& options) {
    Expected<LoadedScene> loaded = without_gil([&] { return load_scene_file(path, options); });
    if (!loaded) raise_os_error(loaded.error().message);
    return std::move(*loaded);
}

}  // namespace

void bind_scene(py::module_& m) {
    bind_view<RenderSettings>(m, "Settings",
                              "A scene's render_settings block (read-only): its properties by "
                              "their names in the scene language.");
    bind_view<Camera>(m, "Camera",
                      "One perspective_camera block (read-only): its properties by their "
                      "names in the scene language.");

    py::class_<PythonScene, std::shared_ptr<PythonScene>>(
        m, "Scene",
        "A scene read and checked without errors. Read-only: render() applies its own "
        "overrides to a copy.")
        .def_property_readonly(
            "path", [](const PythonScene& s) { return s.loaded.path; },
            "The file as given to load(), or parse()'s path")
        .def_property_readonly("settings",
                               [](const PythonScene& s) { return s.loaded.parsed.scene.settings; })
        .def_property_readonly("cameras",
                               [](const PythonScene& s) { return s.loaded.parsed.scene.cameras; })
        .def_property_readonly(
            "warnings", [](const PythonScene& s) { return diagnostic_list(s.warnings, s.loaded); },
            "The warnings `jtracer-cli --check` prints for it, as Diagnostic objects")
        .def("text", &scene_text,
             "The scene as canonical .jts text (every block and property written out), "
             "keeping the file's definitions, named materials, and the values it wrote as "
             "names or expressions; the defines given to load() or parse() replace the "
             "file's own definitions of those names, so that parse() reads it back as the "
             "same scene")
        .def(
            "render",
            [](PythonScene& s, const py::object& width, const py::object& height,
               const py::object& samples, const py::object& camera, const py::object& threads,
               const py::object& region, py::object progress) {
                return render_scene(s, render_arguments(width, height, samples, camera, threads,
                                                        region, std::move(progress)));
            },
            py::arg("width") = py::none(), py::arg("height") = py::none(),
            py::arg("samples") = py::none(), py::arg("camera") = py::none(), py::arg("threads") = 0,
            py::arg("region") = py::none(), py::arg("progress") = py::none(),
            "Renders as `jtracer-cli` renders the same scene with the same options and "
            "returns the image as a (height, width, 3) uint8 array, the top row first; the "
            "same bytes as jtracer-cli's BMP. width, height, samples and camera (a name) "
            "override the scene's; threads=0 uses every core. region=(x0, y0, x1, y1), "
            "counted from the top-left corner as --region, renders only those pixels (the "
            "rest stays black). progress, when given, is called with the fraction done "
            "(0..1) now and then, on the calling thread. The GIL is released while the "
            "render runs; Ctrl+C stops it with KeyboardInterrupt.")
        .def("__repr__", [](const PythonScene& s) {
            const Scene& scene = s.loaded.parsed.scene;
            return "<jtracer.Scene " + py::repr(py::str(s.loaded.path)).cast<std::string>() + ": " +
                   std::to_string(scene.primitives.size()) + " primitives, " +
                   std::to_string(scene.lights.size()) + " lights, " +
                   std::to_string(scene.cameras.size()) + " cameras>";
        });

    m.def(
        "load",
        [](const py::object& path, const py::object& defines, const py::object& clock) {
            const ParseOptions options = options_with(defines, clock);
            return checked_scene(read_file(path_argument(path, "path"), options));
        },
        py::arg("path"), py::arg("defines") = py::none(), py::arg("clock") = py::float_(0.0),
        "Reads and checks a .jts file. Raises SceneError (with .diagnostics) when it has "
        "errors, OSError when it cannot be read. defines, a dict, sets names as "
        "jtracer-cli's --define NAME=VALUE does: a number, three numbers (a vector), or a "
        "str holding the value as a file writes it ('\"out.png\"', \"2 * pi\"); the "
        "file's own definitions of those names are then ignored. A bad name or value "
        "raises ValueError. clock is the value of `clock` in the scene, as jtracer-cli's "
        "--clock V (a finite number; default 0).");
    m.def(
        "parse",
        [](const py::object& text_object, const py::object& path_object, const py::object& defines,
           const py::object& clock) {
            std::string text = text_argument(text_object, "text");
            const std::filesystem::path path = path_argument(path_object, "path");
            const ParseOptions options = options_with(defines, clock);
            // A text of no file has no main file: its includes are read from
            // the working directory and its messages name the main text
            // "<text>". An empty path gives load_scene_text no main file.
            const bool of_no_file = path == "<string>";
            Expected<LoadedScene> loaded = without_gil([&] {
                return load_scene_text(std::move(text), of_no_file ? std::filesystem::path{} : path,
                                       options);
            });
            // It fails only when out of memory: MemoryError, not OSError.
            if (!loaded) throw std::bad_alloc();
            loaded->path = path.string();
            return checked_scene(std::move(*loaded));
        },
        py::arg("text"), py::arg("path") = "<string>", py::arg("defines") = py::none(),
        py::arg("clock") = py::float_(0.0),
        "Parses and checks .jts text. `path` names it in diagnostics, and its folder is "
        "where the scene's relative file names (includes, meshes, image maps) are found; "
        "the default, \"<string>\", looks in the current directory. defines and clock as for "
        "load(). "
        "Raises SceneError.");
    m.def(
        "check",
        [](const py::object& path, const py::object& defines, const py::object& clock) {
            const LoadedScene loaded =
                read_file(path_argument(path, "path"), options_with(defines, clock));
            return diagnostic_list(findings(loaded), loaded);
        },
        py::arg("path"), py::arg("defines") = py::none(), py::arg("clock") = py::float_(0.0),
        "What `jtracer-cli --check` reports for a .jts file, errors and warnings, as a list "
        "of Diagnostic objects (empty: none); defines and clock as for load(). Raises "
        "OSError when it cannot be read.");
}

}  // namespace jt::python
