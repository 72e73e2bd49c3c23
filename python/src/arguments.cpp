// Arguments as Python passes them, converted here rather than by pybind11's
// casters: a caster that refuses a value (a path with a NUL byte, a str with
// a lone surrogate, an int past 32 bits) makes pybind11 raise its generic
// "incompatible function arguments" TypeError, which names neither the
// argument nor what is wrong with it. These raise what Python's own
// functions raise for the same mistake, with the argument's name first.

#include "bindings.hpp"

#include "jtracer/limits.hpp"

#include <climits>
#include <cstring>

namespace jt::python {

namespace {

std::string type_name(const py::handle& value) {
    return py::str(py::type::of(value).attr("__name__")).cast<std::string>();
}

// The bytes of a str (`encode`: UTF-8 strictly, or the file system's encoding
// as os.fsencode), or ValueError naming the argument, as str.encode's
// UnicodeEncodeError does ("'utf-8' codec can't encode character '\udc80' in
// position 3: surrogates not allowed").
std::string encoded(const py::handle& text, const std::string& name, bool file_system) {
    PyObject* bytes =
        file_system ? PyUnicode_EncodeFSDefault(text.ptr()) : PyUnicode_AsUTF8String(text.ptr());
    if (!bytes) {
        const py::error_already_set failure;
        throw py::value_error(
            name + ": " + std::string(failure.what()).substr(std::strlen("UnicodeEncodeError: ")));
    }
    const py::bytes held = py::reinterpret_steal<py::bytes>(bytes);
    return held.cast<std::string>();
}

}  // namespace

std::filesystem::path path_argument(const py::handle& value, const std::string& name) {
    if (!py::isinstance<py::str>(value) && !py::isinstance<py::bytes>(value) &&
        !py::hasattr(value, "__fspath__"))
        throw py::type_error(name + ": a str, bytes or os.PathLike path, not " + type_name(value));
    PyObject* fspath = PyOS_FSPath(value.ptr());
    if (!fspath) throw py::error_already_set();  // __fspath__ raised or returned no path
    const py::object path = py::reinterpret_steal<py::object>(fspath);
    const std::string bytes =
        py::isinstance<py::str>(path) ? encoded(path, name, true) : path.cast<std::string>();
    // As open() and os.stat() refuse it: no file name holds a NUL.
    if (bytes.find('\0') != std::string::npos) throw py::value_error(name + ": embedded null byte");
    return std::filesystem::path(bytes);
}

std::string text_argument(const py::handle& value, const std::string& name) {
    if (!py::isinstance<py::str>(value))
        throw py::type_error(name + ": a str, not " + type_name(value));
    return encoded(value, name, false);
}

std::optional<std::string> optional_text_argument(const py::handle& value,
                                                  const std::string& name) {
    if (value.is_none()) return std::nullopt;
    return text_argument(value, name);
}

int int_argument(const py::handle& value, const std::string& name, int low, int high) {
    // bool is an int subclass, but True is no size or count.
    if (py::isinstance<py::bool_>(value) || !PyIndex_Check(value.ptr()))
        throw py::type_error(name + ": an int, not " + type_name(value));
    const py::int_ number = py::reinterpret_steal<py::int_>(PyNumber_Index(value.ptr()));
    if (!number) throw py::error_already_set();
    int overflow = 0;
    const long long n = PyLong_AsLongLongAndOverflow(number.ptr(), &overflow);
    if (overflow == 0 && n == -1 && PyErr_Occurred()) throw py::error_already_set();
    if (overflow != 0 || n < low || n > high)
        throw py::value_error(name + ": " + std::to_string(low) + ".." + std::to_string(high) +
                              ", not " + py::repr(number).cast<std::string>());
    return static_cast<int>(n);
}

std::optional<int> optional_int_argument(const py::handle& value, const std::string& name, int low,
                                         int high) {
    if (value.is_none()) return std::nullopt;
    return int_argument(value, name, low, high);
}

double number_argument(const py::handle& value, const std::string& name) {
    // A str or a bool converts to a float too ("2", True), but is no number
    // the user meant.
    if (py::isinstance<py::bool_>(value) || py::isinstance<py::str>(value) ||
        py::isinstance<py::bytes>(value) ||
        !(PyFloat_Check(value.ptr()) || PyIndex_Check(value.ptr()) ||
          py::hasattr(value, "__float__")))
        throw py::type_error(name + ": a number, not " + type_name(value));
    const double number = PyFloat_AsDouble(value.ptr());
    if (number == -1.0 && PyErr_Occurred()) {
        if (!PyErr_ExceptionMatches(PyExc_OverflowError)) throw py::error_already_set();
        PyErr_Clear();
        throw py::value_error(name + ": a finite number, not one too large for a double");
    }
    return number;
}

std::optional<py::dict> optional_dict_argument(const py::handle& value, const std::string& name) {
    if (value.is_none()) return std::nullopt;
    if (py::isinstance<py::dict>(value)) return py::reinterpret_borrow<py::dict>(value);
    const py::object mapping = py::module_::import("collections.abc").attr("Mapping");
    if (py::isinstance(value, mapping)) return py::dict(py::reinterpret_borrow<py::object>(value));
    throw py::type_error(name + ": a dict, not " + type_name(value));
}

std::optional<std::array<int, 4>> region_argument(const py::handle& value) {
    if (value.is_none()) return std::nullopt;
    if (py::isinstance<py::str>(value) || !py::isinstance<py::sequence>(value))
        throw py::type_error("region: four ints (x0, y0, x1, y1), not " + type_name(value));
    const py::sequence items = py::reinterpret_borrow<py::sequence>(value);
    if (items.size() != 4)
        throw py::value_error("region: four ints (x0, y0, x1, y1), not " +
                              std::to_string(items.size()));
    std::array<int, 4> corners{};
    for (std::size_t i = 0; i < corners.size(); ++i)
        corners[i] = int_argument(items[i], "region[" + std::to_string(i) + "]", 0, kMaxImageSide);
    return corners;
}

}  // namespace jt::python
