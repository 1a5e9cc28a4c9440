#!/usr/bin/env python3
"""Compares two 8-bit PNGs (RGB or RGBA, not interlaced) with the standard library only: prints the
size and the largest per-channel difference, exits 0 when they are equal (max abs 0), 1 when not, 2
when they cannot be compared. Used by the capture tests to hold an apitrace replay's snapshot
against oasis's own PNG (python3-pil is not needed). Alpha counts only where both images have it.
Usage: png_max_abs.py A.png B.png"""
import struct
import sys
import zlib


def read_png(path):
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError(f"{path}: not a PNG")
    pos, idat, header = 8, [], None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        pos += 12 + length
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat.append(body)
        elif kind == b"IEND":
            break
    width, height, depth, color, _, _, interlace = header
    channels = {2: 3, 6: 4}.get(color)
    if depth != 8 or channels is None or interlace:
        raise ValueError(f"{path}: only 8-bit RGB/RGBA non-interlaced PNGs (depth {depth}, colour type {color})")
    raw = zlib.decompress(b"".join(idat))
    stride = width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        start = y * (stride + 1)
        kind, line = raw[start], bytearray(raw[start + 1:start + 1 + stride])
        for i in range(stride):  # the five PNG filters, undone in place
            left = line[i - channels] if i >= channels else 0
            up = previous[i]
            upper_left = previous[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + left) & 255
            elif kind == 2:
                line[i] = (line[i] + up) & 255
            elif kind == 3:
                line[i] = (line[i] + (left + up) // 2) & 255
            elif kind == 4:
                p = left + up - upper_left
                pa, pb, pc = abs(p - left), abs(p - up), abs(p - upper_left)
                line[i] = (line[i] + (left if pa <= pb and pa <= pc else up if pb <= pc else upper_left)) & 255
        rows.append(bytes(line))
        previous = line
    return width, height, channels, rows


def main():
    if len(sys.argv) != 3:
        print(__doc__.splitlines()[-1])
        return 2
    try:
        a, b = read_png(sys.argv[1]), read_png(sys.argv[2])
    except (OSError, ValueError, TypeError, zlib.error) as error:
        print(f"cannot compare: {error}")
        return 2
    if a[:2] != b[:2]:
        print(f"sizes differ: {a[0]}x{a[1]} against {b[0]}x{b[1]}")
        return 1
    width, height = a[:2]
    compared = min(a[2], b[2])
    max_abs, differing = 0, 0
    for row_a, row_b in zip(a[3], b[3]):
        for x in range(width):
            pa, pb = row_a[x * a[2]:x * a[2] + compared], row_b[x * b[2]:x * b[2] + compared]
            d = max(abs(p - q) for p, q in zip(pa, pb))
            if d:
                differing += 1
                max_abs = max(max_abs, d)
    print(f"{width}x{height}, {'RGBA' if compared == 4 else 'RGB'}: max abs {max_abs}, {differing} pixels differ")
    return 0 if max_abs == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
