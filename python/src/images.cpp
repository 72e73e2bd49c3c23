// Images as NumPy arrays: (height, width, 3) uint8, the top row first, as
// NumPy, Pillow and matplotlib hold pictures. The core's Image8 counts rows
// from the bottom (image.hpp), so each conversion flips the rows.
// write_image and diff are the core's, as jtracer-cli uses them; read_image
// reads a picture as an image map does, JPEG included.

#include "bindings.hpp"

#include "jtracer/image.hpp"
#include "jtracer/image_diff.hpp"
#include "jtracer/image_file.hpp"
#include "jtracer/limits.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <memory>
#include <vector>

namespace jt::python {

namespace {

// `name` is the argument's, first in the message as for every argument.
Image8 from_array(const py::array& array, const std::string& name) {
    if (!py::isinstance<py::array_t<std::uint8_t>>(array) ||
        !array.dtype().is(py::dtype::of<std::uint8_t>()))
        throw py::type_error(name + ": a uint8 array, not " +
                             py::str(array.dtype()).cast<std::string>());
    if (array.ndim() != 3 || array.shape(2) != 3)
        throw py::value_error(name + ": an array of shape (height, width, 3), not " +
                              py::str(py::tuple(array.attr("shape"))).cast<std::string>());
    const auto pixels = array.unchecked<std::uint8_t, 3>();
    const py::ssize_t height = pixels.shape(0), width = pixels.shape(1);
    if (width < 1 || height < 1 || width > kMaxImageSide || height > kMaxImageSide)
        throw py::value_error(name + ": 1.." + std::to_string(kMaxImageSide) +
                              " pixels on each side, not " + std::to_string(width) + "x" +
                              std::to_string(height));
    Image8 image(static_cast<int>(width), static_cast<int>(height));
    for (py::ssize_t row = 0; row < height; ++row) {
        std::uint8_t* out = image.pixel(0, flipped_row(static_cast<int>(row), image.height));
        for (py::ssize_t x = 0; x < width; ++x)
            for (py::ssize_t c = 0; c < 3; ++c) *out++ = pixels(row, x, c);
    }
    return image;
}

// The file is read and decoded without the GIL: a large picture takes a
// second, in which the program's other Python threads carry on. `read` is
// read_image (diff's references, BMP or PNG as jtracer-cli diff reads them)
// or read_shown_image.
Image8 read_or_raise(const std::filesystem::path& path,
                     Expected<Image8> (*read)(const std::filesystem::path&) = read_image) {
    Expected<Image8> image = without_gil([&] { return read(path); });
    if (!image) raise_os_error(image.error().message);
    return std::move(*image);
}

// `name` is the argument's, for the TypeError of anything else: pybind11's
// own cast failure is a RuntimeError that names no argument or type.
Image8 image_or_path(const py::object& value, const char* name) {
    if (py::isinstance<py::array>(value)) return from_array(value.cast<py::array>(), name);
    if (py::isinstance<py::str>(value) || py::isinstance<py::bytes>(value) ||
        py::hasattr(value, "__fspath__"))
        return read_or_raise(path_argument(value, name));
    throw py::type_error(std::string(name) +
                         ": an image (a uint8 array) or the path of a BMP or PNG file, not " +
                         py::str(py::type::of(value).attr("__name__")).cast<std::string>());
}

}  // namespace

py::array_t<std::uint8_t> to_array(const Image8& image) {
    py::array_t<std::uint8_t> array({image.height, image.width, 3});
    std::uint8_t* out = array.mutable_data();
    const std::size_t row_bytes = static_cast<std::size_t>(image.width) * 3;
    for (int row = 0; row < image.height; ++row)
        std::memcpy(out + row * row_bytes, image.pixel(0, flipped_row(row, image.height)),
                    row_bytes);
    return array;
}

py::array_t<std::uint8_t> to_array(Image8&& image) {
    // The rows are turned round where they are, and the array keeps the
    // image's own buffer: a picture read or rendered costs its pixels once.
    const std::size_t row_bytes = static_cast<std::size_t>(image.width) * 3;
    for (int row = 0; row < image.height / 2; ++row)
        std::swap_ranges(image.pixel(0, row), image.pixel(0, row) + row_bytes,
                         image.pixel(0, image.height - 1 - row));
    const py::ssize_t height = image.height, width = image.width;
    auto pixels = std::make_unique<std::vector<std::uint8_t>>(std::move(image.rgb));
    std::uint8_t* data = pixels->data();
    py::capsule owner(pixels.get(),
                      [](void* held) { delete static_cast<std::vector<std::uint8_t>*>(held); });
    pixels.release();  // the capsule's deleter frees it
    return py::array_t<std::uint8_t>({height, width, py::ssize_t{3}}, data, owner);
}

void bind_images(py::module_& m) {
    m.def(
        "read_image",
        [](const py::object& path) {
            return to_array(read_or_raise(path_argument(path, "path"), read_shown_image));
        },
        py::arg("path"),
        "Reads a BMP, PNG or JPEG (told apart by their first bytes) as a (height, width, 3) "
        "uint8 array, the top row first, as an image_map shows it: a JPEG turned upright by "
        "its EXIF orientation. Raises OSError when it cannot.");
    m.def(
        "write_image",
        [](const py::object& path_object, const py::object& array) {
            const std::filesystem::path path = path_argument(path_object, "path");
            if (!py::isinstance<py::array>(array))
                throw py::type_error(
                    "image: a (height, width, 3) uint8 array, not " +
                    py::str(py::type::of(array).attr("__name__")).cast<std::string>());
            const Image8 image = from_array(array.cast<py::array>(), "image");
            // Encoding a large PNG takes a while.
            const Expected<void> written =
                without_gil([&] { return write_image(path, image, format_from_extension(path)); });
            if (!written) raise_os_error(written.error().message);
        },
        py::arg("path"), py::arg("image"),
        "Writes a (height, width, 3) uint8 array as jtracer-cli writes images: PNG for a "
        "name ending in .png, BMP otherwise; through a temporary file, so that a failed "
        "write leaves no partial file. Raises OSError when it cannot.");

    py::class_<ImageDiff>(m, "Diff",
                          "jtracer.diff's result: the figures `jtracer-cli diff` prints.")
        .def_readonly("same_size", &ImageDiff::same_size)
        .def_readonly("max_difference", &ImageDiff::max_channel_difference,
                      "The largest difference of one channel of one pixel, 0..255")
        .def_readonly("pixels", &ImageDiff::pixels, "Pixels in each image (same size only)")
        .def_readonly("pixels_over", &ImageDiff::pixels_over,
                      "Pixels with a channel differing by more than the threshold")
        .def_readonly("percent_over", &ImageDiff::percent_over, "pixels_over, in % of pixels")
        .def_readonly("mae", &ImageDiff::mean_absolute_error,
                      "Mean absolute difference over every channel, 0..255")
        .def_readonly("psnr", &ImageDiff::psnr, "Peak signal-to-noise ratio in dB; inf: equal")
        .def_property_readonly(
            "heat_map",
            [](const ImageDiff& d) -> py::object {
                if (!d.same_size) return py::none();
                return to_array(d.image);
            },
            "The differences as `jtracer-cli diff -o` writes them (None when the sizes differ)")
        .def("__repr__", [](const ImageDiff& d) {
            if (!d.same_size) return std::string("Diff(same_size=False)");
            char text[200];
            std::snprintf(text, sizeof text,
                          "Diff(same_size=True, max_difference=%d, pixels_over=%zu, "
                          "mae=%.4f, psnr=%s)",
                          d.max_channel_difference, d.pixels_over, d.mean_absolute_error,
                          std::isinf(d.psnr) ? "inf" : std::to_string(d.psnr).c_str());
            return std::string(text);
        });
    m.def(
        "diff",
        [](const py::object& expected, const py::object& actual, const py::object& limit) {
            const int threshold = int_argument(limit, "threshold", 0, 255);
            const Image8 a = image_or_path(expected, "expected");
            const Image8 b = image_or_path(actual, "actual");
            py::gil_scoped_release unlocked;
            return diff_images(a, b, threshold);
        },
        py::arg("expected"), py::arg("actual"), py::arg("threshold") = 0,
        "Compares two images (arrays or paths to BMP or PNG files) as `jtracer-cli diff` does: "
        "`threshold` is the largest channel difference still counted as equal.");
}

}  // namespace jt::python
