#!/bin/sh
# A signal (INT, TERM, HUP) while oasis writes leaves nothing behind (docs/outputs.md): each command
# is signalled at the moment its first temporary appears and at several moments of its run; it must
# end by that signal, leave no ".NAME.tmp-PID-N" and no staging or runtime directory, and its output
# directory must hold its whole set of files or none of them.
# usage: interruption.sh CASE OASIS SIGNAL_AT_WRITE WORK_DIR
#   render | compare | main-job | driver-compare | bench
set -u
case_name=$1 oasis=$2 signal_at_write=$3 work=$4
fail() { echo "FAIL ($case_name): $*"; exit 1; }
rm -rf "$work" && mkdir -p "$work" || fail "cannot make $work"
cd "$work" || fail "cannot enter $work"
unset DISPLAY WAYLAND_DISPLAY  # the main job, not the window

case $case_name in
render) command="render --size 640x360 --out out/frame.png"; set_files="frame.png"; delays="0.3 0.8 1.5" ;;
compare) command="compare --size 320x180 --frames 1 --out-dir out"; set_files="deferred.png difference.png forward.png"
    delays="0.3 0.8 1.5 2.5" ;;
main-job) command="--size 320x180 --frames 1 --out-dir out"
    set_files="deferred.png difference.png forward.png overview.png"; delays="0.5 1.5 3" ;;
driver-compare) command="compare --size 160x90 --driver llvmpipe --driver gles --out-dir out"
    set_files="difference.png gles.png llvmpipe.png"; delays="0.3 1 2 3.5" ;;
bench) command="bench --quick --frames 1 --out-dir out"; set_files="bench.csv bench.json bench.svg depth_precision.csv"
    delays="" ;;
*) fail "unknown case" ;;
esac

runs=0
# One run: SIGNAL at MOMENT ("--at-temporary" or "--after S"); checks what is left.
one() {  # SIGNAL MOMENT...
    signal=$1; shift
    rm -rf out tmp && mkdir out tmp
    # shellcheck disable=SC2086
    TMPDIR=$work/tmp "$signal_at_write" "$signal" "$@" out tmp -- "$oasis" $command > run.txt 2>&1
    status=$?
    runs=$((runs + 1))
    if [ "$1" = "--at-temporary" ]; then
        test $status -eq 0 || { cat run.txt; fail "$signal at the first temporary: not ended by the signal"; }
    elif [ $status -eq 4 ]; then
        # Sent at a moment, yet the command exited 0: acceptable only when its work was complete
        # (the whole set written) before the signal landed; the sanitized build spends its last
        # second in LeakSanitizer's exit-time check, with signals blocked.
        test -n "$(ls out)" || { cat run.txt; fail "$signal $*: exited 0 after the signal without its set"; }
    else
        test $status -eq 0 -o $status -eq 3 || { cat run.txt; fail "$signal $*: not ended by the signal"; }
    fi
    left=$(find out tmp -name '.*.tmp-*' -o -name 'oasis-runtime-*' | head -n 5)
    test -z "$left" || { cat run.txt; fail "$signal $*: left behind: $left"; }
    present=$(ls out | sort | tr '\n' ' ')
    wanted=$(for f in $set_files; do echo "$f"; done | sort | tr '\n' ' ')
    test -z "$present" -o "$present" = "$wanted" || { cat run.txt; fail "$signal $*: a part of the set: '$present'"; }
    for f in out/*.png; do
        test -e "$f" || continue
        test "$(tail -c 8 "$f" | od -An -tx1 | tr -d ' \n')" = 49454e44ae426082 || fail "$signal $*: $f is cut short"
    done
}

# Each signal at the first temporary; the bench (about 25 s a run, its measurement before its first
# write) with INT alone: the three signals share one handler, which the other cases test each.
signals="INT TERM HUP"
[ "$case_name" = bench ] && signals=INT
for signal in $signals; do one $signal --at-temporary; done
for delay in $delays; do one TERM --after "$delay"; done
echo "interruption ($case_name): OK, $runs runs"
