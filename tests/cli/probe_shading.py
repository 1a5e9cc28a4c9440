#!/usr/bin/env python3
"""`oasis probe --shading` (issue 31): the terms the frame's GLSL recorded at a pixel recombine to
what the frame stored there. For each pixel kind (sky, terrain, rock, plant, shadowed, lit by point
lights, water) and each pipeline: the parts sum to the lit colour, water and fog carry it to the
surface's radiance, the lights' shares add up, that radiance is the frame's Radiance (at water:
the composite of the mirrored scene, Fresnel and what lies under is), the mirrored scene's is the
frame's Reflection, all within half-float rounding in both pipelines (forward's record shades the
surfaces its shaders built, drawn again unrounded, not the views' G-buffer), and the tone map's
output is Final. Each pixel is first checked to be of its kind,
so a scene change fails here instead of testing something else.
--perturbed SHADERS: the same checks over a copy of SHADERS whose forward surfaces shade 0.4 %
brighter than the record (emit_surface.glsl): they must fail at forward pixels, and only there.
With GALLIUM_DRIVER=NAME among the env, exits 77 (skipped) where that driver is not available.
usage: probe_shading.py OASIS [--perturbed SHADERS] [env NAME=VALUE ...]"""
import json
import os
import shutil
import subprocess
import sys
import tempfile

# Pixel kinds at 320x180 of the default scene with 64 lights (found by probing a grid).
PIXELS = [
    ("sky", 130, 10), ("terrain", 170, 85), ("rock", 130, 60), ("plant", 90, 85),
    ("shadowed", 250, 60), ("lit by lights", 210, 85), ("water", 210, 110), ("water", 290, 135),
]
HALF_STEP = 2.0 ** -10  # Radiance keeps 10 of float's 23 mantissa bits (truncated on llvmpipe)


def close(a, b, relative, absolute=1e-5):
    return all(abs(x - y) <= absolute + relative * max(abs(x), abs(y)) for x, y in zip(a, b))


def terms(surface):
    return {name: term["value"] for name, term in surface["terms"].items()}


def kind_holds(kind, probe, direct):
    flags, stencil = probe["info"]["flag_names"], probe["stencil"]["value"] & 0x7F
    return {
        "sky": probe["sky"],
        "terrain": stencil == 1 and probe["info"]["specular_power"] in (4, 5, 6),
        "rock": stencil == 1 and probe["info"]["specular_power"] == 12,
        "plant": "PLANT" in flags,
        "shadowed": not probe["sky"] and direct.get("shadow", [1])[0] < 0.9,
        "lit by lights": direct.get("lights", [0, 0, 0, 0])[3] >= 1,
        "water": stencil == 2,
    }[kind]


def check_surface(t, where, problems):
    """The recorded parts recombine to the surface's radiance (the same float arithmetic)."""
    def need(ok, what):
        if not ok:
            problems.append(f"{where}: {what}")
    if "sky" in t:
        need(close(t["sky"], t["radiance"], 1e-6), "sky != radiance")
        return
    albedo, sun, lobe = t["albedo"][:3], t["sun_at_surface"], t["specular_lobe"]
    need(close([s * t["shadow"][0] for s in t["sun_radiance"]], sun, 1e-5), "sun x visibility != sun_at_surface")
    need(close([a * s * lobe[0] for a, s in zip(albedo, sun)], t["diffuse_part"], 1e-5), "albedo sun N.L != diffuse_part")
    need(close([a * b for a, b in zip(albedo, t["ambient"])], t["ambient_part"], 1e-5), "albedo x ambient != ambient_part")
    need(close([s * lobe[3] for s in sun], t["specular_part"], 1e-5), "sun x specular != specular_part")
    need(abs(max(t["normal"][3], 0.0) - lobe[0]) < 1e-6, "max(N.L, 0) differs from the lobe's")
    parts = [a + b + c for a, b, c in zip(t["diffuse_part"], t["ambient_part"], t["specular_part"])]
    need(close(parts, t["lit"], 1e-5), f"parts {parts} != lit {t['lit']}")
    T, scatter = t["water_crossed"][:3], t["water_scatter"]
    after = [l * tr + s * (1 - tr) for l, tr, s in zip(t["lit"], T, scatter)] if t["water_crossed"][3] > 0 else t["lit"]
    need(close(after, t["after_water"], 1e-5), "lit through water != after_water")
    fog = t["fog"][0]
    surface = [a * (1 - fog) + f * fog for a, f in zip(t["after_water"], t["fog_colour"])]
    need(close(surface, t["surface"], 1e-5), "mix(after_water, fog) != surface")
    shares = [t[name] for name in t if name.startswith("light ")]
    if t["lights"][3] <= 8:
        summed = [sum(share[c] for share in shares) for c in range(3)]
        need(close(summed, t["lights"][:3], 1e-4, 1e-6), "light shares do not sum to lights")
    need(close([s + l for s, l in zip(t["surface"], t["lights"][:3])], t["radiance"], 1e-5), "surface + lights != radiance")


def check_pixels(oasis, env_args):
    """Every pixel in both pipelines: the problems found and the number of pixels checked."""
    failures, checked = [], 0
    for pipeline in ("deferred", "forward"):
        for kind, x, y in PIXELS:
            command = ["env", *env_args, oasis, "probe", "--size", "320x180", "--lights", "64", "--pipeline", pipeline,
                       "--at", f"{x},{y}", "--shading", "--json"]
            run = subprocess.run(command, capture_output=True, text=True)
            if run.returncode != 0:
                failures.append(f"{' '.join(command)}: exit {run.returncode}: {run.stderr[-400:]}")
                continue
            probe = json.loads(run.stdout)
            shading = probe["shading"]
            where = f"{pipeline} {kind} at {x},{y}"
            direct = terms(shading["direct"])
            if not kind_holds(kind, probe, direct):
                failures.append(f"{where}: the pixel is no longer of its kind (stencil {probe['stencil']}, "
                                f"flags {probe['info']['flag_names']}): choose another")
                continue
            problems = []
            check_surface(direct, where + " direct", problems)
            radiance = probe["radiance"][:3]
            if "water" in shading:
                water = terms(shading["water"])
                mirrored = terms(shading["mirrored"])
                check_surface(mirrored, where + " mirrored", problems)
                if not close(water["under"], direct["radiance"], 1e-6):
                    problems.append(f"{where}: under != the direct scene's radiance")
                if not close(mirrored["radiance"], probe["reflection"][:3], HALF_STEP, 2e-4):
                    problems.append(f"{where}: mirrored radiance {mirrored['radiance']} != Reflection {probe['reflection']}")
                if not close(water["reflected"], probe["reflection"][:3], 1e-6):
                    problems.append(f"{where}: reflected != Reflection")
                F, glint, fog = water["fresnel"][:3]
                sun = direct.get("sun_radiance") or shading["mirrored"]["terms"].get("sun_radiance", {}).get("value")
                composite = [(F * r + glint * s) * (1 - fog) + (1 - F * (1 - fog)) * u
                             for r, s, u in zip(water["reflected"], sun, water["under"])]
                if not close(composite, water["result"][:3], 1e-5):
                    problems.append(f"{where}: Fresnel recombination {composite} != water result {water['result']}")
                expected = water["result"][:3]
            else:
                expected = direct["radiance"]
            if not close(expected, radiance, HALF_STEP, 2e-4):
                problems.append(f"{where}: recorded radiance {expected} != the frame's Radiance {radiance}")
            tone = terms(shading["tone_map"])
            if not close(tone["input"][:3], radiance, 0.0, 0.0):
                problems.append(f"{where}: tone map input != Radiance")
            final = [round(v * 255.0) for v in tone["output"]]
            if any(abs(a - b) > 0 for a, b in zip(final, probe["final"][:3])):
                problems.append(f"{where}: tone map output x 255 {final} != Final {probe['final'][:3]}")
            failures += problems
            checked += 1
            print(f"{where}: {'ok' if not problems else 'FAILED'}")
    print(f"{checked} pixels checked, {len(failures)} problems")
    for failure in failures:
        print("  " + failure)
    return failures, checked


def skip_unless_driver(oasis, env_args):
    """Where the env asks Mesa for a driver (GALLIUM_DRIVER), exit 77 unless oasis gets it."""
    wanted = [a.split("=", 1)[1] for a in env_args if a.startswith("GALLIUM_DRIVER=")]
    if not wanted:
        return
    run = subprocess.run(["env", *env_args, oasis, "caps", "--json"], capture_output=True, text=True)
    renderer = json.loads(run.stdout).get("renderer", "") if run.returncode == 0 and run.stdout else ""
    if not renderer.startswith(wanted[0]):
        print(f"SKIPPED: {wanted[0]} is not available here (renderer '{renderer}', exit {run.returncode})")
        sys.exit(77)


def perturbed_copy(shaders, into):
    """SHADERS copied with the forward surfaces' radiance 0.4 % above what the record computes."""
    copy = os.path.join(into, "shaders")
    shutil.copytree(shaders, copy)
    path = os.path.join(copy, "common", "emit_surface.glsl")
    text = open(path).read()
    exact = "vec3 radiance = shadeSurface(s) + allPointLights(s);"
    if text.count(exact) != 1:
        sys.exit(f"the perturbation does not apply: no single '{exact}' in {path}")
    open(path, "w").write(text.replace(exact, "vec3 radiance = shadeSurface(s) * 1.004 + allPointLights(s);"))
    return copy


def main():
    oasis, args = sys.argv[1], sys.argv[2:]
    if args[:1] != ["--perturbed"]:  # args: [env NAME=VALUE ...]
        skip_unless_driver(oasis, args[1:])
        failures, checked = check_pixels(oasis, args[1:])
        sys.exit(1 if failures or checked < 2 * len(PIXELS) else 0)
    with tempfile.TemporaryDirectory() as work:
        failures, checked = check_pixels(oasis, ["OASIS_SHADER_DIR=" + perturbed_copy(args[1], work), *args[3:]])
    caught = [f for f in failures if f.startswith("forward ") and "!= the frame's Radiance" in f]
    others = [f for f in failures if f not in caught]
    print(f"perturbed forward shading: {len(caught)} forward pixels caught, {len(others)} other problems")
    sys.exit(0 if caught and not others and checked == 2 * len(PIXELS) else 1)


if __name__ == "__main__":
    main()
