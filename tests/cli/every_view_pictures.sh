#!/usr/bin/env bash
# Renders every debug view x pipeline x G-buffer layout in two scenes (day; night with four
# lights and the half-size reflection) plus the quarter-size reflection and the separate tone map
# (whose Final takes the G-buffer albedo's memory), 198 PNGs at 320x180, into a folder; with a second folder it compares the two bit for bit. Issue 43 item 1 moved the frame's
# targets into the graph and had to leave every picture as it was: before/after a change, run
#   tests/cli/every_view_pictures.sh render OLD/build/oasis before/
#   tests/cli/every_view_pictures.sh render build/oasis after/
#   tests/cli/every_view_pictures.sh compare before/ after/
set -euo pipefail
views=(final albedo normal position info depth stencil reflection radiance reflection-raw
       vegetation atlas light-volumes shadow overview)
error_views=(normal-error position-error position-error-steps)
scenes=(day night)
scene_args() {
  case $1 in
    day) echo "--size 320x180" ;;
    night) echo "--size 320x180 --hour 21 --lights 4 --reflection-resolution half" ;;
    quarter) echo "--size 320x180 --hour 17 --reflection-resolution quarter" ;;
    separate) echo "--size 320x180 --tone-map separate" ;;
  esac
}
render() {  # oasis folder
  local oasis=$1 out=$2 n=0
  mkdir -p "$out"
  one() {  # name, args...
    local name=$1; shift
    "$oasis" render "$@" --out "$out/$name.png" 2> "$out/$name.log" || { cat "$out/$name.log" >&2; exit 1; }
    n=$((n + 1))
  }
  for scene in "${scenes[@]}"; do
    for pipeline in forward deferred; do
      for layout in full standard compact; do
        for view in "${views[@]}"; do
          one "$scene-$pipeline-$layout-$view" $(scene_args "$scene") --pipeline $pipeline --gbuffer $layout --view $view
        done
      done
    done
    for layout in standard compact; do
      for view in "${error_views[@]}"; do
        one "$scene-deferred-$layout-$view" $(scene_args "$scene") --pipeline deferred --gbuffer $layout --view $view
      done
    done
  done
  for pipeline in forward deferred; do
    for view in final reflection; do
      one "quarter-$pipeline-compact-$view" $(scene_args quarter) --pipeline $pipeline --view $view
    done
    one "separate-$pipeline-compact-final" $(scene_args separate) --pipeline $pipeline --view final
  done
  echo "rendered $n pictures into $out"
}
compare() {  # before after: the pixels (IHDR and the inflated IDAT), not the text chunks, which
  # carry the command line and version
  python3 - "$1" "$2" <<'PY'
import os, struct, sys, zlib
def pixels(path):
    data, header, idat = open(path, "rb").read()[8:], b"", b""
    while data:
        length, = struct.unpack(">I", data[:4])
        kind, body = data[4:8], data[8:8 + length]
        header = body if kind == b"IHDR" else header
        idat += body if kind == b"IDAT" else b""
        data = data[12 + length:]
    return header, zlib.decompress(idat)
before, after = sys.argv[1], sys.argv[2]
names = sorted(n for n in os.listdir(before) if n.endswith(".png"))
same = [n for n in names if os.path.exists(os.path.join(after, n))
        and pixels(os.path.join(before, n)) == pixels(os.path.join(after, n))]
for n in names:
    if n not in same: print("differs:", n)
count = len([n for n in os.listdir(after) if n.endswith(".png")])
print(f"{len(same)} identical pixel for pixel, {len(names) - len(same)} different, of {len(names)} (after: {count})")
sys.exit(0 if len(same) == len(names) == count else 1)
PY
}
case ${1:-} in
  render) render "$2" "$3" ;;
  compare) compare "$2" "$3" ;;
  *) echo "usage: $0 render OASIS FOLDER | compare BEFORE AFTER" >&2; exit 2 ;;
esac
