#!/usr/bin/env python3
"""Writes scenes/maps/sky.png, the sky map of scenes/sky.jts (docs/language.md 14.3).

An equirectangular picture of every direction, 1024 x 512: a blue sky paling to
the horizon, a sun with its glow, low hills all round and a dark ground below.
Column u = 0.5 is the direction -z; the top row is straight up. Everything is
periodic in u, so the seam at +z shows no step. Plain Python (zlib only), so the
file is the same on every machine: run it from the repository's root.
"""

import math
import struct
import zlib

WIDTH, HEIGHT = 1024, 512
SUN_U, SUN_ELEVATION = 0.56, math.radians(14.0)  # a little right of -z, low


def mix(a, b, t):
    return tuple(x + (y - x) * t for x, y in zip(a, b))


def direction(u, elevation):
    azimuth = (u - 0.5) * 2.0 * math.pi  # u = 0.5 + atan2(d.x, -d.z) / (2 pi)
    c = math.cos(elevation)
    return (c * math.sin(azimuth), math.sin(elevation), -c * math.cos(azimuth))


def hills(u):
    """The height of the skyline above the horizon, radians; periodic in u."""
    a = 2.0 * math.pi * u
    return math.radians(3.5 + 2.0 * math.sin(3 * a + 0.4) + 1.2 * math.sin(7 * a + 1.9)
                        + 0.5 * math.sin(17 * a + 0.3))


def clouds(u, elevation):
    """Cloud cover 0..1: soft bands of sines, periodic in u, between 8 and 50 degrees up."""
    if not math.radians(8.0) < elevation < math.radians(50.0):
        return 0.0
    a = 2.0 * math.pi * u
    e = elevation / math.radians(50.0)
    density = (math.sin(5 * a + 3.0 * e + 0.7) * math.sin(11 * e + 0.5)
               + 0.6 * math.sin(9 * a - 5.0 * e + 2.1) * math.sin(17 * e + 1.3)
               + 0.3 * math.sin(23 * a + 1.1) * math.sin(29 * e))
    fade = math.sin(math.pi * (elevation - math.radians(8.0)) / math.radians(42.0))
    return max(0.0, min(1.0, (density - 0.55) * 1.6)) * fade


def colour(u, v):
    elevation = (v - 0.5) * math.pi
    sun = direction(SUN_U, SUN_ELEVATION)
    d = direction(u, elevation)
    cos_sun = max(-1.0, min(1.0, sum(x * y for x, y in zip(d, sun))))
    angle = math.acos(cos_sun)
    skyline = hills(u)
    t = min(1.0, max(0.0, elevation) / math.radians(60.0)) ** 0.6
    sky = mix((0.86, 0.90, 0.95), (0.22, 0.42, 0.82), t)
    sky = mix(sky, (0.97, 0.97, 0.98), 0.85 * clouds(u, elevation))
    glow = math.exp(-angle / math.radians(12.0))
    sky = mix(sky, (1.0, 0.93, 0.75), 0.75 * glow)
    if angle < math.radians(2.2):  # the disc, its edge softened over a texel
        sky = mix(sky, (1.0, 0.98, 0.90), min(1.0, (math.radians(2.2) - angle) / 0.006))
    # The hills: bluish with distance, lit toward the sun.
    hill = mix((0.24, 0.32, 0.36), (0.36, 0.42, 0.38), 0.5 + 0.5 * cos_sun)
    # The ground, darkening toward the nadir.
    ground = mix((0.30, 0.36, 0.22), (0.10, 0.11, 0.08), min(1.0, -elevation / (0.5 * math.pi)))
    # Each edge blended over one texel's height, so that a magnified map shows
    # a slope, not steps.
    texel = math.pi / HEIGHT
    def cover(edge):
        return max(0.0, min(1.0, (elevation - edge) / texel + 0.5))
    c = mix(ground, hill, cover(0.0))
    c = mix(c, sky, cover(skyline))
    return tuple(max(0, min(255, int(x * 255.0 + 0.5))) for x in c)


def png(width, height, rows):
    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data
                + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF))

    raw = bytearray()
    previous = bytes(width * 3)
    for row in rows:
        raw.append(2)  # the "up" filter: rows of a smooth sky differ little
        raw.extend((row[i] - previous[i]) & 0xFF for i in range(len(row)))
        previous = row
    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header)
            + chunk(b"IDAT", zlib.compress(bytes(raw), 9)) + chunk(b"IEND", b""))


def main():
    rows = []
    for top in range(HEIGHT):  # PNG rows run from the top: v = 1 first
        v = (HEIGHT - 1 - top + 0.5) / HEIGHT
        row = bytearray()
        for i in range(WIDTH):
            row.extend(colour((i + 0.5) / WIDTH, v))
        rows.append(bytes(row))
    with open("scenes/maps/sky.png", "wb") as out:
        out.write(png(WIDTH, HEIGHT, rows))


if __name__ == "__main__":
    main()
