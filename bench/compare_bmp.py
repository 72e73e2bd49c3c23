#!/usr/bin/env python3
"""Compares two 24-bit BMP files of the same size: how far apart their pixels are.

usage: compare_bmp.py A.bmp B.bmp
Prints the mean absolute channel difference, the share of pixels that differ
by more than 8 (of 255) in any channel, and the mean of each channel of both.
"""

import struct
import sys


def read_bmp(path):
    with open(path, "rb") as f:
        data = f.read()
    if data[:2] != b"BM":
        raise SystemExit(f"{path}: not a BMP file")
    offset = struct.unpack_from("<I", data, 10)[0]
    width, height = struct.unpack_from("<ii", data, 18)
    bits = struct.unpack_from("<H", data, 28)[0]
    if bits != 24:
        raise SystemExit(f"{path}: {bits} bits a pixel, expected 24")
    row = (width * 3 + 3) & ~3
    rows = [data[offset + y * row: offset + y * row + width * 3] for y in range(abs(height))]
    if height < 0:  # stored top-down
        rows.reverse()
    return width, abs(height), rows


def main():
    if len(sys.argv) != 3:
        raise SystemExit(__doc__)
    wa, ha, a = read_bmp(sys.argv[1])
    wb, hb, b = read_bmp(sys.argv[2])
    if (wa, ha) != (wb, hb):
        raise SystemExit(f"sizes differ: {wa}x{ha} and {wb}x{hb}")
    total = 0
    far = 0
    largest = 0
    differing = 0
    sums_a = [0, 0, 0]
    sums_b = [0, 0, 0]
    for ra, rb in zip(a, b):
        for x in range(0, wa * 3, 3):
            worst = 0
            for c in range(3):
                va, vb = ra[x + c], rb[x + c]
                sums_a[c] += va
                sums_b[c] += vb
                d = abs(va - vb)
                total += d
                differing += d > 0
                worst = max(worst, d)
            far += worst > 8
            largest = max(largest, worst)
    pixels = wa * ha
    print(f"{differing} of {3 * pixels} channel values differ, by at most {largest}; "
          f"mean |difference| {total / (3 * pixels):.4f} of 255; "
          f"{100.0 * far / pixels:.1f}% of pixels differ by more than 8")
    names = "BGR"
    print("mean channel (B, G, R):",
          " ".join(f"{names[c]} {sums_a[c] / pixels:.1f}/{sums_b[c] / pixels:.1f}" for c in range(3)))


if __name__ == "__main__":
    main()
