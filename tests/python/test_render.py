# Scene.render: jtracer-cli's bytes, its options, progress, the GIL and Ctrl+C.
import os
import re
import signal
import subprocess
import sys
import threading
import time

import jtracer
import numpy as np
import pytest
from conftest import bmp_pixels, run


@pytest.mark.parametrize(
    "options, flags",
    [
        # An odd width: BMP rows are padded, the array's are not.
        (dict(width=161, height=91), ["--width", "161", "--height", "91"]),
        (dict(width=64, height=48, samples=4, camera="High Angle"),
         ["--width", "64", "--height", "48", "--samples", "4", "--camera", "High Angle"]),
        (dict(width=97, height=55, region=(10, 5, 60, 40), threads=1),
         ["--width", "97", "--height", "55", "--region", "10,5,60,40", "--threads", "1"]),
    ],
)
def test_render_is_the_cli_bmp(tmp_path, cli, showcase, options, flags):
    image = jtracer.load(showcase).render(**options)
    run(cli, "-q", showcase, "-o", tmp_path / "cli.bmp", *flags)
    expected = bmp_pixels(tmp_path / "cli.bmp")
    assert image.dtype == np.uint8 and image.shape == expected.shape
    assert image.shape == (options["height"], options["width"], 3)
    assert np.array_equal(image, expected)
    assert image.flags["C_CONTIGUOUS"] and image.any()
    if "region" in options:
        x0, y0, x1, y1 = options["region"]
        assert not image[:y0].any() and not image[y1:].any() and not image[:, x1:].any()
        assert image[y0:y1, x0:x1].any()


def test_a_model_file_is_read_by_the_model_reader_as_in_the_cli(tmp_path, cli, source_dir):
    # The module opens the model reader (core/scene/src/io/model_reader.hpp) by its own RUNPATH.
    mesh = source_dir / "scenes" / "mesh.jts"
    image = jtracer.load(mesh).render(width=80, height=45)
    run(cli, "-q", mesh, "-o", tmp_path / "cli.bmp", "--width", "80", "--height", "45")
    assert np.array_equal(image, bmp_pixels(tmp_path / "cli.bmp"))


def test_the_scene_size_without_overrides(source_dir):
    scene = jtracer.load(source_dir / "scenes" / "manual" / "sphere.jts")
    s = scene.settings
    image = scene.render()
    assert image.shape == (s.height, s.width, 3)
    # The top row is the top of the picture: the same as rendering only it.
    top = scene.render(region=(0, 0, s.width, 1))
    assert np.array_equal(top[0], image[0]) and not top[1:].any()


def test_bad_options_raise(showcase):
    scene = jtracer.load(showcase)
    with pytest.raises(ValueError, match='^camera: the scene has no camera named "Side".*"Main", "High Angle"'):
        scene.render(width=8, height=8, camera="Side")
    with pytest.raises(ValueError, match="width: 1..65535, not 0"):
        scene.render(width=0)
    with pytest.raises(ValueError, match="samples"):
        scene.render(width=8, height=8, samples=5000)
    with pytest.raises(ValueError, match="region"):
        scene.render(width=8, height=8, region=(0, 0, 9, 4))
    with pytest.raises(ValueError, match="region"):
        scene.render(width=8, height=8, region=(4, 0, 2, 4))
    with pytest.raises(TypeError, match="progress"):
        scene.render(width=8, height=8, progress=3)


def test_a_size_too_large_is_the_arguments_error_or_the_scenes(showcase, tmp_path):
    # Asked for by the arguments: their error, not one located at the
    # scene's own width or height, which they replaced.
    scene = jtracer.load(showcase)
    with pytest.raises(ValueError, match=r"^width/height: a 65535 x 65535 image .*\(4 GiB"):
        scene.render(width=65535, height=65535)
    with pytest.raises(ValueError, match="^width: a 65535 x 65535 image"):
        jtracer.parse(scene.text().replace("height: 450;", "height: 65535;")).render(width=65535)
    # Written in the scene: the scene's error, at its height.
    huge = tmp_path / "huge.jts"
    huge.write_text(scene.text().replace("width: 800;", "width: 65535;").replace(
        "height: 450;", "height: 65535;"))
    with pytest.raises(jtracer.SceneError, match="4 GiB") as raised:
        jtracer.load(huge)
    assert raised.value.diagnostics[0].severity == "error"
    assert raised.value.diagnostics[0].line > 0


def test_progress_reports_rising_fractions_ending_at_one(showcase):
    seen = []
    jtracer.load(showcase).render(width=400, height=225, samples=8, progress=seen.append)
    assert seen[-1] == 1.0
    assert all(0.0 <= f <= 1.0 for f in seen)
    assert seen == sorted(seen)


def test_an_exception_in_the_progress_callable_stops_the_render(showcase):
    def stop(fraction):
        raise RuntimeError("stop here")

    started = time.monotonic()
    with pytest.raises(RuntimeError, match="stop here"):
        jtracer.load(showcase).render(width=1600, height=900, samples=64, progress=stop)
    assert time.monotonic() - started < 10


def test_other_python_threads_run_while_it_renders(showcase):
    scene = jtracer.load(showcase)
    ticks = 0
    done = threading.Event()

    def count():
        nonlocal ticks
        while not done.is_set():
            ticks += 1
            time.sleep(0.001)

    counter = threading.Thread(target=count)
    counter.start()
    started = time.monotonic()
    scene.render(width=400, height=225, samples=16, threads=1)
    took = time.monotonic() - started
    done.set()
    counter.join()
    # Holding the GIL would leave the counter at a tick or two.
    assert took > 0.2 and ticks > 0.25 * took / 0.001


# The command line's bound (tests/hardening/interruption_test.cpp): on an idle
# machine the render stops within a tick and a tile, some 0.1 s, but a loaded
# one (the suite runs tests side by side) may take seconds to schedule it; an
# unanswered Ctrl+C leaves the render running for minutes.
STOP_LIMIT_SECONDS = 5.0


@pytest.mark.parametrize("with_progress", [False, True])
def test_ctrl_c_interrupts_promptly(source_dir, with_progress):
    # Without a progress callable no Python code runs during the render: only
    # the module's own look at the signals can raise KeyboardInterrupt.
    script = f"""
import sys, time, jtracer
scene = jtracer.load({str(source_dir / "scenes" / "showcase.jts")!r})
def started(fraction):
    if not started.said:
        started.said = True
        print("started", flush=True)
started.said = False
if not {with_progress}:
    started(0.0)
try:
    scene.render(width=3000, height=2000, samples=256,
                 progress=started if {with_progress} else None)
    print("finished")
except KeyboardInterrupt:
    print("KeyboardInterrupt", time.monotonic(), flush=True)
"""
    child = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, text=True)
    try:
        assert child.stdout.readline().strip() == "started"
        time.sleep(0.5)
        sent = time.monotonic()
        child.send_signal(signal.SIGINT)
        out, _ = child.communicate(timeout=30)
    finally:
        child.kill()
        child.wait()
    words = out.split()
    assert words and words[0] == "KeyboardInterrupt", out
    assert float(words[1]) - sent < STOP_LIMIT_SECONDS
    assert child.returncode == 0


# The sanitizers reserve terabytes of address space up front, which no cap allows.
@pytest.mark.skipif(os.environ.get("JT_SANITIZED") == "1",
                    reason="an address-space cap cannot hold the sanitizers' reservations")
def test_a_frame_larger_than_the_memory_left_raises_memory_error(showcase):
    # In a child under a 3 GB address-space limit, as `ulimit -v` sets: the
    # check comes before any allocation, with jtracer-cli's reason in the
    # arguments' words, and the interpreter carries on.
    code = f"""
import resource, jtracer
resource.setrlimit(resource.RLIMIT_AS, (3 << 30, 3 << 30))
scene = jtracer.load({str(showcase)!r})
try:
    scene.render(width=30000, height=30000, samples=2)
except MemoryError as error:
    print(error)
print(scene.render(width=16, height=9).shape)
"""
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          timeout=300)
    assert done.returncode == 0, done.stderr
    lines = done.stdout.splitlines()
    assert re.fullmatch(r"a 30000 x 30000 image with 2 samples needs about 27\.7 GiB of memory, "
                        r"more than the [0-9.]+ GiB available; choose a smaller width/height "
                        r"or fewer samples", lines[0]), lines
    assert lines[1] == "(9, 16, 3)"
