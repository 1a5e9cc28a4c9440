#!/bin/sh
# compare --driver / --reference end to end (commands/driver_compare.h), one case per ctest test:
#   same       llvmpipe against llvmpipe: max abs 0, both frames and difference.png written
#   forced     llvmpipe against no-ssbo (--force no-ssbo, bit-identical by design): max abs 0
#   native     this machine's default driver (no renderer check) against llvmpipe at 64x36: where the
#              default is llvmpipe (this project's machines), identical; and native against a frame
#              it rendered, as --reference: identical
#   zink       llvmpipe against zink over lavapipe: a finite PSNR of at least $ZINK_MIN_PSNR dB
#              (exit 77 = skipped, saying why, when zink is not on this machine)
#   reference  a frame `render` wrote, as --reference: identical (the size taken from the file)
#   altered    a frame of another hour, its provenance stripped (else compare would render its hour:
#              tests/cli/provenance.sh), as --reference: PSNR under 30 dB, difference.png with its legend
#   timeout    a child that really hangs (stopped with SIGSTOP as soon as it runs: it cannot even act
#              on the SIGTERM that comes first) is killed at --driver-timeout: exit 1 naming the
#              set-up and the limit, no process of it and nothing it staged left; and a limit far
#              below a render's time stops the first child at once
# Usage: driver_compare.sh OASIS_EXECUTABLE SCRATCH_DIR CASE
oasis=$1
scratch=$2
case=$3
size=160x90
ZINK_MIN_PSNR=30
rm -rf "$scratch" && mkdir -p "$scratch" || exit 1

fail() { echo "FAIL: $*"; exit 1; }
# field NAME: a top-level number or boolean of the JSON in $scratch/out.json
field() { python3 -c "import json,sys; print(json.load(open(sys.argv[1]))[sys.argv[2]])" "$scratch/out.json" "$1"; }
# png_size FILE: "WxH" from the PNG header
png_size() { python3 -c "import struct,sys; d=open(sys.argv[1],'rb').read(24); assert d[:8]==b'\x89PNG\r\n\x1a\n'; print('%dx%d' % struct.unpack('>II', d[16:24]))" "$1"; }
compare() {
    "$oasis" compare --json --out-dir "$scratch/out" "$@" > "$scratch/out.json" 2> "$scratch/stderr"
}
expect_identical() {
    [ "$(field max_abs)" = 0 ] || fail "max abs $(field max_abs), expected 0: $(cat "$scratch/out.json")"
    [ "$(field identical)" = True ] || fail "not reported identical: $(cat "$scratch/out.json")"
}
expect_difference_png() {
    [ -f "$scratch/out/difference.png" ] || fail "no difference.png"
    got=$(png_size "$scratch/out/difference.png") || fail "difference.png is not a PNG"
    # The heat map is the frame's size; the legend strip adds rows under it.
    width=${got%x*}
    height=${got#*x}
    [ "$width" = 160 ] && [ "$height" -gt 90 ] || fail "difference.png is $got, expected 160 wide with a legend under 90 rows"
}

case $case in
same)
    compare --driver llvmpipe --driver llvmpipe --size $size || fail "exit $?: $(cat "$scratch/stderr")"
    expect_identical
    for image in llvmpipe.png llvmpipe-2.png; do
        [ "$(png_size "$scratch/out/$image")" = $size ] || fail "$image is not a $size PNG (the frame alone, no legend)"
    done
    expect_difference_png ;;
forced)
    compare --driver llvmpipe --driver no-ssbo --size $size || fail "exit $?: $(cat "$scratch/stderr")"
    expect_identical ;;
native)
    compare --driver native --driver llvmpipe --size 64x36 || fail "exit $?: $(cat "$scratch/stderr")"
    renderer=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['a']['renderer'])" "$scratch/out.json")
    case $renderer in
    llvmpipe*) expect_identical ;;
    *) echo "native is $renderer here, not llvmpipe: max abs $(field max_abs), PSNR $(field psnr_db) dB" ;;
    esac
    echo "native ($renderer) against llvmpipe at 64x36: max abs $(field max_abs)"
    "$oasis" render --size 64x36 --legend off --out "$scratch/native-ref.png" > /dev/null 2>&1 || fail "render failed"
    compare --driver native --reference "$scratch/native-ref.png" || fail "--reference: exit $?: $(cat "$scratch/stderr")"
    expect_identical ;;
zink)
    compare --driver llvmpipe --driver zink --size $size
    code=$?
    if [ $code -ne 0 ] && grep -q "is not available here" "$scratch/stderr"; then
        echo "SKIPPED: $(head -n 1 "$scratch/stderr")"
        exit 77
    fi
    [ $code -eq 0 ] || fail "exit $code: $(cat "$scratch/stderr")"
    psnr=$(field psnr_db)
    python3 -c "import math,sys; p=float(sys.argv[1]); sys.exit(0 if math.isfinite(p) and p >= float(sys.argv[2]) else 1)" \
        "$psnr" $ZINK_MIN_PSNR || fail "zink against llvmpipe: PSNR $psnr dB, expected finite and >= $ZINK_MIN_PSNR"
    echo "zink against llvmpipe at $size: PSNR $psnr dB, max abs $(field max_abs)"
    expect_difference_png ;;
reference)
    "$oasis" render --size $size --legend off --out "$scratch/ref.png" > /dev/null || fail "render failed"
    compare --reference "$scratch/ref.png" || fail "exit $?: $(cat "$scratch/stderr")"
    expect_identical ;;
altered)
    "$oasis" render --size $size --hour 18 --legend off --out "$scratch/sent.png" > /dev/null || fail "render failed"
    # Every chunk but the text chunks, so the reference has no oasis:options to render with.
    python3 -c "
import struct, sys
data, out, at = open(sys.argv[1], 'rb').read(), [], 8
while at < len(data):
    length, kind = struct.unpack('>I4s', data[at:at + 8])
    if kind not in (b'iTXt', b'tEXt', b'zTXt'): out.append(data[at:at + 12 + length])
    at += 12 + length
open(sys.argv[2], 'wb').write(data[:8] + b''.join(out))" "$scratch/sent.png" "$scratch/ref.png" || fail "cannot strip"
    compare --driver llvmpipe --reference "$scratch/ref.png" || fail "exit $?: $(cat "$scratch/stderr")"
    grep -q "has no oasis provenance" "$scratch/stderr" || fail "no warning for a reference without provenance"
    psnr=$(field psnr_db)
    python3 -c "import sys; sys.exit(0 if float(sys.argv[1]) < 30 else 1)" "$psnr" ||
        fail "a frame at 18:00 against 10:00: PSNR $psnr dB, expected under 30"
    [ "$(field max_abs)" -gt 0 ] || fail "max abs 0 against a different frame"
    expect_difference_png ;;
timeout)
    mkdir -p "$scratch/out" "$scratch/tmp" || fail "cannot make the directories"
    export TMPDIR="$scratch/tmp"  # where compare stages the children's frames
    start=$(date +%s)
    compare --driver llvmpipe --driver no-ssbo --size 32x18 --driver-timeout 15 &
    comparing=$!
    child=
    for _ in $(seq 200); do
        child=$(pgrep -f "render .*--out $scratch/tmp/.*llvmpipe.png" | head -n 1)
        [ -n "$child" ] && break
        sleep 0.05
    done
    [ -n "$child" ] || fail "the child render never appeared"
    kill -STOP "$child"
    wait $comparing
    code=$?
    elapsed=$(($(date +%s) - start))
    hung=$elapsed
    [ $code -eq 1 ] || fail "a hung child: exit $code, expected 1: $(cat "$scratch/stderr")"
    grep -q "^oasis: set-up llvmpipe: \`oasis render\` did not finish within --driver-timeout 15 s" "$scratch/stderr" ||
        fail "the message does not name the set-up and the limit: $(cat "$scratch/stderr")"
    [ $elapsed -ge 15 ] && [ $elapsed -le 45 ] || fail "killed after $elapsed s, expected the 15 s limit"
    [ -s "$scratch/out.json" ] && fail "a killed compare printed a result: $(cat "$scratch/out.json")"
    sleep 1
    kill -0 "$child" 2> /dev/null && fail "the hung child is still running"
    left=$(find "$scratch/tmp" "$scratch/out" -mindepth 1)
    [ -z "$left" ] || fail "left behind: $left"
    start=$(date +%s)
    compare --driver gles --driver llvmpipe --size 160x90 --driver-timeout 0.1
    code=$?
    elapsed=$(($(date +%s) - start))
    [ $code -eq 1 ] || fail "a 0.1 s limit: exit $code, expected 1: $(cat "$scratch/stderr")"
    grep -q "^oasis: set-up gles: .* within --driver-timeout 0.1 s: its process group was killed" "$scratch/stderr" ||
        fail "a 0.1 s limit: $(cat "$scratch/stderr")"
    [ $elapsed -le 5 ] || fail "a 0.1 s limit took $elapsed s"
    [ -e "$scratch/out/gles.png" ] && fail "a killed child left its frame"
    sleep 1
    pgrep -f "$scratch/tmp/.*gles.png" > /dev/null && fail "the killed child is still running"
    [ -z "$(ls -A "$scratch/tmp")" ] || fail "left behind: $(ls -A "$scratch/tmp")"
    echo "timeout: a hung child killed after $hung s at its 15 s limit; a 0.1 s limit killed the first child in $elapsed s" ;;
*) fail "unknown case '$case'" ;;
esac
echo "PASS: $case"
