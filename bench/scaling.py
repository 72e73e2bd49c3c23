#!/usr/bin/env python3
"""What a render costs against resolution, scene size and threads, as a table and a plot.

Three series, each a median of alternated runs of jtracer-cli (wall time of the
whole process, and the render seconds of its summary line):
  resolution: one scene (default sphereflake) at 320x180 ... 2560x1440;
  scene size: spheres_1k ... spheres_1m at one size (default 1920x1080);
  threads:    one scene on 1 and 2 threads, alternated.
From the 1-thread run, the share of the whole process that renders (tiles run in
parallel) gives the parallel fraction p; Amdahl's law with the 1-thread time and
the per-thread ray rate then gives the time on N threads, T(1) * ((1 - p) + p / N),
on paper for 64. The measured 2-thread time checks the model.

Writes FIGURES.json and the plot (PNG, matplotlib; Debian's python3-matplotlib is
installed when missing, as bench/run.sh installs POV-Ray). With --replot, only
redraws the PNG from the JSON.

usage: scaling.py --cli PATH --scenes DIR --out PNG [--json FILE] [--runs N]
                  [--scene NAME] [--size WxH] [--replot]
"""

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from race import jtracer_rays  # noqa: E402

RESOLUTIONS = [(320, 180), (640, 360), (1280, 720), (1920, 1080), (2560, 1440)]
SIZES = ["spheres_1k", "spheres_10k", "spheres_100k", "spheres_1m"]
COUNTS = {"spheres_1k": 1e3, "spheres_10k": 1e4, "spheres_100k": 1e5, "spheres_1m": 1e6}
PAPER_THREADS = [1, 2, 4, 8, 16, 32, 64]


def run(cli, scene, image, threads, size=None):
    """(wall s, render s, rays) of one jtracer-cli run."""
    command = [cli, scene, "-o", image, "--threads", str(threads)]
    if size:
        command += ["--width", str(size[0]), "--height", str(size[1])]
    start = time.perf_counter()
    out = subprocess.run(command, capture_output=True, text=True, check=True)
    wall = time.perf_counter() - start
    rays, seconds = jtracer_rays(out.stdout + out.stderr)
    return wall, seconds, rays


def medians(samples):
    return {k: statistics.median(v) for k, v in samples.items()}


def measure(args):
    scene = os.path.join(args.scenes, args.scene + ".jts")
    size = tuple(int(v) for v in args.size.split("x"))
    load_before = os.getloadavg()
    figures = {"runs": args.runs, "scene": args.scene, "size": list(size)}
    with tempfile.TemporaryDirectory() as work:
        image = os.path.join(work, "out.bmp")
        walls = {r: [] for r in RESOLUTIONS}
        renders = {r: [] for r in RESOLUTIONS}
        for _ in range(args.runs):
            for r in RESOLUTIONS:
                wall, seconds, _ = run(args.cli, scene, image, 2, r)
                walls[r].append(wall)
                renders[r].append(seconds)
        figures["resolution"] = [{"width": r[0], "height": r[1], "wall": statistics.median(walls[r]),
                                  "render": statistics.median(renders[r])} for r in RESOLUTIONS]
        print("resolution done", file=sys.stderr)

        names = [n for n in SIZES if os.path.exists(os.path.join(args.scenes, n + ".jts"))]
        walls = {n: [] for n in names}
        renders = {n: [] for n in names}
        for _ in range(args.runs):
            for n in names:
                wall, seconds, _ = run(args.cli, os.path.join(args.scenes, n + ".jts"), image, 2, size)
                walls[n].append(wall)
                renders[n].append(seconds)
        figures["scene_size"] = [{"scene": n, "primitives": COUNTS[n], "wall": statistics.median(walls[n]),
                                  "render": statistics.median(renders[n])} for n in names]
        print("scene size done", file=sys.stderr)

        samples = {t: {"wall": [], "render": [], "rays": []} for t in (1, 2)}
        for _ in range(args.runs):
            for t in (1, 2):
                wall, seconds, rays = run(args.cli, scene, image, t, size)
                samples[t]["wall"].append(wall)
                samples[t]["render"].append(seconds)
                samples[t]["rays"].append(rays)
        figures["threads"] = {str(t): medians(samples[t]) for t in (1, 2)}
    figures["load_before"] = load_before
    figures["load_after"] = os.getloadavg()
    return figures


def model(figures):
    """Amdahl's law from the 1-thread run: p = render share of the whole process."""
    one, two = figures["threads"]["1"], figures["threads"]["2"]
    p = one["render"] / one["wall"]
    per_thread = one["rays"] / one["render"] / 1e6
    predicted = {n: one["wall"] * ((1 - p) + p / n) for n in PAPER_THREADS}
    # p from the measured pair instead: T2 = T1 (1 - p/2).
    p_measured = 2 * (1 - two["wall"] / one["wall"])
    return p, per_thread, predicted, p_measured


def report(figures):
    print(f"medians of {figures['runs']} alternated runs of jtracer-cli; load average "
          f"{figures['load_before'][0]:.2f} before, {figures['load_after'][0]:.2f} after")
    print()
    print(f"| {figures['scene']} at | megapixels | wall s | render s |")
    print("|---|---:|---:|---:|")
    for r in figures["resolution"]:
        print(f"| {r['width']}x{r['height']} | {r['width'] * r['height'] / 1e6:.2f} | {r['wall']:.3f} "
              f"| {r['render']:.3f} |")
    print()
    w, h = figures["size"]
    print(f"| scene at {w}x{h} | primitives | wall s | render s |")
    print("|---|---:|---:|---:|")
    for s in figures["scene_size"]:
        print(f"| {s['scene']} | {s['primitives']:,.0f} | {s['wall']:.3f} | {s['render']:.3f} |")
    print()
    p, per_thread, predicted, p_measured = model(figures)
    one, two = figures["threads"]["1"], figures["threads"]["2"]
    print(f"{figures['scene']} at {w}x{h}: 1 thread {one['wall']:.3f} s wall ({one['render']:.3f} s render, "
          f"{per_thread:.2f} Mrays/s a thread); 2 threads {two['wall']:.3f} s wall ({two['render']:.3f} s render)")
    print(f"parallel fraction p = render / whole run on 1 thread = {p:.3f}; from the measured 1 and 2 "
          f"thread walls, {p_measured:.3f}")
    print("| threads | wall s (1, 2 measured; the rest Amdahl from p) | speed-up |")
    print("|---:|---:|---:|")
    for n in PAPER_THREADS:
        measured = {1: one["wall"], 2: two["wall"]}.get(n)
        shown = f"{measured:.3f} (model {predicted[n]:.3f})" if measured else f"{predicted[n]:.3f}"
        print(f"| {n} | {shown} | {one['wall'] / predicted[n]:.1f}x |")


def plot(figures, out):
    try:
        import matplotlib
    except ImportError:
        print("== installing python3-matplotlib (Debian package)", file=sys.stderr)
        root = [] if os.geteuid() == 0 else ["sudo"]
        subprocess.run(root + ["apt-get", "install", "-y", "-q", "python3-matplotlib"], check=True,
                       env=dict(os.environ, DEBIAN_FRONTEND="noninteractive"))
        try:
            import matplotlib
        except ImportError:
            sys.exit("scaling.py: matplotlib is installed for Debian's python3: run it with /usr/bin/python3")
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 3, figsize=(15, 4.6))
    res = figures["resolution"]
    mp = [r["width"] * r["height"] / 1e6 for r in res]
    ax = axes[0]
    ax.plot(mp, [r["wall"] for r in res], "o-", label="whole run (wall)")
    ax.plot(mp, [r["render"] for r in res], "s--", label="render only")
    for x, r in zip(mp, res):
        ax.annotate(f"{r['width']}x{r['height']}", (x, r["wall"]), textcoords="offset points",
                    xytext=(0, 6), ha="center", fontsize=7)
    ax.set_xlabel("megapixels")
    ax.set_ylabel("seconds")
    ax.set_title(f"{figures['scene']}: cost against resolution (2 threads)")
    ax.set_ylim(bottom=0)
    ax.grid(alpha=0.3)
    ax.legend()

    sizes = figures["scene_size"]
    ax = axes[1]
    ax.plot([s["primitives"] for s in sizes], [s["wall"] for s in sizes], "o-", label="whole run (wall)")
    ax.plot([s["primitives"] for s in sizes], [s["render"] for s in sizes], "s--", label="render only")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("spheres")
    ax.set_ylabel("seconds")
    w, h = figures["size"]
    ax.set_title(f"random spheres at {w}x{h}: cost against scene size")
    ax.grid(alpha=0.3, which="both")
    ax.legend()

    p, _, predicted, _ = model(figures)
    one, two = figures["threads"]["1"], figures["threads"]["2"]
    ax = axes[2]
    ax.plot(PAPER_THREADS, [one["wall"] / predicted[n] for n in PAPER_THREADS], "o--",
            label=f"Amdahl, p = {p:.3f} (on paper)")
    ax.plot([1, 2], [1.0, one["wall"] / two["wall"]], "s", markersize=9, label="measured")
    ax.plot(PAPER_THREADS, PAPER_THREADS, ":", color="grey", label="ideal")
    ax.set_xscale("log", base=2)
    ax.set_yscale("log", base=2)
    ax.set_xticks(PAPER_THREADS)
    ax.set_xticklabels([str(n) for n in PAPER_THREADS])
    ax.set_xlabel("threads")
    ax.set_ylabel("speed-up of the whole run")
    ax.set_title(f"{figures['scene']} at {w}x{h}: threads")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8)
    fig.suptitle(f"jtracer-cli, medians of {figures['runs']} alternated runs; load average "
                 f"{figures['load_before'][0]:.1f} before, {figures['load_after'][0]:.1f} after", fontsize=10)
    fig.tight_layout()
    fig.savefig(out, dpi=90)
    print(f"wrote {out}", file=sys.stderr)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cli")
    parser.add_argument("--scenes")
    parser.add_argument("--out", required=True, help="the PNG")
    parser.add_argument("--json", help="the figures (default: beside the PNG)")
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--scene", default="sphereflake")
    parser.add_argument("--size", default="1920x1080")
    parser.add_argument("--replot", action="store_true")
    args = parser.parse_args()
    path = args.json or os.path.splitext(args.out)[0] + ".json"
    if args.replot:
        with open(path, encoding="utf-8") as f:
            figures = json.load(f)
    else:
        if not args.cli or not args.scenes:
            parser.error("--cli and --scenes are needed unless --replot")
        figures = measure(args)
        with open(path, "w", encoding="utf-8") as f:
            json.dump(figures, f, indent=1)
    report(figures)
    plot(figures, args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
