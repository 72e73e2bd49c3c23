// The `jtracer` Python module: a thin layer over the core (docs/python.md).

#include "bindings.hpp"

#include "jtracer/version.hpp"

PYBIND11_MODULE(jtracer, m) {
    m.doc() =
        "JTracer from Python: load, check and render .jts scenes to NumPy arrays, compare "
        "and write images, as jtracer-cli does.";
    m.attr("__version__") = std::string(jt::project_version);
    m.attr("version_string") = std::string(jt::version_string());
    jt::python::bind_errors(m);
    jt::python::bind_images(m);
    jt::python::bind_scene(m);
}
