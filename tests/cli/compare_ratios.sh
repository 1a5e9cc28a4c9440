#!/bin/sh
# compare's timing lines agree with themselves (issue 31, defect 5): each "Nx floor" is the printed
# median ms over the printed median floor ms (within the rounding of the two printed numbers), the
# rounds' range is printed beside each median, one line says whether the rounds were steady or
# NOISY (over 10%), and the JSON carries the same numbers under new keys beside the old ones.
# Usage: compare_ratios.sh OASIS_EXECUTABLE SCRATCH_DIR
oasis=$1 scratch=$2/compare-ratios
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$scratch" && mkdir -p "$scratch"
"$oasis" compare --size 160x90 --frames 3 --out-dir "$scratch/out" > "$scratch/text.txt" 2> /dev/null || fail "compare failed"
cat "$scratch/text.txt"
awk '
  /^  floor / { floor = $2 }
  /^  (forward|deferred) +[0-9]/ { ms[$1] = $2; ratio = $4; gsub(/[(x]/, "", ratio); r[$1] = ratio
                             if ($0 !~ /x floor; rounds [0-9.]+ to [0-9.]+ ms\)$/) { print "no rounds range: " $0; bad = 1 } }
  END {
    if (floor <= 0) { print "no floor line"; exit 1 }
    for (p in ms) {
      expected = ms[p] / floor; slack = expected * (0.006 / floor + 0.006 / ms[p]) + 0.006
      if (r[p] - expected > slack || expected - r[p] > slack) { print p ": " r[p] "x floor, but " ms[p] " / " floor " = " expected; bad = 1 }
    }
    exit bad
  }' "$scratch/text.txt" || fail "ratios that disagree with the milliseconds beside them"
grep -Eq '^  (steady|NOISY): the rounds spread by up to [0-9]+% of their median \(highest - lowest; noisy above 10%' "$scratch/text.txt" ||
    fail "no steady/NOISY line"
json=$("$oasis" compare --size 160x90 --frames 3 --json --out-dir "$scratch/json" 2> /dev/null) || fail "compare --json failed"
echo "$json" | python3 -c '
import json, sys
j = json.load(sys.stdin)
for key in ("forward_floor_ratio", "deferred_floor_ratio", "floor_ms", "forward_over_floor", "deferred_over_floor",
            "forward_ms_lowest", "forward_ms_highest", "floor_ms_lowest", "floor_ms_highest", "rounds_spread", "noisy"):
    assert key in j, key
assert abs(j["forward_over_floor"] - j["forward_ms"] / j["floor_ms"]) < 1e-3 * j["forward_over_floor"], j
assert j["noisy"] == (j["rounds_spread"] > j["noise_threshold"]), j
' || fail "the JSON keys"
echo "compare_ratios: ratios agree with the milliseconds"
