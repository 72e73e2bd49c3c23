# read_image, write_image and diff against jtracer-cli's files and figures.
import re
import struct

import jtracer
import numpy as np
import pytest
from conftest import bmp_pixels, run


def gradient(height=7, width=5):
    y, x = np.mgrid[0:height, 0:width]
    return np.stack([x * 40, y * 30, (x + y) * 9], axis=-1).astype(np.uint8)


@pytest.mark.parametrize("name", ["a.png", "a.bmp", "A.PNG"])
def test_write_then_read_gives_the_array_back(tmp_path, name):
    image = gradient()
    jtracer.write_image(tmp_path / name, image)
    assert np.array_equal(jtracer.read_image(tmp_path / name), image)


def test_write_image_picks_the_format_and_row_order_as_the_cli(tmp_path):
    image = gradient()
    jtracer.write_image(tmp_path / "a.bmp", image)
    jtracer.write_image(str(tmp_path / "a.png"), image)
    assert (tmp_path / "a.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    # Top row first in the array, bottom row first in the BMP, as a BMP holds it.
    assert np.array_equal(bmp_pixels(tmp_path / "a.bmp"), image)
    # A strided view writes the pixels it shows.
    flipped = image[::-1, ::2]
    jtracer.write_image(tmp_path / "b.png", flipped)
    assert np.array_equal(jtracer.read_image(tmp_path / "b.png"), flipped)


def test_bad_arrays_and_paths_are_clear_errors(tmp_path):
    with pytest.raises(TypeError, match="uint8"):
        jtracer.write_image(tmp_path / "f.png", gradient().astype(np.float32))
    with pytest.raises(ValueError, match="shape"):
        jtracer.write_image(tmp_path / "g.png", np.zeros((4, 4), np.uint8))
    with pytest.raises(ValueError, match="pixels on each side"):
        jtracer.write_image(tmp_path / "e.png", np.zeros((0, 4, 3), np.uint8))
    with pytest.raises(OSError, match="cannot"):
        jtracer.write_image(tmp_path / "no" / "such" / "dir.png", gradient())
    assert not (tmp_path / "no").exists()
    (tmp_path / "junk.png").write_bytes(b"not an image")
    with pytest.raises(OSError, match="junk.png"):
        jtracer.read_image(tmp_path / "junk.png")
    with pytest.raises(OSError, match="missing.png"):
        jtracer.diff(tmp_path / "missing.png", gradient())


def cli_figures(printed):
    """The figures `jtracer-cli diff` prints, by the module's names."""
    psnr = re.search(r"^PSNR: (\S+)", printed, re.M).group(1)
    return {
        "max_difference": int(re.search(r"^max channel difference: (\d+)", printed, re.M).group(1)),
        "pixels_over": int(re.search(r"^pixels over threshold \d+: (\d+) of", printed, re.M).group(1)),
        "pixels": int(re.search(r" of (\d+) \(", printed).group(1)),
        "mae": float(re.search(r"^mean absolute error: (\S+)", printed, re.M).group(1)),
        "psnr": float(psnr),
    }


@pytest.mark.parametrize("threshold", [0, 3, 40])
def test_diff_has_the_cli_figures(tmp_path, cli, threshold):
    a = gradient(30, 20)
    b = a.copy()
    b[3, 4] = [255, 0, 0]
    b[10:12, 5:9, 1] += 5
    jtracer.write_image(tmp_path / "a.png", a)
    jtracer.write_image(tmp_path / "b.bmp", b)
    code, printed, _ = run(cli, "diff", tmp_path / "a.png", tmp_path / "b.bmp",
                           "--threshold", threshold, "-o", tmp_path / "heat.png", check=False)
    assert code == 1
    d = jtracer.diff(a, tmp_path / "b.bmp", threshold=threshold)
    figures = cli_figures(printed)
    assert d.same_size
    assert (d.max_difference, d.pixels_over, d.pixels) == (
        figures["max_difference"], figures["pixels_over"], figures["pixels"])
    assert d.max_difference == 95 and d.pixels == 600  # |(160, 90, 63) - (255, 0, 0)|
    assert d.pixels_over == {0: 9, 3: 9, 40: 1}[threshold]
    assert d.mae == pytest.approx(figures["mae"], abs=5e-5)
    assert d.psnr == pytest.approx(figures["psnr"], abs=5e-3)
    assert d.percent_over == pytest.approx(100.0 * d.pixels_over / 600)
    assert np.array_equal(d.heat_map, jtracer.read_image(tmp_path / "heat.png"))


def test_diff_of_equal_and_of_different_sizes():
    a = gradient()
    same = jtracer.diff(a, a.copy())
    assert (same.max_difference, same.pixels_over, same.mae) == (0, 0, 0.0)
    assert same.psnr == float("inf")
    other = jtracer.diff(a, gradient(8, 5))
    assert not other.same_size and other.heat_map is None
    with pytest.raises(ValueError, match="threshold"):
        jtracer.diff(a, a, threshold=256)


def test_diff_of_neither_an_array_nor_a_path_is_a_type_error_naming_the_argument(tmp_path):
    image = np.zeros((2, 2, 3), np.uint8)
    jtracer.write_image(tmp_path / "z.png", image)
    with pytest.raises(TypeError, match=r"^expected: an image \(a uint8 array\) or the path "
                                        r"of a BMP or PNG file, not int$"):
        jtracer.diff(3, image)
    with pytest.raises(TypeError, match="^actual: .*, not list$"):
        jtracer.diff(image, [[0, 0, 0]])
    # Paths of every kind still are paths.
    for path in (tmp_path / "z.png", str(tmp_path / "z.png"), bytes(tmp_path / "z.png")):
        assert jtracer.diff(path, image).max_difference == 0


def test_a_device_is_refused_at_once(tmp_path):
    # Read whole, /dev/zero took all the memory there was.
    with pytest.raises(OSError, match="it is a device, not a file"):
        jtracer.read_image("/dev/zero")
    with pytest.raises(OSError, match="it is a device, not a file"):
        jtracer.diff("/dev/urandom", np.zeros((2, 2, 3), np.uint8))


def jpeg_frame_size(data):
    """(height, width) from a JPEG's frame header, read here rather than by the module."""
    at = 2
    while True:
        marker, length = data[at + 1], struct.unpack(">H", data[at + 2:at + 4])[0]
        if marker in (0xC0, 0xC1, 0xC2):
            return struct.unpack(">HH", data[at + 5:at + 9])
        at += 2 + length


def with_exif_orientation(data, orientation):
    """The JPEG with an APP1 EXIF segment whose one tag is its orientation."""
    tiff = b"II*\x00" + struct.pack("<I", 8) + struct.pack("<H", 1)
    tiff += struct.pack("<HHII", 0x0112, 3, 1, orientation) + struct.pack("<I", 0)
    body = b"Exif\x00\x00" + tiff
    return data[:2] + b"\xff\xe1" + struct.pack(">H", len(body) + 2) + body + data[2:]


def test_read_image_reads_a_jpeg_as_an_image_map_shows_it(tmp_path, source_dir):
    data = (source_dir / "scenes" / "maps" / "label.jpg").read_bytes()
    image = jtracer.read_image(source_dir / "scenes" / "maps" / "label.jpg")
    assert image.shape == (*jpeg_frame_size(data), 3)
    assert image.dtype == np.uint8 and image.std() > 0
    # Orientation 6: stored a quarter turn anticlockwise, shown turned clockwise.
    (tmp_path / "turned.jpeg").write_bytes(with_exif_orientation(data, 6))
    assert np.array_equal(jtracer.read_image(tmp_path / "turned.jpeg"), np.rot90(image, -1))


def test_read_image_of_a_file_that_is_no_image_names_the_formats(tmp_path):
    (tmp_path / "model.obj").write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
    with pytest.raises(OSError) as raised:
        jtracer.read_image(tmp_path / "model.obj")
    message = str(raised.value)
    assert "model.obj" in message and "not a BMP, PNG or JPEG image" in message
    assert "signature" not in message


def test_a_missing_file_is_reported_in_the_same_words_everywhere(tmp_path):
    # One fact, one wording: the core's "cannot read 'PATH': REASON", whether
    # the file is a scene, a picture or a reference.
    missing = tmp_path / "missing"
    expected = f"^cannot read '{re.escape(str(missing))}': no such file$"
    for call in (jtracer.load, jtracer.check, jtracer.read_image,
                 lambda path: jtracer.diff(path, gradient())):
        with pytest.raises(OSError, match=expected):
            call(missing)
    with pytest.raises(OSError, match=f"^cannot read '{re.escape(str(tmp_path))}': it is a "
                                      "directory, not a file$"):
        jtracer.read_image(tmp_path)
