# Sourced by the window tests: oasis's real window under Xvfb with a window manager (twm: minimise
# and restore need one), driven by real X events (xdotool), with waits on what oasis prints and
# screenshots (xwd, read by xwd_stats.py). Each test script calls window_test_begin first, which
# runs the script again inside xvfb-run.
#   usage in a test: window_test_begin NAME OASIS WORK_DIR "$0" "$@"; start_oasis ARGS...; ...; finish_oasis

WINDOW_LIB_DIR=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)

# window_test_begin NAME OASIS WORK_DIR SCRIPT ARGS...: re-runs SCRIPT ARGS under xvfb-run (once);
# inside, sets the test's name, OASIS, WORK (emptied) and the logs, and starts twm.
window_test_begin() {
    if [[ -z ${OASIS_WINDOW_TEST_IN_XVFB:-} ]]; then
        local tool
        for tool in xvfb-run xdotool xwd twm python3; do
            command -v "$tool" > /dev/null || { echo "oasis window test: $tool is missing (bash .ci/setup installs it)" >&2; exit 1; }
        done
        exec env OASIS_WINDOW_TEST_IN_XVFB=1 xvfb-run -a -s "-screen 0 ${OASIS_XVFB_SCREEN:-800x600x24}" bash "${@:4}"
    fi
    TEST_NAME=$1
    OASIS=$2
    WORK=$3
    rm -rf "$WORK" && mkdir -p "$WORK"
    OUT_LOG=$WORK/stdout.txt
    ERR_LOG=$WORK/stderr.txt
    OASIS_PID=
    # twm with X's core "fixed" font (Xvfb has no others) and no placement by hand; no title bars
    # so the window's origin is where xdotool puts it.
    printf '%s\n' 'RandomPlacement' 'NoTitle' 'TitleFont "fixed"' 'ResizeFont "fixed"' 'MenuFont "fixed"' \
        'IconFont "fixed"' 'IconManagerFont "fixed"' > "$WORK/twmrc"
    LANG=C LC_ALL=C twm -f "$WORK/twmrc" > "$WORK/twm.log" 2>&1 &
    TWM_PID=$!
    trap 'window_test_cleanup' EXIT
}

window_test_cleanup() {
    [[ -n $OASIS_PID ]] && kill "$OASIS_PID" 2> /dev/null
    kill "$TWM_PID" 2> /dev/null
    return 0
}

fail() {
    echo "FAIL ($TEST_NAME): $*" >&2
    echo "--- oasis stdout (last 20 lines)" >&2
    tail -n 20 "$OUT_LOG" >&2 2> /dev/null
    echo "--- oasis stderr (last 20 lines)" >&2
    tail -n 20 "$ERR_LOG" >&2 2> /dev/null
    exit 1
}

step() { echo "[$TEST_NAME] $*"; }

# Starts `oasis window ARGS` in the background and waits for its first frame and its X window.
start_oasis() {
    "$OASIS" window "$@" > "$OUT_LOG" 2> "$ERR_LOG" &
    OASIS_PID=$!
    wait_for "$OUT_LOG" 0 'oasis: first frame drawn' 120
    WINDOW=$(timeout 30 xdotool search --sync --onlyvisible --name '^oasis$' | head -n 1)
    [[ -n $WINDOW ]] || fail "no X window named oasis"
    # Keys go where the pointer is (twm's focus follows it): into the window, away from the panel.
    xdotool mousemove --window "$WINDOW" 5 5
}

assert_alive() {
    kill -0 "$OASIS_PID" 2> /dev/null || { wait "$OASIS_PID"; fail "oasis exited (status $?) $*"; }
}

# The number of lines in a log now: later waits look only at what comes after.
mark() { wc -l < "$1"; }

# wait_for LOG FROM_LINE REGEX SECONDS: until a line after FROM_LINE matches (extended regex).
wait_for() {
    local log=$1 from=$2 pattern=$3 seconds=$4
    local deadline=$((SECONDS + seconds))
    # grep without -q reads to the end: with pipefail, an early exit would fail tail with SIGPIPE.
    while ! tail -n "+$((from + 1))" "$log" | grep -E -- "$pattern" > /dev/null; do
        assert_alive "while waiting for /$pattern/"
        ((SECONDS < deadline)) || fail "no line matching /$pattern/ in $(basename "$log") within $seconds s"
        sleep 0.1
    done
}

# expect_none LOG FROM_LINE REGEX: no line after FROM_LINE matches.
expect_none() {
    if tail -n "+$(($2 + 1))" "$1" | grep -E -- "$3" >&2; then fail "unexpected line matching /$3/ in $(basename "$1")"; fi
}

press() { xdotool key --delay 50 "$@"; }

# Seconds of CPU (user + system) oasis has used so far.
cpu_seconds() {
    awk -v hz="$(getconf CLK_TCK)" '{ printf "%.2f\n", ($14 + $15) / hz }' "/proc/$OASIS_PID/stat"
}

# screenshot NAME [X,Y,W,H]: the window's contents into NAME.png beside the logs; prints
# "mean R G B stddev S" of the region (default: all of it).
screenshot() {
    xwd -silent -id "$WINDOW" -out "$WORK/$1.xwd" || fail "xwd could not capture the window"
    python3 "$WINDOW_LIB_DIR/xwd_stats.py" "$WORK/$1.xwd" ${2:+--region "$2"} --png "$WORK/$1.png"
    rm -f "$WORK/$1.xwd"
}

# H hides the panel (and shows it again), so the frame under it can be measured.
toggle_panel() {
    press h
    sleep 0.5
}

# assert_drawn NAME: a screenshot of the window (panel hidden) is a picture: not black, not one
# flat colour (the grey oasis shows when it can draw nothing).
assert_drawn() {
    local stats
    stats=$(screenshot "$1")
    step "screenshot $1.png: $stats"
    awk -v s="$stats" 'BEGIN { split(s, f, " "); mean = (f[2] + f[3] + f[4]) / 3;
                               exit !(mean > 20 && f[6] > 8) }' || fail "$1: the frame looks black or flat ($stats)"
}

# Esc closes the window; oasis must exit 0 and print its closing counts.
finish_oasis() {
    press Escape
    local deadline=$((SECONDS + 30)) status=0
    while kill -0 "$OASIS_PID" 2> /dev/null; do
        ((SECONDS < deadline)) || fail "oasis did not close within 30 s of Esc"
        sleep 0.1
    done
    wait "$OASIS_PID" || status=$?
    OASIS_PID=
    ((status == 0)) || fail "oasis exited with status $status after Esc"
    grep -E 'oasis: window closed:' "$OUT_LOG" || fail "no closing line"
    expect_none "$ERR_LOG" 0 'GL (error|debug)'
}
