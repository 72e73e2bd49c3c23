# The module lets other Python threads run while it reads files: a scene with
# a large model, a large picture. Each call here reads a named pipe that a
# Python thread fills, so a call that held the GIL would wait for a thread that
# cannot run; the calls run in a child interpreter that is given 20 s (it needs
# a fraction of one).
import os
import subprocess
import sys
import textwrap

import jtracer
import numpy as np
import pytest

CHILD = textwrap.dedent(
    """
    import os, sys, threading
    import numpy as np
    import jtracer

    folder, call = sys.argv[1], sys.argv[2]
    pipe = os.path.join(folder, "pipe")
    os.mkfifo(pipe)

    image = np.random.default_rng(1).integers(0, 256, (300, 300, 3), np.uint8)
    jtracer.write_image(os.path.join(folder, "picture.png"), image)
    png = open(os.path.join(folder, "picture.png"), "rb").read()
    scene = b"render_settings { width: 4; height: 3; } cameras { perspective_camera { } }\\n"
    scene += b"# " + b"x" * 300000 + b"\\n"
    data = {"read_image": png, "diff": png, "load": scene, "check": scene}[call]
    # More than a pipe holds (64 KiB): the writer can finish, and close the
    # pipe so that the reading call sees its end, only once that call reads,
    # and then only if it lets this thread run.
    assert len(data) > 2 * 65536
    fd = os.open(pipe, os.O_RDWR)  # opened before the call, which then waits for the end

    def feed():
        view = memoryview(data)
        while view:
            view = view[os.write(fd, view):]
        os.close(fd)

    writer = threading.Thread(target=feed)
    writer.start()
    if call == "read_image":
        assert np.array_equal(jtracer.read_image(pipe), image)
    elif call == "diff":
        assert jtracer.diff(pipe, image).max_difference == 0
    elif call == "load":
        assert jtracer.load(pipe).settings.width == 4
    else:
        assert {d.severity for d in jtracer.check(pipe)} == {"warning"}
    writer.join()
    print("done")
    """
)


@pytest.mark.parametrize("call", ["read_image", "diff", "load", "check"])
def test_a_file_read_lets_other_threads_run(tmp_path, call):
    try:
        done = subprocess.run(
            [sys.executable, "-c", CHILD, str(tmp_path), call],
            capture_output=True,
            text=True,
            timeout=20,
            env=os.environ,
        )
    except subprocess.TimeoutExpired:
        pytest.fail(f"jtracer.{call} held the GIL while it read: the thread filling the pipe never ran")
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "done"


def test_read_image_hands_over_its_pixels_without_a_second_copy(tmp_path):
    # A 6000 x 4000 picture of one colour: 72 MB of pixels in a PNG of a few
    # hundred KB. Reading it may cost the pixels once, not twice.
    path = tmp_path / "flat.png"
    flat = np.full((4000, 6000, 3), (10, 200, 30), np.uint8)
    jtracer.write_image(path, flat)
    del flat
    child = textwrap.dedent(
        """
        import sys
        import numpy as np
        import jtracer
        def peak_kb():
            # This process's own peak (getrusage's counts the parent's before exec).
            with open("/proc/self/status") as status:
                return next(int(l.split()[1]) for l in status if l.startswith("VmHWM:"))
        before = peak_kb()
        image = jtracer.read_image(sys.argv[1])
        assert image.shape == (4000, 6000, 3) and image.dtype == np.uint8
        assert (image[0, 0] == (10, 200, 30)).all() and (image[-1, -1] == (10, 200, 30)).all()
        assert image.flags.c_contiguous and image.flags.writeable
        print(peak_kb() - before)
        """
    )
    done = subprocess.run(
        [sys.executable, "-c", child, str(path)], capture_output=True, text=True, timeout=120
    )
    assert done.returncode == 0, done.stderr
    grown_mb = int(done.stdout) / 1024
    pixels_mb = 4000 * 6000 * 3 / 2**20
    assert grown_mb < 1.5 * pixels_mb, f"peak grew {grown_mb:.0f} MB for {pixels_mb:.0f} MB of pixels"
