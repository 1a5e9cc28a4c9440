#!/usr/bin/env bash
# The web build's download size (docs/web.md): oasis.wasm + oasis.js gzipped must stay under 3 MB;
# prints each file's size and the total. usage: size.sh BUILD_WEB_DIR
set -euo pipefail
dir=${1:-build-web}
total=0
for f in oasis.wasm oasis.js oasis.data; do
    raw=$(stat -c %s "$dir/$f")
    gz=$(gzip -9 -c "$dir/$f" | wc -c)
    printf 'web size: %-10s %9d bytes, %9d gzipped\n' "$f" "$raw" "$gz"
    [ "$f" = oasis.data ] || total=$((total + gz))
done
awk -v t="$total" 'BEGIN { printf "web size: oasis.wasm + oasis.js gzipped: %d bytes (%.2f MB; limit 3 MB)\n", t, t / 1e6 }'
[ "$total" -lt 3000000 ]
