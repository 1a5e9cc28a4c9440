#!/usr/bin/env python3
"""Reads a screenshot that xwd wrote (ZPixmap, 24 or 32 bits a pixel) and prints the mean and standard
deviation of its RGB values over a rectangle: "mean R G B stddev S" (S over all three channels). With
--png it also writes the rectangle as a PNG, so people can look at what the window test saw.
Standard library only: the window tests must run where Python has no imaging packages.

usage: xwd_stats.py FILE.xwd [--region X,Y,W,H] [--png OUT.png]"""
import argparse
import math
import struct
import sys
import zlib


def read_xwd(path):
    data = open(path, "rb").read()
    header = struct.unpack(">25I", data[:100])
    (header_size, _version, pixmap_format, _depth, width, height, _xoffset, byte_order, _unit, _bit_order,
     _pad, bits_per_pixel, bytes_per_line, _visual, red_mask, green_mask, blue_mask, _bits_rgb, _entries,
     ncolors) = header[:20]
    if pixmap_format != 2 or bits_per_pixel not in (24, 32):
        sys.exit(f"xwd_stats: {path}: only ZPixmap screenshots of 24 or 32 bits a pixel are read")
    pixels = data[header_size + 12 * ncolors:]
    step = bits_per_pixel // 8
    endian = "<" if byte_order == 0 else ">"

    def shift(mask):
        return (mask & -mask).bit_length() - 1

    shifts = [(m, shift(m)) for m in (red_mask, green_mask, blue_mask)]

    def pixel(x, y):
        at = y * bytes_per_line + x * step
        raw = pixels[at:at + step] + (b"\0" if step == 3 else b"")
        value = struct.unpack(endian + "I", raw)[0]
        return [(value & m) >> s for m, s in shifts]

    return width, height, pixel


def write_png(path, width, height, rows):
    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF)

    raw = b"".join(b"\0" + bytes(value for rgb in row for value in rgb) for row in rows)
    with open(path, "wb") as out:
        out.write(b"\x89PNG\r\n\x1a\n")
        out.write(chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)))
        out.write(chunk(b"IDAT", zlib.compress(raw, 6)))
        out.write(chunk(b"IEND", b""))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("xwd")
    parser.add_argument("--region", help="X,Y,W,H (default: the whole image)")
    parser.add_argument("--png")
    args = parser.parse_args()
    width, height, pixel = read_xwd(args.xwd)
    x0, y0, w, h = map(int, args.region.split(",")) if args.region else (0, 0, width, height)
    w, h = min(w, width - x0), min(h, height - y0)
    if w <= 0 or h <= 0:
        sys.exit(f"xwd_stats: region {args.region} is outside the {width}x{height} screenshot")
    rows = [[pixel(x, y) for x in range(x0, x0 + w)] for y in range(y0, y0 + h)]
    values = [c for row in rows for rgb in row for c in rgb]
    means = [sum(rgb[k] for row in rows for rgb in row) / (w * h) for k in range(3)]
    mean = sum(values) / len(values)
    stddev = math.sqrt(sum((v - mean) ** 2 for v in values) / len(values))
    print("mean %.1f %.1f %.1f stddev %.1f" % (means[0], means[1], means[2], stddev))
    if args.png:
        write_png(args.png, w, h, rows)


if __name__ == "__main__":
    main()
