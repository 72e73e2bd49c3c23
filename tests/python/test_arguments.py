# Arguments of the wrong type or value raise TypeError or ValueError naming
# the argument and what is wrong, as Python's own functions do, never
# pybind11's "incompatible function arguments" list of signatures.
import jtracer
import numpy as np
import pytest

SMALL = """render_settings { width: 8; height: 4; }
cameras { perspective_camera { position: <0, 0, 5>; look_at: <0, 0, 0>; aspect: 2; } }
scene { sphere { radius: 1; } point_light { position: <1, 2, 3>; intensity: <1, 1, 1>; } }
"""

PIXELS = np.zeros((2, 2, 3), np.uint8)


@pytest.fixture(scope="module")
def scene():
    return jtracer.parse(SMALL)


@pytest.mark.parametrize(
    "call",
    [
        lambda: jtracer.load("a\0b.jts"),
        lambda: jtracer.check(b"a\0b.jts"),
        lambda: jtracer.parse(SMALL, path="a\0b.jts"),
        lambda: jtracer.read_image("a\0b.png"),
        lambda: jtracer.write_image("a\0b.png", PIXELS),
    ],
    ids=["load", "check", "parse", "read_image", "write_image"],
)
def test_a_path_with_a_nul_byte_is_a_value_error(call):
    with pytest.raises(ValueError, match="^path: embedded null byte$"):
        call()


def test_diff_names_the_path_with_a_nul_byte():
    with pytest.raises(ValueError, match="^actual: embedded null byte$"):
        jtracer.diff(PIXELS, "a\0b.png")


def test_a_path_of_another_type_is_a_type_error():
    with pytest.raises(TypeError, match="^path: a str, bytes or os.PathLike path, not int$"):
        jtracer.load(3)


def test_text_with_a_lone_surrogate_is_a_value_error(scene):
    with pytest.raises(ValueError, match=r"^text: .*surrogates not allowed"):
        jtracer.parse(SMALL + "\udc80")
    with pytest.raises(ValueError, match=r"^camera: .*surrogates not allowed"):
        scene.render(camera="\udc80")
    with pytest.raises(ValueError, match=r"^defines\['a'\]: .*surrogates not allowed"):
        jtracer.parse(SMALL, defines={"a": "\udc80"})
    with pytest.raises(TypeError, match="^text: a str, not bytes$"):
        jtracer.parse(SMALL.encode())


def test_write_image_names_an_image_that_is_no_array(tmp_path):
    with pytest.raises(TypeError, match=r"^image: a \(height, width, 3\) uint8 array, not list$"):
        jtracer.write_image(tmp_path / "a.png", [[[0, 0, 0]]])
    assert not list(tmp_path.iterdir())


def test_ints_past_32_bits_are_out_of_range(scene):
    with pytest.raises(ValueError, match=r"^region\[2\]: 0..65535, not 10000000000$"):
        scene.render(region=(0, 0, 10**10, 1))
    with pytest.raises(ValueError, match="^width: 1..65535, not 10000000000$"):
        scene.render(width=10**10)
    with pytest.raises(ValueError, match="^threshold: 0..255, not -10000000000$"):
        jtracer.diff(PIXELS, PIXELS, threshold=-(10**10))


def test_a_region_is_four_ints(scene):
    with pytest.raises(ValueError, match=r"^region: four ints \(x0, y0, x1, y1\), not 3$"):
        scene.render(region=(0, 0, 1))
    with pytest.raises(TypeError, match=r"^region\[1\]: an int, not float$"):
        scene.render(region=(0, 0.5, 1, 1))
    with pytest.raises(TypeError, match=r"^region: four ints .*, not str$"):
        scene.render(region="0,0,1,1")
    assert scene.render(region=[0, 0, np.int64(8), 4]).shape == (4, 8, 3)


@pytest.mark.parametrize("name", ["width", "height", "samples", "threads"])
def test_a_bool_is_no_size_or_count(scene, name):
    with pytest.raises(TypeError, match=f"^{name}: an int, not bool$"):
        scene.render(**{name: True})


def test_a_bool_is_no_threshold():
    with pytest.raises(TypeError, match="^threshold: an int, not bool$"):
        jtracer.diff(PIXELS, PIXELS, threshold=True)
    with pytest.raises(TypeError, match=r"^region\[0\]: an int, not bool$"):
        jtracer.parse(SMALL).render(region=(False, 0, 1, 1))


def test_sizes_of_other_int_types_are_taken(scene):
    assert scene.render(width=np.uint16(6), height=2).shape == (2, 6, 3)


@pytest.mark.parametrize(
    "call",
    [
        lambda: jtracer.load("a.jts", clock="a"),
        lambda: jtracer.check("a.jts", clock=True),
        lambda: jtracer.parse(SMALL, clock=None),
    ],
    ids=["load", "check", "parse"],
)
def test_a_clock_that_is_no_number_is_a_type_error(call):
    with pytest.raises(TypeError, match="^clock: a number, not (str|bool|NoneType)$"):
        call()


def test_a_clock_too_large_for_a_double_is_a_value_error():
    with pytest.raises(ValueError, match="^clock: a finite number"):
        jtracer.parse(SMALL, clock=10**400)


@pytest.mark.parametrize(
    "call",
    [
        lambda: jtracer.load("a.jts", defines=[1]),
        lambda: jtracer.check("a.jts", defines="a=1"),
        lambda: jtracer.parse(SMALL, defines=[("a", 1)]),
    ],
    ids=["load", "check", "parse"],
)
def test_defines_that_are_no_dict_are_a_type_error(call):
    with pytest.raises(TypeError, match="^defines: a dict, not (list|str)$"):
        call()


def test_defines_and_clock_take_any_mapping_and_number():
    import types

    import numpy

    scene = jtracer.parse(
        SMALL.replace("width: 8", "width: w"),
        defines=types.MappingProxyType({"w": 8}),
        clock=numpy.float32(0.5),
    )
    assert scene.settings.width == 8


@pytest.mark.parametrize(
    "call, message",
    [
        (lambda p: jtracer.write_image(p, PIXELS.astype(np.int64)),
         "^image: a uint8 array, not int64$"),
        (lambda p: jtracer.write_image(p, PIXELS[:, :, 0]),
         r"^image: an array of shape \(height, width, 3\), not \(2, 2\)$"),
        (lambda p: jtracer.diff(PIXELS, np.zeros((0, 2, 3), np.uint8)),
         "^actual: 1..65535 pixels on each side, not 2x0$"),
        (lambda p: jtracer.diff(PIXELS.astype(np.float32), PIXELS),
         "^expected: a uint8 array, not float32$"),
    ],
    ids=["write_image dtype", "write_image shape", "diff size", "diff dtype"],
)
def test_an_array_that_is_no_image_names_its_argument(tmp_path, call, message):
    with pytest.raises((TypeError, ValueError), match=message):
        call(tmp_path / "a.png")
