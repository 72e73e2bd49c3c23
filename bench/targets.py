#!/usr/bin/env python3
"""Prints every performance target of the race with PASS or MISS and by how much.

Reads what bench/run.sh --targets had the other scripts write: race.py's medians
(--race), kernel_limit.py's (--kernel) and startup_cost.py's (--startup). Any of
them may be missing; its targets then read "not measured".

The targets:
  JTracer's wall time <= 1/3 of Tachyon's and <= 1/6 of POV-Ray's, on each race
      scene at 1920x1080 and 1024x1024 and on a million spheres at 320x240 and
      1920x1080 (whole process: read, parse, build, render, write);
  a million triangles from file to a 1080p BMP in under 3 s (mesh_1m);
  a 1x1 render, start-up and safe write included, in under 20 ms;
and, beside each scene, JTracer's rays per second as a share of Embree's native
kernel (no target: how far from the kernel's limit the tracer is).

usage: targets.py [--race FILE] [--kernel FILE] [--startup FILE]
       targets.py --list-scenes   (for bench/run.sh)
"""

import argparse
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from generate_scenes import TACHYON_SCENES  # noqa: E402

RACE_SCENES = list(TACHYON_SCENES)
SCENES = RACE_SCENES + [n + "_1024" for n in RACE_SCENES] + ["spheres_1m_320", "spheres_1m"]
TACHYON_TARGET = 1.0 / 3.0
POVRAY_TARGET = 1.0 / 6.0
MESH_SECONDS = 3.0
STARTUP_MS = 20.0


def load(path):
    if not path or not os.path.exists(path):
        return None
    with open(path, encoding="utf-8") as f:
        return json.load(f)


def verdict(measured, target, unit=""):
    """PASS or MISS against an upper bound, and by how much."""
    if measured is None:
        return "not measured", ""
    if measured <= target:
        return "PASS", f"{100 * (1 - measured / target):.0f}% under the bound"
    return "MISS", f"{measured / target:.2f}x the bound (needs {100 * (1 - target / measured):.0f}% less time)"


def ratio(scene, other, measure="wall"):
    times = scene[measure]
    if times.get("jtracer") is None or times.get(other) is None:
        return None
    return times["jtracer"] / times[other]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--race")
    parser.add_argument("--kernel")
    parser.add_argument("--startup")
    parser.add_argument("--list-scenes", action="store_true",
                        help="print the scenes the targets are measured on and stop")
    args = parser.parse_args()
    if args.list_scenes:
        print("\n".join(SCENES))
        return 0
    race, kernel, startup = load(args.race), load(args.kernel), load(args.startup)
    by_name = {s["name"]: s for s in race["scenes"]} if race else {}
    shares = {s["name"]: s["share"] for s in kernel["scenes"]} if kernel else {}

    if race:
        print(f"race: medians of {race['runs']} alternated runs, {race['threads']} threads, load average "
              f"{race['load_before'][0]:.2f} before and {race['load_after'][0]:.2f} after")
    if kernel:
        print(f"kernel share: medians of {kernel['runs']} alternated runs, load average "
              f"{kernel['load_before'][0]:.2f} before and {kernel['load_after'][0]:.2f} after")
    print()
    print("| scene | size | JT/Tachyon wall (<= 0.333) | by how much | JT/POV-Ray wall (<= 0.167) | by how much "
          "| share of Embree's kernel |")
    print("|---|---|---|---|---|---|---:|")
    passed = failed = 0
    for name in SCENES:
        scene = by_name.get(name)
        cells = []
        for other, target in (("tachyon", TACHYON_TARGET), ("povray", POVRAY_TARGET)):
            r = ratio(scene, other) if scene else None
            word, margin = verdict(r, target)
            passed += word == "PASS"
            failed += word == "MISS"
            # On a busy machine the CPU-time ratio is the steadier figure: shown beside.
            cpu = ratio(scene, other, "cpu") if scene else None
            cells.append(f"{r:.3f} **{word}** (CPU {cpu:.3f})" if r is not None else word)
            cells.append(margin)
        share = shares.get(name)
        print(f"| {name} | {scene['size'] if scene else ''} | " + " | ".join(cells)
              + f" | {f'{100 * share:.0f}%' if share is not None else 'not measured'} |")

    print()
    print("| target | measured | verdict | by how much |")
    print("|---|---:|---|---|")
    mesh = by_name.get("mesh_1m")
    seconds = mesh["wall"].get("jtracer") if mesh else None
    word, margin = verdict(seconds, MESH_SECONDS)
    passed += word == "PASS"
    failed += word == "MISS"
    cpu = f" ({mesh['cpu']['jtracer']:.2f} s CPU)" if mesh else ""
    print(f"| 1M triangles from file to a 1080p BMP < {MESH_SECONDS:.0f} s (mesh_1m, whole process) "
          f"| {f'{seconds:.2f} s{cpu}' if seconds is not None else ''} | **{word}** | {margin} |")
    ms = startup["one_pixel_ms"] if startup else None
    word, margin = verdict(ms, STARTUP_MS)
    passed += word == "PASS"
    failed += word == "MISS"
    where = f" ({startup['scene']}, {startup['runs']} runs, load {startup['load_before'][0]:.2f})" if startup else ""
    print(f"| 1x1 render with the safe write < {STARTUP_MS:.0f} ms{where} "
          f"| {f'{ms:.1f} ms' if ms is not None else ''} | **{word}** | {margin} |")
    print()
    print(f"{passed} targets met, {failed} missed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
