#!/bin/sh
# Issue 28's catalogue, kept fixed: each case the re-probe found, run as it was found. Bad inputs
# (a directory, a device, a FIFO, a lying PNG header, a FIFO or directory among the shaders) are
# refused in time naming the file; a failed stdout is exit 1; compare --driver checks every
# set-up's arguments before it renders; the messages name the right thing.
# Issue 42's received PNGs (part pngs): judged by their header before their pixels, a size over
# the cap refused in well under a second, cut files and bad CRCs refused with a reason; and the
# check's --diff arguments (part arguments).
# usage: reliability.sh PART OASIS SHADER_DIR WORK_DIR
#   inputs | stdout | messages | pngs | arguments
set -u
part=$1 oasis=$2 shaders=$3 work=$4
fail() { echo "FAIL ($part): $*"; exit 1; }
rm -rf "$work" && mkdir -p "$work" || fail "cannot make $work"
cd "$work" || fail "cannot enter $work"
cases=0

# Runs oasis (within 60 s: a hang is a failure) and expects exit STATUS and stderr matching TEXT.
expect() {  # STATUS TEXT ARGS...
    status=$1 text=$2; shift 2
    cases=$((cases + 1))
    timeout 60 "$oasis" "$@" > out.txt 2> err.txt
    code=$?
    [ $code -eq "$status" ] || fail "oasis $*: exit $code, expected $status: $(cat err.txt)"
    [ -z "$text" ] || grep -q -- "$text" err.txt || fail "oasis $*: stderr lacks '$text': $(cat err.txt)"
}

case $part in
inputs)
    mkdir d.png
    expect 2 "cannot read d.png: it is a directory" compare --size 64x36 --reference d.png
    ln -s /dev/zero z.png
    expect 2 "cannot read z.png: it is a device" compare --size 64x36 --reference z.png
    mkfifo f.png
    expect 2 "cannot read f.png: it is a FIFO" compare --size 64x36 --reference f.png
    expect 1 "cannot write f.png: it is a FIFO (named pipe) that no process reads" render --size 64x36 --out f.png
    # A PNG whose header claims 100000x100000 pixels (its CRC right: libpng checks it), and one cut
    # after its signature.
    printf '\211PNG\r\n\032\n\000\000\000\015IHDR\000\001\206\240\000\001\206\240\010\006\000\000\000\250\122\013\310' > huge.png
    expect 2 "its header says 100000x100000 pixels" compare --size 64x36 --reference huge.png
    printf '\211PNG\r\n\032\n' > cut.png
    expect 2 "cannot read cut.png: not a readable PNG" compare --size 64x36 --reference cut.png
    # compare --driver: the gles child would refuse --force gl33; nothing may be rendered or written.
    expect 2 "set-up gles: --force gl33" compare --size 64x36 --driver llvmpipe --driver gles --force gl33 --out-dir set
    [ ! -e set ] || fail "compare --driver wrote $(ls set) before a child's arguments were checked"
    # Shaders: a FIFO and a directory where a shader file should be.
    cp -r "$shaders" fifo-shaders && rm fifo-shaders/common/sky.glsl && mkfifo fifo-shaders/common/sky.glsl
    export OASIS_SHADER_DIR="$work/fifo-shaders"
    expect 1 "common/sky.glsl: it is a FIFO" render --size 32x18 --out a.png
    cp -r "$shaders" dir-shaders && rm dir-shaders/common/sky.glsl && mkdir dir-shaders/common/sky.glsl
    export OASIS_SHADER_DIR="$work/dir-shaders"
    expect 1 "common/sky.glsl: it is a directory" render --size 32x18 --out a.png
    unset OASIS_SHADER_DIR ;;
stdout)
    for args in "probe --size 64x36 --at 3,3 --json" "probe --size 64x36 --at 3,3" "caps --json" \
                "compare --size 64x36 --frames 1 --json --out-dir c" "bench --quick --frames 1 --json --out-dir b"; do
        cases=$((cases + 1))
        # shellcheck disable=SC2086
        timeout 300 "$oasis" $args > /dev/full 2> err.txt
        code=$?
        [ $code -eq 1 ] || fail "$args > /dev/full: exit $code, expected 1"
        grep -q "^oasis: cannot write stdout: No space left on device" err.txt || fail "$args > /dev/full: $(cat err.txt)"
    done
    cases=$((cases + 1))
    timeout 60 "$oasis" caps --json >&- 2> err.txt
    code=$?
    [ $code -eq 1 ] && grep -q "^oasis: cannot write stdout" err.txt || fail "caps --json >&-: exit $code: $(cat err.txt)" ;;
messages)
    expect 0 "" render --size 32x18 --lights 0000000004 --out lights.png
    cases=$((cases + 1))
    "$oasis" probe --size 64x36 --at 32,1 --json > sky.json 2> /dev/null || fail "probe of a sky pixel failed"
    grep -q '"sky": true' sky.json && grep -q '"world": null' sky.json || fail "a sky pixel's world is not null: $(cat sky.json)"
    cases=$((cases + 1))
    "$oasis" --help | grep -q "every command, the window included" || fail "--help still limits --api gles"
    cases=$((cases + 1))
    env -u DISPLAY WAYLAND_DISPLAY=wayland-oasis-test timeout 60 "$oasis" window --size 64x36 > out.txt 2> err.txt
    code=$?
    [ $code -eq 1 ] && grep -q "WAYLAND_DISPLAY is set to 'wayland-oasis-test' but DISPLAY is not" err.txt ||
        fail "the window with only WAYLAND_DISPLAY: exit $code: $(cat err.txt)" ;;
pngs)
    # PNGs made with Python's zlib (another writer than oasis's libpng): NAME WIDTH HEIGHT [cut|crc].
    png() {
        python3 - "$@" <<'PY'
import struct, sys, zlib
name, width, height = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
spoil = sys.argv[4] if len(sys.argv) > 4 else ""
def chunk(kind, data, delta=0):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", (zlib.crc32(kind + data) + delta) & 0xFFFFFFFF)
rows = min(height, 64)  # a large picture's header only needs to be there: it is refused before its data
data = zlib.compress(b"".join(b"\0" + b"\x10\x20\x30\xff" * width for _ in range(rows)))
body = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)) +
        chunk(b"IDAT", data, 1 if spoil == "crc" else 0) + chunk(b"IEND", b""))
open(name, "wb").write(body[:len(body) // 2] if spoil == "cut" else body)
PY
    }
    # 16384x16384 (issue 42: 32 s and 2.1 GB before its provenance was refused): refused at once.
    png big.png 16384 16384
    start=$(date +%s%N)
    expect 2 "its header says 16384x16384 pixels; oasis reads at most 4096 a side unless --allow-large" \
        compare --reference big.png
    ms=$(( ($(date +%s%N) - start) / 1000000 ))
    [ $ms -lt 1000 ] || fail "compare --reference big.png took $ms ms"
    echo "pngs: a 16384x16384 reference refused in $ms ms"
    # Past the renderer's limit even with --allow-large; --allow-large without --reference is exit 2.
    png huge.png 40000 40000
    expect 2 "its header says 40000x40000 pixels; oasis reads at most 32768 a side" compare --allow-large --reference huge.png
    expect 2 "option --allow-large belongs to \`oasis compare --reference\`" compare --allow-large
    expect 2 "option --allow-large belongs to \`oasis compare --reference\`" render --allow-large
    # Cut in the middle, and a spoilt CRC of the image data: refused naming why, never "()".
    png cut.png 64 36 cut
    expect 2 "cannot read cut.png: not a readable PNG (the file ends early: it is cut)" compare --reference cut.png
    png crc.png 64 36 crc
    expect 2 "cannot read crc.png: not a readable PNG (IDAT: CRC error)" compare --reference crc.png
    for f in err.txt; do ! grep -q "()" $f || fail "an empty reason: $(cat $f)"; done ;;
arguments)
    # Issue 42, point 10: a third --diff argument is named as one too many; options of the rendering
    # check are refused with --diff, not ignored.
    printf '{}' > a.json
    expect 2 "unexpected argument 'c' (--diff takes two reports: --diff A.json B.json)" check --diff a.json a.json c
    for option in --quick "--write-references refs" "--references refs" --tables; do
        # shellcheck disable=SC2086
        expect 2 "option ${option%% *} does nothing with --diff" check --diff a.json a.json $option
    done
    [ ! -e refs ] || fail "check --diff --write-references made refs" ;;
*) fail "unknown part" ;;
esac
echo "reliability ($part): $cases cases, 0 failures"
