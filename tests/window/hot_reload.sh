#!/usr/bin/env bash
# Shader hot reload under abuse, in the real window under Xvfb with real key presses (xdotool):
# on a copy of the shader tree (OASIS_SHADER_DIR), shader files are broken (a syntax error),
# emptied, deleted and restored while the window runs. Each failed reload (R) must name file:line
# and keep the previous programs; a switch that needs programs never built before (Tab to forward,
# G to the full layout, 3 to the normal view) must be undone with the error shown while the last
# working configuration is drawn; the depth convention (Z) still switches; after restoring and R
# everything works again and the window exits 0 on Esc.
#   usage: hot_reload.sh OASIS SHADER_DIR WORK_DIR
set -uo pipefail
. "$(dirname "$0")/window_lib.sh"
SOURCE_SHADERS=$2
window_test_begin window.hot_reload "$1" "$3" "$0" "$@"

export OASIS_SHADER_DIR=$WORK/shaders
cp -r "$SOURCE_SHADERS" "$OASIS_SHADER_DIR"
originals=$WORK/originals
cp -r "$SOURCE_SHADERS" "$originals"
restore() { cp "$originals/$1" "$OASIS_SHADER_DIR/$1"; }
# Appends a line that is not GLSL; prints its line number.
break_file() {
    echo 'this is not GLSL;' >> "$OASIS_SHADER_DIR/$1"
    wc -l < "$OASIS_SHADER_DIR/$1"
}
# reload_fails REGEX: R, then the reload's failure naming REGEX (file:line) on stderr.
reload_fails() {
    local from
    from=$(mark "$ERR_LOG")
    press r
    wait_for "$ERR_LOG" "$from" 'oasis: reload: [0-9]+ of [0-9]+ programs failed and keep their previous version' 30
    wait_for "$ERR_LOG" "$from" "$1" 5
    assert_alive "after a failed reload"
}
reload_succeeds() {
    local from
    from=$(mark "$OUT_LOG")
    press r
    wait_for "$OUT_LOG" "$from" 'oasis: shaders reloaded: [0-9]+ programs rebuilt' 30
}
# switch_undone KEY WANTED REGEX: KEY asks for a configuration (WANTED, a regex) whose programs do
# not build; the switch is undone, saying why (REGEX) and what is drawn instead.
switch_undone() {
    local from
    from=$(mark "$ERR_LOG")
    press "$1"
    wait_for "$ERR_LOG" "$from" "oasis: cannot switch to $2[^;]*; drawing .* instead: " 30
    wait_for "$ERR_LOG" "$from" "$3" 5
    sleep 0.5
    assert_alive "after $1 with a broken shader"
}
# switch_works KEY: KEY's switch draws without a new error.
switch_works() {
    local from
    from=$(mark "$ERR_LOG")
    press "$1"
    sleep 1
    assert_alive "after $1"
    expect_none "$ERR_LOG" "$from" 'cannot (switch|draw)'
}

start_oasis --size 320x180 --gbuffer compact  # deferred: the window starts with it
screenshot start > /dev/null

step "1. common/sky.glsl with a syntax error: R fails naming it, Tab to forward (never built) is undone"
line=$(break_file common/sky.glsl)
reload_fails "common/sky.glsl:$line"
switch_undone Tab 'forward, compact G-buffer' "common/sky.glsl:$line"
screenshot broken-sky-panel > /dev/null
toggle_panel
assert_drawn broken-sky-frame
toggle_panel

step "2. restored: R rebuilds, Tab draws forward, Tab back to deferred"
restore common/sky.glsl
reload_succeeds
switch_works Tab
switch_works Tab

step "3. common/gbuffer.glsl broken: G to the full layout and 3 to the normal view are undone, Z still switches"
line=$(break_file common/gbuffer.glsl)
reload_fails "common/gbuffer.glsl:$line"
switch_undone g 'deferred, full G-buffer' "common/gbuffer.glsl:$line"
switch_undone 3 'deferred, compact G-buffer, standard depth, view normal' "common/gbuffer.glsl:$line"
switch_works z
switch_works z
screenshot broken-gbuffer-panel > /dev/null

step "4. restored; terrain.frag emptied: R names terrain.frag:1, Tab keeps the forward programs built in 2"
restore common/gbuffer.glsl
reload_succeeds
: > "$OASIS_SHADER_DIR/terrain.frag"
reload_fails 'terrain.frag:1: the file is empty'
switch_works Tab
switch_works Tab

step "5. common/sky.glsl deleted: R names the including file:line, G is undone"
restore terrain.frag
rm "$OASIS_SHADER_DIR/common/sky.glsl"
reload_fails "common/lighting.glsl:[0-9]+: cannot read shader $OASIS_SHADER_DIR/common/sky.glsl"
switch_undone g 'deferred, full G-buffer' "cannot read shader $OASIS_SHADER_DIR/common/sky.glsl"

step "6. everything restored: R, then G, 3, 1, Tab all draw"
restore common/sky.glsl
reload_succeeds
for key in g 3 1 Tab; do switch_works "$key"; done
screenshot recovered-panel > /dev/null
toggle_panel
assert_drawn recovered-frame
finish_oasis
summary=$(grep 'oasis: window closed:' "$OUT_LOG")
[[ $summary =~ ' 4 switches undone' ]] || fail "expected 4 switches undone (steps 1, 3, 3, 5): $summary"
step "passed"
