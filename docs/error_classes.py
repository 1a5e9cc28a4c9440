#!/usr/bin/env python3
"""The data behind `oasis check`'s cross-driver rules (docs/check.md, "What the cross-driver rule can
and cannot see" and "Edges and interiors"): the quick check's cases drawn (a) by llvmpipe through
shader copies that each carry one small shading error of issue 40's point 3, and (b) by other drivers
through the real shaders, each frame judged against its llvmpipe reference frame as another driver's
is (the references copied without their oasis:renderer chunk, so that llvmpipe's frames meet
cross-driver and cross-driver-interior rather than identical). Each row is read from the check's own
report.json: the whole frame's numbers (PSNR, max abs, pixels over 24 levels, mean signed) and the
interior's (the pixels the case's geometry calls interior: their max abs, pixels over the interior
rule's level, mean signed). A tolerance separates the two only where every error class lies beyond it
and every driver within it; the table shows where that holds.

usage: error_classes.py OASIS SHADERS REFERENCES WORK [DRIVER...] [REPORT.json]
  DRIVER: zink | softpipe (GALLIUM_DRIVER), or DRIVER:full for the whole check instead of --quick
  REPORT.json: a check report of another driver (the browser's, web-check-report.json), its row from
  the numbers it holds (pixels over 24 are its cross-driver rule's)
Prints a markdown table; exit 0 (it measures, it does not judge)."""
import json
import os
import shutil
import struct
import subprocess
import sys

# The check's note on a frame shifted beyond every measured driver (kMeanShiftNote in
# src/check/check_judge.h).
MEAN_NOTE = 0.1
AREA = 256 * 144

# Each class: the file under the shader tree, the line as it is, the line with the error.
ERROR_CLASSES = {
    "sky 3% too bright": ("common/sky.glsl", "    return gradient * (1.0 - 0.35 * sqrt(down));",
                          "    return 1.03 * gradient * (1.0 - 0.35 * sqrt(down));"),
    "sky 10% too bright": ("common/sky.glsl", "    return gradient * (1.0 - 0.35 * sqrt(down));",
                           "    return 1.10 * gradient * (1.0 - 0.35 * sqrt(down));"),
    "sun N.L sign flipped within 0.15 of 0": (
        "common/lighting.glsl", "    float diffuse = max(dot(n, toSun), 0.0);",
        "    float diffuse = max(abs(dot(n, toSun)) < 0.15 ? -dot(n, toSun) : dot(n, toSun), 0.0);"),
    "shadow cascade edge margin removed": ("common/shadows.glsl", "    float margin = 2.0 * 2.0 / mapSize.x;",
                                           "    float margin = 0.0;"),
    "SSBO light list 1.25x too bright": (
        "common/lights.glsl", "PointLight lightAt(int i) { return lights[i]; }",
        "PointLight lightAt(int i) { PointLight l = lights[i]; l.colourIntensity.w *= 1.25; return l; }"),
}


def strip_renderer(source, target):
    """The reference PNGs without their oasis:renderer text chunk: no driver is their own."""
    os.makedirs(target)
    for name in os.listdir(source):
        if not name.endswith(".png"):
            continue
        with open(os.path.join(source, name), "rb") as f:
            data = f.read()
        out, at = [data[:8]], 8
        while at < len(data):
            length, kind = struct.unpack(">I4s", data[at:at + 8])
            chunk = data[at:at + 12 + length]
            at += 12 + length
            if not (kind in (b"iTXt", b"tEXt", b"zTXt") and chunk[8:].startswith(b"oasis:renderer\0")):
                out.append(chunk)
        with open(os.path.join(target, name), "wb") as f:
            f.write(b"".join(out))


def check(oasis, references, out, environment, full=False):
    """The check's report.json of one run (quick unless `full`), every case run once."""
    arguments = [oasis, "check", "--retries", "0", "--references", references, "--out-dir", out]
    subprocess.run(arguments + ([] if full else ["--quick"]), env=environment, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL)
    with open(os.path.join(out, "report.json")) as f:
        return json.load(f)


def interior_level(report):
    for c in report["cases"]:
        if c.get("interior"):
            return c["interior"]["level"]
    return None


def row(label, report):
    cases = [c for c in report["cases"] if c["verdict"] != "skip" and c.get("psnr_db") is not None]
    if not cases:
        return f"| {label} | no case judged | | | | | | | | | |"
    means = [c["mean_signed"] for c in cases]
    inside = [c["interior"] for c in cases if c.get("interior")]
    whole = (f"| {label} | {sum(c['max_abs'] > 0 for c in cases)} of {len(cases)} | "
             f"{min(c['psnr_db'] for c in cases):.2f} | {max(c['max_abs'] for c in cases)} | "
             f"{100 * max(c['pixels_over'] for c in cases) / AREA:.2f}% | {min(means):+.3f} .. {max(means):+.3f} | "
             f"{sum(1 for m in means if abs(m) > MEAN_NOTE)} |")
    if not inside:
        return whole + " not split | | | |"
    over = max(i["over"] / max(i["pixels"], 1) for i in inside)
    inner = [i["mean_signed"] for i in inside]
    return whole + (f" {max(i['max_abs'] for i in inside)} | {100 * over:.2f}% | {min(inner):+.3f} .. {max(inner):+.3f} | "
                    f"{sum(1 for i in inside if not i['pass'])} of {len(inside)} |")


def report_row(path):
    with open(path) as f:
        report = json.load(f)
    renderer = report["driver"]["renderer"]
    renderer = "SwiftShader in Chromium" if "SwiftShader" in renderer else renderer.split(" (")[0]
    return row(renderer + " (its check report)", report)


def main():
    if len(sys.argv) < 5:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    oasis, shaders, references, work = (os.path.abspath(a) for a in sys.argv[1:5])
    drivers = [a for a in sys.argv[5:] if not a.endswith(".json")]
    reports = [os.path.abspath(a) for a in sys.argv[5:] if a.endswith(".json")]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    anonymous = os.path.join(work, "references")
    strip_renderer(references, anonymous)
    rows, level = [], None
    for number, (label, (path, line, error)) in enumerate(ERROR_CLASSES.items()):
        tree = os.path.join(work, f"shaders-{number}")
        shutil.copytree(shaders, tree)
        with open(os.path.join(tree, path)) as f:
            text = f.read()
        if text.count(line) != 1:
            rows.append(f"| llvmpipe, {label} | the line to perturb is not in {path} once | | | | | | | | | |")
            continue
        with open(os.path.join(tree, path), "w") as f:
            f.write(text.replace(line, error))
        report = check(oasis, anonymous, tree + "-check", dict(os.environ, OASIS_SHADER_DIR=tree))
        level = level or interior_level(report)
        rows.append(row("llvmpipe, " + label, report))
    for driver in drivers:
        name, _, scope = driver.partition(":")
        environment = dict(os.environ, GALLIUM_DRIVER=name, LIBGL_ALWAYS_SOFTWARE="1")
        report = check(oasis, anonymous, os.path.join(work, driver.replace(":", "-")), environment, scope == "full")
        level = level or interior_level(report)
        rows.append(row(f"{name} (the real shaders{', the full check' if scope == 'full' else ''})", report))
    for path in reports:
        rows.append(report_row(path))
    print("| frames | cases that differ | lowest PSNR (dB) | largest max abs | most pixels over 24 | mean signed (levels) "
          f"| cases beyond {MEAN_NOTE} | interior max abs | interior pixels over {level} | interior mean signed "
          "| cases failing cross-driver-interior |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for text in rows:
        print(text)


if __name__ == "__main__":
    main()
