#!/usr/bin/env python3
"""The fixed cost of a jtracer-cli run: everything but tracing the pixels.

Two figures per binary, medians of alternated runs:
  whole run minus render: the wall time of `jtracer-cli SCENE` less the render
      seconds of its summary line (start, read, parse, validate, prepare, write;
      the summary rounds to 10 ms, which the median evens out only roughly);
  1x1 run: the wall time of the same scene rendered at 1x1 pixel.
With several binaries (--cli A --cli B), their runs alternate, so that a change
can be measured before and after on a busy machine.

usage: startup_cost.py --cli PATH [--cli PATH ...] SCENE.jts [--runs N] [--threads N] [--json FILE]
(FILE: the medians of the first --cli, for bench/targets.py)
"""

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from race import jtracer_rays, write_json  # noqa: E402


def timed(command):
    start = time.perf_counter()
    out = subprocess.run(command, capture_output=True, text=True, check=True)
    return time.perf_counter() - start, out.stdout + out.stderr


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cli", action="append", required=True)
    parser.add_argument("--runs", type=int, default=21)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--json", help="also write the first binary's medians to this file")
    parser.add_argument("scene")
    args = parser.parse_args()
    fixed = {cli: [] for cli in args.cli}
    tiny = {cli: [] for cli in args.cli}
    load_before = os.getloadavg()
    with tempfile.TemporaryDirectory() as work:
        image = os.path.join(work, "out.bmp")
        for _ in range(args.runs):
            for cli in args.cli:
                base = [cli, args.scene, "-o", image, "--threads", str(args.threads)]
                wall, output = timed(base)
                fixed[cli].append(wall - jtracer_rays(output)[1])
                wall, _ = timed(base + ["-q", "--width", "1", "--height", "1"])
                tiny[cli].append(wall)
    load_after = os.getloadavg()
    print(f"{args.scene}: medians of {args.runs} alternated runs, {args.threads} threads; load "
          f"average {load_before[0]:.2f} before, {load_after[0]:.2f} after")
    for cli in args.cli:
        print(f"  {cli}: whole run minus render {1000 * statistics.median(fixed[cli]):.1f} ms, "
              f"1x1 run {1000 * statistics.median(tiny[cli]):.1f} ms")
    if args.json:
        cli = args.cli[0]
        write_json(args.json, {"scene": os.path.basename(args.scene), "runs": args.runs,
                               "threads": args.threads, "load_before": load_before, "load_after": load_after,
                               "fixed_ms": 1000 * statistics.median(fixed[cli]),
                               "one_pixel_ms": 1000 * statistics.median(tiny[cli])})
    return 0


if __name__ == "__main__":
    sys.exit(main())
