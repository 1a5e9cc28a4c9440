#!/usr/bin/env python3
"""Reads a screenshot that xwd wrote (ZPixmap, 24 or 32 bits a pixel) and prints the mean and standard
deviation of its RGB values over a rectangle: "mean R G B stddev S" (S over all three channels). With
--png it also writes the rectangle as a PNG, so people can look at what the window test saw.
Standard library only: the window tests must run where Python has no imaging packages.

With --compare PNG it also prints "psnr P maxabs M" of the region against the same region of that
PNG (8-bit RGB or RGBA, as oasis writes them), so a window test can hold a screenshot against the
headless render of the same frame.

usage: xwd_stats.py FILE.xwd [--region X,Y,W,H] [--png OUT.png] [--compare IN.png]"""
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


def read_png(path):
    """The rows of an 8-bit RGB or RGBA, non-interlaced PNG as [[r, g, b], ...] lists."""
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        sys.exit(f"xwd_stats: {path} is not a PNG")
    at, idat, header = 8, b"", None
    while at < len(data):
        length, kind = struct.unpack(">I4s", data[at:at + 8])
        body = data[at + 8:at + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        at += 12 + length
    width, height, depth, colour, _compression, _filter, interlace = header
    if depth != 8 or colour not in (2, 6) or interlace:
        sys.exit(f"xwd_stats: {path}: only 8-bit RGB/RGBA non-interlaced PNGs are read")
    step = 3 if colour == 2 else 4
    raw, stride, rows, previous = zlib.decompress(idat), width * step, [], bytearray(width * step)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):  # undo the row's filter (PNG spec, section 9)
            left = line[i - step] if i >= step else 0
            up, corner = previous[i], (previous[i - step] if i >= step else 0)
            if kind == 1:
                line[i] = (line[i] + left) & 255
            elif kind == 2:
                line[i] = (line[i] + up) & 255
            elif kind == 3:
                line[i] = (line[i] + (left + up) // 2) & 255
            elif kind == 4:
                p = left + up - corner
                pa, pb, pc = abs(p - left), abs(p - up), abs(p - corner)
                line[i] = (line[i] + (left if pa <= pb and pa <= pc else up if pb <= pc else corner)) & 255
        rows.append([list(line[x * step:x * step + 3]) for x in range(width)])
        previous = line
    return width, height, rows


def compare(rows, x0, y0, png):
    width, height, reference = read_png(png)
    if y0 + len(rows) > height or x0 + len(rows[0]) > width:
        sys.exit(f"xwd_stats: the region is outside {png} ({width}x{height})")
    squared, worst, count = 0, 0, 0
    for y, row in enumerate(rows):
        for x, rgb in enumerate(row):
            for k in range(3):
                d = abs(rgb[k] - reference[y0 + y][x0 + x][k])
                squared, worst, count = squared + d * d, max(worst, d), count + 1
    mse = squared / count
    return (100.0 if mse == 0 else 10.0 * math.log10(255.0 ** 2 / mse)), worst


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("xwd")
    parser.add_argument("--region", help="X,Y,W,H (default: the whole image)")
    parser.add_argument("--png")
    parser.add_argument("--compare")
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
    if args.compare:
        psnr, worst = compare(rows, x0, y0, args.compare)
        print("psnr %.2f maxabs %d" % (psnr, worst))


if __name__ == "__main__":
    main()
