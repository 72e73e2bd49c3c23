#pragma once
// The pieces of the `jtracer` Python module, one file each, registered by
// module.cpp. Everything they do is the core's (or frontend/'s, for what the
// command line does to a scene before it renders): these files only convert
// between Python objects and the core's types.

#include "jtracer/diagnostics.hpp"
#include "jtracer/frontend/argument_names.hpp"
#include "jtracer/image.hpp"
#include "jtracer/render_job.hpp"
#include "jtracer/scene_file.hpp"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <array>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace jt::python {

namespace py = pybind11;

// Diagnostic and SceneError (errors.cpp).
void bind_errors(py::module_& m);
// Diagnostic objects for `diagnostics` of `loaded`, each naming its own file:
// the path as given, or an included file as --check names it.
py::list diagnostic_list(const std::vector<Diagnostic>& diagnostics, const LoadedScene& loaded);
// Raises jtracer.SceneError: its text is `message` (what --check prints), its
// .diagnostics the list.
[[noreturn]] void raise_scene_error(const std::string& message,
                                    const std::vector<Diagnostic>& diagnostics,
                                    const LoadedScene& loaded);
// How the core's and the front end's messages name this module's arguments:
// "width", not "--width"; "set by defines", not "set by --define"; "... or
// pass width= to Scene.render()".
inline const frontend::ArgumentNames python_names = {.values = {.defines = "defines",
                                                                .define_before = "defines['",
                                                                .define_after = "']",
                                                                .clock = "clock="},
                                                     .prefix = "",
                                                     .after_pass = "= to Scene.render()"};
// `work()`, run without the GIL: a read, parse or encode of seconds in which
// the program's other Python threads carry on. `work` touches no Python
// object; its result is returned once the GIL is held again.
template <class Work>
auto without_gil(Work&& work) {
    py::gil_scoped_release unlocked;
    return std::forward<Work>(work)();
}

// Raises OSError with the core's message ("cannot read 'a.png': no such file").
[[noreturn]] void raise_os_error(const std::string& message);

// Arguments converted with errors that name them (arguments.cpp): TypeError
// for the wrong type, ValueError for a wrong value ("width: 1..65535, not 0",
// "path: embedded null byte"). `name` is the argument's as the user wrote it.
std::filesystem::path path_argument(const py::handle& value, const std::string& name);
std::string text_argument(const py::handle& value, const std::string& name);
std::optional<std::string> optional_text_argument(const py::handle& value, const std::string& name);
// An int (not a bool) in low..high.
int int_argument(const py::handle& value, const std::string& name, int low, int high);
std::optional<int> optional_int_argument(const py::handle& value, const std::string& name, int low,
                                         int high);
// A real number (an int or float, not a bool or str) as a double.
double number_argument(const py::handle& value, const std::string& name);
// None, or a dict (a copy of any other Mapping).
std::optional<py::dict> optional_dict_argument(const py::handle& value, const std::string& name);
// None, or four ints x0, y0, x1, y1, each 0..kMaxImageSide.
std::optional<std::array<int, 4>> region_argument(const py::handle& value);

// Arrays, read_image, write_image, diff (images.cpp).
void bind_images(py::module_& m);
// An image as a (height, width, 3) uint8 array, top row first: a copy, or,
// given the image to keep, its own pixels without one.
py::array_t<std::uint8_t> to_array(const Image8& image);
py::array_t<std::uint8_t> to_array(Image8&& image);

// load, parse, check, Scene and its views (scene.cpp).
void bind_scene(py::module_& m);

// A loaded scene as Python holds it. Read-only from Python: every render
// starts from `loaded` and applies its own overrides to a copy.
struct PythonScene {
    LoadedScene loaded;  // as read and checked, without a source map
    std::vector<Diagnostic> warnings;
    // The last render's prepared scene: the next one reuses its acceleration
    // structure (prepare_scene's `previous`). Renders may run at once on
    // several Python threads (the GIL is released), hence the mutex.
    std::mutex prepared_mutex;
    std::shared_ptr<const PreparedScene> prepared;
};

// Scene.render's arguments, converted and in the command line's ranges
// (nullopt: the scene's own).
struct RenderArguments {
    std::optional<int> width, height, samples;
    std::optional<std::string> camera;
    int threads = 0;
    std::optional<std::array<int, 4>> region;  // x0, y0, x1, y1 from the top-left corner
    py::object progress;                       // None or a callable taking a fraction
};

// Scene.render (render.cpp): its arguments as Python passes them, then the render.
RenderArguments render_arguments(const py::handle& width, const py::handle& height,
                                 const py::handle& samples, const py::handle& camera,
                                 const py::handle& threads, const py::handle& region,
                                 py::object progress);
py::array_t<std::uint8_t> render_scene(PythonScene& scene, const RenderArguments& arguments);

}  // namespace jt::python
