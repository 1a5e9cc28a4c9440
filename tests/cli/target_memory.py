#!/usr/bin/env python3
"""The GPU memory of each frame's targets as `compare --passes --json` reports it (issue 43, items 1
and 5: `target_memory_bytes`, measured from what the frame graph allocated). For every layout: the
forward frame holds no G-buffer, so it holds at least the G-buffer's colour targets (and the depth
copy where the deferred frame makes one) less than the deferred frame, whose targets are exactly
those of the deferred graph's running passes plus Display; and `render --graph` prints the held
total the JSON gives.
Usage: target_memory.py OASIS OUT_DIR"""
import json
import os
import re
import subprocess
import sys

SIZE = (96, 54)


def run(oasis, *arguments):
    return subprocess.run([oasis, *arguments], check=True, capture_output=True, text=True).stdout


def main(oasis, out_dir):
    os.makedirs(out_dir, exist_ok=True)
    failures = []
    for layout in ("full", "standard", "compact"):
        report = json.loads(run(oasis, "compare", "--size", f"{SIZE[0]}x{SIZE[1]}", "--frames", "1", "--passes",
                                "--json", "--gbuffer", layout, "--out-dir", os.path.join(out_dir, layout)))
        memory = report["target_memory_bytes"]
        pixels = SIZE[0] * SIZE[1]
        # The G-buffer's bytes per pixel (colour targets, depth-stencil and the depth copy) less the
        # depth-stencil's, which forward keeps: at most 8 bytes (D32F_S8).
        gbuffer_colour = (report["gbuffer_bytes_per_pixel"] - 8) * pixels
        saved = memory["deferred"] - memory["forward"]
        print(f"{layout}: forward {memory['forward']}, deferred {memory['deferred']} bytes; "
              f"deferred - forward {saved} >= {gbuffer_colour}")
        if saved < gbuffer_colour:
            failures.append(f"{layout}: the forward frame holds G-buffer memory ({saved} < {gbuffer_colour})")
        for pipeline in ("forward", "deferred"):
            graph = run(oasis, "render", "--size", f"{SIZE[0]}x{SIZE[1]}", "--graph", "--gbuffer", layout,
                        "--pipeline", pipeline)
            held = re.search(r"# targets held after the frame: ([0-9.]+) MiB", graph)
            named = set(re.findall(r"^# (\S+) +\S+ -> ", graph, re.M))
            if not held:
                failures.append(f"{layout} {pipeline}: render --graph prints no held total")
                continue
            if abs(float(held.group(1)) * 1024 * 1024 - memory[pipeline]) > 0.01 * 1024 * 1024:
                failures.append(f"{layout} {pipeline}: render --graph holds {held.group(1)} MiB, compare "
                                f"{memory[pipeline]} bytes")
            gbuffer_named = named & {"albedo", "normal", "position", "info", "scene-depth"}
            if pipeline == "forward" and gbuffer_named:
                failures.append(f"{layout} forward: G-buffer targets in the frame: {sorted(gbuffer_named)}")
            if pipeline == "deferred" and "albedo" not in named:
                failures.append(f"{layout} deferred: no albedo among the frame's targets: {sorted(named)}")
    for failure in failures:
        print("FAIL:", failure)
    return 1 if failures else 0


if __name__ == "__main__":
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    sys.exit(main(sys.argv[1], sys.argv[2]))
