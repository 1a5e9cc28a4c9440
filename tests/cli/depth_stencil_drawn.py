#!/usr/bin/env python3
"""Depth and stencil read by drawing (render/depth_stencil_readback.h): the path WebGL 2 and ES drivers
without GL_NV_read_depth_stencil take, and `--force gles30` takes on llvmpipe, which reads them
directly otherwise. Against the direct read of the same frame (`--api gles`): the probe's and the
pixel history's stencil equal exactly; the stored 24-bit depth within 1 of it (the drawn read goes
through the sampler's float, whose conversion is the driver's: llvmpipe's is 1 over at most
pixels); every other field of the probe equal; the stencil view's read-back equal pixel for pixel;
and the report says which way it read and why.
usage: depth_stencil_drawn.py OASIS OUT_DIR"""
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "capture"))
from png_max_abs import read_png  # noqa: E402

oasis, out = sys.argv[1], sys.argv[2]
os.makedirs(out, exist_ok=True)
SIZE = "320x180"
DIRECT = ["--api", "gles"]
DRAWN = ["--api", "gles", "--force", "gles30"]
# Sky, terrain, plant, rock and water pixels of the default scene at hour 15 (checked below by their stencil).
PIXELS = [(240, 36), (100, 150), (160, 120), (300, 170), (210, 110), (20, 100)]
failures = []


def run(*args):
    done = subprocess.run([oasis, *args], capture_output=True, text=True)
    if done.returncode != 0:
        failures.append(f"{' '.join(args)}: exit {done.returncode}: {done.stderr[-300:]}")
    return done


def probe(tier, x, y, *extra):
    done = run("probe", *tier, "--size", SIZE, "--hour", "15", "--gbuffer", "standard", "--at", f"{x},{y}", "--json", *extra)
    return json.loads(done.stdout) if done.returncode == 0 else None


def depth_and_stencil(texel):
    return int(texel["values"][0]), int(texel["values"][1])


def without_depth(report):
    """The probe with the stored depth's two spellings taken out (compared on their own)."""
    report = json.loads(json.dumps(report))
    report["stored"].pop("depth-stencil", None)
    report["depth"].pop("stored", None)
    return report


stencils = set()
off_by_one = 0
for x, y in PIXELS:
    direct, drawn = probe(DIRECT, x, y), probe(DRAWN, x, y)
    if not direct or not drawn:
        continue
    (d0, s0), (d1, s1) = depth_and_stencil(direct["stored"]["depth-stencil"]), depth_and_stencil(drawn["stored"]["depth-stencil"])
    stencils.add(s0)
    off_by_one += d0 != d1
    print(f"{x},{y}: stencil {s0} / {s1}, 24-bit depth {d0} / {d1} (direct / drawn)")
    if s0 != s1:
        failures.append(f"{x},{y}: the drawn stencil {s1} is not the stored {s0}")
    if abs(d0 - d1) > 1:
        failures.append(f"{x},{y}: the drawn 24-bit depth {d1} is more than 1 from the stored {d0}")
    if without_depth(direct) != without_depth(drawn):
        failures.append(f"{x},{y}: the probes differ beyond the stored depth")
if len(stencils) < 3:
    failures.append(f"the pixels cover too few stencil marks to test the bits: {sorted(stencils)}")

# The pixel history reads every pass's depth-stencil writes the same way.
x, y = PIXELS[4]
histories = [probe(tier, x, y, "--history") for tier in (DIRECT, DRAWN)]
if all(histories):
    pairs = 0
    for a, b in zip(histories[0]["history"], histories[1]["history"]):
        for name, texel in a["targets"].items():
            if name in ("depth-stencil", "scene-depth") and name in b["targets"]:
                da, sa = depth_and_stencil({"values": texel["stored"]})
                db, sb = depth_and_stencil({"values": b["targets"][name]["stored"]})
                pairs += 1
                if sa != sb or abs(da - db) > 1:
                    failures.append(f"history {a['pass']} {name}: drawn {db},{sb} against stored {da},{sa}")
    print(f"history at {x},{y}: {pairs} depth-stencil writes compared")
    if pairs < 3:
        failures.append(f"history at {x},{y}: only {pairs} depth-stencil writes to compare")

# The stencil view's read-back: the same picture either way.
images = []
for name, tier in (("direct", DIRECT), ("drawn", DRAWN)):
    path = os.path.join(out, f"stencil-{name}.png")
    run("render", *tier, "--size", SIZE, "--hour", "15", "--gbuffer", "standard", "--view", "stencil",
        "--stencil-view", "read-back", "--legend", "off", "--out", path)
    images.append(read_png(path) if os.path.exists(path) else None)
if all(images):
    (w0, h0, c0, rows0), (w1, h1, c1, rows1) = images
    p0 = [bytes(r[i:i + c0]) for r in rows0 for i in range(0, len(r), c0)]
    p1 = [bytes(r[i:i + c1]) for r in rows1 for i in range(0, len(r), c1)]
    differ = sum(1 for a, b in zip(p0, p1) if a != b)
    colours = len(set(p0))
    print(f"stencil view read-back: {differ} of {len(p0)} pixels differ; {colours} colours")
    if (w0, h0) != (w1, h1) or differ:
        failures.append(f"the drawn stencil view differs from the direct one at {differ} pixels")
    if colours < 3:
        failures.append("the stencil view shows fewer than 3 colours: nothing to compare")

# The report names the way and why.
caps = run("caps", *DRAWN).stdout + run("caps", *DRAWN).stderr
if "depth-stencil-read" not in caps or "GL_NV_read_depth_stencil" not in caps:
    failures.append("oasis caps --force gles30 does not report depth-stencil-read and why")

print(f"24-bit depth off by one at {off_by_one} of {len(PIXELS)} pixels")
for failure in failures:
    print("FAIL:", failure)
sys.exit(1 if failures else 0)
