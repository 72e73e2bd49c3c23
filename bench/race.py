#!/usr/bin/env python3
"""Races jtracer-cli against Tachyon and POV-Ray 3.7 on the benchmark scenes and prints a table.

For each scene the renderers run in turn (JTracer, Tachyon, POV-Ray, JTracer, ...)
so that a busy spell of the machine hurts all alike; the table shows medians.
Wall time is the whole process: reading and parsing the file, building the
acceleration structure, rendering and writing the image. Peak memory is the
child's maximum resident set size (getrusage). Images are kept in the work
directory as SCENE.jtracer.bmp, SCENE.tachyon.bmp and SCENE.povray.bmp.

Before a scene is timed with Tachyon, check_silhouettes.py renders both sides in
flat per-primitive colours: Tachyon is timed only where it shows the same
geometry. A scene with a shape Tachyon lacks (an ellipsoid) has no Tachyon column.

With --json FILE, the medians are also written there for bench/targets.py.

usage: race.py --cli PATH --converter PATH --tachyon-converter PATH --scenes DIR --out DIR
               [--runs N] [--threads N] [--only NAME ...] [--no-povray] [--no-tachyon]
               [--json FILE]
"""

import argparse
import json
import os
import re
import resource
import statistics
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from generate_scenes import TACHYON_SCENES  # noqa: E402

SUMMARY = re.compile(r"wrote .*?: (\d+)x(\d+), .*?, ([\d.]+) s, ([\d.]+) (M )?rays")


def run_timed(command, attempts=1):
    """Runs a command; returns (wall seconds, CPU seconds, peak RSS MiB, stdout + stderr).

    With attempts > 1, a failed run is tried again: POV-Ray 3.7 sometimes dies at
    start-up on a busy machine ("Timed out waiting for worker thread startup").
    """
    for attempt in range(1, attempts + 1):
        result = run_once(command, last=attempt == attempts)
        if result:
            return result
        print(f"  run failed, trying again ({attempt}/{attempts - 1})", file=sys.stderr)
    raise AssertionError("unreachable")


def run_once(command, last):
    """One run_timed attempt; None when it failed and is not the last."""
    start = time.perf_counter()
    # A fresh process per run, so ru_maxrss of this wait is this child's alone.
    pid = os.fork()
    if pid == 0:
        try:
            out = os.open(command_log(), os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o644)
            os.dup2(out, 1)
            os.dup2(out, 2)
            os.execvp(command[0], command)
        finally:
            os._exit(127)
    _, status, usage = os.wait4(pid, 0)
    wall = time.perf_counter() - start
    with open(command_log(), encoding="utf-8", errors="replace") as f:
        output = f.read()
    if os.waitstatus_to_exitcode(status) != 0:
        if not last:
            return None
        sys.exit(f"failed ({os.waitstatus_to_exitcode(status)}): {' '.join(command)}\n{output}")
    return wall, usage.ru_utime + usage.ru_stime, usage.ru_maxrss / 1024.0, output


_log_path = None


def command_log():
    return _log_path


def jtracer_rays(output):
    """Rays traced and render seconds, from the CLI's summary line."""
    match = SUMMARY.search(output)
    if not match:
        sys.exit("cannot find the ray count in jtracer-cli's summary:\n" + output)
    seconds = float(match.group(3))
    rays = float(match.group(4)) * (1e6 if match.group(5) else 1.0)
    return rays, seconds


# The scenes in the order of the table; the generator writes them all.
ORDER = ["showcase", "hall_of_mirrors", "forest", "lights16", "spheres_1k", "spheres_10k",
         "spheres_100k", "spheres_1m_320", "spheres_1m", "mesh_100k", "mesh_1m"]
ORDER += list(TACHYON_SCENES) + [n + "_1024" for n in TACHYON_SCENES]


def scene_names(scenes_dir, only):
    """The generated scenes in table order, those in `only` if given; exits when none."""
    names = [n for n in ORDER if os.path.exists(os.path.join(scenes_dir, n + ".jts"))]
    if only:
        names = [n for n in names if n in only]
    if not names:
        sys.exit("no scenes to run")
    return names


def median_or_nan(values):
    return statistics.median(values) if values else float("nan")


def ratio(a, b):
    return a / b if b == b and b > 0 else float("nan")


def figure(value, digits=3):
    return "n/a" if value != value else f"{value:.{digits}f}"


def tachyon_ready(args, scene, dat, name):
    """The reason Tachyon is left out of this scene, or None when it is raced."""
    converted = subprocess.run([args.tachyon_converter, scene, dat], capture_output=True, text=True)
    if converted.returncode == 1:
        print(f"  {name}: no Tachyon: {converted.stderr.splitlines()[0]}", file=sys.stderr)
        return "no such shape"
    if converted.returncode != 0:
        sys.exit(f"jts-to-tachyon failed on {scene}:\n{converted.stderr}")
    check = subprocess.run([sys.executable, os.path.join(os.path.dirname(__file__), "check_silhouettes.py"),
                            "--cli", args.cli, "--converter", args.tachyon_converter, "--tachyon",
                            args.tachyon, "--threads", str(args.threads), scene,
                            os.path.join(args.out, "silhouettes")], capture_output=True, text=True)
    print("  " + check.stdout.strip().replace("\n", "\n  "), file=sys.stderr)
    if check.returncode != 0:
        return "silhouettes differ"
    return None


def main():
    global _log_path
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cli", required=True)
    parser.add_argument("--converter", required=True, help="jts-to-pov")
    parser.add_argument("--tachyon-converter", help="jts-to-tachyon")
    parser.add_argument("--tachyon", default="tachyon-nox")
    parser.add_argument("--scenes", required=True, help="directory of the generated .jts scenes")
    parser.add_argument("--out", required=True, help="where the converted scenes and images go")
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--only", nargs="*")
    parser.add_argument("--no-povray", action="store_true")
    parser.add_argument("--no-tachyon", action="store_true")
    parser.add_argument("--json", help="also write the medians to this file")
    args = parser.parse_args()
    if not args.no_tachyon and not args.tachyon_converter:
        parser.error("--tachyon-converter is needed unless --no-tachyon")
    os.makedirs(args.out, exist_ok=True)
    _log_path = os.path.join(args.out, "last_run.log")

    names = scene_names(args.scenes, args.only)
    load_before = os.getloadavg()
    rows = []
    for name in names:
        scene = os.path.join(args.scenes, name + ".jts")
        pov, dat = os.path.join(args.out, name + ".pov"), os.path.join(args.out, name + ".dat")
        jt_image = os.path.join(args.out, name + ".jtracer.bmp")
        pov_image = os.path.join(args.out, name + ".povray.bmp")
        tachyon_image = os.path.join(args.out, name + ".tachyon.bmp")
        with open(scene, encoding="ascii") as f:
            head = f.read(4096)
        width = int(re.search(r"width:\s*(\d+)", head).group(1))
        height = int(re.search(r"height:\s*(\d+)", head).group(1))
        commands = {"jtracer": [args.cli, scene, "-o", jt_image, "--threads", str(args.threads)]}
        if not args.no_tachyon and tachyon_ready(args, scene, dat, name) is None:
            commands["tachyon"] = [args.tachyon, dat, "-numthreads", str(args.threads), "-aasamples", "0",
                                   "-shade_phong", "-format", "BMP", "-o", tachyon_image]
        if not args.no_povray:
            subprocess.run([args.converter, scene, pov], check=True)
            commands["povray"] = ["povray", "+I" + pov, "+O" + pov_image, f"+W{width}", f"+H{height}",
                                  f"+WT{args.threads}", "-A", "-D", "+FB", "File_Gamma=1.0", "-V", "-GA"]
        walls = {k: [] for k in commands}
        cpus = {k: [] for k in commands}
        peaks = {k: [] for k in commands}
        rates = []
        for run in range(args.runs):
            for renderer, command in commands.items():
                # POV-Ray 3.7 sometimes dies at start-up on a busy machine.
                wall, cpu, rss, output = run_timed(command, attempts=3 if renderer == "povray" else 1)
                walls[renderer].append(wall)
                cpus[renderer].append(cpu)
                peaks[renderer].append(rss)
                if renderer == "jtracer":
                    rays, seconds = jtracer_rays(output)
                    rates.append(rays / seconds / 1e6)  # while rendering, as the CLI reports
            print(f"  {name} run {run + 1}/{args.runs}: "
                  + ", ".join(f"{k} {v[-1]:.3f} s" for k, v in walls.items()), file=sys.stderr)
        wall = {k: median_or_nan(walls.get(k, [])) for k in ("jtracer", "tachyon", "povray")}
        cpu = {k: median_or_nan(cpus.get(k, [])) for k in ("jtracer", "tachyon", "povray")}
        peak = {k: max(peaks[k]) if peaks.get(k) else float("nan") for k in ("jtracer", "tachyon", "povray")}
        rows.append((name, f"{width}x{height}", wall, cpu, peak, statistics.median(rates)))

    load_after = os.getloadavg()
    print()
    print(f"median of {args.runs} runs each, alternated; {args.threads} threads; "
          "wall = whole process (read, parse, build, render, write)")
    print("(CPU s = user + system time of the process: the figure to trust when the machine is busy)")
    print(f"load average (1, 5, 15 min) before: {' '.join(f'{x:.2f}' for x in load_before)}, "
          f"after: {' '.join(f'{x:.2f}' for x in load_after)}")
    print("| scene | size | JTracer s | Tachyon s | POV-Ray s | JT/Tachyon | JT/POV-Ray "
          "| JTracer CPU s | Tachyon CPU s | POV-Ray CPU s | CPU JT/Tachyon | CPU JT/POV-Ray "
          "| JTracer Mrays/s | peak MiB JT / Tachyon / POV-Ray |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for name, size, wall, cpu, peak, rate in rows:
        print(f"| {name} | {size} | {figure(wall['jtracer'])} | {figure(wall['tachyon'])} "
              f"| {figure(wall['povray'])} | {figure(ratio(wall['jtracer'], wall['tachyon']))} "
              f"| {figure(ratio(wall['jtracer'], wall['povray']))} | {figure(cpu['jtracer'])} "
              f"| {figure(cpu['tachyon'])} | {figure(cpu['povray'])} "
              f"| {figure(ratio(cpu['jtracer'], cpu['tachyon']))} "
              f"| {figure(ratio(cpu['jtracer'], cpu['povray']))} | {rate:.1f} "
              f"| {figure(peak['jtracer'], 0)} / {figure(peak['tachyon'], 0)} / {figure(peak['povray'], 0)} |")
    if args.json:
        write_json(args.json, {
            "runs": args.runs, "threads": args.threads, "load_before": load_before, "load_after": load_after,
            "scenes": [{"name": name, "size": size, "wall": wall, "cpu": cpu, "peak_mib": peak, "mrays_per_s": rate}
                       for name, size, wall, cpu, peak, rate in rows]})
    return 0


def write_json(path, data):
    """`data` as JSON; NaN (a renderer not raced) becomes null."""
    def clean(value):
        if isinstance(value, float) and value != value:
            return None
        if isinstance(value, dict):
            return {k: clean(v) for k, v in value.items()}
        if isinstance(value, (list, tuple)):
            return [clean(v) for v in value]
        return value
    with open(path, "w", encoding="utf-8") as f:
        json.dump(clean(data), f, indent=1)


if __name__ == "__main__":
    sys.exit(main())
