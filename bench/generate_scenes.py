#!/usr/bin/env python3
"""Writes the benchmark scenes (.jts) into a work directory.

Every scene is generated from a fixed seed, so two runs give identical files.
Large scenes are never committed: they are cheap to regenerate.

Two scenes also write the model file they name beside them (knot_100k.ply,
knot_1m.ply).

usage: generate_scenes.py OUT_DIR [--showcase PATH] [--skip-million] [--only NAME ...]
       generate_scenes.py --list-race   (the race scenes' names, for bench/run.sh)
"""

import argparse
import io
import math
import os
import random
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import generate_model  # noqa: E402  (beside this script)

WIDTH, HEIGHT = 1920, 1080
ASPECT = WIDTH / HEIGHT
# The second size of the scenes written for the race against Tachyon.
SQUARE = (1024, 1024)


def settings(out, recurse_depth, background=(0.05, 0.06, 0.1), ambient=(0.2, 0.2, 0.2),
             size=(WIDTH, HEIGHT)):
    out.write("render_settings {\n")
    out.write(f"    width: {size[0]};\n    height: {size[1]};\n")
    out.write(f"    recurse_depth: {recurse_depth};\n")
    out.write("    background: <%g, %g, %g>;\n" % background)
    out.write("    ambient_light: <%g, %g, %g>;\n" % ambient)
    out.write("}\n")


def camera(out, position, look_at, fov, aspect=ASPECT):
    out.write("cameras {\n    perspective_camera {\n")
    out.write("        position: <%g, %g, %g>;\n" % position)
    out.write("        look_at: <%g, %g, %g>;\n" % look_at)
    out.write(f"        aspect: {aspect!r};\n        fov: {fov};\n")
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


def soft_showcase(out, showcase_path, opaque):
    """The showcase at its own 800x450 with its three lights soft (radius 0.5,
    16 shadow samples: 48 shadow rays a hit); `opaque` takes the glass ball's
    transmission away, so that shadow rays are any-hit queries."""
    with open(showcase_path, encoding="ascii") as f:
        text = f.read()
    text = text.replace("        intensity:", "        radius: 0.5;\n        shadow_samples: 16;\n        intensity:")
    if opaque:
        text = text.replace("transmission: 0.9;", "transmission: 0.0;")
    out.write(text)


def soft_lights(write, out, *args):
    """What `write` writes, its lights made soft as soft_showcase's are."""
    text = io.StringIO()
    write(text, *args)
    out.write(text.getvalue().replace(
        "; intensity: <", "; radius: 0.5; shadow_samples: 16; intensity: <"))


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


def random_sphere_text(rng, center, radius):
    colour = tuple(0.2 + 0.8 * rng.random() for _ in range(3))
    return ("sphere{center:<%.4f,%.4f,%.4f>;radius:%.4f;material{pigment:<%.3f,%.3f,%.3f>;"
            "ambient:<0.2,0.2,0.2>;diffuse:<0.8,0.8,0.8>;}}\n" % (center + (radius,) + colour))


def random_spheres(out, count, size=(WIDTH, HEIGHT)):
    """`count` spheres of random size and colour in a box whose side grows as the
    cube root of the count, so that the image looks alike at every size."""
    rng = random.Random(count)
    side = 10.0 * (count / 1000.0) ** (1.0 / 3.0)
    radius = 0.35 * side / count ** (1.0 / 3.0)
    settings(out, 0, size=size)
    distance = side * 1.9
    camera(out, (0.35 * distance, 0.5 * distance, distance), (0.0, 0.0, 0.0), 45, size[0] / size[1])
    out.write("scene {\n")
    write = out.write
    for _ in range(count):
        x, y, z = (side * (rng.random() - 0.5) for _ in range(3))
        write(random_sphere_text(rng, (x, y, z), radius * (0.5 + rng.random())))
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


# Scenes of the race against Tachyon: only spheres, planes and cylinders under
# rotations and translations, which Tachyon shows as they are (jts-to-tachyon).
# Each function takes the image size; the camera's aspect follows it.


def sphere_text(center, radius, mat):
    return "    sphere { center: <%.6f, %.6f, %.6f>; radius: %.6f; %s }\n" % (center + (radius, mat))


def cylinder_text(base, direction, length, radius, mat):
    """A cylinder of `length` from `base` along the unit `direction`: the y axis
    turned by zrotate (away from +y) and then yrotate (about y), docs/language.md §5.2."""
    tilt = math.degrees(math.acos(max(-1.0, min(1.0, direction[1]))))
    turn = math.degrees(math.atan2(direction[2], -direction[0])) if tilt > 1e-9 else 0.0
    return ("    cylinder { radius: %.6f; height: %.6f; %s transform { zrotate: %.6f; "
            "yrotate: %.6f; translate: <%.6f, %.6f, %.6f>; } }\n"
            % ((radius, length, mat, tilt, turn) + tuple(base)))


def unit(v):
    length = math.sqrt(sum(c * c for c in v))
    return tuple(c / length for c in v)


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def frame(axis):
    """Two unit vectors perpendicular to the unit `axis` and to each other."""
    helper = (1.0, 0.0, 0.0) if abs(axis[0]) < 0.9 else (0.0, 1.0, 0.0)
    u = unit(cross(axis, helper))
    return u, cross(axis, u)


def sphereflake(out, size):
    """Haines' sphereflake: every sphere carries nine of a third its radius (six
    around its equator, three above), four levels deep: 7381 mirror spheres."""
    settings(out, 4, background=(0.1, 0.12, 0.2), size=size)
    camera(out, (1.75, 1.3, 2.15), (0.0, 0.5, 0.0), 45, size[0] / size[1])
    out.write("scene {\n")
    floor(out, (0.55, 0.5, 0.45))
    mat = material((0.75, 0.7, 0.65), diffuse=0.5, specular=0.6, specular_k=60, reflection=0.5)
    directions = [(math.cos(math.radians(a)), 0.0, math.sin(math.radians(a))) for a in range(0, 360, 60)]
    directions += [(0.55 * math.cos(math.radians(a)), 0.83, 0.55 * math.sin(math.radians(a)))
                   for a in (30, 150, 270)]

    def flake(center, radius, axis, level):
        out.write(sphere_text(center, radius, mat))
        if level == 0:
            return
        u, v = frame(axis)
        child = radius / 3.0
        for d in directions:
            # d is (along u, along axis, along v) in the parent's frame.
            world = unit(tuple(d[0] * u[i] + d[1] * axis[i] + d[2] * v[i] for i in range(3)))
            flake(tuple(center[i] + (radius + child) * world[i] for i in range(3)), child, world, level - 1)

    flake((0.0, 0.5, 0.0), 0.5, (0.0, 1.0, 0.0), 4)
    light(out, (4.0, 6.0, 3.0), (0.6, 0.6, 0.6))
    light(out, (-5.0, 4.0, 2.0), (0.3, 0.3, 0.35))
    light(out, (1.0, 3.0, -5.0), (0.25, 0.2, 0.2))
    out.write("}\n")


SHELL_COUNT = 5761


def nested_shells(out, size):
    """Spheres of growing radius along a widening spiral, each overlapping dozens
    of its neighbours: the classic worst case of a bounding volume hierarchy. Lit
    and coloured like the random spheres, so that spheres_5761 is its fair twin."""
    rng = random.Random(5761)
    settings(out, 0, size=size)
    camera(out, (0.0, 30.0, 42.0), (0.0, 0.0, 0.0), 45, size[0] / size[1])
    out.write("scene {\n")
    for i in range(SHELL_COUNT):
        t = i / SHELL_COUNT
        angle = 0.03 * i
        reach = 1.0 + 14.0 * t
        center = (reach * math.cos(angle), 8.0 * (t - 0.5), reach * math.sin(angle))
        out.write(random_sphere_text(rng, center, 0.2 + 2.3 * t))
    light(out, (25.0, 50.0, 35.0), (0.9, 0.9, 0.9))
    out.write("}\n")


def lattice(out, size, n=13):
    """A cubic grid of n^3 mirror spheres, each joined to its neighbours by
    cylinders: 8281 primitives for n = 13."""
    settings(out, 3, size=size)
    camera(out, (n * 1.6, n * 1.3, n * 1.9), ((n - 1) / 2, (n - 1) / 2, (n - 1) / 2), 45,
           size[0] / size[1])
    out.write("scene {\n")
    floor(out, (0.5, 0.5, 0.5))
    ball = material((0.85, 0.3, 0.25), diffuse=0.6, specular=0.7, specular_k=80, reflection=0.45)
    rod = material((0.7, 0.75, 0.8), diffuse=0.8, specular=0.3, specular_k=30)
    axes = ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0))
    for i in range(n):
        for j in range(n):
            for k in range(n):
                p = (float(i), 1.0 + j, float(k))
                out.write(sphere_text(p, 0.28, ball))
                for a, axis in enumerate(axes):
                    if (i, j, k)[a] + 1 < n:
                        out.write(cylinder_text(p, axis, 1.0, 0.07, rod))
    light(out, (n * 2.0, n * 3.0, n * 1.0), (0.7, 0.7, 0.7))
    light(out, (-n * 1.0, n * 2.0, n * 2.5), (0.35, 0.35, 0.4))
    out.write("}\n")


def tree(out, size, depth=11):
    """A branching tree: every branch a cylinder with a sphere at its far joint and
    two thinner, shorter branches from there, 2^(depth+1) - 1 = 4095 branches
    (8190 primitives) for depth 11."""
    rng = random.Random(11)
    settings(out, 0, background=(0.55, 0.7, 0.9), ambient=(0.25, 0.25, 0.25), size=size)
    camera(out, (0.0, 6.5, 17.0), (0.0, 5.5, 0.0), 45, size[0] / size[1])
    out.write("scene {\n")
    floor(out, (0.4, 0.55, 0.3))
    bark = material((0.45, 0.32, 0.2), specular=0.1, specular_k=10)
    leaf = material((0.25, 0.6, 0.2), specular=0.3, specular_k=30)

    def branch(base, direction, length, radius, level):
        tip = tuple(base[i] + length * direction[i] for i in range(3))
        out.write(cylinder_text(base, direction, length, radius, bark if level > 2 else leaf))
        out.write(sphere_text(tip, radius * 1.2, bark if level > 2 else leaf))
        if level == 0:
            return
        u, v = frame(direction)
        spin = rng.uniform(0.0, 2.0 * math.pi)
        for side in (0.0, math.pi):
            spread = math.radians(rng.uniform(22.0, 38.0))
            around = spin + side
            out_of_axis = tuple(math.cos(around) * u[i] + math.sin(around) * v[i] for i in range(3))
            child = unit(tuple(math.cos(spread) * direction[i] + math.sin(spread) * out_of_axis[i]
                               for i in range(3)))
            branch(tip, child, length * rng.uniform(0.72, 0.82), radius * 0.7, level - 1)

    branch((0.0, 0.0, 0.0), (0.0, 1.0, 0.0), 3.0, 0.35, depth)
    light(out, (12.0, 20.0, 14.0), (0.75, 0.7, 0.6))
    light(out, (-10.0, 12.0, 8.0), (0.25, 0.28, 0.35))
    out.write("}\n")


def few(out, size):
    """Thirty-two primitives (25 spheres, 6 cylinders, a floor), two lights, two
    bounces: a scene where the fixed costs (start-up, build, writing) dominate."""
    rng = random.Random(32)
    settings(out, 2, size=size)
    camera(out, (0.0, 4.0, 11.0), (0.0, 0.8, 0.0), 45, size[0] / size[1])
    out.write("scene {\n")
    floor(out, (0.6, 0.6, 0.6), reflection=0.2)
    for i in range(5):
        for j in range(5):
            pigment = tuple(0.3 + 0.7 * rng.random() for _ in range(3))
            out.write(sphere_text((-4.0 + 2.0 * i, 0.5, -4.0 + 2.0 * j), 0.5,
                                  material(pigment, specular=0.5, specular_k=50, reflection=0.3)))
    for i in range(6):
        out.write(cylinder_text((-5.0 + 2.0 * i, 0.0, -6.0), (0.0, 1.0, 0.0), 2.5, 0.25,
                                material((0.8, 0.8, 0.75), specular=0.3)))
    light(out, (5.0, 8.0, 6.0), (0.7, 0.7, 0.7))
    light(out, (-6.0, 5.0, 4.0), (0.3, 0.3, 0.35))
    out.write("}\n")


def knot_mesh(out, out_dir, triangles, model_name):
    """A torus knot of `triangles` triangles (bench/generate_model.py, written
    beside the scene), smooth-shaded, over a floor, one light: meshes raced
    against POV-Ray's mesh2 (Tachyon reads no model files)."""
    path = os.path.join(out_dir, model_name)
    temporary = path + ".tmp"
    generate_model.write_knot(temporary, triangles)
    os.replace(temporary, path)
    settings(out, 1)
    camera(out, (0.0, 3.5, 9.5), (0.0, 0.0, 0.0), 40)
    out.write("scene {\n")
    out.write("    plane { normal: <0, 1, 0>; distance: -1.6; ")
    out.write(material((0.6, 0.6, 0.6), specular=0.0) + " }\n")
    out.write(f"    mesh {{ file: \"{model_name}\"; ")
    out.write(material((0.85, 0.45, 0.2), specular=0.5, specular_k=60, reflection=0.2) + " }\n")
    light(out, (4.0, 9.0, 6.0), (0.9, 0.9, 0.9))
    out.write("}\n")


def separate_spheres(out, size):
    """spheres of the nested-shells count scattered as random_spheres does."""
    random_spheres(out, SHELL_COUNT, size)


# name -> writer(out, size) of the race against Tachyon, written at both sizes:
# NAME at 1920x1080, NAME_1024 at 1024x1024. The one list of them: race.py,
# targets.py and run.sh take it from here.
TACHYON_SCENES = {
    "sphereflake": sphereflake,
    "nested_shells": nested_shells,
    "spheres_5761": separate_spheres,
    "lattice": lattice,
    "tree": tree,
    "few": few,
}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out_dir", nargs="?")
    parser.add_argument("--list-race", action="store_true",
                        help="print the names of the race scenes at 1920x1080 and write nothing")
    parser.add_argument("--showcase", default=os.path.join(os.path.dirname(__file__), "..", "scenes", "showcase.jts"))
    parser.add_argument("--skip-million", action="store_true",
                        help="leave out spheres_1m, spheres_1m_320 and mesh_1m")
    parser.add_argument("--only", nargs="*", help="write only the scenes with these names")
    args = parser.parse_args()
    if args.list_race:
        print("\n".join(TACHYON_SCENES))
        return 0
    if args.out_dir is None:
        parser.error("the folder to write the scenes into is missing")

    scenes = {
        "showcase": lambda out: showcase(out, args.showcase),
        "showcase_soft": lambda out: soft_showcase(out, args.showcase, False),
        "showcase_soft_opaque": lambda out: soft_showcase(out, args.showcase, True),
        "hall_of_mirrors": hall_of_mirrors,
        "forest": forest,
        "lights16": sixteen_lights,
        "spheres_1k": lambda out: random_spheres(out, 1000),
        "spheres_10k": lambda out: random_spheres(out, 10000),
        "spheres_100k": lambda out: random_spheres(out, 100000),
        "spheres_1m": lambda out: random_spheres(out, 1000000),
        # The same million spheres at 320x240: the cost of the scene, not of the pixels.
        "spheres_1m_320": lambda out: random_spheres(out, 1000000, size=(320, 240)),
        "mesh_100k": lambda out: knot_mesh(out, args.out_dir, 100000, "knot_100k.ply"),
        "mesh_1m": lambda out: knot_mesh(out, args.out_dir, 1000000, "knot_1m.ply"),
    }
    # Soft-light twins of two race scenes (opaque, with a BVH), for the shadow rays' timings.
    scenes["few_soft"] = lambda out: soft_lights(few, out, (WIDTH, HEIGHT))
    scenes["nested_shells_soft_1024"] = lambda out: soft_lights(nested_shells, out, SQUARE)
    for name, write in TACHYON_SCENES.items():
        scenes[name] = lambda out, write=write: write(out, (WIDTH, HEIGHT))
        scenes[name + "_1024"] = lambda out, write=write: write(out, SQUARE)
    os.makedirs(args.out_dir, exist_ok=True)
    for name, write in scenes.items():
        if args.only and name not in args.only:
            continue
        if args.skip_million and name in ("spheres_1m", "spheres_1m_320", "mesh_1m"):
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
