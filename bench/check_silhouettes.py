#!/usr/bin/env python3
"""Checks that JTracer and Tachyon see the same geometry in a scene.

Converts SCENE.jts with `jts-to-tachyon --silhouette`, which writes both
renderers' scenes with every primitive flat in one of seven colours chosen by its
index (black = nothing), renders both, and compares which colour every pixel
shows. The race times only scenes that pass, so that neither renderer is timed
on a picture with less in it.

usage: check_silhouettes.py --cli PATH --converter PATH [--tachyon PATH] SCENE.jts WORK_DIR
                            [--size WxH] [--threads N] [--min-agreement F]
Exit status 0 when the masks agree on at least --min-agreement of the pixels
(default 0.995; a pixel agrees when the other image shows its colour within one pixel)
and every colour covers about as many pixels in both, 1 otherwise.

Tachyon aims its rays at pixel corners and JTracer at pixel centres, so Tachyon's mask
is rendered at twice the size and every other pixel of every other row kept: those are
the rays through JTracer's pixel centres. Without it, scenes whose primitives are a
pixel or less across (a million spheres at 320x240) agree on only 92% of the pixels.
"""

import argparse
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from compare_bmp import read_bmp  # noqa: E402

# A colour covering this share of either image must cover a share within this
# factor in the other; pixels on silhouette edges may land either way.
MIN_SHARE, MAX_SHARE_RATIO = 0.001, 1.1


def classes(path):
    """Per pixel, the 3-bit colour code (bit 0 red, 1 green, 2 blue), row by row."""
    width, height, rows = read_bmp(path)
    codes = bytearray()
    for row in rows:  # BMP rows hold B, G, R
        for x in range(0, width * 3, 3):
            codes.append((row[x + 2] > 127) | (row[x + 1] > 127) << 1 | (row[x] > 127) << 2)
    return width, height, codes


def every_other_pixel(mask):
    """The pixels of a mask rendered at twice the size whose rays pass through the
    centres of the pixels at the size asked for."""
    width, height, codes = mask
    half_width, half_height = width // 2, height // 2
    kept = bytearray()
    for y in range(0, 2 * half_height, 2):
        kept += codes[y * width: y * width + 2 * half_width: 2]
    return half_width, half_height, kept


def compare(a, b):
    """(share of pixels that agree, list of complaints about colour coverage).

    A pixel agrees when the other image shows its colour there or at one of the
    eight pixels around it: Tachyon aims its rays at pixel corners, JTracer at
    pixel centres, so edges move by half a pixel.
    """
    (wa, ha, ca), (wb, hb, cb) = a, b
    if (wa, ha) != (wb, hb):
        return 0.0, [f"sizes differ: {wa}x{ha} and {wb}x{hb}"]
    pixels = wa * ha

    def near(codes, i, code):
        y, x = divmod(i, wa)
        for v in range(max(y - 1, 0), min(y + 2, ha)):
            row = v * wa
            if code in codes[row + max(x - 1, 0): row + min(x + 2, wa)]:
                return True
        return False

    agree = sum(1 for i, (x, y) in enumerate(zip(ca, cb))
                if x == y or (near(cb, i, x) and near(ca, i, y)))
    problems = []
    for code in range(8):
        share_a, share_b = ca.count(code) / pixels, cb.count(code) / pixels
        big, small = max(share_a, share_b), min(share_a, share_b)
        if big >= MIN_SHARE and (small == 0 or big / small > MAX_SHARE_RATIO):
            problems.append(f"colour {code} covers {100 * share_a:.2f}% of JTracer's image "
                            f"and {100 * share_b:.2f}% of Tachyon's")
    return agree / pixels, problems


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cli", required=True)
    parser.add_argument("--converter", required=True)
    parser.add_argument("--tachyon", default="tachyon-nox")
    parser.add_argument("--size", help="render at WxH instead of the scene's size")
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--min-agreement", type=float, default=0.995)
    parser.add_argument("scene")
    parser.add_argument("work_dir")
    args = parser.parse_args()

    os.makedirs(args.work_dir, exist_ok=True)
    name = os.path.splitext(os.path.basename(args.scene))[0]
    stem = os.path.join(args.work_dir, name + ".silhouette")
    mask_jts, mask_dat = stem + ".jts", stem + ".dat"
    jt_image, tachyon_image = stem + ".jtracer.bmp", stem + ".tachyon.bmp"
    subprocess.run([args.converter, args.scene, mask_dat, "--silhouette", mask_jts], check=True)
    jt_command = [args.cli, mask_jts, "-o", jt_image, "--threads", str(args.threads), "-q"]
    if args.size:
        width, height = args.size.lower().split("x")
        jt_command += ["--width", width, "--height", height]
    subprocess.run(jt_command, check=True)
    jt_mask = classes(jt_image)
    width, height = jt_mask[0], jt_mask[1]
    tachyon_command = [args.tachyon, mask_dat, "-numthreads", str(args.threads), "-aasamples", "0",
                       "-format", "BMP", "-o", tachyon_image, "-res", str(2 * width), str(2 * height)]
    subprocess.run(tachyon_command, check=True, stdout=subprocess.DEVNULL)

    agreement, problems = compare(jt_mask, every_other_pixel(classes(tachyon_image)))
    verdict = "agree" if agreement >= args.min_agreement and not problems else "DISAGREE"
    print(f"{name}: silhouettes {verdict}: {100 * agreement:.2f}% of pixels show the same primitive "
          f"colour within a pixel ({jt_image}, {tachyon_image})")
    for problem in problems:
        print(f"  {problem}")
    return 0 if verdict == "agree" else 1


if __name__ == "__main__":
    sys.exit(main())
