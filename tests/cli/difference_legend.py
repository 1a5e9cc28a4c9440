#!/usr/bin/env python3
"""Checks difference.png's legend strip (issue 31, defect 6): no line of its text is hidden under
the colour bar (the two rows right above the bar are background, not the tops of a covered line of
text), and the frame part shows a non-zero difference of one level visibly (red at least 128).
Usage: difference_legend.py DIFFERENCE.png FRAME_HEIGHT [--expect-visible]"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "capture"))
from png_max_abs import read_png  # noqa: E402


def main():
    path, frame_height = sys.argv[1], int(sys.argv[2])
    width, height, channels, rows = read_png(path)
    pixel = lambda x, y: rows[y][x * channels:x * channels + 3]
    pad = 4 * min(max(width / 640, 1), 2)
    left = int(pad) + 1
    # The bar's left end is black to dark red (green and blue 0); text and background are grey.
    bar = next((y for y in range(frame_height, height) if pixel(left, y)[1] == 0 and pixel(left, y)[2] == 0), None)
    if bar is None:
        print(f"{path}: no colour bar found under row {frame_height}")
        return 1
    for y in (bar - 2, bar - 1):
        bright = [x for x in range(width) if max(pixel(x, y)) > 80]
        if bright:
            print(f"{path}: row {y}, right above the colour bar (row {bar}), holds text at x {bright[:8]}: "
                  "a line of the title is under the bar")
            return 1
    if "--expect-visible" in sys.argv:
        reds = [pixel(x, y)[0] for y in range(frame_height) for x in range(width)]
        faint = [r for r in reds if 0 < r < 128]
        if faint:
            print(f"{path}: {len(faint)} differing pixels drawn fainter than red 128 (darkest {min(faint)})")
            return 1
    print(f"{path}: colour bar at row {bar}, nothing hidden under it")
    return 0


if __name__ == "__main__":
    sys.exit(main())
