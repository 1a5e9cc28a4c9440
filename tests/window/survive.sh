#!/usr/bin/env bash
# The window survives what a desktop does to it, driven by real X events under Xvfb + twm:
# resizes (down to 1x1, and a 0x0 request), minimise and restore (no drawing while minimised: it
# uses almost no CPU then), and 1,000 pipeline switches with Tab; no GL error, exit 0 on Esc,
# and a frame that is a picture at the end.
#   usage: survive.sh OASIS WORK_DIR
set -uo pipefail
. "$(dirname "$0")/window_lib.sh"
window_test_begin window.survive "$1" "$2" "$0" "$@"

start_oasis --size 160x90
step "window $WINDOW up"

for size in "1 1" "0 0" "640 360" "33 17" "2 1" "320 180"; do
    xdotool windowsize "$WINDOW" $size
    sleep 0.4
    assert_alive "after resizing to $size"
done
step "resized 6 times, alive"

for round in 1 2 3; do
    from=$(mark "$OUT_LOG")
    xdotool windowminimize "$WINDOW"
    wait_for "$OUT_LOG" "$from" 'oasis: window minimised: drawing paused' 10
    before=$(cpu_seconds)
    sleep 1
    after=$(cpu_seconds)
    awk -v a="$before" -v b="$after" 'BEGIN { exit !(b - a < 0.2) }' ||
        fail "minimised, oasis still used $before -> $after s of CPU in 1 s: is it drawing?"
    xdotool windowmap "$WINDOW"
    wait_for "$OUT_LOG" "$from" 'oasis: window restored: drawing again' 10
    step "minimise/restore $round: CPU while minimised $before -> $after s"
done
xdotool mousemove --window "$WINDOW" 5 5

# 50 ms a key: GLFW takes a release and a press of the same key less than 20 ms apart for auto-
# repeat (GLFW_REPEAT, which Tab ignores), as Xvfb has no detectable auto-repeat.
start=$SECONDS
press --delay 50 --repeat 1000 Tab
sleep 1
assert_alive "after 1000 Tab presses"
step "1000 Tab presses in $((SECONDS - start)) s"
toggle_panel
assert_drawn survive-end
finish_oasis
summary=$(grep 'oasis: window closed:' "$OUT_LOG")
[[ $summary =~ ' 1000 pipeline switches, 0 switches undone' ]] || fail "expected 1000 pipeline switches: $summary"
[[ $summary =~ 'minimised 3 times' ]] || fail "expected 3 minimisations: $summary"
[[ $summary =~ ([0-9]+)\ resizes ]] && ((BASH_REMATCH[1] >= 4)) || fail "expected at least 4 resizes: $summary"
[[ $summary =~ ([0-9]+)\ frames\ drawn ]] && ((BASH_REMATCH[1] >= 300)) || fail "too few frames drawn: $summary"
step "passed"
