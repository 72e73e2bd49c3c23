#!/usr/bin/env python3
"""Writes the benchmark scenes (.jts) into a work directory.

Every scene is generated from a fixed seed, so two runs give identical files.
Large scenes are never committed: they are cheap to regenerate.

usage: generate_scenes.py OUT_DIR [--showcase PATH] [--skip-million] [--only NAME ...]
"""

import argparse
import math
import os
import random
import sys

WIDTH, HEIGHT = 1920, 1080
ASPECT = WIDTH / HEIGHT


def settings(out, recurse_depth, background=(0.05, 0.06, 0.1), ambient=(0.2, 0.2, 0.2)):
    out.write("render_settings {\n")
    out.write(f"    width: {WIDTH};\n    height: {HEIGHT};\n")
    out.write(f"    recurse_depth: {recurse_depth};\n")
    out.write("    background: <%g, %g, %g>;\n" % background)
    out.write("    ambient_light: <%g, %g, %g>;\n" % ambient)
    out.write("}\n")


def camera(out, position, look_at, fov):
    out.write("cameras {\n    perspective_camera {\n")
    out.write("        position: <%g, %g, %g>;\n" % position)
    out.write("        look_at: <%g, %g, %g>;\n" % look_at)
    out.write(f"        aspect: {ASPECT!r};\n        fov: {fov};\n")
    out.write("    }\n}\n")


def material(pigment, diffuse=0.8, specular=0.3, specular_k=40.0, reflection=0.0, ambient=0.2):
    text = "material { pigment: <%.4f, %.4f, %.4f>; " % pigment
    text += f"ambient: <{ambient}, {ambient}, {ambient}>; "
    text += f"diffuse: <{diffuse}, {diffuse}, {diffuse}>; "
    if specular > 0:
        text += f"specular: <{specular}, {specular}, {specular}>; specular_k: {specular_k}; "
    if reflection > 0:
        text += f"reflection: {reflection}; "
    return text + "}"


def light(out, position, intensity):
    out.write("    point_light { position: <%g, %g, %g>; " % position)
    out.write("intensity: <%.3f, %.3f, %.3f>; }\n" % intensity)


def floor(out, pigment=(0.6, 0.6, 0.6), reflection=0.0):
    out.write("    plane { normal: <0, 1, 0>; distance: 0; ")
    out.write(material(pigment, specular=0.0, reflection=reflection) + " }\n")


def showcase(out, showcase_path):
    """The repository's showcase, rendered at 1920x1080."""
    with open(showcase_path, encoding="ascii") as f:
        text = f.read()
    text = text.replace("width: 800;", f"width: {WIDTH};").replace("height: 450;", f"height: {HEIGHT};")
    out.write(text)


def hall_of_mirrors(out):
    """Mirror spheres between two facing mirror walls: every ray bounces to depth 8."""
    rng = random.Random(8)
    settings(out, 8)
    camera(out, (0.0, 3.0, 11.0), (0.0, 1.5, 0.0), 50)
    out.write("scene {\n")
    floor(out, (0.5, 0.5, 0.55), reflection=0.5)
    for normal, distance in (((1, 0, 0), -8), ((-1, 0, 0), -8), ((0, 0, 1), -10), ((0, 0, -1), -14)):
        out.write("    plane { normal: <%d, %d, %d>; distance: %d; " % (normal + (distance,)))
        out.write(material((0.9, 0.9, 0.95), diffuse=0.1, specular=0.0, reflection=0.9) + " }\n")
    for i in range(5):
        for j in range(5):
            x, z = -6 + 3 * i, -6 + 3 * j
            pigment = tuple(0.3 + 0.7 * rng.random() for _ in range(3))
            out.write("    sphere { center: <%g, 1, %g>; radius: 1; " % (x, z))
            out.write(material(pigment, diffuse=0.3, specular=0.8, specular_k=120, reflection=0.7) + " }\n")
    light(out, (0.0, 9.0, 4.0), (0.8, 0.8, 0.8))
    light(out, (-5.0, 6.0, 8.0), (0.4, 0.35, 0.3))
    out.write("}\n")


def random_spheres(out, count):
    """`count` spheres of random size and colour in a box whose side grows as the
    cube root of the count, so that the image looks alike at every size."""
    rng = random.Random(count)
    side = 10.0 * (count / 1000.0) ** (1.0 / 3.0)
    radius = 0.35 * side / count ** (1.0 / 3.0)
    settings(out, 0)
    distance = side * 1.9
    camera(out, (0.35 * distance, 0.5 * distance, distance), (0.0, 0.0, 0.0), 45)
    out.write("scene {\n")
    write = out.write
    for _ in range(count):
        x, y, z = (side * (rng.random() - 0.5) for _ in range(3))
        r = radius * (0.5 + rng.random())
        cr, cg, cb = (0.2 + 0.8 * rng.random() for _ in range(3))
        write(
            "sphere{center:<%.4f,%.4f,%.4f>;radius:%.4f;material{pigment:<%.3f,%.3f,%.3f>;"
            "ambient:<0.2,0.2,0.2>;diffuse:<0.8,0.8,0.8>;}}\n" % (x, y, z, r, cr, cg, cb)
        )
    light(out, (side, side * 2, side * 1.5), (0.9, 0.9, 0.9))
    out.write("}\n")


def forest(out):
    """Trunks (rotated, scaled cylinders) under crowns (non-uniformly scaled spheres)."""
    rng = random.Random(42)
    settings(out, 0, background=(0.5, 0.7, 0.9), ambient=(0.3, 0.3, 0.3))
    camera(out, (0.0, 6.0, 30.0), (0.0, 3.0, 0.0), 50)
    out.write("scene {\n")
    floor(out, (0.35, 0.5, 0.25))
    for i in range(40):
        for j in range(40):
            x = -40 + 2.0 * i + rng.uniform(-0.6, 0.6)
            z = -60 + 2.0 * j + rng.uniform(-0.6, 0.6)
            height = rng.uniform(2.0, 4.0)
            lean_x, lean_z, turn = rng.uniform(-6, 6), rng.uniform(-6, 6), rng.uniform(0, 360)
            out.write("    cylinder { radius: 0.2; height: 1; ")
            out.write(material((0.45, 0.3, 0.15), specular=0.0))
            out.write(" transform { scale: <1, %.3f, 1>; yrotate: %.2f; xrotate: %.2f; " % (height, turn, lean_x))
            out.write("zrotate: %.2f; translate: <%.3f, 0, %.3f>; } }\n" % (lean_z, x, z))
            crown = (0.1 + 0.2 * rng.random(), 0.4 + 0.4 * rng.random(), 0.1 + 0.15 * rng.random())
            sx, sy, sz = rng.uniform(0.8, 1.3), rng.uniform(1.2, 2.2), rng.uniform(0.8, 1.3)
            out.write("    sphere { radius: 1; ")
            out.write(material(crown, specular=0.2, specular_k=20))
            out.write(" transform { scale: <%.3f, %.3f, %.3f>; yrotate: %.2f; " % (sx, sy, sz, turn))
            out.write("translate: <%.3f, %.3f, %.3f>; } }\n" % (x, height + sy * 0.8, z))
    light(out, (30.0, 50.0, 40.0), (0.9, 0.85, 0.7))
    out.write("}\n")


def sixteen_lights(out):
    """16 coloured point lights over a grid of spheres: 16 shadow rays a hit."""
    rng = random.Random(16)
    settings(out, 0, ambient=(0.05, 0.05, 0.05))
    camera(out, (0.0, 9.0, 16.0), (0.0, 0.0, 0.0), 45)
    out.write("scene {\n")
    floor(out, (0.8, 0.8, 0.8))
    for i in range(8):
        for j in range(8):
            out.write("    sphere { center: <%g, 0.6, %g>; radius: 0.6; " % (-7 + 2 * i, -7 + 2 * j))
            out.write(material((0.9, 0.9, 0.9), diffuse=0.9, specular=0.5, specular_k=60) + " }\n")
    for k in range(16):
        angle = 2 * math.pi * k / 16
        colour = tuple(0.08 + 0.12 * rng.random() for _ in range(3))
        light(out, (9 * math.cos(angle), 4 + 2 * (k % 2), 9 * math.sin(angle)), colour)
    out.write("}\n")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out_dir")
    parser.add_argument("--showcase", default=os.path.join(os.path.dirname(__file__), "..", "scenes", "showcase.jts"))
    parser.add_argument("--skip-million", action="store_true", help="leave out spheres_1m")
    parser.add_argument("--only", nargs="*", help="write only the scenes with these names")
    args = parser.parse_args()

    scenes = {
        "showcase": lambda out: showcase(out, args.showcase),
        "hall_of_mirrors": hall_of_mirrors,
        "forest": forest,
        "lights16": sixteen_lights,
        "spheres_1k": lambda out: random_spheres(out, 1000),
        "spheres_10k": lambda out: random_spheres(out, 10000),
        "spheres_100k": lambda out: random_spheres(out, 100000),
        "spheres_1m": lambda out: random_spheres(out, 1000000),
    }
    os.makedirs(args.out_dir, exist_ok=True)
    for name, write in scenes.items():
        if args.only and name not in args.only:
            continue
        if args.skip_million and name == "spheres_1m":
            continue
        path = os.path.join(args.out_dir, name + ".jts")
        temporary = path + ".tmp"
        with open(temporary, "w", encoding="ascii") as out:
            write(out)
        os.replace(temporary, path)
        print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
