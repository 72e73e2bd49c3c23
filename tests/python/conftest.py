# What the tests of the jtracer module share: the programs and folders ctest
# names in the environment (tests/python/CMakeLists.txt).
import os
import pathlib
import struct
import subprocess

import numpy as np
import pytest


def _path(variable):
    value = os.environ.get(variable)
    if not value:
        pytest.exit(f"{variable} is not set: run these tests from ctest", returncode=2)
    return pathlib.Path(value)


@pytest.fixture(scope="session")
def cli():
    return _path("JT_CLI")


@pytest.fixture(scope="session")
def source_dir():
    return _path("JT_SOURCE_DIR")


@pytest.fixture(scope="session")
def showcase(source_dir):
    return source_dir / "scenes" / "showcase.jts"


def run(*command, check=True):
    """Runs a program; returns (exit code, stdout, stderr)."""
    done = subprocess.run([str(c) for c in command], capture_output=True, text=True, timeout=600)
    if check and done.returncode != 0:
        raise AssertionError(f"{command} exited {done.returncode}: {done.stderr}")
    return done.returncode, done.stdout, done.stderr


def bmp_pixels(path):
    """The pixels of a 24-bit BMP as a (height, width, 3) RGB array, top row first,
    read from the file's bytes here rather than by the module under test."""
    data = pathlib.Path(path).read_bytes()
    assert data[:2] == b"BM"
    offset = struct.unpack_from("<I", data, 10)[0]
    width, height = struct.unpack_from("<ii", data, 18)
    bits = struct.unpack_from("<H", data, 28)[0]
    assert bits == 24 and height > 0  # bottom-up rows, as jtracer-cli writes them
    stride = (width * 3 + 3) // 4 * 4
    rows = np.frombuffer(data, np.uint8, stride * height, offset).reshape(height, stride)
    bgr = rows[:, : width * 3].reshape(height, width, 3)
    return bgr[::-1, :, ::-1]
