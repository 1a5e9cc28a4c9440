#!/bin/sh
# `oasis caps` says for each feature whether the driver has it (available), whether oasis uses it,
# and who limits it when not (driver, forced tier or not asked for), as text and JSON (issue 29):
#   - caps --json, plain and under --api gles --force gles30: every feature has "used", "reason",
#     "available" and "limited_by" (null exactly when used), the values the report allows;
#   - under --api gles --force gles30 on a driver with GL_EXT_clip_control, GL_EXT_clip_cull_distance
#     and GL_EXT_depth_clamp (llvmpipe's ES 3.2), clip-control, clip-distances and depth-clamp are
#     available, not used, limited by the forced tier, the reason naming the tier and what the driver
#     has, in both the JSON and the text table; without them the driver is the limit;
#   - the text table has its header, and no row says "NOT used" or "not used" (the used column does).
# Usage: caps_columns.sh OASIS_EXECUTABLE
oasis=$1
fail() { echo "FAIL: $*"; exit 1; }

check_json() {  # check_json LABEL JSON: every feature carries the four keys, consistent
    echo "$2" | python3 -c '
import json, sys
caps, label = json.load(sys.stdin), sys.argv[1]
allowed = {None, "driver", "forced tier", "not asked for"}
for name, f in caps["features"].items():
    for key in ("used", "reason", "available", "limited_by"):
        assert key in f, "%s: %s has no %s: %s" % (label, name, key, f)
    assert list(f)[:2] == ["used", "reason"], "%s: %s: used and reason first, as before: %s" % (label, name, f)
    assert f["limited_by"] in allowed, "%s: %s: limited_by %r" % (label, name, f["limited_by"])
    assert (f["limited_by"] is None) == f["used"], "%s: %s: limited_by null exactly when used: %s" % (label, name, f)
    assert f["available"] or f["limited_by"] == "driver" or f["used"], "%s: %s: %s" % (label, name, f)
print("%s: %d features, each with available, used, limited_by" % (label, len(caps["features"])))' "$1" ||
        fail "$1: $2"
}

plain=$("$oasis" caps --json 2> /dev/null) || fail "caps --json failed"
check_json "caps --json" "$plain"
es30=$("$oasis" caps --api gles --force gles30 --json 2> /dev/null) || fail "caps --api gles --force gles30 --json failed"
check_json "caps --api gles --force gles30 --json" "$es30"
es32=$("$oasis" caps --api gles --json 2> /dev/null) || fail "caps --api gles --json failed"

# The same three features on the unforced ES context: does this driver have the extensions?
for feature in clip-control clip-distances depth-clamp; do
    driver_has=$(echo "$es32" | python3 -c 'import json,sys; print(json.load(sys.stdin)["features"][sys.argv[1]]["available"])' "$feature")
    got=$(echo "$es30" | python3 -c '
import json, sys
f = json.load(sys.stdin)["features"][sys.argv[1]]
print("%s|%s|%s|%s" % (f["available"], f["used"], f["limited_by"], f["reason"]))' "$feature")
    if [ "$driver_has" = True ]; then
        case $got in
        "True|False|forced tier|"*"in the forced ES 3.0 tier (--force gles30; the driver has "*) ;;
        *) fail "$feature under --force gles30 on a driver that has it: $got" ;;
        esac
    else
        case $got in
        "False|False|driver|"*) ;;
        *) fail "$feature under --force gles30 on a driver without it: $got" ;;
        esac
    fi
    echo "$feature, --force gles30 (driver has it: $driver_has): $got"
done

text=$("$oasis" caps --api gles --force gles30 2> /dev/null) || fail "caps --api gles --force gles30 failed"
echo "$text" | sed -n '/^features/,$p'
echo "$text" | grep -qE '^  feature +available +used +limited by +reason$' || fail "no column header"
echo "$text" | sed -n '/^  feature /,$p' | grep -qE 'NOT used|not used' &&
    fail "a feature row still says 'NOT used' or 'not used' (the used column says it)"
if echo "$es32" | grep -q '"clip-control": {[^}]*"available": true'; then
    echo "$text" | grep -qE '^  clip-control +yes +no +forced tier +.*no GL_EXT_clip_control in the forced ES 3.0 tier' ||
        fail "the clip-control row does not say available yes, used no, limited by forced tier"
fi
echo "PASS: caps columns"
