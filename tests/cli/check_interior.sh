#!/bin/sh
# `oasis check`'s interior rule (cross-driver-interior, check/check_judge.h) as another driver meets
# it: the reference frames copied without the driver that drew them (their oasis:renderer chunk
# dropped), so llvmpipe's own frames are judged as another rasteriser's are, by cross-driver and
# cross-driver-interior, not by identical. Three of the quick check's cases (day, night: the sky's
# smallest shift, and a stencil view, which has no split) pass with every shaded case's interior
# measured (pixels split, max abs 0, mean 0); a copy of the shaders whose sky is 3% too bright
# (max abs 2: inside cross-driver's tolerance) fails both shaded cases by the interior rule, the
# whole frame still passing cross-driver (the shading oracle fails them too, through the fog's sky
# colour: before the rule they failed by the oracle alone), and passes the stencil view.
# usage: check_interior.sh OASIS SHADER_DIR REFERENCES WORK_DIR
set -u
oasis=$1 shaders=$2 references=$3 work=$4
fail() { echo "FAIL (check_interior): $*"; exit 1; }
rm -rf "$work" && mkdir -p "$work/references" || fail "cannot make $work"
cd "$work" || fail "cannot enter $work"

# Each reference PNG with its oasis:renderer text chunk left out (every other chunk as it was).
python3 - "$references" references << 'PYTHON' || fail "cannot copy the references"
import os, struct, sys
source, target = sys.argv[1:3]
copied = 0
for name in sorted(os.listdir(source)):
    if not name.endswith(".png"):
        continue
    data = open(os.path.join(source, name), "rb").read()
    out, at, dropped = [data[:8]], 8, 0
    while at < len(data):
        length, kind = struct.unpack(">I4s", data[at:at + 8])
        chunk = data[at:at + 12 + length]
        at += 12 + length
        if kind in (b"iTXt", b"tEXt", b"zTXt") and chunk[8:].startswith(b"oasis:renderer\0"):
            dropped += 1
            continue
        out.append(chunk)
    assert dropped == 1, (name, dropped)
    open(os.path.join(target, name), "wb").write(b"".join(out))
    copied += 1
assert copied >= 8, copied
PYTHON

cp -r "$shaders" sky3 || fail "cannot copy the shaders"
line="    return gradient * (1.0 - 0.35 * sqrt(down));"
[ "$(grep -cF "$line" sky3/common/sky.glsl)" -eq 1 ] || fail "the perturbation does not apply: no single '$line' in sky.glsl"
python3 -c "import sys; p, a, b = sys.argv[1:4]; t = open(p).read(); open(p, 'w').write(t.replace(a, b))" \
    sky3/common/sky.glsl "$line" "    return 1.03 * gradient * (1.0 - 0.35 * sqrt(down));" || fail "cannot perturb sky.glsl"

# quick SHADERS OUT EXPECTED_EXIT
quick() {
    OASIS_SHADER_DIR=$1 "$oasis" check --case '01-*' --case '24-*' --case '10-*' --retries 0 --references "$work/references" --out-dir "$2" > "$2.txt" 2> "$2.err"
    code=$?
    [ $code -eq "$3" ] || fail "$2: exit $code, expected $3: $(tail -n 12 "$2.txt" "$2.err")"
}
quick "$shaders" clean 0
quick "$work/sky3" sky3 1

python3 - clean/report.json sky3/report.json << 'PYTHON' || fail "the reports"
import json, sys
clean, sky = (json.load(open(p)) for p in sys.argv[1:3])
shaded = 0
for c in clean["cases"]:
    if c["verdict"] == "skip":
        continue
    assert c["reference_rule"] == "cross-driver", (c["name"], c["reference_rule"])
    assert c["verdict"] == "pass", (c["name"], c["reason"])
    i = c["interior"]
    if c["oracle"] is None:  # the stencil views: no shading, no split
        assert i is None, (c["name"], i)
        continue
    shaded += 1
    assert set(i) >= {"pixels", "max_abs", "over", "mean_signed"}, i
    assert 0 < i["pixels"] < 256 * 144 and i["max_abs"] == 0 and i["mean_signed"] == 0 and i["pass"], (c["name"], i)
assert shaded == 2 and len(clean["cases"]) == 3, (shaded, len(clean["cases"]))
failed = 0
for c in sky["cases"]:
    if c["verdict"] == "skip":
        continue
    i, why = c["interior"], c["reason"]
    if c["verdict"] == "fail":
        failed += 1
        # Failed by the interiors: the whole frame still passes cross-driver.
        assert "against the reference frame's interiors" in why and "against the reference frame: " not in why, why
        assert c["max_abs"] <= 6 and not i["pass"] and i["mean_signed"] > 0, (c["name"], i)
        print("%s: fails, interior %d pixels, max abs %d, mean %+.3f levels (whole frame %.1f dB, max abs %d)" %
              (c["name"], i["pixels"], i["max_abs"], i["mean_signed"], c["psnr_db"], c["max_abs"]))
    else:
        assert c["verdict"] == "pass", (c["name"], c["verdict"], why)
        print("%s: passes (%s)" % (c["name"], "interior mean %+.3f" % i["mean_signed"] if i else "no split"))
assert failed == 2, failed
PYTHON
echo "check_interior: OK"
