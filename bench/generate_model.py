#!/usr/bin/env python3
"""Writes a (p, q) torus knot tube as a binary little-endian PLY with exact
vertex normals (the tube's normal is the direction from the knot's curve) and
texture coordinates: scenes/models/knot.ply, and the benchmark's million-
triangle model, which is generated at bench time and never committed.

  bench/generate_model.py --triangles 20000 scenes/models/knot.ply

The grid is around x around, y along the knot; each cell is two triangles,
so the model has 2 * around * along triangles; the seam vertices are doubled
(same position, u = 1 instead of 0) so that the texture does not jump.
"""

import argparse
import math
import struct
import sys


def knot_point(t, p, q):
    r = 2.0 + math.cos(q * t)
    return (r * math.cos(p * t), -math.sin(q * t), r * math.sin(p * t))


def normalize(v):
    n = math.sqrt(sum(c * c for c in v))
    return tuple(c / n for c in v)


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def frame(t, p, q):
    """The knot's point, and two unit vectors across the curve there."""
    h = 1e-4
    c = knot_point(t, p, q)
    ahead = knot_point(t + h, p, q)
    behind = knot_point(t - h, p, q)
    tangent = normalize(tuple(a - b for a, b in zip(ahead, behind)))
    curvature = tuple(a + b - 2 * m for a, b, m in zip(ahead, behind, c))
    n = normalize(cross(cross(tangent, curvature), tangent))
    b = cross(tangent, n)
    return c, n, b


def write(path, along, around, p, q, tube, normals=True):
    rows = []  # (position, normal) per grid point, the seams doubled
    for i in range(along + 1):
        t = 2.0 * math.pi * (i % along) / along
        c, n, b = frame(t, p, q)
        for j in range(around + 1):
            a = 2.0 * math.pi * (j % around) / around
            d = tuple(math.cos(a) * nc + math.sin(a) * bc for nc, bc in zip(n, b))
            pos = tuple(cc + tube * dc for cc, dc in zip(c, d))
            rows.append((pos, d, i / along * 8.0, j / around))
    with open(path, "wb") as out:
        vertices = len(rows)
        faces = 2 * along * around
        out.write(
            (
                "ply\nformat binary_little_endian 1.0\n"
                "comment a (%d, %d) torus knot written by bench/generate_model.py\n"
                "element vertex %d\n"
                "property float x\nproperty float y\nproperty float z\n"
                "%s"
                "property float s\nproperty float t\n"
                "element face %d\nproperty list uchar uint vertex_indices\nend_header\n"
                % (
                    p,
                    q,
                    vertices,
                    "property float nx\nproperty float ny\nproperty float nz\n" if normals else "",
                    faces,
                )
            ).encode()
        )
        vertex = struct.Struct("<8f" if normals else "<5f")
        for pos, d, s, t in rows:
            out.write(vertex.pack(*pos, *d, s, t) if normals else vertex.pack(*pos, s, t))
        face = struct.Struct("<B3I")
        w = around + 1
        for i in range(along):
            for j in range(around):
                k = i * w + j
                # Counter-clockwise seen from outside the tube.
                out.write(face.pack(3, k, k + 1, k + w + 1))
                out.write(face.pack(3, k, k + w + 1, k + w))
    return faces


def write_knot(path, triangles, p=2, q=3, tube=0.45, normals=True):
    """A knot of about `triangles` triangles; returns how many it has."""
    # along = 8 * around keeps the cells about square.
    around = max(3, round(math.sqrt(triangles / 16.0)))
    along = max(3, round(triangles / (2.0 * around)))
    return write(path, along, around, p, q, tube, normals)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("output")
    parser.add_argument("--triangles", type=int, default=20000)
    parser.add_argument("--p", type=int, default=2)
    parser.add_argument("--q", type=int, default=3)
    parser.add_argument("--tube", type=float, default=0.45)
    parser.add_argument(
        "--no-normals",
        action="store_true",
        help="leave the vertex normals out (for smooth_angle, docs/language.md 14.4)",
    )
    args = parser.parse_args()
    faces = write_knot(
        args.output, args.triangles, args.p, args.q, args.tube, not args.no_normals
    )
    print("%s: %d triangles" % (args.output, faces), file=sys.stderr)


if __name__ == "__main__":
    main()
