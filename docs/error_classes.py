#!/usr/bin/env python3
"""The data behind `oasis check`'s cross-driver rule (docs/check.md, "What the cross-driver rule can
and cannot see"): the quick check's cases drawn (a) by llvmpipe through shader copies that each carry
one small shading error of issue 40's point 3, and (b) by other drivers through the real shaders,
each frame compared with its llvmpipe reference frame by the numbers the rules use (PSNR, max abs,
pixels over 24 levels) and the mean signed difference. A tolerance separates the two only where
every error class lies beyond it and every driver within it; the table shows where that holds.

usage: error_classes.py OASIS SHADERS REFERENCES WORK [DRIVER...] [REPORT.json]
  DRIVER: zink | softpipe (GALLIUM_DRIVER)
  REPORT.json: a check report of another driver (the browser's, web-check-report.json), its row from
  the numbers it holds (pixels over 24 are its cross-driver rule's)
Prints a markdown table; exit 0 (it measures, it does not judge)."""
import json
import math
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "capture"))
from png_max_abs import read_png  # noqa: E402

# The check's note on a frame shifted beyond every measured driver (kMeanShiftNote in
# src/check/check_case_judge.cpp): twice the largest |mean signed| of zink, softpipe and SwiftShader.
MEAN_NOTE = 0.1

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


def numbers(result, reference):
    """PSNR (dB, 100 when identical), max abs, pixels over 24 levels, mean signed (levels)."""
    (w, h, ca, rows_a), (w2, h2, cb, rows_b) = read_png(result), read_png(reference)
    if (w, h) != (w2, h2):
        raise ValueError(f"{result}: {w}x{h}, reference {w2}x{h2}")
    a, b = b"".join(rows_a), b"".join(rows_b)
    squares = signed = peak = over = 0
    for p in range(w * h):
        worst = 0
        for c in range(3):
            d = a[p * ca + c] - b[p * cb + c]
            squares += d * d
            signed += d
            worst = max(worst, abs(d))
        peak = max(peak, worst)
        over += worst > 24
    mse = squares / (3 * w * h)
    psnr = 100.0 if mse == 0 else min(100.0, 10 * math.log10(255 * 255 / mse))
    return psnr, peak, over, signed / (3 * w * h), w * h


def quick_cases(oasis, references, work):
    """The quick check's cases and the render line of each (its `reproduce`)."""
    out = os.path.join(work, "quick")
    subprocess.run([oasis, "check", "--quick", "--references", references, "--out-dir", out],
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    with open(os.path.join(out, "report.json")) as f:
        report = json.load(f)
    return [(c["name"], c["reproduce"].split()) for c in report["cases"] if c["verdict"] != "skip"]


def render(oasis, line, out, environment):
    arguments = line[1:]
    at = arguments.index("--out")
    arguments[at + 1] = out
    run = subprocess.run([oasis] + arguments, env=environment, capture_output=True, text=True)
    return run.returncode == 0 and os.path.exists(out)


def measure(label, oasis, cases, references, work, environment):
    rows = []
    os.makedirs(work, exist_ok=True)
    for name, line in cases:
        out = os.path.join(work, name + ".png")
        if render(oasis, line, out, environment):
            rows.append(numbers(out, os.path.join(references, name + ".png")))
    if not rows:
        return f"| {label} | no frame rendered | | | |"
    psnr = min(r[0] for r in rows)
    peak = max(r[1] for r in rows)
    over = max(r[2] / r[4] for r in rows)
    means = [r[3] for r in rows]
    changed = sum(1 for r in rows if r[1] > 0)
    shifted = sum(1 for m in means if abs(m) > MEAN_NOTE)
    return (f"| {label} | {changed} of {len(rows)} | {psnr:.2f} | {peak} | {100 * over:.2f}% | "
            f"{min(means):+.3f} .. {max(means):+.3f} | {shifted} |")


def report_row(path):
    with open(path) as f:
        report = json.load(f)
    rows = [c for c in report["cases"] if c.get("psnr_db") is not None and c["verdict"] != "skip"]
    if not rows:
        return f"| {path}: no judged case | | | | | | |"
    area = 256 * 144
    means = [c["mean_signed"] for c in rows]
    renderer = report["driver"]["renderer"]
    renderer = "SwiftShader in Chromium" if "SwiftShader" in renderer else renderer.split(" (")[0]
    return (f"| {renderer} (its check report) | {sum(c['max_abs'] > 0 for c in rows)} of {len(rows)} | "
            f"{min(c['psnr_db'] for c in rows):.2f} | {max(c['max_abs'] for c in rows)} | "
            f"{100 * max(c['pixels_over'] for c in rows) / area:.2f}% | {min(means):+.3f} .. {max(means):+.3f} | "
            f"{sum(1 for m in means if abs(m) > MEAN_NOTE)} |")


def main():
    if len(sys.argv) < 5:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    oasis, shaders, references, work = (os.path.abspath(a) for a in sys.argv[1:5])
    drivers = [a for a in sys.argv[5:] if not a.endswith(".json")]
    reports = [os.path.abspath(a) for a in sys.argv[5:] if a.endswith(".json")]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    cases = quick_cases(oasis, references, work)
    print("| frames | cases that differ | lowest PSNR (dB) | largest max abs | most pixels over 24 | mean signed (levels) "
          f"| cases beyond {MEAN_NOTE} |")
    print("| --- | --- | --- | --- | --- | --- | --- |")
    for label, (path, line, error) in ERROR_CLASSES.items():
        tree = os.path.join(work, "shaders-" + str(len(os.listdir(work))))
        shutil.copytree(shaders, tree)
        with open(os.path.join(tree, path)) as f:
            text = f.read()
        if text.count(line) != 1:
            print(f"| {label} | the line to perturb is not in {path} once | | | |")
            continue
        with open(os.path.join(tree, path), "w") as f:
            f.write(text.replace(line, error))
        environment = dict(os.environ, OASIS_SHADER_DIR=tree)
        print(measure("llvmpipe, " + label, oasis, cases, references, tree + "-frames", environment))
    for driver in drivers:
        environment = dict(os.environ, GALLIUM_DRIVER=driver, LIBGL_ALWAYS_SOFTWARE="1")
        print(measure(driver + " (the real shaders)", oasis, cases, references,
                      os.path.join(work, driver), environment))
    for path in reports:
        print(report_row(path))


if __name__ == "__main__":
    main()
