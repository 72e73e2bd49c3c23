# jtracer.load / parse / check, SceneError and the scene's read-only views.
import os
import re

import jtracer
import numpy as np
import pytest
from conftest import run

BAD = """render_settings { width: 64; height: 32; }
cameras { perspective_camera { position: <0, 0, 5>; look_at: <0, 0, 0>; aspect: 2; } }
scene {
    sphere { radius: -1; }
    point_light { position: <1, 2, 3>; intensity: <1, 1, 1>; colour: 2; }
}
"""

WARNED = """render_settings { width: 64; height: 32; }
cameras { perspective_camera { position: <0, 0, 5>; look_at: <0, 0, 0>; aspect: 1; } }
scene { sphere { radius: 1; } }
"""


def test_scene_error_is_what_check_prints(tmp_path, cli):
    path = tmp_path / "bad.jts"
    path.write_text(BAD)
    code, _, printed = run(cli, "--check", path, check=False)
    assert code == 1
    with pytest.raises(jtracer.SceneError) as raised:
        jtracer.load(path)
    assert str(raised.value) + "\n" == printed
    diagnostics = raised.value.diagnostics
    assert len(diagnostics) >= 2
    # Each Diagnostic's str() is the header line --check prints for it.
    headers = [line for line in printed.splitlines() if re.match(r"\S.*: (error|warning): ", line)]
    assert [str(d) for d in diagnostics] == headers
    first = diagnostics[0]
    assert (first.file, first.line, first.severity) == (str(path), 4, "error")
    assert first.column > 0 and "radius" in first.message
    assert jtracer.check(path) == diagnostics


def test_check_lists_warnings_without_raising(tmp_path, cli):
    path = tmp_path / "warned.jts"
    path.write_text(WARNED)
    _, _, printed = run(cli, "--check", path)
    found = jtracer.check(path)
    assert found and all(d.severity == "warning" for d in found)
    assert [str(d) for d in found] == [l for l in printed.splitlines() if ": warning: " in l]
    scene = jtracer.load(path)
    assert scene.warnings == found
    assert jtracer.check(tmp_path / "../" / tmp_path.name / "warned.jts")[0].file.endswith(
        "warned.jts"
    )


def test_parse_names_its_text_and_finds_files_beside_its_path(source_dir):
    with pytest.raises(jtracer.SceneError) as raised:
        jtracer.parse(BAD)
    assert raised.value.diagnostics[0].file == "<string>"
    assert str(raised.value).startswith("<string>:4:")
    # The globe's image map is found from the path's folder, as load would.
    globe = source_dir / "scenes" / "globe.jts"
    scene = jtracer.parse(globe.read_text(), path=globe)
    assert scene.render(width=32, height=18).shape == (18, 32, 3)


def test_unreadable_files_raise_oserror(tmp_path):
    with pytest.raises(OSError, match="no such file"):
        jtracer.load(tmp_path / "missing.jts")
    with pytest.raises(OSError, match="directory"):
        jtracer.check(tmp_path)


def test_views_have_the_schema_names_and_values(showcase):
    scene = jtracer.load(showcase)
    text = scene.text()
    settings = scene.settings
    assert (settings.width, settings.height) == (800, 450)
    assert settings.active_camera == "Main"
    assert isinstance(settings.background, tuple) and len(settings.background) == 3
    # Every property the canonical text writes for the block is an attribute of
    # the view, with the same name (the schema's) and the same value.
    block = re.search(r"render_settings \{(.*?)\n\}", text, re.S).group(1)
    written = dict(re.findall(r"^\s+(\w+): (.+);$", block, re.M))
    assert written and set(written) <= set(settings.to_dict())
    assert written["width"] == "800" and written["filename"] == '"showcase.bmp"'
    names = [c.name for c in scene.cameras]
    assert names == ["Main", "High Angle"]
    main = scene.cameras[0]
    assert set(main.to_dict()) == {
        "name", "position", "look_at", "up", "aspect", "fov", "aperture", "focus_distance"}
    assert main.aperture == 0.0 and main.focus_distance is None  # unset: follows look_at
    assert main.fov == pytest.approx(38.0)
    assert "Camera(name='Main', position=(0.0, 2.4, 9.0)" in repr(main)
    with pytest.raises(AttributeError):
        main.fov = 10.0  # read-only
    with pytest.raises(AttributeError):
        scene.settings.width = 1


def test_text_reads_back_as_the_same_scene(showcase):
    scene = jtracer.load(showcase)
    again = jtracer.parse(scene.text(), path=showcase)
    assert again.text() == scene.text()
    assert again.cameras == scene.cameras and again.settings == scene.settings


def test_version_is_the_programs(cli):
    _, printed, _ = run(cli, "--version")
    assert printed.split()[1] == jtracer.__version__
    assert printed.strip() == "jtracer-cli " + jtracer.version_string
    assert re.fullmatch(r"\d+\.\d+\.\d+", jtracer.__version__)


DEFINED = """define r = 1;
define out = "a.bmp";
render_settings { width: 16; height: 16; filename: out; ambient_light: <1, 1, 1>; }
cameras { perspective_camera { position: <0, 0, 5>; look_at: <0, 0, 0>; fov: 30 + clock; } }
scene { sphere { radius: r; material { pigment: <1, 1, 1>; ambient: <1, 1, 1>; } } }
"""


def test_defines_set_names_as_the_command_line_does(tmp_path, cli):
    plain = jtracer.parse(DEFINED)
    assert plain.settings.filename == "a.bmp"
    scene = jtracer.parse(DEFINED, defines={"r": 0.5, "out": '"b.bmp"', "fov_unused": 2})
    assert scene.settings.filename == "b.bmp"
    notes = [d for d in scene.warnings if d.severity == "note"]
    assert [(d.line, d.column) for d in notes] == [(1, 8), (2, 8)]
    assert "'r' is set by defines;" in notes[0].message
    assert any(d.message == "defines['fov_unused']: the scene defines no 'fov_unused'"
               for d in scene.warnings), [d.message for d in scene.warnings]
    # The same image as jtracer-cli --define gives.
    path = tmp_path / "defined.jts"
    path.write_text(DEFINED)
    loaded = jtracer.load(path, defines={"r": "2 * 0.25"})
    run(cli, str(path), "--define", "r=0.5", "-o", str(tmp_path / "cli.bmp"), "-q")
    assert (loaded.render() == jtracer.read_image(tmp_path / "cli.bmp")).all()
    assert not (loaded.render() == plain.render()).all()


def test_bad_defines_raise_value_or_type_errors():
    # In Python's words: no --define or --clock to point at, no column of a
    # text the caller never wrote.
    with pytest.raises(ValueError,
                       match=r"^defines\['clock'\]: clock cannot be defined; set it with clock=$"):
        jtracer.parse(DEFINED, defines={"clock": 1})
    with pytest.raises(ValueError, match=r"^defines\['r'\]: a finite number, not nan$"):
        jtracer.parse(DEFINED, defines={"r": float("nan")})
    with pytest.raises(ValueError, match=r"^defines\['c'\]: a finite number, not -inf$"):
        jtracer.parse(DEFINED, defines={"c": (0, float("-inf"), 0)})
    with pytest.raises(ValueError, match=r"^defines\['r'\]: a finite number, not one too large"):
        jtracer.parse(DEFINED, defines={"r": 10**400})
    with pytest.raises(ValueError, match="division by zero"):
        jtracer.parse(DEFINED, defines={"r": "1 / 0"})
    with pytest.raises(ValueError, match="three numbers"):
        jtracer.parse(DEFINED, defines={"c": (1, 2)})
    with pytest.raises(TypeError):
        jtracer.parse(DEFINED, defines={"r": True})
    with pytest.raises(TypeError):
        jtracer.parse(DEFINED, defines={1: 2})
    vector = jtracer.parse(DEFINED.replace("define r = 1;", "define r = 1;\ndefine c = <0, 0, 0>;"),
                           defines={"c": (0, 1, 0)})
    assert vector.cameras[0].fov == 30


NAMED = (
    "define r = 2;\n"
    "material glossy { reflection: 0.5; pigment: <1, 0, 0> * r / 2; }\n"
    "render_settings { width: 8 * r; height: 8; }\n"
    "cameras { perspective_camera { name: \"c\"; position: <0, 1, 5> * r; } }\n"
    "scene { sphere { radius: r / 2; material: glossy; }\n"
    "        point_light { position: <0, r, 0>; intensity: <1, 1, 1>; } }\n"
)


def test_text_keeps_the_names_and_expressions_of_the_file():
    scene = jtracer.parse(NAMED)
    text = scene.text()
    for written in ("define r = 2;\n", "material glossy {\n", "    width: 8 * r;\n",
                    "        radius: r / 2;\n", "        material: glossy;\n",
                    "        position: <0, 1, 5> * r;\n", "    pigment: <1, 0, 0> * r / 2;\n"):
        assert written in text
    again = jtracer.parse(text)
    assert again.text() == text
    assert again.settings == scene.settings and again.cameras == scene.cameras


def test_text_holds_the_defines_it_was_read_with(tmp_path):
    path = tmp_path / "named.jts"
    path.write_text(NAMED)
    scene = jtracer.load(path, defines={"r": 3})
    text = scene.text()
    assert "define r = 3;\n" in text and "define r = 2;" not in text
    again = jtracer.parse(text)
    assert again.settings.width == 24 and again.cameras == scene.cameras


def test_text_writes_out_an_include_that_defines_a_given_name(tmp_path):
    (tmp_path / "defs.jts").write_text("define r = 2;\n")
    (tmp_path / "lamp.jts").write_text("point_light { position: <0, r, 0>; }\n")
    main = tmp_path / "main.jts"
    main.write_text('include "defs.jts";\n' + NAMED.split("\n", 1)[1].replace(
        "        point_light { position: <0, r, 0>; intensity: <1, 1, 1>; } }",
        '        include "lamp.jts"; }'))
    kept = jtracer.load(main).text()
    assert 'include "defs.jts";\n' in kept and 'include "lamp.jts";\n' in kept
    assert "define" not in kept
    scene = jtracer.load(main, defines={"r": 3})
    text = scene.text()
    assert "define r = 3;\n" in text and "defs.jts" not in text
    assert 'include "lamp.jts";\n' in text
    again = jtracer.parse(text, path=main)
    assert again.settings == scene.settings and again.cameras == scene.cameras
    assert np.array_equal(again.render(), scene.render()) and again.text() == text


def test_includes_are_read_from_the_paths_folder_and_diagnostics_name_their_file(tmp_path):
    (tmp_path / "parts").mkdir()
    (tmp_path / "parts" / "ball.jts").write_text("sphere { radius: 2; }\n")
    main = tmp_path / "main.jts"
    main_text = WARNED.replace("scene { sphere { radius: 1; } }",
                               'scene { include "parts/ball.jts"; }')
    main.write_text(main_text)
    loaded = jtracer.load(main)
    parsed = jtracer.parse(main_text, path=main)
    # The text keeps the include, and reads back from the same path.
    text = loaded.text()
    assert 'include "parts/ball.jts";' in text and "radius" not in text
    assert parsed.text() == text and jtracer.parse(text, path=main).text() == text
    # Without a path the include is read from the working directory.
    with pytest.raises(jtracer.SceneError, match="parts/ball.jts"):
        jtracer.parse(main_text)
    (tmp_path / "parts" / "ball.jts").write_text("sphere { radius: -1; }\n")
    with pytest.raises(jtracer.SceneError) as raised:
        jtracer.load(main)
    first = raised.value.diagnostics[0]
    assert (first.file, first.line, first.column) == (str(tmp_path / "parts/ball.jts"), 1, 18)
    assert str(raised.value).startswith(f"{tmp_path}/parts/ball.jts:1:18: error: ")
    assert f"note: included from {main}:3:17" in str(raised.value)


TIMED = """render_settings { width: 32; height: 16; }
cameras { perspective_camera { position: <0, 1, 5>; look_at: <0, 0.5, 0>; aspect: 2; } }
scene {
    sphere { center: <2 * clock - 1, 0.5, 0>; radius: 0.5;
             material { pigment: <1, 0.2, 0.1>; ambient: <1, 1, 1>; diffuse: <1, 1, 1>; } }
    point_light { position: <3, 5, 4>; intensity: <1, 1, 1>; }
}
"""


def test_clock_renders_the_frames_jtracer_cli_renders(tmp_path, cli):
    path = tmp_path / "timed.jts"
    path.write_text(TIMED)
    # Frame 1 of 3 is at clock 0.5: the file --frames writes, --clock's bytes.
    run(cli, path, "--frames", "3", "-o", tmp_path / "frame-%d.png", "-q")
    frame = jtracer.read_image(tmp_path / "frame-1.png")
    assert (jtracer.load(path, clock=0.5).render() == frame).all()
    assert (jtracer.parse(TIMED, clock=0.5).render() == frame).all()
    assert not (jtracer.load(path).render() == frame).all(), "the default clock is 0"
    # The text keeps `clock` and reads back as the same scene at that clock.
    scene = jtracer.load(path, clock=0.5)
    assert "2 * clock - 1" in scene.text()
    assert (jtracer.parse(scene.text(), clock=0.5).render() == frame).all()
    # check() sees what the clock makes: a radius that only goes wrong at 1.
    path.write_text(TIMED.replace("radius: 0.5;", "radius: 1 - clock;"))
    assert jtracer.check(path, clock=0.5) == []
    assert [d.severity for d in jtracer.check(path, clock=1)] == ["error"]
    with pytest.raises(ValueError, match="clock: a finite number"):
        jtracer.load(path, clock=float("nan"))
    with pytest.raises(ValueError, match="clock: a finite number"):
        jtracer.parse(TIMED, clock=float("inf"))


SIZELESS = """cameras { perspective_camera { position: <0, 1, 5>; look_at: <0, 0.5, 0>; aspect: 2; } }
scene { sphere { material { pigment: <1, 0, 0>; ambient: <1, 1, 1>; } } }
"""


def test_a_scene_without_a_size_loads_and_renders_at_the_size_asked(tmp_path, cli):
    # As `jtracer-cli scene.jts --width 32 --height 16` renders a file without
    # width and height: load() used to refuse it, telling to "pass --width".
    path = tmp_path / "sizeless.jts"
    path.write_text(SIZELESS)
    scene = jtracer.load(path)
    assert (scene.settings.width, scene.settings.height) == (0, 0)
    assert scene.warnings == []
    run(cli, path, "--width", "32", "--height", "16", "-o", tmp_path / "cli.bmp", "-q")
    assert (scene.render(width=32, height=16) == jtracer.read_image(tmp_path / "cli.bmp")).all()
    # Without them, render() says what to pass, in Python's words.
    with pytest.raises(jtracer.SceneError) as raised:
        scene.render(width=32)
    assert [d.message for d in raised.value.diagnostics] == [
        "the image height is 0: set 'height' in render_settings or pass height= to "
        "Scene.render()"]
    assert "--height" not in str(raised.value)
    # check() still lists them, as --check does; any other error still raises.
    assert [d.message for d in jtracer.check(path)] == [
        "the image width is 0: set 'width' in render_settings or pass width= to Scene.render()",
        "the image height is 0: set 'height' in render_settings or pass height= to "
        "Scene.render()"]
    with pytest.raises(jtracer.SceneError, match="radius"):
        jtracer.parse(SIZELESS.replace("sphere {", "sphere { radius: -1;"))


def test_a_folder_named_in_latin1_gives_the_errors_not_a_decoding_failure(tmp_path):
    # A path is bytes; a folder from another system (Latin-1 "modèles") is not
    # UTF-8. Its scene's errors are a SceneError and check's list, the file
    # named as os.fsdecode names it; an unreadable image there is an OSError.
    folder = tmp_path / os.fsdecode(b"mod\xe8les")
    folder.mkdir()
    scene = folder / "bad.jts"
    scene.write_text('scene { mesh { file: "gone.obj"; } }\n')
    with pytest.raises(jtracer.SceneError) as raised:
        jtracer.load(scene)
    missing = [d for d in raised.value.diagnostics if "gone.obj" in d.message]
    assert len(missing) == 1 and missing[0].file == str(scene)
    assert "gone.obj" in str(raised.value) and "gone.obj" in repr(missing[0])
    assert any("gone.obj" in d.message for d in jtracer.check(scene))
    with pytest.raises(OSError, match="gone.png"):
        jtracer.read_image(folder / "gone.png")
