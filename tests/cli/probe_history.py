#!/usr/bin/env python3
"""`oasis probe --history` (issue 31): every pass of the frame is listed in the pipeline's order; the
value the last writer of each target left is what the finished frame holds there; the value each
pass left is what a frame stopped right after it holds; a pass that ran and did not write says why.
usage: probe_history.py OASIS"""
import json
import subprocess
import sys

SIZE = "320x180"
# A terrain pixel, a sky pixel and a water pixel of the default scene at 320x180.
PIXELS = [("terrain", 170, 85), ("sky", 130, 10), ("water", 210, 110)]
failures = []


def probe(oasis, *args):
    run = subprocess.run([oasis, "probe", "--size", SIZE, "--json", *args], capture_output=True, text=True)
    if run.returncode != 0:
        failures.append(f"probe {' '.join(args)}: exit {run.returncode}: {run.stderr[-300:]}")
        return None
    return json.loads(run.stdout)


def last_writes(history):
    values = {}
    for entry in history:
        if entry["wrote"]:
            for name, texel in entry["targets"].items():
                values[name] = texel["stored"]
    return values


def check_finished_frame(oasis, kind, x, y, pipeline, extra):
    where = f"{pipeline} {' '.join(extra)} {kind} {x},{y}"
    result = probe(oasis, "--pipeline", pipeline, "--at", f"{x},{y}", "--history", *extra)
    if result is None:
        return None
    history = result["history"]
    ran = [entry["pass"] for entry in history]
    if len(set(ran)) != len(ran) or len(history) < 10:
        failures.append(f"{where}: the history lists {len(history)} passes, names repeated or missing: {ran}")
    for entry in history:
        if entry["ran"] and not entry["wrote"] and not entry["reason"]:
            failures.append(f"{where}: {entry['pass']} ran, did not write, and gives no reason")
        if not entry["ran"] and entry["targets"]:
            failures.append(f"{where}: {entry['pass']} did not run but has values")
    # Issue 43, item 7: a pass wrote the pixel only where it did. The reflection's clear is a
    # stencil-masked draw at the frame's size (the default full-resolution reflection): it writes
    # the water's pixels and no other (it once said "a clear: every pixel" at every pixel).
    for entry in history:
        if entry["pass"].startswith("ReflectionClearPass") and entry["ran"] and entry["wrote"] != (kind == "water"):
            failures.append(f"{where}: {entry['pass']} wrote {entry['wrote']} at a {kind} pixel: {entry['reason']}")
    final = last_writes(history)
    stored = {name: texel["values"] for name, texel in result["stored"].items()}
    # Final is what the frame displays; off the water (where the views' fill redraws the G-buffer
    # with the direct scene) the surface targets and depth are the frame's own too.
    compared = ["final"] if kind == "water" else ["final", "albedo", "normal", "info", "depth-stencil"]
    for name in compared:
        if name in final and name in stored and final[name] != stored[name]:
            failures.append(f"{where}: the history's last {name} {final[name]} != the frame's {stored[name]}")
        if name == "final" and name not in final:
            failures.append(f"{where}: no pass wrote final")
    print(f"{where}: {sum(e['wrote'] for e in history)} of {sum(e['ran'] for e in history)} passes that ran wrote")
    return history


def check_stopped_frames(oasis, kind, x, y, history):
    """After each pass that wrote: a frame stopped before the next pass that ran holds its values."""
    ran = [entry for entry in history if entry["ran"]]
    checked = 0
    for index, entry in enumerate(ran[:-1]):
        if not entry["wrote"] or entry["pass"].startswith("Clear"):
            continue
        following = ran[index + 1]["pass"]
        stopped = probe(oasis, "--pipeline", "deferred", "--tone-map", "separate", "--at", f"{x},{y}",
                        "--stop-before", following)
        if stopped is None:
            continue
        for name, texel in entry["targets"].items():
            # A stopped frame shows Final black (it is not reached): every other target as it stood.
            if name == "final":
                continue
            if name in stopped["stored"] and stopped["stored"][name]["values"] != texel["stored"]:
                failures.append(f"{kind} {x},{y}: after {entry['pass']} the history has {name} {texel['stored']}, "
                                f"a frame stopped before {following} {stopped['stored'][name]['values']}")
        checked += 1
    print(f"{kind} {x},{y}: {checked} passes checked against frames stopped after them")
    if checked < 2:
        failures.append(f"{kind} {x},{y}: only {checked} passes could be checked against stopped frames")


def main():
    oasis = sys.argv[1]
    for kind, x, y in PIXELS:
        for pipeline in ("deferred", "forward"):
            check_finished_frame(oasis, kind, x, y, pipeline, [])
        check_finished_frame(oasis, kind, x, y, "deferred", ["--gbuffer", "full"])
    # Every layout (standard too) and the ES 3.0 tier in both pipelines.
    check_finished_frame(oasis, "terrain", 170, 85, "deferred", ["--gbuffer", "standard"])
    check_finished_frame(oasis, "water", 210, 110, "forward", ["--api", "gles", "--force", "gles30"])
    check_finished_frame(oasis, "terrain", 170, 85, "deferred", ["--api", "gles", "--force", "gles30"])
    for kind, x, y in [PIXELS[0], PIXELS[2]]:
        history = check_finished_frame(oasis, kind, x, y, "deferred", ["--tone-map", "separate"])
        if history:
            check_stopped_frames(oasis, kind, x, y, history)
    for failure in failures:
        print("  " + failure)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
