#!/usr/bin/env bash
# The window's panel and inspector, second round (issue 31), under Xvfb with real X events:
#   - --start-paused: the clock stands still from the first frame (the default camera flies with
#     it, so two screenshots seconds apart would differ if it ran);
#   - the panel at 1280x720 is narrow (at most 360 px), no line in it is wider than what it shows
#     (a hovered probe's long lines wrap), and it fits the window after a resize to 900x500;
#   - the frame time stays in a small overlay when H hides the panel;
#   - in the live split, the probe of a pixel on side B is side B's (oasis probe --pipeline
#     deferred, byte for byte), and side A's is A's;
#   - I: a pin's shading and history equal `oasis probe --shading --history --json`;
#   - F freezes the pins: what they held while the clock ran is what they showed when frozen.
#   usage: panel.sh OASIS WORK_DIR
set -uo pipefail
export OASIS_XVFB_SCREEN=1400x900x24  # room for the whole 1280x720 window wherever twm puts it
. "$(dirname "$0")/window_lib.sh"
window_test_begin "window.panel" "$1" "$2" "$0" "$@"

scene=(--hour 12 --ripples 0 --wind 0 --vegetation off)
start_oasis --size 1280x720 --start-paused "${scene[@]}"
paused_at=$(grep -m1 '^oasis: paused at --time ' "$OUT_LOG" | sed -E 's/^oasis: paused at --time ([^ ]+).*/\1/')
[[ -n $paused_at ]] || fail "--start-paused: no 'paused at --time' line before the first frame"
scene+=(--time "$paused_at")

# check_panel W H: the last panel line is for a W x H window, the panel is inside it, no wider than
# 360 px, and its widest line fits what it shows.
check_panel() {
    local line
    line=$(grep '^oasis: panel ' "$OUT_LOG" | tail -n 1)
    step "$line"
    awk -v l="$line" -v W="$1" -v H="$2" 'BEGIN {
        if (!match(l, /panel [0-9]+x[0-9]+ at -?[0-9]+,-?[0-9]+ in a [0-9]+x[0-9]+ window/)) exit 1
        split(substr(l, RSTART, RLENGTH), f, /[ x,]+/)   # panel W H at X Y in a WW HH window
        pw = f[2]; ph = f[3]; px = f[5]; py = f[6]; ww = f[9]; wh = f[10]
        n = split(l, g, " "); widest = g[n - 3]; shown = g[n]
        exit !(ww == W && wh == H && pw <= 360 && px >= 0 && py >= 0 && px + pw <= W && py + ph <= H && widest <= shown) }' ||
        fail "the panel does not fit: $line (for a $1x$2 window)"
}

# The clock stands still: the frame right of the panel, 2 s apart, pixel for pixel.
xdotool mousemove --window "$WINDOW" 1270 5
sleep 1
screenshot still-1 > /dev/null
sleep 2
xwd -silent -id "$WINDOW" -out "$WORK/still-2.xwd" || fail "xwd could not capture the window"
moved=$(python3 "$WINDOW_LIB_DIR/xwd_stats.py" "$WORK/still-2.xwd" --region 360,0,800,600 --compare "$WORK/still-1.png" |
        grep -oE 'maxabs [0-9]+' | cut -d' ' -f2)
step "--start-paused: the frame 2 s later differs by max abs $moved"
[[ $moved == 0 ]] || fail "--start-paused: the frame moved ($moved levels) while the clock should stand still"

# A hovered probe's lines are in the panel: they wrap instead of running out of it.
xdotool mousemove --window "$WINDOW" 800 400
sleep 2
from=$(mark "$OUT_LOG")
press p
wait_for "$OUT_LOG" "$from" '^oasis: probe \{' 30
screenshot panel-1280x720 > /dev/null
check_panel 1280 720

# H hides the panel; the frame time stays in the overlay at the bottom right (white on black).
toggle_panel
overlay=$(screenshot overlay-only 1000,690,276,26)
step "panel hidden: the overlay's corner: $overlay"
awk -v s="$overlay" 'BEGIN { split(s, f, " "); exit !(f[6] > 30) }' || fail "no frame-time overlay with the panel hidden ($overlay)"

toggle_panel

# A smaller window: the panel shrinks with it and scrolls.
from=$(mark "$OUT_LOG")
xdotool windowsize "$WINDOW" 900 500
wait_for "$OUT_LOG" "$from" '^oasis: panel .* in a 900x500 window' 60
sleep 1
screenshot panel-900x500 > /dev/null
check_panel 900 500

# C: forward | deferred split at the middle (450): each side's probe is its own pipeline's.
press c
sleep 4
without_encoding_error() { sed -E 's/, "encoding_error": (null|\{[^}]*\})//'; }
probe_side() {  # X Y SIDE PIPELINE
    local from window_probe headless_probe
    xdotool mousemove --window "$WINDOW" "$1" "$2"
    sleep 2
    from=$(mark "$OUT_LOG")
    press p
    wait_for "$OUT_LOG" "$from" "^oasis: probe \\($3: $4" 60
    window_probe=$(tail -n "+$((from + 1))" "$OUT_LOG" | grep -m1 "^oasis: probe ($3: " | sed -E 's/^oasis: probe \([^)]*\) //' |
                   without_encoding_error)
    headless_probe=$("$OASIS" probe --size 900x500 "${scene[@]}" --pipeline "$4" --at "$1,$2" --json | without_encoding_error) ||
        fail "oasis probe --pipeline $4 failed"
    [[ $window_probe == "$headless_probe" ]] || {
        echo "window:   $window_probe" >&2
        echo "headless: $headless_probe" >&2
        fail "side $3's probe at $1,$2 is not the $4 frame's"
    }
    step "split: the probe at $1,$2 is side $3's ($4), equal to oasis probe"
}
probe_side 700 250 B deferred
probe_side 400 250 A forward

# A pin on side B; I: its shading and history, as `oasis probe --shading --history` gives them.
xdotool mousemove --window "$WINDOW" 700 250
sleep 1
xdotool click 1
sleep 2
from=$(mark "$OUT_LOG")
press i
wait_for "$OUT_LOG" "$from" '^oasis: probe in depth #1 \(B: ' 120
deep=$(tail -n "+$((from + 1))" "$OUT_LOG" | grep -m1 '^oasis: probe in depth #1 (B: ' | sed -E 's/^[^{]*//' | without_encoding_error)
headless_deep=$("$OASIS" probe --size 900x500 "${scene[@]}" --pipeline deferred --at 700,250 --shading --history --json |
                without_encoding_error) || fail "oasis probe --shading --history failed"
[[ $deep == "$headless_deep" ]] || {
    echo "window:   ${deep:0:600}" >&2
    echo "headless: ${headless_deep:0:600}" >&2
    fail "pin 1's shading and history differ from oasis probe --shading --history"
}
grep -q '"shading": {' <<<"$deep" && grep -q '"history": \[' <<<"$deep" || fail "I printed no shading or history"
step "I: pin 1's shading and history equal oasis probe --shading --history ($(grep -o '"pass"' <<<"$deep" | wc -l) passes)"

# F freezes the pin; the clock runs (Space) and the camera flies on; F again: it held its values.
from=$(mark "$OUT_LOG")
press f
wait_for "$OUT_LOG" "$from" '^oasis: pin frozen #1 ' 30
frozen=$(tail -n "+$((from + 1))" "$OUT_LOG" | grep -m1 '^oasis: pin frozen #1 ' | sed -E 's/^[^{]*//')
press space
sleep 4
from=$(mark "$OUT_LOG")
press f
wait_for "$OUT_LOG" "$from" '^oasis: pin thawed, it held #1 ' 30
held=$(tail -n "+$((from + 1))" "$OUT_LOG" | grep -m1 '^oasis: pin thawed, it held #1 ' | sed -E 's/^[^{]*//')
[[ $held == "$frozen" ]] || fail "the frozen pin changed while the clock ran"
from=$(mark "$OUT_LOG")
press p
wait_for "$OUT_LOG" "$from" '^oasis: probe \(B: ' 60
now=$(tail -n "+$((from + 1))" "$OUT_LOG" | grep -m1 '^oasis: probe (B: ' | sed -E 's/^[^{]*//')
[[ $now != "$frozen" ]] || fail "the pixel's probe did not change while the clock ran: freezing proves nothing here"
step "F: the pin held its values while the clock ran (the pixel's probe changed meanwhile)"
finish_oasis
step "OK"
