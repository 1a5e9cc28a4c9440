#!/bin/sh
# apitrace end to end: a headless `oasis render` traced through EGL (the environment docs/captures.md
# gives for libepoxy) has its frames (set-up, shader warm-up, the frame), and eglretrace replays
# them headless (surfaceless EGL), stepping 3 frames. Skipped (77) without apitrace.
# Usage: apitrace_replay.sh OASIS_EXECUTABLE SCRATCH_DIR
oasis=$1
scratch=$2
for tool in apitrace eglretrace; do
    command -v $tool > /dev/null || { echo "SKIP: $tool is not installed (apt-get install apitrace; .ci/setup does)"; exit 77; }
done
wrapper=$(dirname "$(command -v apitrace)")/../lib/x86_64-linux-gnu/apitrace/wrappers/egltrace.so
[ -f "$wrapper" ] || { echo "SKIP: apitrace's egltrace.so is missing ($wrapper; package apitrace-tracers)"; exit 77; }
rm -rf "$scratch" && mkdir -p "$scratch/shim" "$scratch/snap" && cd "$scratch" || exit 1

# libepoxy resolves glXGetCurrentContext in libGL.so.1, which apitrace's EGL wrapper redirects to
# itself (no GLX there: abort). Loading the wrapper as libEGL.so.1 instead, with TRACE_LIBGL empty,
# keeps libGL.so.1 the real one (docs/captures.md).
ln -s "$wrapper" shim/libEGL.so.1
TRACE_LIBGL= LD_LIBRARY_PATH="$scratch/shim" apitrace trace --api egl -o render.trace \
    "$oasis" render --size 160x90 --legend off --out frame.png > trace.log 2>&1 || { cat trace.log; exit 1; }
terminators=$(apitrace dump render.trace | grep -c 'glFrameTerminatorGREMEDY()')
echo "frame terminators: $terminators (expected 3: set-up, shader warm-up, the frame)"
[ "$terminators" -eq 3 ] || exit 1

# The context versions the driver refused are in the trace too; replaying them would fail.
refused=$(apitrace dump render.trace | grep -E '^[0-9]+ eglCreateContext\(.*\) = NULL' | cut -d' ' -f1 | paste -sd, -)
WAFFLE_PLATFORM=surfaceless_egl eglretrace --headless ${refused:+--ignore-calls=$refused} render.trace \
    > replay.log 2>&1 || { cat replay.log; exit 1; }
grep -E 'Rendered [0-9]+ frames' replay.log
grep -q 'Rendered 3 frames' replay.log || { echo "the replay did not step 3 frames"; cat replay.log; exit 1; }
# Not checked here (docs/captures.md, "What does not work yet"): the replayed image. In this
# environment libepoxy resolves the GL 1.x entry points (glViewport, glClear, glReadPixels) from
# the real libGL.so.1, so the tracer never sees them and the replay cannot redraw the frame.
echo "apitrace replay: OK (3 frames traced and replayed)"
