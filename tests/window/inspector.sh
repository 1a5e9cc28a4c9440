#!/usr/bin/env bash
# The inspector in the real window under Xvfb, driven by real X events (xdotool), against the
# headless commands on the same still frame (no ripples, wind, plants or lights; a fixed camera
# and hour; the clock paused with Space, which prints the time: the clouds drift with it, and the
# headless commands take that --time):
#   - the window's frame (panel hidden) equals `oasis render` of that frame, view final and view
#     normal (key 3), within 40 dB: the same renderer, through a window;
#   - hovering a pixel and pressing P prints the probe there, and it is `oasis probe --at X,Y`'s
#     JSON, byte for byte;
#   - a click pins a probe: a numbered marker appears at the pixel;
#   - C splits the frame live: each half is its pipeline's headless frame, the divider between;
#   - after a click on the panel the view keys still work (2: albedo, against the headless view);
#   - M switches the views to the mirrored scene under the water: the albedo view and a water
#     pixel's probe equal the headless `--water-scene mirrored` ones.
#   usage: inspector.sh OASIS WORK_DIR [--api gles [--force gles30]]
#   (with --api gles the window, its panel and every headless command run on OpenGL ES: the
#   window's EGL context and ImGui's ES backend against the headless ES context)
set -uo pipefail
. "$(dirname "$0")/window_lib.sh"
window_test_begin "window.inspector${3:+ ${*:3}}" "$1" "$2" "$0" "$@"

scene=(--size 480x270 --camera 435,4,140,30,-3 --hour 12 --ripples 0 --wind 0 --vegetation off "${@:3}")
start_oasis "${scene[@]}"
if [[ " ${*:3} " == *" --api gles "* ]]; then
    grep -q '^oasis: window on .*OpenGL ES 3' "$OUT_LOG" || fail "--api gles: the window is not on an OpenGL ES context"
    step "$(grep -m1 '^oasis: window on' "$OUT_LOG")"
fi
toggle_panel  # H: the frame alone, and the cursor never over the panel
press o       # O: without the frame-time overlay in the corner either
from=$(mark "$OUT_LOG")
press space
wait_for "$OUT_LOG" "$from" '^oasis: paused at --time ' 30
paused_at=$(tail -n "+$((from + 1))" "$OUT_LOG" | grep -m1 '^oasis: paused at --time ' | sed 's/^oasis: paused at --time //')
step "Space: the clock paused at --time $paused_at"
scene+=(--time "$paused_at")  # from here on, the headless commands render the paused frame

# The window's framebuffer is 480x270 at the window's top-left (no title bar under twm here).
compare_with_headless() {  # VIEW KEY
    local view=$1 stats psnr
    [[ -n $2 ]] && press "$2" && sleep 1
    "$OASIS" render "${scene[@]}" --view "$view" --legend off --out "$WORK/headless-$view.png" > /dev/null ||
        fail "oasis render --view $view failed"
    xwd -silent -id "$WINDOW" -out "$WORK/window-$view.xwd" || fail "xwd could not capture the window"
    stats=$(python3 "$WINDOW_LIB_DIR/xwd_stats.py" "$WORK/window-$view.xwd" --region 0,0,480,270 \
            --png "$WORK/window-$view.png" --compare "$WORK/headless-$view.png")
    stats=$(tr '\n' ' ' <<<"$stats")
    step "view $view: window against headless: $stats"
    psnr=$(grep -oE 'psnr [0-9.]+' <<<"$stats" | cut -d' ' -f2)
    [[ -n $psnr ]] || fail "view $view: no PSNR from xwd_stats.py ($stats)"
    awk -v p="$psnr" 'BEGIN { exit !(p + 0 >= 40) }' || fail "view $view: the window's frame differs from the headless render ($stats)"
}
compare_with_headless final ""

# Hover a lakeside pixel, P: the probe printed must be the headless probe of that pixel.
x=300 y=200
xdotool mousemove --window "$WINDOW" "$x" "$y"
sleep 1
from=$(mark "$OUT_LOG")
press p
wait_for "$OUT_LOG" "$from" '^oasis: probe \{' 30
# The command also measures the layout's encoding error against full (two more frames); the
# window does not, so that one field is left out of the comparison.
without_encoding_error() { sed -E 's/, "encoding_error": (null|\{[^}]*\})//'; }
window_probe=$(tail -n "+$((from + 1))" "$OUT_LOG" | grep -m1 '^oasis: probe {' | sed 's/^oasis: probe //' | without_encoding_error)
headless_probe=$("$OASIS" probe "${scene[@]}" --at "$x,$y" --json | without_encoding_error) || fail "oasis probe failed"
[[ $window_probe == "$headless_probe" ]] || {
    echo "window:   $window_probe" >&2
    echo "headless: $headless_probe" >&2
    fail "the hovered probe differs from oasis probe --at $x,$y"
}
step "hovered $x,$y: the window's probe equals oasis probe ($(grep -o '"final": \[[^]]*\]' <<<"$headless_probe"))"

# A click pins probe 1: its marker (a magenta ring) appears around the pixel.
xdotool click 1
sleep 1
xwd -silent -id "$WINDOW" -out "$WORK/pinned.xwd" || fail "xwd could not capture the window"
marker=$(python3 "$WINDOW_LIB_DIR/xwd_stats.py" "$WORK/pinned.xwd" --region $((x - 7)),$((y - 1)),3,3 --png "$WORK/pinned.png")
step "pinned at $x,$y: the ring's left edge $marker"
awk -v s="$marker" 'BEGIN { split(s, f, " "); exit !(f[2] > 120 && f[3] < 90 && f[4] > 120) }' ||
    fail "no magenta pin marker left of $x,$y ($marker)"

# A right click unpins it; the normal view (key 3) in the window against the headless one.
xdotool click 3
xdotool mousemove --window "$WINDOW" 5 5
compare_with_headless normal 3

# C: the live split of the final frame, forward | deferred at the middle: each half is exactly that
# pipeline's headless frame (the two differ by a few levels in each half, so only the right side
# matches), below the labels at the top; the divider is drawn at columns 239 and 240.
press 1
press c
sleep 3
for pipeline in forward deferred; do
    "$OASIS" render "${scene[@]}" --pipeline "$pipeline" --legend off --out "$WORK/final-$pipeline.png" > /dev/null ||
        fail "oasis render --pipeline $pipeline failed"
done
xwd -silent -id "$WINDOW" -out "$WORK/split.xwd" || fail "xwd could not capture the window"
half_against() {  # REGION PNG: prints the max abs difference
    python3 "$WINDOW_LIB_DIR/xwd_stats.py" "$WORK/split.xwd" --region "$1" --compare "$WORK/$2" |
        grep -oE 'maxabs [0-9]+' | cut -d' ' -f2
}
left=0,30,238,240 right=242,30,238,240
step "split: left half against forward $(half_against $left final-forward.png), against deferred $(half_against $left final-deferred.png); right half against deferred $(half_against $right final-deferred.png), against forward $(half_against $right final-forward.png) (max abs)"
[[ $(half_against $left final-forward.png) == 0 && $(half_against $right final-deferred.png) == 0 ]] ||
    fail "split: the halves are not the forward and deferred frames"
[[ $(half_against $left final-deferred.png) != 0 && $(half_against $right final-forward.png) != 0 ]] ||
    fail "split: the pipelines' frames do not differ in each half, so the split proves nothing here"
divider=$(python3 "$WINDOW_LIB_DIR/xwd_stats.py" "$WORK/split.xwd" --region 239,100,2,100 --png "$WORK/split.png")
awk -v s="$divider" 'BEGIN { split(s, f, " "); exit !(f[2] > 250 && f[3] > 250 && f[4] > 250) }' ||
    fail "no white divider at column 239 ($divider)"
press c c c c  # the comparison off again (C cycles the five modes)

# Keys after a click on the panel: H shows it, a click on its title bar focuses it, then 2
# (albedo) and H must still reach the window: the albedo view equals the headless one.
press h
sleep 1
xdotool mousemove --window "$WINDOW" 200 18 click 1
sleep 1
xdotool mousemove --window "$WINDOW" 5 260
press 2 h
sleep 2
compare_with_headless albedo ""

# M: the views show the mirrored scene under the water; the albedo view then equals
# `oasis render --water-scene mirrored`, and a water pixel's probe is `oasis probe --water-scene mirrored`.
press m
sleep 2
scene+=(--water-scene mirrored)
compare_with_headless albedo ""
x=240 y=160
xdotool mousemove --window "$WINDOW" "$x" "$y"
sleep 1
from=$(mark "$OUT_LOG")
press p
wait_for "$OUT_LOG" "$from" '^oasis: probe \{' 30
window_probe=$(tail -n "+$((from + 1))" "$OUT_LOG" | grep -m1 '^oasis: probe {' | sed 's/^oasis: probe //' | without_encoding_error)
headless_probe=$("$OASIS" probe "${scene[@]}" --at "$x,$y" --json | without_encoding_error) || fail "oasis probe failed"
[[ $window_probe == "$headless_probe" ]] || {
    echo "window:   $window_probe" >&2
    echo "headless: $headless_probe" >&2
    fail "the hovered water probe (M: mirrored) differs from oasis probe --water-scene mirrored --at $x,$y"
}
grep -q '"water_scene": "the mirrored scene' <<<"$window_probe" || fail "the water pixel's probe does not say mirrored"
step "M, water pixel $x,$y: the window's probe equals oasis probe --water-scene mirrored"
finish_oasis
step "OK"
