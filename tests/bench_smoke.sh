#!/bin/sh
# CI smoke test of `oasis bench --quick`: exits 0, prints JSON whose `configs` each carry the
# required keys, at two light counts at least, at least one configuration on the Pareto frontier, and
# writes non-empty CSV and SVG.
# usage: bench_smoke.sh OASIS OUT_DIR
set -eu
oasis=$1 out=$2
rm -rf "$out" && mkdir -p "$out"
"$oasis" bench --quick --json --out-dir "$out" > "$out/stdout.json" 2> "$out/stderr.txt" || {
    echo "oasis bench --quick failed:"; cat "$out/stderr.txt"; exit 1; }
for file in bench.csv bench.json bench.svg; do
    test -s "$out/$file" || { echo "missing or empty: $out/$file"; exit 1; }
done
cmp -s "$out/stdout.json" "$out/bench.json" || { echo "stdout JSON differs from bench.json"; exit 1; }
json="$out/bench.json"
grep -q '"configs": \[' "$json" || { echo "no configs list"; exit 1; }
configs=$(grep -c '^ *{"pipeline": ' "$json" || true)
test "$configs" -ge 3 || { echo "expected at least 3 configs, found $configs"; exit 1; }
for key in pipeline layout width height lights ms_median floor_ms floor_ratio psnr_db bytes_per_pixel pareto \
           traffic_bytes_per_pixel cleared_bytes_per_pixel floor_traffic_bytes_per_pixel; do
    n=$(grep '^ *{"pipeline": ' "$json" | grep -c "\"$key\": " || true)
    test "$n" -eq "$configs" || { echo "key $key in $n of $configs configs"; exit 1; }
done
grep -Eq '"frame_clock": "wall-glfinish", "pass_clock": "(gpu-timer-query|wall-glfinish)", "pass_clock_reason": "timer queries (not )?trusted' "$json" ||
    { echo "bench.json does not say which clock timed the passes and why"; exit 1; }
grep -q '"pareto": true' "$json" || { echo "no configuration on the Pareto frontier"; exit 1; }
counts=$(grep '^ *{"pipeline": ' "$json" | grep -o '"lights": [0-9]*' | sort -u | wc -l)
test "$counts" -ge 2 || { echo "expected configurations at two light counts at least, found $counts"; exit 1; }
grep -q '"ms_median": [0-9]' "$json" || { echo "ms_median is not a number"; exit 1; }
test "$(wc -l < "$out/bench.csv")" -eq $((configs + 1)) || { echo "CSV rows do not match configs"; exit 1; }
grep -q '<polyline class="pareto"' "$out/bench.svg" || { echo "SVG has no frontier"; exit 1; }
# The depth-precision comparison: its JSON list and its CSV agree.
grep -q '"depth_precision": \[' "$json" || { echo "no depth_precision list"; exit 1; }
test "$(grep -c '^ *{"depth": ' "$json")" -eq $(($(wc -l < "$out/depth_precision.csv") - 1)) ||
    { echo "depth_precision.csv rows do not match the JSON list"; exit 1; }
grep -q '^\[[0-9]*/[0-9]*\] ' "$out/stderr.txt" || { echo "no progress lines on stderr"; exit 1; }
echo "bench smoke: $configs configs OK"
