#!/bin/sh
# `oasis check` end to end (check/check.h), one case per ctest test:
#   quick      --quick on this machine's llvmpipe against the repository's reference frames: exit 0,
#              report.json with the keys scripts depend on and counts that add up, report.html
#              opened in chromium-headless-shell showing the same counts, within the 90 s budget
#   perturbed  the full check recorded as this driver's baseline, every case's reproduce line drawing its
#              frame bit for bit, a --quick run against the baseline passing; then a copy of the
#              shaders whose UBO light list returns each light 4x as bright: the check of the UBO
#              cases and four others fails exactly the cases that draw lights through the UBO path into the final
#              frame (not the far lands, out of the lights' sight) and names for each the light list as
#              the shaders decode it, before any pass ("(before the passes)" / LightList); every
#              other case passes; --diff against the clean run lists those cases as regressions and exits 1
#   tiles      a copy of the shaders whose tiling compute pass writes each tile's lists one tile on
#              (the last wrapping to the first), the lighting reading them where they belong: every
#              tiled case that draws the final frame fails, each naming LightTilingPass / LightTiles
#              (the lights its lists miss at the differing pixels), not the lighting that follows
#   usage      bad arguments: exit 2
# usage: check.sh OASIS SHADER_DIR REFERENCES WORK_DIR CASE
set -u
oasis=$1 shaders=$2 references=$3 work=$4 case=$5
fail() { echo "FAIL ($case): $*"; exit 1; }
rm -rf "$work" && mkdir -p "$work" || fail "cannot make $work"
cd "$work" || fail "cannot enter $work"

case $case in
quick)
    start=$(date +%s)
    "$oasis" check --quick --references "$references" --out-dir out > out.txt 2> err.txt
    code=$? elapsed=$(($(date +%s) - start))
    [ $code -eq 0 ] || fail "exit $code: $(tail -n 20 out.txt err.txt)"
    [ $elapsed -le 90 ] || fail "--quick took $elapsed s, over its 90 s budget"
    grep -q "case 1 of [0-9]*, 0[0-9]-" err.txt || fail "no progress line (case i of n, name): $(head -n 3 err.txt)"
    python3 - out/report.json << 'EOF' || fail "report.json"
import json, sys
report = json.load(open(sys.argv[1]))
for key in ("summary", "driver", "caps", "cases", "oasis"):
    assert key in report, key
summary, cases = report["summary"], report["cases"]
assert summary["fail"] == 0 and summary["pass"] + summary["skip"] == len(cases) >= 6, summary
for c in cases:
    for key in ("name", "options", "verdict", "reason", "psnr_db", "max_abs", "pixels_over", "first_divergence"):
        assert key in c, (c["name"], key)
    assert c["verdict"] in ("pass", "fail", "skip"), c
    assert isinstance(c["options"], list) and all(isinstance(o, str) for o in c["options"]), c["options"]
    assert c["verdict"] != "pass" or c["max_abs"] == 0, ("llvmpipe against its own references", c)
    # Each case's own seconds: a case that rendered ran a child process of its own (a GL context
    # and a frame: well over 50 ms here), rendered ahead of its judging; never the judging alone.
    assert c["verdict"] == "skip" or c["seconds"] >= 0.05, ("the case's seconds", c["name"], c["seconds"])
assert "llvmpipe" in report["driver"]["renderer"], report["driver"]
assert all({"feature", "available", "used", "limited_by"} <= set(row) for row in report["caps"]), report["caps"]
print("report.json: %d cases, %s" % (len(cases), summary))
EOF
    if browser=$(command -v chromium-headless-shell); then
        profile=$(mktemp -d)
        # The browser is not oasis: the sanitizer build's preload and options are not for it.
        env -u LD_PRELOAD -u ASAN_OPTIONS -u UBSAN_OPTIONS -u LSAN_OPTIONS timeout 120 "$browser" --headless --no-sandbox --disable-gpu --disable-dev-shm-usage --disable-background-networking \
            --disable-component-update --no-first-run --user-data-dir="$profile" --dump-dom "file://$work/out/report.html" \
            > dom.html 2> chromium.log || fail "chromium exited $? on report.html"
        rm -rf "$profile"
        for verdict in pass fail skip; do
            expected=$(python3 -c "import json; print(json.load(open('out/report.json'))['summary']['$verdict'])")
            shown=$(sed -n "s/.*id=\"count-$verdict\">\([0-9]*\)<.*/\1/p" dom.html)
            [ "$shown" = "$expected" ] || fail "report.html shows $verdict '$shown', report.json has '$expected'"
        done
        # The cases' "s" column shows each case's seconds as report.json has them (never 0.0 for all).
        python3 - dom.html out/report.json << 'EOF' || fail "report.html's seconds"
import json, re, sys
shown = re.findall(r'<span class="n">([0-9.]+)</span></summary>', open(sys.argv[1]).read())
cases = json.load(open(sys.argv[2]))["cases"]
assert len(shown) == len(cases), (len(shown), len(cases))
pairs = zip(sorted(float(s) for s in shown), sorted(c["seconds"] for c in cases))
assert all(abs(a - b) <= 0.051 for a, b in pairs), (shown, [c["seconds"] for c in cases])
assert sum(float(s) > 0 for s in shown) >= sum(c["verdict"] != "skip" for c in cases), shown
EOF
    else
        echo "(chromium-headless-shell absent: report.html not opened)"
    fi
    echo "check quick: $(grep "^oasis check: " out.txt | tail -n 1) in $elapsed s" ;;
perturbed)
    # The clean run records every case's frame (--baseline): each case's reproduce line must draw it
    # bit for bit; a second run judged against that baseline passes.
    "$oasis" check --references "$references" --out-dir clean --baseline baseline > clean.txt 2> clean.err ||
        fail "the clean check failed: $(grep -v '^  pass' clean.txt)"
    python3 - clean/report.json "$oasis" "$(dirname "$0")/../capture/png_max_abs.py" << 'EOF' || fail "a reproduce line"
import json, os, shlex, subprocess, sys
report, oasis, compare = json.load(open(sys.argv[1])), sys.argv[2], sys.argv[3]
os.makedirs("reproduced", exist_ok=True)
checked = 0
for c in report["cases"]:
    assert c["context"]["gl_version"], c["name"]
    if c["verdict"] == "skip":
        continue
    words = shlex.split(c["reproduce"])
    assert words[:2] == ["oasis", "render"] and words[-1] == c["name"] + ".png", c["reproduce"]
    subprocess.run([oasis] + words[1:], cwd="reproduced", check=True, stderr=subprocess.DEVNULL)
    same = subprocess.run([sys.executable, compare, "reproduced/" + c["name"] + ".png", "baseline/" + c["name"] + ".png"],
                          capture_output=True, text=True)
    assert same.returncode == 0, (c["name"], c["reproduce"], same.stdout, same.stderr)
    checked += 1
assert checked == len([c for c in report["cases"] if c["verdict"] != "skip"]) >= 40, checked
print("reproduce: %d cases drawn again bit for bit by their reproduce lines" % checked)
EOF
    "$oasis" check --quick --references "$references" --baseline baseline --out-dir again > again.txt 2> again.err ||
        fail "the second run against this driver's baseline: $(grep -v '^  pass' again.txt)"
    cp -r "$shaders" shaders || fail "cannot copy the shaders"
    # The UBO light list only (both of its lightAt() definitions: GLSL 4.00 on and before).
    sed -i 's|PointLight lightAt(int i) { return lightBlocks\[i / LIGHTS_UBO_CAPACITY\].lights\[i % LIGHTS_UBO_CAPACITY\]; }|PointLight lightAt(int i) { PointLight l = lightBlocks[i / LIGHTS_UBO_CAPACITY].lights[i % LIGHTS_UBO_CAPACITY]; l.colourIntensity.w *= 4.0; return l; }|; s|^    return lightBlocks\[0\].lights\[index\];|    PointLight l = lightBlocks[0].lights[index]; l.colourIntensity.w *= 4.0; return l;|' shaders/common/lights.glsl
    [ "$(grep -c 'colourIntensity.w \*= 4.0' shaders/common/lights.glsl)" -eq 2 ] || fail "the perturbation did not apply"
    # The UBO cases and four others as controls (the clean run above passed all 45).
    OASIS_SHADER_DIR=$work/shaders "$oasis" check --case '*-ubo-*' --case '0[1-4]-*' --references "$references" \
        --out-dir perturbed > perturbed.txt 2> perturbed.err
    code=$?
    [ $code -eq 1 ] || fail "the perturbed check: exit $code, expected 1"
    python3 - clean/report.json perturbed/report.json << 'EOF' || fail "the perturbed check's verdicts"
import json, sys
clean, perturbed = (json.load(open(path)) for path in sys.argv[1:3])
names = [c["name"] for c in perturbed["cases"]]
assert [c["name"] for c in clean["cases"] if c["name"] in names] == names and len(names) >= 14, names
expected = 0
for c in perturbed["cases"]:
    on_path = "-ubo-" in c["name"] and "-final-" in c["name"] and "-far-" not in c["name"]
    expected += on_path
    assert (c["verdict"] == "fail") == on_path, (c["name"], c["verdict"], c["reason"])
    if on_path:
        # The lights the shaders decode differ from the main path's (every one 4x as bright): named
        # before the first pass that reads them, in both pipelines.
        divergence = c["first_divergence"]
        assert divergence and divergence["pass"] == "(before the passes)" and divergence["target"] == "LightList" \
            and divergence["pixels"] > 0, (c["name"], divergence)
assert expected >= 5, expected
print("perturbed: %d cases on the UBO path failed, each naming its pass; %d others passed" % (expected, len(perturbed["cases"]) - expected))
EOF
    "$oasis" check --diff clean/report.json perturbed/report.json > diff.txt 2> diff.err
    code=$?
    [ $code -eq 1 ] || fail "--diff clean perturbed: exit $code, expected 1: $(cat diff.err)"
    grep -q "^regressions ([1-9]" diff.txt || fail "--diff lists no regressions: $(head -n 20 diff.txt)"
    "$oasis" check --diff clean/report.json clean/report.json > same.txt || fail "--diff of a report with itself: exit $?"
    echo "check perturbed: OK ($(grep '^regressions' diff.txt))" ;;
tiles)
    cp -r "$shaders" shaders || fail "cannot copy the shaders"
    # The writer's tile index one on (wrapped, so every write stays inside the buffer); the readers
    # (common/light_tiles.glsl's lightTileOf in the lighting) are left as they are.
    sed -i 's|^    int tileBase = lightTileOf(first, frameSize) \* LIGHT_TILE_STRIDE;|    int tileBase = ((lightTileOf(first, frameSize) + 1) % (tiles.x * tiles.y)) * LIGHT_TILE_STRIDE;|' shaders/light_tiles.comp
    grep -q '(lightTileOf(first, frameSize) + 1)' shaders/light_tiles.comp || fail "the perturbation did not apply"
    OASIS_SHADER_DIR=$work/shaders "$oasis" check --case '*-tiled-*' --references "$references" \
        --out-dir perturbed > perturbed.txt 2> perturbed.err
    code=$?
    [ $code -eq 1 ] || fail "the perturbed check: exit $code, expected 1: $(tail -n 5 perturbed.txt perturbed.err)"
    verdicts=$(python3 - perturbed/report.json << 'EOF'
import json, sys
cases = json.load(open(sys.argv[1]))["cases"]
assert len(cases) >= 3 and all("-tiled-" in c["name"] for c in cases), [c["name"] for c in cases]
named = 0
for c in cases:
    if c["verdict"] == "skip":
        continue
    assert c["verdict"] == "fail", (c["name"], c["verdict"], c["reason"])
    divergence = c["first_divergence"]
    assert divergence and divergence["pass"] == "LightTilingPass" and divergence["target"] == "LightTiles" \
        and divergence["pixels"] > 0, (c["name"], divergence, c["reason"])
    named += 1
assert named >= 3, named
print("%d tiled cases failed, each naming LightTilingPass / LightTiles" % named)
EOF
) || fail "the perturbed check's verdicts: $verdicts"
    echo "check tiles: OK ($verdicts)" ;;
usage)
    for args in "--quick --frames 3" "--diff a.json" "--out-dir" "--size 64x36" "--api vulkan"; do
        # shellcheck disable=SC2086
        "$oasis" check $args > /dev/null 2> err.txt
        code=$?
        [ $code -eq 2 ] || fail "check $args: exit $code, expected 2"
        grep -q "^oasis: " err.txt || fail "check $args: no message"
    done
    "$oasis" check --diff missing.json missing.json > /dev/null 2> err.txt
    [ $? -eq 2 ] || fail "--diff of missing files is not exit 2"
    echo "check usage: OK" ;;
*) fail "unknown case" ;;
esac
