#!/bin/sh
# Every output is written whole or not at all (docs/outputs.md): a write that fails is exit 1 with
# "oasis: cannot write PATH: REASON", no "wrote" line for it, and no half-written or temporary file.
# The failures are real: /dev/full (ENOSPC), a 64 KiB tmpfs (ENOSPC; needs mount, else skipped with
# exit 77) and a file-size limit (ulimit -f: EFBIG, SIGXFSZ ignored).
# usage: output_failures.sh CASE OASIS WORK_DIR
#   dev-full | stdout | full-tmpfs | size-limit-compare | size-limit-bench
set -u
case_name=$1 oasis=$2 work=$3
fail() { echo "FAIL ($case_name): $*"; exit 1; }
umount "$work/fs" 2> /dev/null  # left mounted by an interrupted run
rm -rf "$work" && mkdir -p "$work" || fail "cannot make $work"
cd "$work" || fail "cannot enter $work"

# Runs oasis with $@, keeping stdout, stderr and the exit status (stdout and stderr go to files
# outside any limited directory).
run() {
    "$oasis" "$@" > "$work/stdout.txt" 2> "$work/stderr.txt"
    status=$?
}

# The exit status is 1, stderr names the file (one of the given names) and why, stdout says no "wrote".
expect_refused() {  # REASON NAME...
    reason=$1; shift
    test "$status" -eq 1 || { cat "$work/stderr.txt"; fail "exit $status, expected 1"; }
    named=no
    for name in "$@"; do grep -qxF "oasis: cannot write $name: $reason" "$work/stderr.txt" && named=yes; done
    test $named = yes || { cat "$work/stderr.txt"; fail "no 'oasis: cannot write NAME: $reason' for one of: $*"; }
    ! grep -q wrote "$work/stdout.txt" "$work/stderr.txt" || fail "a 'wrote' line for a failed write"
}

# DIR holds exactly the listed entries (no temporaries, nothing half-written beside them).
expect_entries() {  # DIR NAME...
    dir=$1; shift
    found=$(ls -A "$dir" | sort | tr '\n' ' ')
    wanted=$(for name in "$@"; do echo "$name"; done | sort | tr '\n' ' ')
    test "$found" = "$wanted" || fail "$dir holds '$found', expected '$wanted'"
}

case $case_name in
dev-full)
    run render --size 32x18 --out /dev/full
    expect_refused "No space left on device" /dev/full ;;
stdout)
    # /dev/stdout is written in place (it cannot be renamed over), to a file and to a pipe alike; the
    # report lines go to stderr so that the PNG stays clean.
    "$oasis" render --size 32x18 --out /dev/stdout > file.png 2> stderr.txt || fail "exit $? writing to a file"
    "$oasis" render --size 32x18 --out /dev/stdout 2> /dev/null | cat > piped.png
    cmp -s file.png piped.png || fail "the PNG written to a file and to a pipe differ"
    test "$(head -c 8 file.png | od -An -tx1 | tr -d ' ')" = 89504e470d0a1a0a || fail "no PNG signature"
    test "$(tail -c 8 file.png | od -An -tx1 | tr -d ' ')" = 49454e44ae426082 || fail "does not end with IEND"
    grep -q "oasis: wrote /dev/stdout" stderr.txt || fail "no report on stderr" ;;
full-tmpfs)
    # compare into a 64 KiB file system holding an earlier run's three (small, complete) images:
    # this run's images do not fit (640x360: libpng packs 160x90 frames into 64 KiB); the earlier
    # ones stay byte for byte, nothing else appears.
    mkdir fs earlier
    if ! mount -t tmpfs -o size=64k oasis-test fs 2> mount.txt; then
        echo "SKIP: cannot mount a tmpfs here ($(cat mount.txt)); the size-limit cases still run"; exit 77
    fi
    trap 'umount "$work/fs"' EXIT
    "$oasis" compare --size 32x18 --frames 1 --out-dir earlier > /dev/null 2>&1 || fail "the small compare failed"
    cp earlier/*.png fs/
    run compare --size 640x360 --frames 1 --out-dir fs
    expect_refused "No space left on device" fs/forward.png fs/deferred.png fs/difference.png
    expect_entries fs forward.png deferred.png difference.png
    for name in forward.png deferred.png difference.png; do
        cmp -s "earlier/$name" "fs/$name" || fail "fs/$name is not the earlier run's complete file"
    done
    # An empty file system of that size: nothing at all is left.
    rm fs/*.png
    run compare --size 640x360 --frames 1 --out-dir fs
    expect_refused "No space left on device" fs/forward.png fs/deferred.png fs/difference.png
    expect_entries fs ;;
size-limit-compare)
    # Files may grow to 32 KiB: a 320x180 frame's PNG cannot. Output goes through a pipe (the limit
    # applies to regular files only), so only the images meet it.
    status=0
    both=$(sh -c "trap '' XFSZ; ulimit -f 64; exec \"\$0\" compare --size 320x180 --frames 1 --out-dir out 2>&1" \
        "$oasis") || status=$?
    printf '%s\n' "$both" > stderr.txt && : > stdout.txt
    expect_refused "File too large" out/forward.png out/deferred.png out/difference.png
    expect_entries out ;;
size-limit-bench)
    # The bench's four reports under a 4 KiB limit: none is written, the measurements are still
    # printed.
    status=0
    both=$(sh -c "trap '' XFSZ; ulimit -f 8; exec \"\$0\" bench --quick --out-dir out 2>&1" "$oasis") || status=$?
    printf '%s\n' "$both" > stderr.txt && : > stdout.txt
    expect_refused "File too large" out/bench.csv out/bench.json out/bench.svg out/depth_precision.csv
    expect_entries out
    grep -q "^depth precision at" stderr.txt || fail "the measurements were not printed" ;;
*)
    echo "usage: output_failures.sh dev-full|stdout|full-tmpfs|size-limit-compare|size-limit-bench OASIS WORK_DIR"
    exit 2 ;;
esac
echo "output failures ($case_name): OK"
