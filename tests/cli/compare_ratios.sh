#!/bin/sh
# compare's timing lines agree with themselves (issue 31, defect 5) and carry their uncertainty
# (issue 44): each "Nx floor" is the printed median ms over the printed median floor ms (within the
# rounding of the two printed numbers) with its interval, each median has a 95% interval that holds
# it, a CV and its outliers, the rounds' range is printed beside it, one line gives deferred over
# forward with a verdict its interval decides, one the rounds, warm-up and seed; the JSON carries the
# old keys and the new *_stats, deferred_over_forward and seed, and --seed repeats the order.
# Usage: compare_ratios.sh OASIS_EXECUTABLE SCRATCH_DIR
oasis=$1 scratch=$2/compare-ratios
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$scratch" && mkdir -p "$scratch"
"$oasis" compare --size 160x90 --frames 7 --out-dir "$scratch/out" > "$scratch/text.txt" 2> /dev/null || fail "compare failed"
cat "$scratch/text.txt"
awk '
  /^  floor +[0-9]/ { floor = $2 }
  /^  (forward|deferred) +[0-9]/ {
    ms[$1] = $2; ratio = $0; sub(/.*\(/, "", ratio); sub(/x floor.*/, "", ratio); r[$1] = ratio
    if ($0 !~ /x floor \[[0-9.]+, [0-9.]+\]; rounds [0-9.]+ to [0-9.]+ ms\)$/) { print "no ratio interval or rounds range: " $0; bad = 1 } }
  /^  (forward|deferred|floor) +[0-9]/ {
    if ($0 !~ / ms\/frame \[[0-9.]+, [0-9.]+\] 95% CI, CV [0-9.]+%, (no outliers|outliers [0-9]+ mild [0-9]+ severe)  \(/) {
      print "no interval, CV or outliers: " $0; bad = 1 }
    lo = $0; sub(/^[^[]*\[/, "", lo); hi = lo; sub(/,.*/, "", lo); sub(/^[^ ]* /, "", hi); sub(/\].*/, "", hi)
    if (lo + 0 > $2 + 0.006 || hi + 0 < $2 - 0.006) { print $1 ": median " $2 " outside its interval [" lo ", " hi "]"; bad = 1 } }
  END {
    if (floor <= 0) { print "no floor line"; exit 1 }
    for (p in ms) {
      expected = ms[p] / floor; slack = expected * (0.006 / floor + 0.006 / ms[p]) + 0.006
      if (r[p] - expected > slack || expected - r[p] > slack) { print p ": " r[p] "x floor, but " ms[p] " / " floor " = " expected; bad = 1 }
    }
    exit bad
  }' "$scratch/text.txt" || fail "timing lines that disagree or lack their intervals"
grep -Eq '^  (deferred is (faster|slower) than forward: [0-9.]+x \[[0-9.]+, [0-9.]+\]|no difference shown at this noise: deferred/forward [0-9.]+x \[[0-9.]+, [0-9.]+\] — more --frames)$' \
    "$scratch/text.txt" || fail "no verdict line"
grep -Eq '^  7 rounds after 2 warm-up frames of each \(discarded\): a forward frame, a deferred frame and the floor in a random order each round \(seed [0-9]+; --seed repeats it\)' \
    "$scratch/text.txt" || fail "no rounds/warm-up/seed line"
grep -Eq '^  precision: the widest interval, (forward|deferred|floor)'"'"'s, is \+-[0-9.]+% of its median' "$scratch/text.txt" ||
    fail "no precision line"
json=$("$oasis" compare --size 160x90 --frames 7 --seed 44 --json --out-dir "$scratch/json" 2> /dev/null) || fail "compare --json failed"
echo "$json" | python3 -c '
import json, sys
j = json.load(sys.stdin)
for key in ("forward_floor_ratio", "deferred_floor_ratio", "floor_ms", "forward_over_floor", "deferred_over_floor",
            "forward_ms_lowest", "forward_ms_highest", "floor_ms_lowest", "floor_ms_highest", "rounds_spread", "noisy",
            "forward_over_floor_ci", "deferred_over_floor_ci"):
    assert key in j, key
assert abs(j["forward_over_floor"] - j["forward_ms"] / j["floor_ms"]) < 1e-3 * j["forward_over_floor"], j
assert j["noisy"] == (j["rounds_spread"] > j["noise_threshold"]), j
assert j["seed"] == 44, j["seed"]
# One name per quantity (issue 44, item 7): bytes_per_pixel here is the G-buffer alone, named as bench.json names it.
assert j["gbuffer_bytes_per_pixel"] == j["bytes_per_pixel"], j
for stream in ("forward", "deferred", "floor"):
    s = j[stream + "_stats"]
    assert set(s) == {"median_ms", "ci_ms", "cv", "outliers", "rounds", "warmup"}, s
    assert abs(s["median_ms"] - j[stream + "_ms"]) < 1e-3, (s, j[stream + "_ms"])
    assert s["ci_ms"][0] <= s["median_ms"] <= s["ci_ms"][1], s
    assert set(s["outliers"]) == {"mild", "severe"} and s["rounds"] == 7 and s["warmup"] == 2, s
r = j["deferred_over_forward"]
assert set(r) == {"ratio", "ci", "verdict"}, r
lo, hi = r["ci"]
expected = "faster" if hi < 1 else "slower" if lo > 1 else "no difference shown"
assert r["verdict"] == expected, r
assert abs(r["ratio"] - j["deferred_ms"] / j["forward_ms"]) < 1e-3 * r["ratio"], (r, j["deferred_ms"], j["forward_ms"])
' || fail "the JSON keys"
echo "compare_ratios: ratios agree with the milliseconds, every time has its interval"
