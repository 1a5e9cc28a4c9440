#!/usr/bin/env bash
# Produces docs/shadows.md's cost table: for each size and shadow setting (off, low, medium, high),
# the ShadowPass's median ms in each pipeline, both frames and the floor from one
# `oasis compare --passes` run, forward vs deferred PSNR, and the deferred frame's PSNR against the
# same frame with high shadows (the reference level). Morning sun (08:00): long shadows in view.
# usage: docs/shadow_cost.sh [path/to/oasis] [frames]   (run on an idle machine; prints markdown)
set -euo pipefail
oasis=${1:-build/oasis}
frames=${2:-5}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
pose=(--hour 8 --camera 420,14,170,60,-10)
# One value from the JSON line: a quoted string whole, or a number.
field() { sed -E "s/.*\"$1\": (\"([^\"]*)\"|([^,}]*)).*/\2\3/" <<<"$2"; }
# The ShadowPass row of a pipeline's per-pass list in the JSON (0 where it did not run).
shadow_ms() { grep -oE "\"$1_passes_ms\": \{[^}]*\}" <<<"$2" | grep -oE '"ShadowPass": [0-9.]+' | sed 's/.*: //' || echo 0; }
echo "| size | shadows | ShadowPass fwd ms | ShadowPass def ms | forward ms | deferred ms | floor ms | PSNR fwd vs def | deferred vs high |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"
for size in 1280x720 640x360; do
  "$oasis" render --size "$size" "${pose[@]}" --shadow-quality high --legend off --out "$out/high.png" > /dev/null 2>&1
  for setting in off low medium high; do
    if [[ $setting == off ]]; then flags=(--shadows off); else flags=(--shadow-quality "$setting"); fi
    json=$("$oasis" compare --size "$size" "${pose[@]}" "${flags[@]}" --frames "$frames" --passes --json \
           --out-dir "$out" 2>/dev/null)
    against=$("$oasis" compare --reference "$out/high.png" --size "$size" "${pose[@]}" "${flags[@]}" \
              --out-dir "$out/ref" 2>&1 | grep -oE 'PSNR [0-9.]+ dB' | head -1 | sed 's/PSNR //')
    awk -v size="$size" -v setting="$setting" -v sf="$(shadow_ms forward "$json")" -v sd="$(shadow_ms deferred "$json")" \
        -v f="$(field forward_ms "$json")" -v d="$(field deferred_ms "$json")" -v floor="$(field floor_ms "$json")" \
        -v psnr="$(field psnr_db "$json")" -v against="$against" 'BEGIN {
      printf "| %s | %s | %.1f | %.1f | %.1f | %.1f | %.1f | %.2f dB | %s |\n",
             size, setting, sf, sd, f, d, floor, psnr, against }'
  done
done
