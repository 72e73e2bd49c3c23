#!/usr/bin/env python3
"""Races jtracer-cli against POV-Ray 3.7 on the benchmark scenes and prints a table.

For each scene the two renderers run alternately (JTracer, POV-Ray, JTracer, ...)
so that a busy spell of the machine hurts both alike; the table shows medians.
Wall time is the whole process: reading and parsing the file, building the
acceleration structure, rendering and writing the image. Peak memory is the
child's maximum resident set size (getrusage). Images are kept in the work
directory as SCENE.jtracer.bmp and SCENE.povray.bmp.

usage: race.py --cli PATH --converter PATH --scenes DIR --out DIR [--runs N] [--threads N]
               [--only NAME ...] [--no-povray]
"""

import argparse
import os
import re
import resource
import statistics
import subprocess
import sys
import time

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


def main():
    global _log_path
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cli", required=True)
    parser.add_argument("--converter", required=True)
    parser.add_argument("--scenes", required=True, help="directory of the generated .jts scenes")
    parser.add_argument("--out", required=True, help="where the .pov files and images go")
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--only", nargs="*")
    parser.add_argument("--no-povray", action="store_true")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    _log_path = os.path.join(args.out, "last_run.log")

    order = ["showcase", "hall_of_mirrors", "forest", "lights16",
             "spheres_1k", "spheres_10k", "spheres_100k", "spheres_1m"]
    names = [n for n in order if os.path.exists(os.path.join(args.scenes, n + ".jts"))]
    if args.only:
        names = [n for n in names if n in args.only]
    if not names:
        sys.exit("no scenes to run")

    rows = []
    for name in names:
        scene = os.path.join(args.scenes, name + ".jts")
        pov = os.path.join(args.out, name + ".pov")
        jt_image = os.path.join(args.out, name + ".jtracer.bmp")
        pov_image = os.path.join(args.out, name + ".povray.bmp")
        subprocess.run([args.converter, scene, pov], check=True)
        with open(scene, encoding="ascii") as f:
            head = f.read(4096)
        width = int(re.search(r"width:\s*(\d+)", head).group(1))
        height = int(re.search(r"height:\s*(\d+)", head).group(1))
        jt_command = [args.cli, scene, "-o", jt_image, "--threads", str(args.threads)]
        pov_command = ["povray", "+I" + pov, "+O" + pov_image, f"+W{width}", f"+H{height}",
                       f"+WT{args.threads}", "-A", "-D", "+FB", "File_Gamma=1.0", "-V", "-GA"]
        jt_walls, jt_cpus, jt_rss, pov_walls, pov_cpus, rates = [], [], [], [], [], []
        for run in range(args.runs):
            wall, cpu, rss, output = run_timed(jt_command)
            rays, seconds = jtracer_rays(output)
            jt_walls.append(wall)
            jt_cpus.append(cpu)
            jt_rss.append(rss)
            rates.append(rays / seconds / 1e6)  # while rendering, as the CLI reports
            if not args.no_povray:
                wall, cpu, _, _ = run_timed(pov_command, attempts=3)
                pov_walls.append(wall)
                pov_cpus.append(cpu)
            print(f"  {name} run {run + 1}/{args.runs}: jtracer {jt_walls[-1]:.3f} s"
                  + (f", povray {pov_walls[-1]:.3f} s" if pov_walls else ""), file=sys.stderr)
        jt = statistics.median(jt_walls)
        pv = statistics.median(pov_walls) if pov_walls else float("nan")
        jt_cpu = statistics.median(jt_cpus)
        pv_cpu = statistics.median(pov_cpus) if pov_cpus else float("nan")
        rows.append((name, f"{width}x{height}", jt, pv, jt / pv if pov_walls else float("nan"),
                     jt_cpu, pv_cpu, jt_cpu / pv_cpu if pov_cpus else float("nan"),
                     statistics.median(rates), max(jt_rss)))

    print()
    print(f"median of {args.runs} runs each, alternated; {args.threads} threads; "
          "wall = whole process (read, parse, build, render, write)")
    print("(CPU s = user + system time of the process: the figure to trust when the machine is busy)")
    print("| scene | size | JTracer s | POV-Ray s | ratio | JTracer CPU s | POV-Ray CPU s | CPU ratio "
          "| JTracer Mrays/s | JTracer peak MiB |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    for name, size, jt, pv, ratio, jt_cpu, pv_cpu, cpu_ratio, rate, rss in rows:
        print(f"| {name} | {size} | {jt:.3f} | {pv:.3f} | {ratio:.3f} | {jt_cpu:.3f} | {pv_cpu:.3f} "
              f"| {cpu_ratio:.3f} | {rate:.1f} | {rss:.0f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
