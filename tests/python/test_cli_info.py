# jtracer-cli info: what a scene holds, on a scene with spheres, a mesh from
# each model format the project reads and an image map; --json parsed.
import json
import math
import os
import pathlib
import shutil
import subprocess

import pytest
from conftest import run

MODELS = pathlib.Path("/usr/share/assimp/models")  # assimp-testmodels, as tests/language use


@pytest.fixture
def scene(tmp_path, source_dir):
    shutil.copy(MODELS / "OBJ" / "box.obj", tmp_path)
    shutil.copy(source_dir / "scenes" / "models" / "knot.ply", tmp_path)
    shutil.copy(MODELS / "STL" / "Spider_ascii.stl", tmp_path)
    shutil.copytree(MODELS / "glTF2" / "BoxTextured-glTF", tmp_path / "gltf")
    shutil.copy(MODELS / "glTF2" / "BoxTextured-glTF-Binary" / "BoxTextured.glb", tmp_path)
    shutil.copy(source_dir / "scenes" / "maps" / "tiles.png", tmp_path)
    meshes = "".join(
        f'    mesh {{ file: "{name}"; material {{ pigment: <1, 1, 1>; }} '
        f"transform {{ translate: <{i * 10}, 0, 0>; }} }}\n"
        for i, name in enumerate(["box.obj", "knot.ply", "Spider_ascii.stl",
                                  "gltf/BoxTextured.gltf", "BoxTextured.glb", "box.obj"])
    )
    path = tmp_path / "inventory.jts"
    path.write_text(f"""render_settings {{ width: 64; height: 48; }}
cameras {{
    perspective_camera {{ name: "front"; position: <0, 0, 10>; look_at: <0, 0, 0>; aspect: 1.3333333333333333; }}
    perspective_camera {{ name: "side"; position: <10, 0, 0>; look_at: <0, 0, 0>; aspect: 1.3333333333333333; }}
}}
scene {{
    sphere {{ center: <0, 0, -100>; radius: 2; material {{ pigment: <1, 0, 0>; image_map: "tiles.png"; }} }}
    sphere {{ center: <0, 50, 0>; radius: 1; transform {{ scale: <3, 3, 3>; }} }}
    plane {{ normal: <0, 1, 0>; distance: -1; }}
{meshes}    point_light {{ position: <5, 5, 5>; intensity: <1, 1, 1>; }}
}}
""")
    return path


def test_info_json_counts_meshes_maps_lights_and_cameras(cli, scene):
    _, out, _ = run(cli, "info", scene, "--json")
    info = json.loads(out)
    assert info["primitives"] == {"sphere": 2, "plane": 1, "cylinder": 0, "triangle": 0, "mesh": 6}
    meshes = info["meshes"]
    assert [m["file"] for m in meshes] == ["box.obj", "knot.ply", "Spider_ascii.stl",
                                         "gltf/BoxTextured.gltf", "BoxTextured.glb", "box.obj"]
    assert all(m["triangles"] > 0 and m["vertices"] >= 3 for m in meshes)
    assert meshes[0]["triangles"] == 12  # six quads
    assert meshes[1]["triangles"] == 20020 and meshes[1]["vertices"] == 10332
    # STL has facet normals only, and without smooth_angle its triangles are
    # shaded flat (none generated); PLY and glTF carry vertex normals.
    assert meshes[2]["normals"] == "none"
    assert [meshes[i]["normals"] for i in (1, 3, 4)] == ["file"] * 3
    assert [m["read_before"] for m in meshes] == [False] * 5 + [True]
    assert all(m["load_seconds"] >= 0 for m in meshes)
    # Each mesh's world box is its model's box moved by its translate.
    first, last = meshes[0]["bbox"], meshes[5]["bbox"]
    assert last["lower"] == pytest.approx([first["lower"][0] + 50] + first["lower"][1:])
    assert last["upper"] == pytest.approx([first["upper"][0] + 50] + first["upper"][1:])
    # The scene's box holds the spheres (the scaled one reaches y = 153) and
    # the meshes, not the plane.
    box = info["bbox"]
    assert box["lower"][2] == pytest.approx(-102) and box["upper"][1] == pytest.approx(153)
    assert box["upper"][0] >= last["upper"][0] and info["unbounded"] == 1
    assert info["image_maps"] == [{"path": str(scene.parent / "tiles.png"), "width": 64,
                                   "height": 64, "bytes": 64 * 64 * 3}]
    assert info["lights"] == [{"position": [5, 5, 5], "intensity": [1, 1, 1], "radius": 0,
                               "shadow_samples": 16}]
    front, side = info["cameras"]
    assert (front["name"], front["active"], side["active"]) == ("front", True, False)
    assert side["direction"] == pytest.approx([-1, 0, 0])
    assert math.isclose(sum(c * c for c in front["direction"]), 1.0)
    memory = info["memory"]
    assert memory["image_maps"] == 64 * 64 * 3
    assert memory["models"] > 20020 * 12  # the knot's triangles alone
    # Embree's own copy of the triangles and its BVH, as its memory monitor counts them.
    assert memory["embree"] > 20020 * 12
    assert memory["total"] == (memory["models"] + memory["image_maps"] + memory["primitives"]
                               + memory["embree"])


def test_info_text_names_every_mesh_and_camera(cli, scene):
    _, out, _ = run(cli, "info", scene)
    assert "primitives: cylinder 0 mesh 6 plane 1 sphere 2 triangle 0" in out
    for name in ("box.obj", "knot.ply: 20020 triangles", "Spider_ascii.stl", "BoxTextured.glb"):
        assert f"mesh {name}" in out
    assert "the file of an earlier mesh" in out
    assert 'camera "side": at <10, 0, 0> looking at <0, 0, 0> (direction <-1, 0, 0>)' in out
    assert "image map" in out and "64x64" in out
    assert "(and 1 unbounded planes)" in out


def test_info_shows_soft_shadows_and_the_lens(cli, tmp_path):
    path = tmp_path / "soft.jts"
    path.write_text(
        "render_settings { width: 8; height: 8; samples: 16; }\n"
        "cameras { perspective_camera { name: \"lens\"; position: <0, 0, 5>; aperture: 0.25; }\n"
        "          perspective_camera { name: \"near\"; aperture: 0.5; focus_distance: 2; } }\n"
        "scene { point_light { position: <0, 5, 0>; intensity: <1, 1, 1>; radius: 1.5;\n"
        "                      shadow_samples: 32; }\n"
        "        point_light { position: <0, 5, 5>; } }\n")
    _, out, _ = run(cli, "info", path)
    assert "point light at <0, 5, 0>, intensity <1, 1, 1>, radius 1.5 (32 shadow samples)\n" in out
    assert "point light at <0, 5, 5>, intensity <0, 0, 0>\n" in out
    # The focus distance a camera uses: its own, or the distance to look_at.
    assert "fov 45.0, aperture 0.25, in focus at 6.0\n" in out
    assert "fov 45.0, aperture 0.5, in focus at 2.0\n" in out
    info = json.loads(run(cli, "info", path, "--json")[1])
    assert [(l["radius"], l["shadow_samples"]) for l in info["lights"]] == [(1.5, 32), (0, 16)]
    assert [(c["aperture"], c["focus_distance"]) for c in info["cameras"]] == [(0.25, 6), (0.5, 2)]


def test_info_takes_define_and_clock_as_a_render_does(cli, tmp_path):
    path = tmp_path / "moving.jts"
    path.write_text("define r = 1;\n"
                    "cameras { perspective_camera { position: <r, 10 * clock, 5>; } }\n")
    info = json.loads(run(cli, "info", path, "--json", "--clock", "0.5", "--define", "r=3")[1])
    assert info["cameras"][0]["position"] == [3, 5, 5]
    # No width or height: a render's to set, which info does not ask for
    # (it takes no --width).
    _, out, err = run(cli, "info", path)
    assert 'camera "" (active): at <1, 0, 5>' in out and "width" not in err
    code, _, err = run(cli, "info", path, "--clock", "nan", check=False)
    assert code == 2 and "--clock" in err


def test_info_of_a_bad_scene_reports_like_check(cli, tmp_path):
    bad = tmp_path / "bad.jts"
    bad.write_text("scene { sphere { radius: -1; } }\n")
    code, out, err = run(cli, "info", bad, check=False)
    assert code == 1 and out == "" and "bad.jts:1:" in err
    code, _, err = run(cli, "info", tmp_path / "missing.jts", check=False)
    assert code == 3 and "missing.jts" in err
    code, _, err = run(cli, "info", check=False)
    assert code == 2


def test_info_prints_the_warnings_a_render_prints(cli, tmp_path):
    # A model of lines only is left out with a warning: info shows the mesh
    # with 0 triangles and no box, and says why on stderr, as a render does.
    shutil.copy(MODELS / "AC" / "closedLine.ac", tmp_path)
    path = tmp_path / "lines.jts"
    path.write_text('render_settings { width: 8; height: 8; }\n'
                    'cameras { perspective_camera { position: <0, 0, 10>; } }\n'
                    'scene { mesh { file: "closedLine.ac"; } }\n')
    warning = "lines.jts:3:22: warning: mesh 1: 'closedLine.ac' holds only 4 lines, no triangle"
    _, _, rendered = run(cli, path, "-o", tmp_path / "lines.bmp")
    assert warning in rendered
    _, out, err = run(cli, "info", path)
    assert "mesh closedLine.ac: 0 triangles" in out and warning in err
    _, out, err = run(cli, "info", path, "--json")
    assert json.loads(out)["meshes"][0]["triangles"] == 0 and warning in err


def test_info_lists_the_parts_of_a_mesh_with_materials_from_its_file(cli, tmp_path):
    # An OBJ with a face before any usemtl, a red part and a textured one
    # (docs/language.md 14.5); the same file with "scene" has no parts.
    shutil.copy(MODELS / "OBJ" / "SpiderTex.jpg", tmp_path)
    (tmp_path / "m.mtl").write_text("newmtl red\nKd 1 0 0\nnewmtl skin\nmap_Kd -s 2 2 1 SpiderTex.jpg\n")
    (tmp_path / "m.obj").write_text("mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
                                    "f 1 2 3\nusemtl red\nf 2 4 3\nf 1 2 4\nusemtl skin\nf 1 4 3\n")
    scene = tmp_path / "parts.jts"
    scene.write_text("""render_settings { width: 8; height: 8; }
cameras { perspective_camera { position: <0.5, 0.5, 3>; look_at: <0.5, 0.5, 0>; } }
scene {
    mesh { file: "m.obj"; materials: "file"; }
    mesh { file: "m.obj"; }
}
""")
    _, out, _ = run(cli, "info", scene, "--json")
    with_parts, without = json.loads(out)["meshes"]
    assert with_parts["materials"] == "file" and without["materials"] == "scene"
    assert without["parts"] == []
    assert with_parts["parts"] == [
        {"name": "", "base_colour": None, "texture": "", "vertex_colours": False, "triangles": 1},
        {"name": "red", "base_colour": [1, 0, 0], "texture": "", "vertex_colours": False,
         "triangles": 2},
        {"name": "skin", "base_colour": [1, 1, 1], "texture": "SpiderTex.jpg",
         "vertex_colours": False, "triangles": 1},
    ]
    _, out, _ = run(cli, "info", scene)
    assert '  part "red": 2 triangles, base colour <1, 0, 0>\n' in out
    assert '  part "skin": 1 triangles, base colour <1, 1, 1>, texture SpiderTex.jpg\n' in out
    assert "  part (no material): 1 triangles\n" in out


def test_info_json_of_a_scene_in_a_folder_named_in_latin1(tmp_path, cli):
    # The folder's name is not UTF-8 (Latin-1 "modèles"): --json still prints
    # one UTF-8 object, the byte replaced, rather than stopping on it.
    folder = tmp_path / os.fsdecode(b"mod\xe8les")
    folder.mkdir()
    shutil.copy(MODELS / "OBJ" / "box.obj", folder)
    (folder / "scene.jts").write_text(
        'render_settings { width: 8; height: 8; }\n'
        'cameras { perspective_camera { position: <0, 0, 10>; look_at: <0, 0, 0>; } }\n'
        'scene { mesh { file: "box.obj"; } }\n')
    done = subprocess.run([str(cli), "info", "--json", str(folder / "scene.jts")],
                          capture_output=True, timeout=60)
    assert done.returncode == 0, done.stderr
    described = json.loads(done.stdout.decode("utf-8"))
    assert described["meshes"][0]["path"].endswith("mod\ufffdles/box.obj")


def test_info_says_normals_are_generated_only_where_smooth_angle_makes_them(tmp_path, cli):
    shutil.copy(MODELS / "STL" / "Spider_ascii.stl", tmp_path)
    path = tmp_path / "normals.jts"
    path.write_text(
        'render_settings { width: 8; height: 8; }\n'
        'cameras { perspective_camera { position: <0, 0, 10>; look_at: <0, 0, 0>; } }\n'
        'scene {\n'
        '    mesh { file: "Spider_ascii.stl"; smooth_angle: 60; }\n'
        '    mesh { file: "Spider_ascii.stl"; }\n'
        '}\n')
    _, out, _ = run(cli, "info", path, "--json")
    assert [m["normals"] for m in json.loads(out)["meshes"]] == ["generated", "none"]
    _, text, _ = run(cli, "info", path)
    assert "normals generated, smooth" in text and "normals none, smooth" in text


def test_info_json_of_a_material_named_in_latin1(tmp_path, cli):
    # An OBJ exported on a Latin-1 system names its material "Matériau" in
    # bytes that are not UTF-8; --json printed nothing and aborted on it.
    (tmp_path / "m.mtl").write_bytes(b"newmtl Mat\xe9riau\nKd 1 0 0\n")
    (tmp_path / "t.obj").write_bytes(
        b"mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl Mat\xe9riau\nf 1 2 3\n")
    (tmp_path / "s.jts").write_text(
        'render_settings { width: 8; height: 8; }\n'
        'cameras { perspective_camera { position: <0, 0, 5>; look_at: <0, 0, 0>; } }\n'
        'scene { mesh { file: "t.obj"; materials: "file"; } }\n')
    done = subprocess.run([str(cli), "info", "--json", str(tmp_path / "s.jts")],
                          capture_output=True, timeout=60)
    assert done.returncode == 0, done.stderr
    parts = json.loads(done.stdout.decode("utf-8"))["meshes"][0]["parts"]
    assert [p["name"] for p in parts] == ["Mat\ufffdriau"]
