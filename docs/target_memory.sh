#!/usr/bin/env bash
# Produces docs/traffic.md's table of the frame's target memory (issue 43 item 5): for each
# G-buffer layout and frame (default, the separate tone map, the reflection at 1/2 and 1/4),
# `compare --passes --json`'s target_memory_bytes at 1280x720, and which targets the deferred
# frame's plan aliases (render --graph's "in the memory of" lines). About 12 minutes on llvmpipe.
#   docs/target_memory.sh [oasis] (markdown)
set -euo pipefail
oasis=${1:-build/oasis}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
frames=("default:" "--tone-map separate:--tone-map separate" "--reflection-resolution half:--reflection-resolution half"
        "--reflection-resolution quarter:--reflection-resolution quarter")
echo "| frame (1280x720, $("$oasis" caps | sed -n 's/^ *renderer  *//p' | cut -d' ' -f1), default scene) | layout | forward | deferred | deferred's aliasing |"
echo "| --- | --- | --- | --- | --- |"
for frame in "${frames[@]}"; do
  name=${frame%%:*}
  read -r -a extra <<< "${frame#*:}"
  for layout in full standard compact; do
    "$oasis" compare --size 1280x720 --frames 1 --passes --json --gbuffer "$layout" "${extra[@]}" \
      --out-dir "$scratch/out" > "$scratch/compare.json"
    aliased=$("$oasis" render --size 1280x720 --graph --pipeline deferred --gbuffer "$layout" "${extra[@]}" |
              sed -n 's/^# \([a-z-]*\) .*, in the memory of \([a-z-]*\).*/\1 in \2/p' | paste -sd, - | sed 's/,/, /g')
    python3 - "$scratch/compare.json" "$name" "$layout" "${aliased:-none}" <<'PY'
import json, sys
memory = json.load(open(sys.argv[1]))["target_memory_bytes"]
print(f"| {sys.argv[2]} | {sys.argv[3]} | {memory['forward']:,} | {memory['deferred']:,} | {sys.argv[4]} |")
PY
  done
done
