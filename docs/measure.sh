#!/usr/bin/env bash
# Produces docs/measurements.md's timing tables: median ms per frame of each pipeline (wall time around
# glFinish) beside the floor timed in turn with them (compare's rounds: a forward frame, a deferred
# frame, the floor; each ratio is the median of the rounds' own), for each size, layout and
# reflection setting, then the cost of vegetation at several densities.
# usage: docs/measure.sh [path/to/oasis] [frames]   (run on an idle machine; prints markdown)
set -euo pipefail
oasis=${1:-build/oasis}
frames=${2:-15}
out=$(mktemp -d)
# One value from the JSON line: a quoted string whole, or a number.
field() { sed -E "s/.*\"$1\": (\"([^\"]*)\"|([^,}]*)).*/\2\3/" <<<"$2"; }
echo "| size | G-buffer | reflections | forward ms | deferred ms | floor ms | forward / floor | deferred / floor | PSNR fwd vs def |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"
for size in 1280x720 640x360; do
  for layout in compact standard full; do
    for reflections in on off; do
      json=$("$oasis" compare --size "$size" --gbuffer "$layout" --reflections "$reflections" \
             --frames "$frames" --json --out-dir "$out")
      awk -v size="$size" -v layout="$layout" -v bpp="$(field bytes_per_pixel "$json")" -v refl="$reflections" \
          -v f="$(field forward_ms "$json")" -v d="$(field deferred_ms "$json")" \
          -v floor="$(field floor_ms "$json")" -v psnr="$(field psnr_db "$json")" \
          -v fr="$(field forward_floor_ratio "$json")" -v dr="$(field deferred_floor_ratio "$json")" 'BEGIN {
        printf "| %s | %s (%s B/px) | %s | %.1f | %.1f | %.1f | %.2f | %.2f | %.1f dB |\n",
               size, layout, bpp, refl, f, d, floor, fr, dr, psnr }'
    done
  done
done
echo
echo "| vegetation (1280x720, default layout, reflections on) | plants placed | drawn (+ reflected) | forward ms | deferred ms | floor ms | PSNR fwd vs def |"
echo "| --- | --- | --- | --- | --- | --- | --- |"
for vegetation in "off" "on 0.5" "on 1" "on 2" "on 4"; do
  set -- $vegetation
  json=$("$oasis" compare --size 1280x720 --vegetation "$1" --vegetation-density "${2:-1}" \
         --frames "$frames" --json --out-dir "$out")
  label="$1${2:+, density $2}"
  awk -v label="$label" -v placed="$(field plants_placed "$json")" -v drawn="$(field plants_drawn "$json")" \
      -v mirrored="$(field plants_drawn_mirrored "$json")" -v f="$(field forward_ms "$json")" \
      -v d="$(field deferred_ms "$json")" -v floor="$(field floor_ms "$json")" -v psnr="$(field psnr_db "$json")" 'BEGIN {
    printf "| %s | %d | %d (+ %d) | %.1f | %.1f | %.1f | %.1f dB |\n", label, placed, drawn, mirrored, f, d, floor, psnr }'
done
echo
echo "renderer: $(field renderer "$json"); medians of $frames rounds; $(nproc) cores"
rm -rf "$out"
