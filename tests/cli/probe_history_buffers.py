#!/usr/bin/env python3
"""`oasis probe --history`'s buffers (issue 43, item 4): at a night frame with 1024 tiled lights, the
history's first entry, "(before the passes)", holds the light list as the shaders read it and the
lights that reach the pixel's surface; a CPU recount from those numbers agrees, the probe's own GPU
count (lights_reaching) is the same, and every light probe --shading records at the surface is
among them. LightTilingPass's entry holds the pixel's tile (its place from the pixel) and the slice
its surface falls in (recomputed here from the tile's range), whose list holds every light that
reaches the pixel: the lights the tiled lighting adds there are exactly those that reach it.
--perturbed SHADERS: the same over a copy of SHADERS whose tiling pass writes each tile's lists
one tile on (as cli.check_tiles): it must fail at every first-column pixel, naming LightTiles.
usage: probe_history_buffers.py OASIS [--perturbed SHADERS]"""
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile

WIDTH, HEIGHT, TILE, SLICES, MAX_LIGHTS = 320, 180, 16, 4, 256
LIGHTS = 1024
# Pixels of the default scene at 320x180 at 21:00 with 1024 lights, tiled (found with the
# light-volumes view and the probe's lights_reaching): terrain reached by 1 to 4 lights in the
# first column of tiles, whose slots the perturbed pass fills with the lists of the right edge of
# the row below (the sky's at the corner); a water pixel (its direct scene, under the water)
# reached by 3, plants by 1, the sky.
FIRST_COLUMN = [(8, 172), (8, 130), (8, 95), (10, 60)]
PIXELS = FIRST_COLUMN + [(165, 115), (150, 100), (130, 10)]
COMMON = ["--size", f"{WIDTH}x{HEIGHT}", "--lights", str(LIGHTS), "--hour", "21", "--pipeline", "deferred",
          "--light-method", "tiled", "--history", "--shading", "--json"]


def check_pixel(oasis, x, y, env, problems):
    where = f"{x},{y}"
    run = subprocess.run([oasis, "probe", "--at", where, *COMMON], capture_output=True, text=True, env=env)
    if run.returncode != 0:
        problems.append(f"{where}: probe exit {run.returncode}: {run.stderr[-400:]}")
        return 0
    probe = json.loads(run.stdout)
    history = probe["history"]
    inputs = history[0]
    if inputs["pass"] != "(before the passes)" or not inputs["ran"] or inputs["wrote"] or inputs["targets"]:
        problems.append(f"{where}: the first entry is not the uploads: {inputs['pass']} {inputs['ran']} {inputs['wrote']}")
        return 0
    lights, plants = inputs["buffers"]["LightList"], inputs["buffers"]["PlantInstances"]
    if lights["count"] != LIGHTS:
        problems.append(f"{where}: LightList holds {lights['count']} lights as the shaders read it, not {LIGHTS}")
    if plants["count"] != plants["direct"] + plants["mirrored"] or plants["direct"] <= 0:
        problems.append(f"{where}: PlantInstances {plants}")
    reaching = {light["index"]: light for light in lights["reaching"]}
    surface = lights["surface"]
    if (surface is None) != probe["sky"]:
        problems.append(f"{where}: surface {surface} at a pixel whose sky is {probe['sky']}")
    # The CPU's recount from the history's own numbers: each light listed reaches the surface.
    for index, light in reaching.items():
        if surface is None or math.dist(light["position"], surface) >= light["radius"]:
            problems.append(f"{where}: light {index} is listed as reaching {surface} but lies {light}")
    if len(reaching) != probe["lights_reaching"]:
        problems.append(f"{where}: {len(reaching)} lights reach in the history, {probe['lights_reaching']} in the probe")
    recorded = {int(name.split()[1]) for name in probe["shading"]["direct"]["terms"] if name.startswith("light ")}
    if not recorded <= set(reaching):
        problems.append(f"{where}: probe --shading records lights {sorted(recorded - set(reaching))} the history lacks")

    tiling = [e for e in history if e["pass"] == "LightTilingPass"]
    if len(tiling) != 1 or not tiling[0]["ran"] or "LightTiles" not in tiling[0]["buffers"]:
        problems.append(f"{where}: no LightTilingPass entry with its LightTiles: {tiling}")
        return len(reaching)
    tile = tiling[0]["buffers"]["LightTiles"]
    column, row = x // TILE, (HEIGHT - 1 - y) // TILE
    if (tile["column"], tile["row"], tile["tile"]) != (column, row, row * ((WIDTH + TILE - 1) // TILE) + column):
        problems.append(f"{where}: LightTiles tile {tile['tile']} ({tile['column']}, {tile['row']}), not ({column}, {row})")
    if len(tile["slices"]) != SLICES or any(len(s["lights"]) != min(s["count"], MAX_LIGHTS) for s in tile["slices"]):
        problems.append(f"{where}: LightTiles slices {tile['slices']}")
    if surface is None:
        if tile["slice"] is not None:
            problems.append(f"{where}: a slice {tile['slice']} for the sky")
        return len(reaching)
    distance = math.hypot(*surface)
    position = (distance - tile["nearest"]) / max(tile["farthest"] - tile["nearest"], 1e-20) * SLICES
    near_edge = abs(position - round(position)) < 1e-3
    if not near_edge and tile["slice"] != min(max(math.floor(position), 0), SLICES - 1):
        problems.append(f"{where}: LightTiles slice {tile['slice']}, the surface {distance} is at {position} of "
                        f"{tile['nearest']} .. {tile['farthest']}")
    if not tile["nearest"] * (1 - 1e-4) <= distance <= tile["farthest"] * (1 + 1e-4):
        problems.append(f"{where}: LightTiles: the surface at {distance} lies outside its tile's range "
                        f"{tile['nearest']} .. {tile['farthest']}")
    listed = tile["slices"][tile["slice"]]
    if listed["count"] <= MAX_LIGHTS:
        added = {i for i in tile["lights"] if i in reaching}
        if added != set(reaching):
            problems.append(f"{where}: LightTiles slice {tile['slice']} lists {tile['lights']}: the tiled lighting "
                            f"adds {sorted(added)}, lights {sorted(set(reaching) - added)} reach the pixel too")
    print(f"{where}: {len(reaching)} lights reach; tile {tile['tile']} slice {tile['slice']} lists {len(tile['lights'])}")
    return len(reaching)


def check_all(oasis, env):
    problems, lit = [], 0
    for x, y in PIXELS:
        lit += check_pixel(oasis, x, y, env, problems) > 0
    if lit < 4:
        problems.append(f"only {lit} of the pixels are reached by lights: choose others")
    return problems


def main():
    oasis = sys.argv[1]
    if len(sys.argv) == 4 and sys.argv[2] == "--perturbed":
        work = tempfile.mkdtemp(prefix="probe-history-buffers-")
        try:
            shaders = os.path.join(work, "shaders")
            shutil.copytree(sys.argv[3], shaders)
            path = os.path.join(shaders, "light_tiles.comp")
            source = open(path).read()
            line = "    int tileBase = lightTileOf(first, frameSize) * LIGHT_TILE_STRIDE;"
            if line not in source:
                print("the perturbation did not apply")
                sys.exit(1)
            open(path, "w").write(source.replace(
                line, "    int tileBase = ((lightTileOf(first, frameSize) + 1) % (tiles.x * tiles.y)) * LIGHT_TILE_STRIDE;"))
            problems = check_all(oasis, dict(os.environ, OASIS_SHADER_DIR=shaders))
        finally:
            shutil.rmtree(work)
        for problem in problems:
            print("  (expected) " + problem)
        named = {f"{x},{y}" for x, y in FIRST_COLUMN if any(p.startswith(f"{x},{y}:") and "LightTiles" in p for p in problems)}
        print(f"perturbed tile index: {len(named)} of the {len(FIRST_COLUMN)} first-column pixels fail naming LightTiles")
        sys.exit(0 if len(named) == len(FIRST_COLUMN) else 1)
    problems = check_all(oasis, dict(os.environ))
    for problem in problems:
        print("  " + problem)
    print(f"probe history buffers: {len(problems)} problems")
    sys.exit(1 if problems else 0)


if __name__ == "__main__":
    main()
