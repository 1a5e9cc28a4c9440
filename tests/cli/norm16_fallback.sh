#!/bin/sh
# The compact G-buffer's RG16 normal on an OpenGL ES driver without EXT_texture_norm16 (WebGL 2 on
# SwiftShader is one; here llvmpipe's ES context with the extension hidden by
# MESA_EXTENSION_OVERRIDE): the renderer itself draws the standard layout and says so.
#   render  --api gles --gbuffer compact says it fell back and why, and its final frame equals the
#           --gbuffer standard frame bit for bit; without the override compact is drawn
#   check   oasis check --api gles --quick with the extension hidden: no failure, no case skipped
#           for the layout, every compact case run on the standard layout and saying so
# usage: norm16_fallback.sh OASIS REFERENCES WORK_DIR CASE
set -u
oasis=$1 references=$2 work=$3 case=$4
fail() { echo "FAIL ($case): $*"; exit 1; }
rm -rf "$work" && mkdir -p "$work" || fail "cannot make $work"
cd "$work" || fail "cannot enter $work"
hidden() { MESA_SHADER_CACHE_DISABLE=true MESA_EXTENSION_OVERRIDE=-GL_EXT_texture_norm16 "$@"; }

case $case in
render)
    common="--api gles --size 160x90 --pipeline deferred --view final --legend off"
    # shellcheck disable=SC2086
    "$oasis" render $common --gbuffer compact --out shown.png > /dev/null 2> shown.txt || fail "render (extension shown): $(cat shown.txt)"
    grep -q '^oasis: gbuffer compact (asked for; 16-bit unorm colour-renderable (GL_EXT_texture_norm16))' shown.txt ||
        fail "compact not drawn with the extension shown: $(grep gbuffer shown.txt)"
    grep -q 'fallback: norm16' shown.txt && fail "a fallback with the extension shown: $(cat shown.txt)"
    # shellcheck disable=SC2086
    hidden "$oasis" render $common --gbuffer compact --out compact.png > /dev/null 2> compact.txt || fail "render compact: $(cat compact.txt)"
    # shellcheck disable=SC2086
    hidden "$oasis" render $common --gbuffer standard --out standard.png > /dev/null 2> standard.txt || fail "render standard: $(cat standard.txt)"
    why='standard (compact was asked for but its 16-bit unorm target is not colour-renderable: no GL_EXT_texture_norm16 on this OpenGL ES driver)'
    grep -qF "oasis: fallback: norm16-targets: gbuffer $why" compact.txt || fail "no fallback line: $(cat compact.txt)"
    grep -qF "oasis: gbuffer $why" compact.txt || fail "no gbuffer line: $(cat compact.txt)"
    grep -q 'fallback: norm16' standard.txt && fail "--gbuffer standard reports a layout fallback: $(cat standard.txt)"
    python3 - compact.png standard.png << 'EOF' || fail "the fallback's frame is not the standard frame"
import sys, zlib, struct
def pixels(path):
    data = open(path, 'rb').read()
    chunks, pos = [], 8
    while pos < len(data):
        length, kind = struct.unpack('>I4s', data[pos:pos + 8])
        chunks.append((kind, data[pos + 8:pos + 8 + length]))
        pos += 12 + length
    header = next(body for kind, body in chunks if kind == b'IHDR')
    return header, zlib.decompress(b''.join(body for kind, body in chunks if kind == b'IDAT'))
a, b = pixels(sys.argv[1]), pixels(sys.argv[2])
assert a[0] == b[0], 'sizes differ'
assert a[1] == b[1], 'pixels differ'
EOF
    echo "norm16 render: OK (compact falls back to standard, the same pixels)" ;;
check)
    hidden "$oasis" check --api gles --quick --references "$references" --out-dir out > out.txt 2> err.txt
    code=$?
    [ $code -eq 0 ] || fail "exit $code: $(tail -n 20 out.txt err.txt)"
    python3 - out/report.json << 'EOF' || fail "report.json"
import json, sys
report = json.load(open(sys.argv[1]))
summary, cases = report["summary"], report["cases"]
assert summary["fail"] == 0, summary
compact = [c for c in cases if "-compact-" in c["name"]]
assert compact, "no compact case in --quick"
for c in cases:
    assert "drawable" not in c["reason"] and "norm16" not in c["reason"] or c["verdict"] != "skip", (c["name"], c["reason"])
ran = 0
for c in compact:
    if c["verdict"] == "skip":
        continue  # a path this ES context lacks (the gl33 tier), not the layout
    ran += 1
    assert c["verdict"] == "pass", (c["name"], c["reason"])
    assert "drawn with gbuffer standard (compact was asked for" in c["reason"], (c["name"], c["reason"])
    print("%s: %s; PSNR %s dB, max abs %s against its reference" % (c["name"], c["verdict"], c["psnr_db"], c["max_abs"]))
assert ran > 0, "every compact case skipped"
row = [r for r in report["caps"] if r["feature"] == "norm16-targets"]
assert row and not row[0]["available"] and row[0]["limited_by"] == "driver", row
print("check: %s; %d compact cases ran on the standard layout" % (summary, ran))
EOF
    echo "norm16 check: OK" ;;
*) fail "unknown case" ;;
esac
