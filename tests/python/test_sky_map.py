# render_settings' background_map through the module: the schema's view names
# it, the render shows it as jtracer-cli does, and a map that cannot be read is
# the check's located error.
import json
import shutil

import jtracer
import numpy as np
import pytest
from conftest import bmp_pixels, run


def test_settings_name_the_map_and_the_render_is_the_cli_bmp(tmp_path, cli, source_dir):
    sky = source_dir / "scenes" / "sky.jts"
    scene = jtracer.load(sky)
    assert scene.settings.background_map == "maps/sky.png"
    assert scene.settings.to_dict()["background_map"] == "maps/sky.png"
    image = scene.render(width=64, height=36, samples=1)
    run(cli, "-q", sky, "-o", tmp_path / "cli.bmp", "--width", "64", "--height", "36",
        "--samples", "1")
    assert np.array_equal(image, bmp_pixels(tmp_path / "cli.bmp"))
    # The sky fills the top row, where no object is: blue away from the sun.
    left = image[0, :16].astype(int)
    assert (left[:, 2] > left[:, 0] + 50).all()


def test_without_a_map_the_setting_is_empty(showcase):
    assert jtracer.load(showcase).settings.background_map == ""


def test_a_missing_map_is_a_located_error(tmp_path):
    scene = tmp_path / "scene.jts"
    scene.write_text('render_settings { width: 4; height: 4;\n'
                     '    background_map: "nowhere.png"; }\n'
                     'cameras { perspective_camera { } }\nscene { }\n')
    with pytest.raises(jtracer.SceneError) as raised:
        jtracer.load(scene)
    [error] = raised.value.diagnostics
    assert (error.line, error.column, error.severity) == (2, 21, "error")
    assert error.message.startswith("background_map: cannot read ")
    assert "nowhere.png" in error.message


def test_info_lists_the_map_with_its_size_and_memory(cli, source_dir, tmp_path):
    sky = source_dir / "scenes" / "sky.jts"
    _, out, _ = run(cli, "info", sky, "--json")
    info = json.loads(out)
    size = 1024 * 512 * 3
    assert info["background_map"] == {"path": str(sky.parent / "maps" / "sky.png"),
                                      "width": 1024, "height": 512, "bytes": size}
    assert info["image_maps"] == [] and info["memory"]["image_maps"] == size
    _, text, _ = run(cli, "info", sky)
    assert f"background map {sky.parent / 'maps' / 'sky.png'}: 1024x512, 1.50 MiB" in text
    # A file that is both the sky and an image map is listed as both, held once.
    shutil.copy(source_dir / "scenes" / "maps" / "sky.png", tmp_path)
    both = tmp_path / "both.jts"
    both.write_text('render_settings { width: 4; height: 4; background_map: "sky.png"; }\n'
                    'cameras { perspective_camera { } }\n'
                    'scene { sphere { material { image_map: "sky.png"; } } }\n')
    info = json.loads(run(cli, "info", both, "--json")[1])
    assert info["background_map"]["path"] == str(tmp_path / "sky.png")
    assert [m["path"] for m in info["image_maps"]] == [str(tmp_path / "sky.png")]
    assert info["memory"]["image_maps"] == size
    # Without a map: null.
    plain = json.loads(run(cli, "info", source_dir / "scenes" / "glass.jts", "--json")[1])
    assert plain["background_map"] is None
