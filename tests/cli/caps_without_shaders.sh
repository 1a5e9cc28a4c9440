#!/bin/sh
# `oasis caps` needs no shader directory (it reports; the plant atlas is the one thing it would
# compile): with every place oasis looks for shaders hidden (a private mount namespace lays an
# empty tmpfs over each), caps exits 0, reports the compute path as chosen but not built, while
# render still exits 1 saying where it looked. Skipped (77) where mount namespaces are not allowed.
# Usage: caps_without_shaders.sh OASIS_EXECUTABLE SHADER_DIR...
oasis=$1
shift
unshare -m true 2> /dev/null || { echo "skipped: unshare -m is not permitted here"; exit 77; }
hide=""
for dir in "$@" "$(dirname "$oasis")/../share/oasis/shaders"; do
    [ -d "$dir" ] && hide="$hide mount -t tmpfs none '$dir' &&"
done
out=$(unshare -m sh -c "$hide env -u OASIS_SHADER_DIR '$oasis' caps --json" 2>&1)
rc=$?
echo "$out"
[ "$rc" -eq 0 ] || { echo "FAIL: caps exited $rc without shaders"; exit 1; }
echo "$out" | grep -q '"compute-plant-interpretation": {"used": true, "reason": "gpu ([^"]*not built: no shader directory' ||
    { echo "FAIL: caps does not say the atlas was not built"; exit 1; }
out=$(unshare -m sh -c "$hide env -u OASIS_SHADER_DIR '$oasis' render --size 16x9 --out /tmp/oasis-never.png" 2>&1)
rc=$?
[ "$rc" -eq 1 ] && echo "$out" | grep -q "oasis: cannot find oasis's shaders (looked in:" ||
    { echo "FAIL: render without shaders exited $rc: $out"; exit 1; }
echo "caps without shaders: OK"
