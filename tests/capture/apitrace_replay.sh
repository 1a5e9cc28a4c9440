#!/bin/sh
# apitrace end to end, with no special environment: a headless oasis command traced through EGL
# (`apitrace trace --api egl`) records every GL call, and eglretrace replays it headless (surfaceless
# EGL) to snapshots equal to oasis's own PNGs (max abs 0, RGBA), stepping the expected frames.
#   render:  `render --legend off` has 3 frames (set-up, shader warm-up, the frame); the snapshot at
#            the frame's glReadPixels of the view (the PNG's pixels) equals frame.png.
#   compare: forward.png and deferred.png equal the snapshots at their read-backs, and the replay
#            steps every frame the trace ended.
# Skipped (77) with the reason where apitrace, its EGL tracer, eglretrace or python3 is missing.
# Usage: apitrace_replay.sh render|compare OASIS_EXECUTABLE SCRATCH_DIR
mode=$1
oasis=$2
scratch=$3
here=$(cd "$(dirname "$0")" && pwd)
for tool in apitrace eglretrace python3; do
    command -v $tool > /dev/null || { echo "SKIP: $tool is not installed (apt-get install apitrace python3; .ci/setup does)"; exit 77; }
done
wrapper=$(dirname "$(command -v apitrace)")/../lib/x86_64-linux-gnu/apitrace/wrappers/egltrace.so
[ -f "$wrapper" ] || { echo "SKIP: apitrace's egltrace.so is missing ($wrapper; package apitrace-tracers)"; exit 77; }
rm -rf "$scratch" && mkdir -p "$scratch/snap" && cd "$scratch" || exit 1

size=320x180
case $mode in
render) set -- render --size $size --legend off --out frame.png ;;
compare) set -- compare --size $size --frames 1 --out-dir out ;;
*) echo "usage: $0 render|compare OASIS SCRATCH"; exit 2 ;;
esac
apitrace trace --api egl -o oasis.trace "$oasis" "$@" > trace.log 2>&1 || { cat trace.log; exit 1; }
apitrace dump oasis.trace > dump.txt || exit 1

# The 8-bit read-backs of the view, in order: the calls whose snapshots are oasis's PNGs.
readbacks=$(grep -E "^[0-9]+ glReadPixels\(x = 0, y = 0, width = ${size%x*}, height = ${size#*x}, format = GL_RGBA, type = GL_UNSIGNED_BYTE" dump.txt | cut -d' ' -f1)
terminators=$(grep -c 'glFrameTerminatorGREMEDY()' dump.txt)
refused=$(grep -cE '^[0-9]+ egl(CreateContext|MakeCurrent|Initialize|BindAPI)\(.*\) = (NULL|EGL_FALSE)$' dump.txt)
echo "traced: $(grep -cE '^[0-9]+ gl' dump.txt) GL calls, $terminators frames, read-backs at calls" $readbacks
echo "refused EGL calls in the trace: $refused (a replay would stop at them)"
[ "$refused" -eq 0 ] || { grep -E '^[0-9]+ egl(CreateContext|MakeCurrent|Initialize|BindAPI).* = (NULL|EGL_FALSE)$' dump.txt; exit 1; }
# GL 1.x entry points are what a trace without them lacks (libepoxy took them from the real libGL).
for call in glViewport glEnable glBindTexture glDrawArrays glReadPixels; do
    grep -qE "^[0-9]+ $call\(" dump.txt || { echo "the trace has no $call: not every GL call was recorded"; exit 1; }
done

case $mode in
render) expected_frames=3 pngs="frame.png" ;;
compare) expected_frames=$terminators pngs="out/forward.png out/deferred.png" ;;
esac
[ "$terminators" -eq "$expected_frames" ] || { echo "expected $expected_frames frame terminators"; exit 1; }
set -- $readbacks
[ $# -eq $(echo $pngs | wc -w) ] || { echo "expected one read-back per PNG ($pngs)"; exit 1; }

# Snapshots at the read-backs and at every frame end (`frame`): with only call numbers eglretrace
# stops after the last one, and the frame count is then not printed.
WAFFLE_PLATFORM=surfaceless_egl eglretrace --headless --snapshot-alpha -s snap/ -S "$(echo $readbacks | tr ' ' ,),frame" \
    oasis.trace > replay.log 2>&1 || { cat replay.log; exit 1; }
grep -E 'Rendered [0-9]+ frames' replay.log
grep -q "Rendered $expected_frames frames" replay.log || { echo "the replay did not step $expected_frames frames"; cat replay.log; exit 1; }
status=0
for png in $pngs; do
    snapshot=snap/$(printf '%010d' "$1").png
    shift
    printf '%s against the replay at call %s: ' "$png" "${snapshot#snap/}"
    python3 "$here/png_max_abs.py" "$png" "$snapshot" || status=1
done
[ $status -eq 0 ] && echo "apitrace replay: OK ($expected_frames frames traced and replayed, every PNG equal)"
exit $status
