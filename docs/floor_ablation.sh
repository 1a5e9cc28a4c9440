#!/usr/bin/env bash
# Produces docs/measurements.md's table of what the default frame costs against its floor with
# each feature of the scene switched off, and all three off: the evidence for issue 15, item 1
# (deferred within 5x its floor). Each row is one `oasis compare` of 1280x720: rounds of a forward
# frame, a deferred frame and the floor, each ratio the median of the rounds' own.
# usage: docs/floor_ablation.sh [path/to/oasis] [rounds]   (run on an idle machine; prints markdown)
set -euo pipefail
oasis=${1:-build/oasis}
rounds=${2:-15}
out=$(mktemp -d)
field() { sed -E "s/.*\"$1\": (\"([^\"]*)\"|([^,}]*)).*/\2\3/" <<<"$2"; }
echo "| frame (1280x720) | forward ms | deferred ms | floor ms | forward / floor | deferred / floor (lowest-highest round) |"
echo "| --- | --- | --- | --- | --- | --- |"
for features in "default" "--shadows off" "--reflections off" "--vegetation off" \
                "--shadows off --reflections off --vegetation off"; do
  flags=()
  [[ $features == default ]] || read -ra flags <<<"$features"
  json=$("$oasis" compare --size 1280x720 --frames "$rounds" --json --out-dir "$out" "${flags[@]}" 2>/dev/null)
  awk -v label="$features" -v f="$(field forward_ms "$json")" -v d="$(field deferred_ms "$json")" \
      -v floor="$(field floor_ms "$json")" -v fr="$(field forward_floor_ratio "$json")" \
      -v dr="$(field deferred_floor_ratio "$json")" -v lo="$(field deferred_floor_ratio_lowest "$json")" \
      -v hi="$(field deferred_floor_ratio_highest "$json")" 'BEGIN {
    printf "| %s | %.1f | %.1f | %.1f | %.2f | %.2f (%.2f-%.2f) |\n", label, f, d, floor, fr, dr, lo, hi }'
done
echo
echo "renderer: $(field renderer "$json"); medians of $rounds rounds; $(nproc) cores; $(date -u +%F)"
rm -rf "$out"
