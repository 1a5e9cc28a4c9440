#!/usr/bin/env bash
# What the window's live comparison costs: the real window under Xvfb (tests/window/window_lib.sh),
# panel hidden (the inspector off), a fixed camera; ROUNDS rounds of DWELL seconds in each of
# deferred, forward and the four comparison modes (C), interleaved so that a change in the machine's
# load reaches every mode alike; then the median wall ms of a whole loop iteration in each (frames,
# views, split or difference image, swap, glFinish), as the window prints them when it closes, and
# each comparison mode against the two single frames it shows.
#   usage: docs/window_cost.sh OASIS [SIZE (1280x720)] [DWELL (8)] [ROUNDS (3)]
set -uo pipefail
. "$(dirname "$0")/../tests/window/window_lib.sh"
export OASIS_XVFB_SCREEN=1600x1000x24
window_test_begin window_cost "$1" "${OASIS_WINDOW_COST_DIR:-/tmp/oasis-window-cost}" "$0" "$@"
size=${2:-1280x720} dwell=${3:-8} rounds=${4:-3}
start_oasis --size "$size" --camera 435,4,140,30,-3 --hour 12
toggle_panel
for ((round = 0; round < rounds; ++round)); do
    sleep "$dwell"                   # deferred
    press Tab; sleep "$dwell"        # forward
    press Tab                        # deferred again: side A of the layout modes
    for mode in 1 2 3 4; do press c; sleep "$dwell"; done
    press c                          # off
done
finish_oasis > /dev/null
line=$(grep -m1 'window loop ms' "$OUT_LOG") || fail "no loop summary"
echo "$line"
median() { grep -oE "$1 [0-9.]+" <<<"$line" | head -n 1 | awk '{ print $NF }'; }
forward=$(median '(^|: |, )forward') deferred=$(median '(^|: |, )deferred')
echo "size $size: forward $forward ms, deferred $deferred ms, both $(awk -v f="$forward" -v d="$deferred" 'BEGIN { printf "%.2f", f + d }') ms"
for mode in 'split: forward \| deferred' 'split: layout A \| layout B \(deferred\)' 'difference: forward - deferred' \
            'difference: layout A - layout B \(deferred\)'; do
    ms=$(median "$mode")
    # The pipelines' modes show forward and deferred; the layouts' modes two deferred frames.
    if [[ $mode == *layout* ]]; then both=$(awk -v d="$deferred" 'BEGIN { print 2 * d }'); else
        both=$(awk -v f="$forward" -v d="$deferred" 'BEGIN { print f + d }'); fi
    awk -v m="$ms" -v b="$both" -v name="$mode" 'BEGIN { gsub(/\\/, "", name);
        printf "%-45s %8.2f ms = %.3f x its two frames (%.2f ms)\n", name, m, m / b, b }'
done
