# The scripts of docs/python.md run as the page shows them.
import pathlib
import re
import subprocess
import sys

import jtracer
import numpy as np
import pytest
from conftest import run


def block_after(source_dir, heading):
    page = (source_dir / "docs" / "python.md").read_text()
    section = page.split(f"\n## {heading}\n", 1)[1].split("\n## ", 1)[0]
    return re.search(r"```python\n(.*?)```", section, re.S).group(1)


def test_turntable_writes_distinct_frames(tmp_path, source_dir, showcase):
    script = tmp_path / "turntable.py"
    script.write_text(block_after(source_dir, "A turntable"))
    out = tmp_path / "frames"
    done = subprocess.run([sys.executable, script, showcase, out, "4", "64", "36"],
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    frames = sorted(out.glob("frame_*.png"))
    assert [f.name for f in frames] == [f"frame_{i:03d}.png" for i in range(4)]
    images = [jtracer.read_image(f) for f in frames]
    assert all(i.shape == (36, 64, 3) for i in images)
    # Each view differs from the next, and the first is the scene's own camera's
    # (same position and target; only the aspect follows the frame).
    assert all(not np.array_equal(a, b) for a, b in zip(images, images[1:]))
    own = jtracer.load(showcase).render(width=64, height=36)
    assert jtracer.diff(own, images[0]).max_difference <= 1


def test_pytest_example_passes_and_fails(tmp_path, source_dir, cli):
    project = tmp_path / "project"
    (project / "scenes").mkdir(parents=True)
    (project / "references").mkdir()
    for name in ("sphere", "plane"):
        (project / "scenes" / f"{name}.jts").write_bytes(
            (source_dir / "scenes" / "manual" / f"{name}.jts").read_bytes())
        run(cli, "-q", project / "scenes" / f"{name}.jts", "-o",
            project / "references" / f"{name}.png")
    (project / "test_renders.py").write_text(block_after(source_dir, "An image test with pytest"))
    command = [sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", "test_renders.py"]
    passed = subprocess.run(command, cwd=project, capture_output=True, text=True, timeout=300)
    assert passed.returncode == 0, passed.stdout
    assert "2 passed" in passed.stdout
    # A wrong reference fails, naming where the render and the heat map are.
    (project / "references" / "sphere.png").write_bytes(
        (project / "references" / "plane.png").read_bytes())
    failed = subprocess.run(command, cwd=project, capture_output=True, text=True, timeout=300)
    assert failed.returncode == 1
    assert "1 failed, 1 passed" in failed.stdout
    kept = re.search(r"Failed: .* are in (\S+)", failed.stdout).group(1)
    assert {p.name for p in pathlib.Path(kept).iterdir()} == {
        "sphere.png", "sphere.diff.png"}
