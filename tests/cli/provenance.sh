#!/bin/sh
# Provenance in every PNG oasis writes, and compare --reference reading it (commands/provenance.h),
# end to end; one case per ctest test (cli.provenance_CASE):
#   writers    render (a frame, a view with its legend), compare's three, the main job's four and
#              compare --driver's set each carry the keys, with the view, pipeline, legend and options
#   reproduce  `render --hour 18 --legend off` as --reference alone is rendered again identically
#              (max abs 0, the reference's options in the JSON); a forward frame is rendered forward
#   refuse     exit 2, naming what differs, and nothing written: --hour 10 against an 18:00
#              reference, --pipeline forward against a deferred one, a view with its legend strip, a
#              final view with its legend, options this oasis does not know
#   stripped   the same PNG without its text chunks: compared as before, with one warning line
# Usage: provenance.sh OASIS_EXECUTABLE SCRATCH_DIR CASE
oasis=$1
scratch=$2
case=$3
size=160x90
rm -rf "$scratch" && mkdir -p "$scratch" || exit 1

fail() { echo "FAIL: $*"; exit 1; }
# png_text FILE KEY: the value of the PNG's text chunk KEY (exit 1 when absent)
png_text() {
    python3 - "$1" "$2" << 'EOF'
import struct, sys
data = open(sys.argv[1], 'rb').read()
at = 8
while at + 12 <= len(data):
    length, kind = struct.unpack('>I4s', data[at:at + 8])
    body = data[at + 8:at + 8 + length]
    if kind == b'iTXt':
        keyword, _, rest = body.partition(b'\0')
        if keyword.decode('latin-1') == sys.argv[2]:
            # compression flag and method, language tag, translated keyword, then the text
            rest = rest[2:]
            rest = rest.split(b'\0', 2)[2]
            print(rest.decode('utf-8'))
            sys.exit(0)
    at += 12 + length
sys.exit(1)
EOF
}
# rewrite_png IN OUT [KEY VALUE]: IN without its text chunks, or with KEY's text replaced by VALUE
# (the CRC computed again), written to OUT
rewrite_png() {
    python3 - "$@" << 'EOF'
import struct, sys, zlib
data = open(sys.argv[1], 'rb').read()
key = sys.argv[3].encode() if len(sys.argv) > 3 else None
out, at = [data[:8]], 8
while at < len(data):
    length, kind = struct.unpack('>I4s', data[at:at + 8])
    chunk = data[at:at + 12 + length]
    if kind in (b'iTXt', b'tEXt', b'zTXt'):
        if key is None:
            chunk = b''
        elif data[at + 8:at + 8 + length].split(b'\0', 1)[0] == key:
            body = key + b'\0\0\0\0\0' + sys.argv[4].encode()
            chunk = struct.pack('>I', len(body)) + b'iTXt' + body + struct.pack('>I', zlib.crc32(b'iTXt' + body))
    out.append(chunk)
    at += 12 + length
open(sys.argv[2], 'wb').write(b''.join(out))
EOF
}
# expect_keys FILE VIEW PIPELINE LEGEND: every key present, these three as given, options with --size
expect_keys() {
    for key in oasis:version oasis:options oasis:driver-options oasis:view oasis:view-options oasis:pipeline \
               oasis:legend oasis:renderer oasis:gl-version oasis:command; do
        png_text "$1" $key > /dev/null || fail "$1 has no $key"
    done
    [ "$(png_text "$1" oasis:view)" = "$2" ] || fail "$1: oasis:view is '$(png_text "$1" oasis:view)', expected '$2'"
    [ "$(png_text "$1" oasis:pipeline)" = "$3" ] || fail "$1: oasis:pipeline is '$(png_text "$1" oasis:pipeline)', expected '$3'"
    [ "$(png_text "$1" oasis:legend)" = "$4" ] || fail "$1: oasis:legend is '$(png_text "$1" oasis:legend)', expected '$4'"
    png_text "$1" oasis:options | grep -q -- '^--size [0-9]*x[0-9]*' || fail "$1: oasis:options '$(png_text "$1" oasis:options)'"
    png_text "$1" oasis:version | grep -q '^[0-9.]* (' || fail "$1: oasis:version '$(png_text "$1" oasis:version)'"
    [ -n "$(png_text "$1" oasis:renderer)" ] || fail "$1: an empty oasis:renderer"
    png_text "$1" oasis:command | grep -q '^oasis ' || fail "$1: oasis:command '$(png_text "$1" oasis:command)'"
}
# field NAME: a top-level value of the JSON in $scratch/out.json
field() { python3 -c "import json,sys; print(json.load(open(sys.argv[1]))[sys.argv[2]])" "$scratch/out.json" "$1"; }
compare() {
    "$oasis" compare --json --out-dir "$scratch/out" "$@" > "$scratch/out.json" 2> "$scratch/stderr"
}
render() { "$oasis" render --size $size "$@" > /dev/null 2>&1 || fail "render $* failed"; }
# refused WORDS ARGUMENTS: compare exits 2 saying WORDS (a grep pattern) and writes nothing
refused() {
    words=$1
    shift
    rm -rf "$scratch/out"
    compare "$@"
    code=$?
    [ $code -eq 2 ] || fail "compare $*: exit $code, expected 2: $(cat "$scratch/stderr")"
    grep -q -- "$words" "$scratch/stderr" || fail "compare $*: does not say '$words': $(cat "$scratch/stderr")"
    [ -e "$scratch/out" ] && fail "compare $*: refused, yet it made its output directory"
    return 0
}

case $case in
writers)
    render --hour 18 --legend off --out "$scratch/frame.png"
    expect_keys "$scratch/frame.png" final deferred off
    [ "$(png_text "$scratch/frame.png" oasis:options)" = "--size $size --hour 18" ] ||
        fail "render's oasis:options: '$(png_text "$scratch/frame.png" oasis:options)'"
    [ "$(png_text "$scratch/frame.png" oasis:command)" = "oasis render --size $size --hour 18 --legend off --out $scratch/frame.png" ] ||
        fail "render's oasis:command: '$(png_text "$scratch/frame.png" oasis:command)'"
    render --view depth --range 0,1 --pipeline forward --api gles --out "$scratch/depth.png"
    expect_keys "$scratch/depth.png" depth forward "on, frame height 90"
    [ "$(png_text "$scratch/depth.png" oasis:view-options)" = "--range 0,1" ] || fail "oasis:view-options of --range 0,1"
    [ "$(png_text "$scratch/depth.png" oasis:driver-options)" = "--api gles" ] || fail "oasis:driver-options of --api gles"
    "$oasis" compare --size $size --frames 1 --out-dir "$scratch/compare" > /dev/null 2>&1 || fail "compare failed"
    expect_keys "$scratch/compare/forward.png" final forward off
    expect_keys "$scratch/compare/deferred.png" final deferred off
    expect_keys "$scratch/compare/difference.png" difference "forward and deferred" "on, frame height 90"
    env -u DISPLAY -u WAYLAND_DISPLAY "$oasis" --size 320x180 --frames 1 --out-dir "$scratch/main" > /dev/null 2>&1 ||
        fail "the main job failed"
    for image in forward deferred difference overview; do [ -f "$scratch/main/$image.png" ] || fail "no main/$image.png"; done
    expect_keys "$scratch/main/overview.png" overview deferred off
    expect_keys "$scratch/main/difference.png" difference "forward and deferred" "on, frame height 180"
    "$oasis" compare --driver llvmpipe --driver no-ssbo --size $size --out-dir "$scratch/drivers" > /dev/null 2>&1 ||
        fail "compare --driver failed"
    expect_keys "$scratch/drivers/llvmpipe.png" final deferred off
    expect_keys "$scratch/drivers/no-ssbo.png" final deferred off
    [ "$(png_text "$scratch/drivers/no-ssbo.png" oasis:driver-options)" = "--force no-ssbo" ] ||
        fail "the no-ssbo child's oasis:driver-options: '$(png_text "$scratch/drivers/no-ssbo.png" oasis:driver-options)'"
    expect_keys "$scratch/drivers/difference.png" difference deferred "on, frame height 90"
    # A frame narrower than a legend has none, and says so.
    "$oasis" compare --size 64x36 --frames 1 --out-dir "$scratch/narrow" > /dev/null 2>&1 || fail "compare 64x36 failed"
    expect_keys "$scratch/narrow/difference.png" difference "forward and deferred" off ;;
reproduce)
    render --hour 18 --legend off --out "$scratch/r.png"
    compare --reference "$scratch/r.png" || fail "exit $?: $(cat "$scratch/stderr")"
    [ "$(field max_abs)" = 0 ] || fail "the reference's own options: max abs $(field max_abs): $(cat "$scratch/out.json")"
    [ "$(field options)" = "--size $size --hour 18" ] || fail "options $(field options)"
    grep -q "rendering with its options: --size $size --hour 18 --pipeline deferred" "$scratch/stderr" ||
        fail "no note of the options taken: $(cat "$scratch/stderr")"
    [ "$(png_text "$scratch/out/here.png" oasis:options)" = "--size $size --hour 18" ] || fail "here.png's oasis:options"
    # --size alone (the reference's) still takes its options; the same options given again are
    # accepted; a forward frame is rendered forward.
    compare --reference "$scratch/r.png" --size $size || fail "--size given: exit $?: $(cat "$scratch/stderr")"
    [ "$(field max_abs)" = 0 ] || fail "--size given: max abs $(field max_abs)"
    compare --reference "$scratch/r.png" --hour 18 || fail "--hour 18 given: exit $?: $(cat "$scratch/stderr")"
    [ "$(field max_abs)" = 0 ] || fail "--hour 18 given: max abs $(field max_abs)"
    render --pipeline forward --camera 420,6,160,40,-4 --lights 16 --legend off --out "$scratch/forward.png"
    compare --reference "$scratch/forward.png" || fail "exit $?: $(cat "$scratch/stderr")"
    [ "$(field pipeline)" = forward ] || fail "a forward reference compared in the $(field pipeline) pipeline"
    [ "$(field max_abs)" = 0 ] || fail "a forward reference: max abs $(field max_abs)" ;;
refuse)
    render --hour 18 --legend off --out "$scratch/r.png"
    refused "^  --hour: 18 there, 10 here" --reference "$scratch/r.png" --hour 10
    refused "^  --hour: 18 there, the default here" --reference "$scratch/r.png" --ripples 1
    refused "^  --pipeline: deferred there, forward here" --reference "$scratch/r.png" --pipeline forward
    refused "leave the scene options out to render with the reference's: --size $size --hour 18 --pipeline deferred" \
        --reference "$scratch/r.png" --hour 10
    render --view depth --out "$scratch/depth.png"
    refused "is --view depth with a legend strip under the frame" --reference "$scratch/depth.png"
    render --legend on --out "$scratch/legend.png"
    refused "is --view final with a legend strip under the frame" --reference "$scratch/legend.png"
    render --view normal --legend off --out "$scratch/normal.png"
    refused "is --view normal without a legend strip" --reference "$scratch/normal.png"
    rewrite_png "$scratch/r.png" "$scratch/future.png" oasis:options "--size $size --fog thick"
    refused "hold '--fog', not a scene option of this oasis" --reference "$scratch/future.png"
    rewrite_png "$scratch/r.png" "$scratch/out-option.png" oasis:options "--size $size --out /tmp/x.png"
    refused "hold '--out', not a scene option" --reference "$scratch/out-option.png"
    rewrite_png "$scratch/r.png" "$scratch/liar.png" oasis:options "--size 320x180"
    refused "is 160x90 but its oasis:options say --size 320x180" --reference "$scratch/liar.png" ;;
stripped)
    render --hour 18 --legend off --out "$scratch/r.png"
    rewrite_png "$scratch/r.png" "$scratch/bare.png"
    png_text "$scratch/bare.png" oasis:options > /dev/null && fail "the stripped PNG still has oasis:options"
    compare --reference "$scratch/bare.png" --hour 18 || fail "exit $?: $(cat "$scratch/stderr")"
    [ "$(field max_abs)" = 0 ] || fail "a stripped reference with its options given: max abs $(field max_abs)"
    [ "$(grep -c "has no oasis provenance" "$scratch/stderr")" = 1 ] || fail "not one warning: $(cat "$scratch/stderr")"
    grep -q "^oasis: --reference $scratch/bare.png has no oasis provenance: no oasis text chunks" "$scratch/stderr" ||
        fail "the warning: $(cat "$scratch/stderr")"
    # As before provenance: another hour is compared, not refused.
    compare --reference "$scratch/bare.png" || fail "exit $?: $(cat "$scratch/stderr")"
    [ "$(field max_abs)" -gt 0 ] || fail "a stripped 18:00 reference against 10:00: max abs 0" ;;
*) fail "unknown case '$case'" ;;
esac
echo "PASS: $case"
