#!/usr/bin/env python3
"""JTracer's rays per second as a share of the ray kernel's limit, per scene.

Runs jtracer-cli (rays and render seconds from its summary line) and
kernel-limit (the same rays through Embree's native geometry, unshaded: one ray
at a time and packets of 8 and 16) alternately, on the same number of threads,
and prints the medians. The share is JTracer's rate over the best of
kernel-limit's three.

usage: kernel_limit.py --cli PATH --kernel-limit PATH --scenes DIR [--runs N] [--threads N]
                       [--only NAME ...] [--json FILE]  (FILE: the medians, for bench/targets.py)
"""

import argparse
import os
import re
import statistics
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from race import jtracer_rays, scene_names, write_json  # noqa: E402

MODE = re.compile(r"mode (ray\d+): (\d+) rays, ([\d.]+) s")
MODES = ("ray1", "ray8", "ray16")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cli", required=True)
    parser.add_argument("--kernel-limit", required=True)
    parser.add_argument("--scenes", required=True, help="directory of the generated .jts scenes")
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--only", nargs="*")
    parser.add_argument("--json", help="also write the medians to this file")
    args = parser.parse_args()

    names = scene_names(args.scenes, args.only)
    load_before = os.getloadavg()
    rows = []
    for name in names:
        scene = os.path.join(args.scenes, name + ".jts")
        jt_rates, jt_rays = [], 0
        limit = {mode: [] for mode in MODES}
        limit_rays = 0
        for run in range(args.runs):
            image = os.path.join(args.scenes, name + ".kernel_limit.bmp")
            out = subprocess.run([args.cli, scene, "-o", image, "--threads", str(args.threads)],
                                 capture_output=True, text=True, check=True)
            rays, seconds = jtracer_rays(out.stdout + out.stderr)
            jt_rates.append(rays / seconds / 1e6)
            jt_rays = rays
            out = subprocess.run([args.kernel_limit, scene, "--threads", str(args.threads),
                                  "--runs", "1"], capture_output=True, text=True)
            if out.returncode != 0:
                print(f"  {name}: kernel-limit failed: {out.stderr.strip()}", file=sys.stderr)
                break
            for mode, count, seconds in MODE.findall(out.stdout):
                limit[mode].append(int(count) / float(seconds) / 1e6)
                limit_rays = int(count)
            print(f"  {name} run {run + 1}/{args.runs}: jtracer {jt_rates[-1]:.2f} Mrays/s, "
                  + ", ".join(f"{m} {limit[m][-1]:.2f}" for m in MODES if limit[m]), file=sys.stderr)
        if not all(limit[m] for m in MODES):
            continue
        rate = statistics.median(jt_rates)
        best = {m: statistics.median(limit[m]) for m in MODES}
        rows.append((name, jt_rays, limit_rays, rate, best, rate / max(best.values())))

    load_after = os.getloadavg()
    print()
    print(f"median of {args.runs} alternated runs; {args.threads} threads; Mrays/s while rendering "
          "(JTracer: the CLI's summary; Embree: kernel-limit's render loop, no shading)")
    print(f"load average (1, 5, 15 min) before: {' '.join(f'{x:.2f}' for x in load_before)}, "
          f"after: {' '.join(f'{x:.2f}' for x in load_after)}")
    print("| scene | JTracer rays | Embree rays | JTracer Mrays/s | Embree ray1 | Embree ray8 "
          "| Embree ray16 | JTracer's share of the best |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    for name, jt_rays, limit_rays, rate, best, share in rows:
        print(f"| {name} | {jt_rays / 1e6:.2f} M | {limit_rays / 1e6:.2f} M | {rate:.2f} "
              f"| {best['ray1']:.2f} | {best['ray8']:.2f} | {best['ray16']:.2f} | {100 * share:.0f}% |")
    if args.json:
        write_json(args.json, {
            "runs": args.runs, "threads": args.threads, "load_before": load_before, "load_after": load_after,
            "scenes": [{"name": name, "jtracer_mrays_per_s": rate, "embree_mrays_per_s": best, "share": share}
                       for name, jt_rays, limit_rays, rate, best, share in rows]})
    return 0


if __name__ == "__main__":
    sys.exit(main())
