# jtracer-cli's reports for CI: diff --json, --junit on diff and --expect, and
# --expect --update. The JSON is parsed with json, the JUnit XML with
# xml.etree, as a CI system would read them.
import json
import os
import shutil
import subprocess
import xml.etree.ElementTree as ElementTree

import jtracer
import numpy as np
import pytest
from conftest import run


def images(tmp_path):
    y, x = np.mgrid[0:30, 0:20]
    a = np.stack([x * 12, y * 8, (x + y) * 4], axis=-1).astype(np.uint8)
    b = a.copy()
    b[3, 4] = [255, 0, 0]
    b[10:12, 5:9, 1] += 5
    jtracer.write_image(tmp_path / "a.png", a)
    jtracer.write_image(tmp_path / "b.bmp", b)
    jtracer.write_image(tmp_path / "a-copy.bmp", a)
    jtracer.write_image(tmp_path / "small.png", a[:10])
    return tmp_path / "a.png", tmp_path / "b.bmp"


def diff_json(*args):
    code, out, err = run(*args, check=False)
    assert out.count("\n") == 1, out  # one object, one line
    return code, json.loads(out), err


def test_diff_json_has_the_figures_sizes_verdict_and_heat_map(tmp_path, cli):
    a, b = images(tmp_path)
    heat = tmp_path / "heat.png"
    code, report, _ = diff_json(cli, "diff", a, b, "--json", "--threshold", "3",
                                "--max-pixels", "1", "-o", heat)
    assert code == 1
    d = jtracer.diff(a, b, threshold=3)
    assert report["expected"] == {"path": str(a), "width": 20, "height": 30}
    assert report["actual"] == {"path": str(b), "width": 20, "height": 30}
    assert (report["threshold"], report["max_pixels"]) == (3, 1.0)
    assert report["same_size"] is True
    assert report["max_difference"] == d.max_difference == 207  # |(48, 24, 28) - (255, 0, 0)|
    assert (report["pixels"], report["pixels_over"]) == (600, d.pixels_over) == (600, 9)
    assert report["percent_over"] == pytest.approx(1.5)
    assert report["mae"] == pytest.approx(d.mae)
    assert report["psnr"] == pytest.approx(d.psnr)
    assert report["verdict"] == "outside"
    assert report["heat_map"] == str(heat) and heat.exists()
    assert "error" not in report


def test_diff_json_of_equal_images_and_of_other_sizes(tmp_path, cli):
    a, _ = images(tmp_path)
    code, same, _ = diff_json(cli, "diff", a, tmp_path / "a-copy.bmp", "--json")
    assert code == 0
    assert same["verdict"] == "within" and same["max_difference"] == 0
    assert same["psnr"] is None and same["heat_map"] is None  # JSON has no infinity
    code, other, _ = diff_json(cli, "diff", a, tmp_path / "small.png", "--json")
    assert code == 1
    assert other["same_size"] is False and other["verdict"] == "outside"
    assert other["actual"]["height"] == 10 and "pixels_over" not in other


def test_diff_json_of_an_unreadable_image_is_an_error_object(tmp_path, cli):
    a, _ = images(tmp_path)
    code, report, err = diff_json(cli, "diff", a, tmp_path / "missing.png", "--json")
    assert code == 3
    assert report["verdict"] == "error" and "missing.png" in report["error"]
    assert report["actual"]["width"] is None
    assert "missing.png" in err


def junit_case(path):
    root = ElementTree.parse(path).getroot()
    assert root.tag == "testsuites"
    suites = root.findall("testsuite")
    assert len(suites) == 1 and suites[0].get("tests") == "1"
    cases = suites[0].findall("testcase")
    assert len(cases) == 1
    return root, suites[0], cases[0]


def test_diff_junit_fails_with_the_figures(tmp_path, cli):
    a, b = images(tmp_path)
    junit = tmp_path / "report.xml"
    code, _, _ = run(cli, "diff", a, b, "--junit", junit, check=False)
    assert code == 1
    root, suite, case = junit_case(junit)
    assert root.get("failures") == suite.get("failures") == "1"
    assert case.get("name") == str(b) and float(case.get("time")) >= 0
    failure = case.find("failure")
    assert "max channel difference 207" in failure.get("message")
    assert "9 of 600 pixels over threshold 0" in failure.get("message")
    assert "PSNR" in failure.text
    # Within the tolerance: a case that passed.
    code, _, _ = run(cli, "diff", "-q", a, tmp_path / "a-copy.bmp", "--junit", junit,
                     check=False)
    assert code == 0
    root, suite, case = junit_case(junit)
    assert suite.get("failures") == "0" and case.find("failure") is None
    assert case.find("error") is None


def test_diff_junit_records_an_unreadable_image_as_an_error(tmp_path, cli):
    a, _ = images(tmp_path)
    junit = tmp_path / "report.xml"
    code, _, _ = run(cli, "diff", a, tmp_path / "nope.png", "--junit", junit, check=False)
    assert code == 3
    _, suite, case = junit_case(junit)
    assert suite.get("errors") == "1" and "nope.png" in case.find("error").get("message")


def render_reference(cli, scene, path, width=40):
    run(cli, "-q", scene, "-o", path, "--width", width, "--height", "30")


def test_expect_junit_passes_and_fails(tmp_path, cli, source_dir):
    scene = source_dir / "scenes" / "manual" / "sphere.jts"
    other = source_dir / "scenes" / "manual" / "plane.jts"
    reference = tmp_path / "ref.png"
    render_reference(cli, scene, reference)
    junit = tmp_path / "expect.xml"
    run(cli, "-q", scene, "-o", tmp_path / "out.png", "--width", "40", "--height", "30",
        "--expect", reference, "--junit", junit)
    _, suite, case = junit_case(junit)
    assert case.get("name") == str(scene) and case.find("failure") is None
    render_reference(cli, other, reference)
    code, _, _ = run(cli, "-q", scene, "-o", tmp_path / "out.png", "--width", "40",
                     "--height", "30", "--expect", reference, "--junit", junit, check=False)
    assert code == 1
    _, suite, case = junit_case(junit)
    assert suite.get("failures") == "1"
    assert "pixels over threshold" in case.find("failure").get("message")
    assert (tmp_path / "out.diff.png").exists()
    assert str(tmp_path / "out.diff.png") in case.find("system-out").text


def test_expect_junit_of_a_scene_that_fails_is_an_error(tmp_path, cli):
    scene = tmp_path / "bad.jts"
    scene.write_text("scene { sphere { radius: -1; } }\n")
    junit = tmp_path / "expect.xml"
    jtracer.write_image(tmp_path / "ref.png", np.zeros((4, 4, 3), np.uint8))
    code, _, _ = run(cli, scene, "-o", tmp_path / "out.png", "--expect", tmp_path / "ref.png",
                     "--junit", junit, check=False)
    assert code == 1
    _, suite, case = junit_case(junit)
    assert suite.get("errors") == "1" and case.find("error") is not None
    assert not (tmp_path / "out.png").exists()
    # It says that nothing was written rather than ending in "actual ".
    assert case.find("system-out").text.startswith(
        f"expected {tmp_path / 'ref.png'}, actual none (no render was written)\n")
    # The CI page shows why: the scene's error is in the message, and every
    # message the run printed is in system-err.
    message = case.find("error").get("message")
    assert "bad.jts:1:" in message and "radius" in message, message
    assert "exit code 1" in message, message
    assert "bad.jts:1:" in case.find("system-err").text


def test_expect_junit_of_a_missing_model_names_the_file(tmp_path, cli, source_dir):
    scene = tmp_path / "scene.jts"
    scene.write_text((source_dir / "scenes" / "glass.jts").read_text() +
                     '\nscene { mesh { file: "models/gone.obj"; } }\n')
    junit = tmp_path / "expect.xml"
    jtracer.write_image(tmp_path / "ref.png", np.zeros((4, 4, 3), np.uint8))
    code, _, err = run(cli, "-q", scene, "-o", tmp_path / "out.png", "--expect",
                       tmp_path / "ref.png", "--junit", junit, check=False)
    assert code == 1
    _, _, case = junit_case(junit)
    assert "gone.obj" in case.find("error").get("message")
    # What stderr shows, the report keeps.
    assert case.find("system-err").text == err


def stamp(path):
    return path.read_bytes(), path.stat().st_mtime_ns


def test_update_leaves_an_equal_reference_alone(tmp_path, cli, source_dir):
    scene = source_dir / "scenes" / "manual" / "sphere.jts"
    reference = tmp_path / "ref.png"
    render_reference(cli, scene, reference)
    before = stamp(reference)
    code, _, err = run(cli, scene, "-o", tmp_path / "out.png", "--width", "40", "--height", "30",
                       "--expect", reference, "--update", check=False)
    assert code == 0 and "matches" in err and "updated" not in err
    assert stamp(reference) == before


def test_update_writes_a_different_render_over_the_reference(tmp_path, cli, source_dir):
    scene = source_dir / "scenes" / "manual" / "sphere.jts"
    reference = tmp_path / "ref.png"
    render_reference(cli, source_dir / "scenes" / "manual" / "plane.jts", reference)
    junit = tmp_path / "expect.xml"
    code, _, err = run(cli, scene, "-o", tmp_path / "out.png", "--width", "40", "--height", "30",
                       "--expect", reference, "--update", "--junit", junit, check=False)
    assert code == 0
    assert f"updated {reference}" in err
    assert np.array_equal(jtracer.read_image(reference), jtracer.read_image(tmp_path / "out.png"))
    _, suite, case = junit_case(junit)
    assert case.find("failure") is None and "updated" in case.find("system-out").text
    # Another size is a difference too, and a missing reference is made.
    render_reference(cli, scene, reference, width=20)
    code, _, err = run(cli, scene, "-o", tmp_path / "out.png", "--width", "40", "--height", "30",
                       "--expect", reference, "--update", check=False)
    assert code == 0 and jtracer.read_image(reference).shape == (30, 40, 3)
    fresh = tmp_path / "new" / "ref.bmp"
    fresh.parent.mkdir()
    code, _, err = run(cli, scene, "-o", tmp_path / "out.png", "--width", "40", "--height", "30",
                       "--expect", fresh, "--update", check=False)
    assert code == 0 and fresh.read_bytes()[:2] == b"BM"


def test_update_never_follows_a_failed_render(tmp_path, cli):
    reference = tmp_path / "ref.png"
    jtracer.write_image(reference, np.full((4, 4, 3), 7, np.uint8))
    before = stamp(reference)
    bad = tmp_path / "bad.jts"
    bad.write_text("scene { sphere { radius: -1; } }\n")
    code, _, _ = run(cli, bad, "-o", tmp_path / "out.png", "--expect", reference, "--update",
                     check=False)
    assert code == 1
    code, _, _ = run(cli, tmp_path / "missing.jts", "-o", tmp_path / "out.png", "--expect",
                     reference, "--update", check=False)
    assert code == 3
    assert stamp(reference) == before


def test_update_and_json_need_their_command(tmp_path, cli, source_dir):
    scene = source_dir / "scenes" / "manual" / "sphere.jts"
    code, _, err = run(cli, scene, "-o", tmp_path / "out.png", "--update", check=False)
    assert code == 2 and "--update" in err and "--expect" in err
    code, _, err = run(cli, scene, "-o", tmp_path / "out.png", "--junit", tmp_path / "j.xml",
                       check=False)
    assert code == 2 and "--junit" in err


def test_reports_of_a_file_name_that_is_not_utf8_can_be_read(tmp_path, cli):
    # A name from an archive made on another system: Latin-1 "café". The
    # JSON and the JUnit XML must still be UTF-8 that their readers accept,
    # with the byte that is not UTF-8 replaced.
    a, _ = images(tmp_path)
    latin1 = tmp_path / os.fsdecode(b"caf\xe9.png")
    shutil.copy(a, latin1)
    done = subprocess.run([str(cli), "diff", str(a), str(latin1), "--json"], capture_output=True,
                          timeout=60)
    assert done.returncode == 0, done.stderr
    report = json.loads(done.stdout.decode("utf-8"))
    assert report["verdict"] == "within" and report["actual"]["path"].endswith("caf\ufffd.png")
    junit = tmp_path / "report.xml"
    done = subprocess.run([str(cli), "diff", "-q", str(a), str(latin1), "--junit", str(junit)],
                          capture_output=True, timeout=60)
    assert done.returncode == 0, done.stderr
    _, suite, case = junit_case(junit)
    assert suite.get("failures") == "0" and case.get("name").endswith("caf\ufffd.png")


def test_a_junit_report_that_cannot_be_written_stops_before_the_render(tmp_path, cli,
                                                                       source_dir):
    # A CI job that forgot `mkdir -p junit` learns it at once, not after each
    # render, and exits 3 (not the comparison's 0 or 1).
    scene, reference = tmp_path / "scene.jts", tmp_path / "ref.png"
    scene.write_text((source_dir / "scenes" / "glass.jts").read_text())
    jtracer.write_image(reference, np.zeros((4, 4, 3), np.uint8))
    code, _, err = run(cli, "-q", scene, "--width", "16", "--height", "9", "-o",
                       tmp_path / "out.png", "--expect", reference, "--junit",
                       tmp_path / "missing" / "report.xml", check=False)
    assert code == 3
    assert "--junit" in err and "nothing was rendered" in err, err
    assert not (tmp_path / "out.png").exists()
