#!/usr/bin/env bash
# The README's pictures of the window's inspector: the real window under Xvfb at 1280x720 (tests/
# window/window_lib.sh), a fixed frame across the lake; the panel with the probe under the cursor
# and two pinned probes (inspect-probe.png), then the live split forward | deferred
# (inspect-split.png) and their difference (inspect-difference.png), panel hidden.
#   usage: docs/inspect_pictures.sh OASIS   (writes into docs/)
set -uo pipefail
. "$(dirname "$0")/../tests/window/window_lib.sh"
export OASIS_XVFB_SCREEN=1600x1000x24
DOCS=$(cd "$(dirname "$0")" && pwd)
window_test_begin inspect_pictures "$1" "${OASIS_PICTURES_DIR:-/tmp/oasis-inspect-pictures}" "$0" "$@"
start_oasis --size 1280x720 --camera 435,4,140,30,-3 --hour 17 --ripples 0.5
sleep 2
# Pins at a lakeside plant and the water; then the cursor rests on the water for the live probe.
xdotool mousemove --window "$WINDOW" 760 470 click 1
sleep 1
xdotool mousemove --window "$WINDOW" 1000 420 click 1
sleep 1
xdotool mousemove --window "$WINDOW" 880 430
sleep 4
shot() {  # NAME: the window into docs/NAME.png
    xwd -silent -id "$WINDOW" -out "$WORK/$1.xwd" || fail "xwd could not capture the window"
    python3 "$WINDOW_LIB_DIR/xwd_stats.py" "$WORK/$1.xwd" --png "$DOCS/$1.png" > /dev/null || fail "no $1.png"
    step "wrote docs/$1.png"
}
shot inspect-probe
xdotool click 3 && sleep 0.5 && xdotool click 3   # unpin (right clicks unpin the nearest)
xdotool mousemove --window "$WINDOW" 5 700
press h c
sleep 6
shot inspect-split
press c c
sleep 6
shot inspect-difference
finish_oasis > /dev/null
