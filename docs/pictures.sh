#!/usr/bin/env bash
# Renders the README's scene pictures into docs/ (1280x720 PNGs, no legend strip) with the built
# oasis: the default frame in both pipelines and its debug overview; day, dusk and night; sun shadows off and on; water at
# sunset with its stencil and reflection views; the meadow with its vegetation view; lights at night
# with their light-volumes view; and docs/inspecting.md's depth and normal-error views at 640x360
# with their legend strips. Open them after a run: a black or flat picture is a bug.
# tests/docs/docs_current.sh renders them into a scratch directory and holds docs/ to them pixel
# for pixel (issue 31, defect 7: default-deferred.png had drifted by one level).
# usage: docs/pictures.sh [path/to/oasis] [output directory, default docs]
set -euo pipefail
cd "$(dirname "$0")/.."
oasis=$(realpath "${1:-build/oasis}")
out=${2:-docs}
mkdir -p "$out"
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

picture() {
  local name=$1
  shift
  "$oasis" render --legend off "$@" --out "$out/$name" 2> /dev/null
  echo "$out/$name: oasis render $*"
}

# --frames 1: the frames are the same whatever the timing rounds.
"$oasis" compare --frames 1 --out-dir "$scratch" > /dev/null 2>&1
cp "$scratch/forward.png" "$out/default-forward.png"
cp "$scratch/deferred.png" "$out/default-deferred.png"
echo "$out/default-forward.png, $out/default-deferred.png: oasis compare"

# docs/inspecting.md's views with their legend strips (the README's inspector row).
picture inspect-depth-legend.png --size 640x360 --view depth --legend on
picture inspect-normal-error.png --size 640x360 --view normal-error --legend on

picture overview.png --view overview
picture scene-day.png --hour 10
picture scene-dusk.png --hour 18.2
picture scene-night.png --hour 21.5 --lights 64

shadowed=(--hour 8.5 --camera 420,14,170,60,-10)
picture shadows-off.png "${shadowed[@]}" --shadows off
picture shadows-on.png "${shadowed[@]}" --shadows on

sunset=(--hour 17.3 --camera 520,10,140,-90,-3)
picture water-sunset.png "${sunset[@]}"
picture stencil.png "${sunset[@]}" --view stencil
picture reflection.png "${sunset[@]}" --view reflection

meadow=(--camera 420,6,160,40,-4)
picture meadow.png "${meadow[@]}"
picture meadow-vegetation.png "${meadow[@]}" --view vegetation

night=(--lights 1024 --hour 21)
picture lights-night.png "${night[@]}"
picture light-volumes.png "${night[@]}" --view light-volumes
