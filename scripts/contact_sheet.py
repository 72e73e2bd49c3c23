#!/usr/bin/env python3
"""Lays BMP frames of one size out in a grid and writes it as one PNG.

Usage: scripts/contact_sheet.py SHEET.png COLUMNS FRAME.bmp...

For docs/gallery.md's animation: the standard library only (zlib), so that
the gallery needs nothing beyond what building JTracer needs. Reads the
uncompressed 24-bit BMPs jtracer-cli writes; a 2-pixel dark gap separates
the frames.
"""
import struct
import sys
import zlib

GAP = 2
GAP_RGB = bytes((16, 16, 20))


def read_bmp(path):
    data = open(path, "rb").read()
    if data[:2] != b"BM":
        sys.exit(f"contact_sheet: {path}: not a BMP")
    offset = struct.unpack_from("<I", data, 10)[0]
    width, height, _planes, bits = struct.unpack_from("<iiHH", data, 18)
    if bits != 24:
        sys.exit(f"contact_sheet: {path}: {bits}-bit BMP; expected 24-bit")
    stride = (width * 3 + 3) & ~3
    rows = []
    for y in range(abs(height)):
        row_index = abs(height) - 1 - y if height > 0 else y
        row = data[offset + row_index * stride : offset + row_index * stride + width * 3]
        rgb = bytearray(len(row))
        rgb[0::3], rgb[1::3], rgb[2::3] = row[2::3], row[1::3], row[0::3]  # BGR -> RGB
        rows.append(bytes(rgb))
    return width, abs(height), rows


def png_chunk(kind, payload):
    body = kind + payload
    return struct.pack(">I", len(payload)) + body + struct.pack(">I", zlib.crc32(body))


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    out, columns, paths = sys.argv[1], int(sys.argv[2]), sys.argv[3:]
    frames = [read_bmp(p) for p in paths]
    width, height = frames[0][0], frames[0][1]
    if any(f[0] != width or f[1] != height for f in frames):
        sys.exit("contact_sheet: the frames differ in size")
    rows_of_frames = (len(frames) + columns - 1) // columns
    sheet_width = columns * width + (columns + 1) * GAP
    gap_row = GAP_RGB * sheet_width
    lines = []
    for r in range(rows_of_frames):
        lines += [gap_row] * GAP
        row_frames = frames[r * columns : (r + 1) * columns]
        for y in range(height):
            line = GAP_RGB * GAP
            for c in range(columns):
                line += row_frames[c][2][y] if c < len(row_frames) else GAP_RGB * width
                line += GAP_RGB * GAP
            lines.append(line)
    lines += [gap_row] * GAP
    raw = b"".join(b"\x00" + line for line in lines)
    header = struct.pack(">IIBBBBB", sheet_width, len(lines), 8, 2, 0, 0, 0)
    with open(out + ".tmp", "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + png_chunk(b"IHDR", header) +
                png_chunk(b"IDAT", zlib.compress(raw, 9)) + png_chunk(b"IEND", b""))
    import os
    os.replace(out + ".tmp", out)


if __name__ == "__main__":
    main()
