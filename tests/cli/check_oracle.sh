#!/bin/sh
# `oasis check`'s shading oracle (check/shading_oracle.h) against perturbed copies of the shaders,
# one check case each: the sun's N.L 1 % too large (common/lighting.glsl) fails the day case's
# oracle naming specular_lobe (whose first value is max(N.L, 0)); the point lights' falloff window
# squared no more (common/lights.glsl) fails the night case's oracle naming a light ("light N");
# the unperturbed shaders pass both with pixels checked.
# usage: check_oracle.sh OASIS SHADER_DIR REFERENCES WORK_DIR
set -u
oasis=$1 shaders=$2 references=$3 work=$4
fail() { echo "FAIL (check_oracle): $*"; exit 1; }
rm -rf "$work" && mkdir -p "$work" || fail "cannot make $work"
cd "$work" || fail "cannot enter $work"

# perturb NAME FILE FROM TO: a copy of the shaders with FROM replaced by TO once in FILE.
perturb() {
    cp -r "$shaders" "$1" || fail "cannot copy the shaders"
    [ "$(grep -cF "$3" "$1/common/$2")" -eq 1 ] || fail "the perturbation $1 does not apply: no single '$3' in $2"
    python3 -c "import sys; p, a, b = sys.argv[1:4]; t = open(p).read(); open(p, 'w').write(t.replace(a, b))" \
        "$1/common/$2" "$3" "$4" || fail "cannot perturb $2"
}
perturb sun-ndotl lighting.glsl "float diffuse = max(dot(n, toSun), 0.0);" "float diffuse = max(dot(n, toSun), 0.0) * 1.01;"
perturb light-falloff lights.glsl "return window * window / (distanceToLight * distanceToLight + 1.0);" \
    "return window / (distanceToLight * distanceToLight + 1.0);"

# oracle CASE SHADERS OUT VERDICT [TERM]: the case's oracle verdict and, failing, the term it names.
oracle() {
    OASIS_SHADER_DIR=$2 "$oasis" check --case "$1" --references "$references" --out-dir "$3" > "$3.txt" 2> "$3.err"
    python3 - "$3/report.json" "$4" "${5:-}" << 'EOF' || fail "$3: $(tail -n 5 "$3.txt" "$3.err")"
import json, re, sys
report, verdict, term = json.load(open(sys.argv[1])), sys.argv[2], sys.argv[3]
[case] = report["cases"]
o = case["oracle"]
assert o is not None, case["name"]
for key in ("pixels_checked", "left_out", "max_relative_error", "bound", "verdict"):
    assert key in o, key
assert o["pixels_checked"] >= 50, o
assert o["verdict"] == verdict, o
if verdict == "fail":
    assert re.fullmatch(term, o["differing_term"]), (term, o)
    assert case["verdict"] == "fail" and "shading oracle: " + o["differing_term"] in case["reason"], case
    print("%s: fails naming %s (max %.3g relative, bound %.3g): %s" % (case["name"], o["differing_term"],
          o["max_relative_error"], o["bound"], o["detail"]))
else:
    assert o["max_relative_error"] <= o["bound"], o
    print("%s: passes, %d pixels checked, max %.3g relative, left out %s" % (case["name"], o["pixels_checked"],
          o["max_relative_error"], o["left_out"]))
EOF
}
oracle '01-*' "$shaders" clean-day pass
oracle '01-*' "$work/sun-ndotl" sun-ndotl fail specular_lobe
oracle '24-*' "$shaders" clean-night pass
oracle '24-*' "$work/light-falloff" light-falloff fail 'light [0-9]+'
echo "check_oracle: OK"
