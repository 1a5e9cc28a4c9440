#!/usr/bin/env bash
# Renders the README's scene pictures into docs/ (1280x720 PNGs, no legend strip) with the built
# oasis: the default frame in both pipelines and its debug overview; day, dusk and night; sun shadows off and on; water at
# sunset with its stencil and reflection views; the meadow with its vegetation view; lights at night
# with their light-volumes view. Open them after a run: a black or flat picture is a bug.
# usage: docs/pictures.sh [path/to/oasis]
set -euo pipefail
cd "$(dirname "$0")/.."
oasis=$(realpath "${1:-build/oasis}")
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

picture() {
  local name=$1
  shift
  "$oasis" render --legend off "$@" --out "docs/$name" > /dev/null
  echo "docs/$name: oasis render $*"
}

"$oasis" compare --out-dir "$scratch" > /dev/null
cp "$scratch/forward.png" docs/default-forward.png
cp "$scratch/deferred.png" docs/default-deferred.png
echo "docs/default-forward.png, docs/default-deferred.png: oasis compare"

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
