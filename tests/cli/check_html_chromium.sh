#!/bin/sh
# report.html of `oasis check` opened in a real browser (Debian's chromium-headless-shell): the
# counts the page shows are the report's, the browser decodes every embedded image, the flip and
# zoom controls work (check_html_controls.js, appended to a copy of the page, drives them), and a
# screenshot (WORK_DIR/report.png, 1200x900) is left for a person to look at.
# usage: check_html_chromium.sh SAMPLE_PROGRAM DOCS_DIR WORK_DIR
# Exits 77 (ctest: Skipped), saying why, when chromium-headless-shell is not installed.
sample=$1; docs=$2; work=$3
browser=$(command -v chromium-headless-shell) || {
  echo "check_html_in_chromium: skipped: chromium-headless-shell is not installed (.ci/setup installs it; or apt-get install chromium-headless-shell)"
  exit 77
}
fail() { echo "check_html_in_chromium: FAILED: $*"; exit 1; }

rm -rf "$work" && mkdir -p "$work" || fail "cannot make $work"
counts=$("$sample" "$work/report.html" "$docs") || fail "the sample report was not written"
profile=$(mktemp -d) || fail "no temporary directory"
trap 'rm -rf "$profile"' EXIT
# As root there is no sandbox; no GPU here; a container's /dev/shm is small; nothing to fetch.
open_page() {
  timeout 120 "$browser" --headless --no-sandbox --disable-gpu --disable-dev-shm-usage \
    --disable-background-networking --disable-component-update --no-first-run \
    --user-data-dir="$profile" "$@" 2>> "$work/chromium.log"
}

open_page --dump-dom "file://$work/report.html" > "$work/dom.html" ||
  fail "chromium exited $? on --dump-dom (log: $work/chromium.log)"
for verdict in pass fail skip; do
  expected=$(echo "$counts" | sed -n "s/.*$verdict \([0-9]*\).*/\1/p")
  shown=$(sed -n "s/.*id=\"count-$verdict\">\([0-9]*\)<.*/\1/p" "$work/dom.html")
  [ -n "$expected" ] && [ "$shown" = "$expected" ] || fail "#count-$verdict shows '$shown', the report has '$expected'"
done
# The page's own script counts the images the browser decoded: all of them, and at least one.
decoded=$(sed -n 's/.*id="images-decoded"[^>]*>\([0-9]*\) of \([0-9]*\) images decoded.*/\1 of \2/p' "$work/dom.html")
set -- $decoded
[ $# -eq 3 ] && [ "$1" = "$3" ] && [ "$1" -gt 0 ] || fail "images decoded by chromium: '$decoded' (or the page's script did not run)"

{ cat "$work/report.html"; echo "<script>"; cat "$(dirname "$0")/check_html_controls.js"; echo "</script>"; } > "$work/controls.html"
open_page --dump-dom "file://$work/controls.html" > "$work/controls-dom.html" ||
  fail "chromium exited $? on the controls' page (log: $work/chromium.log)"
controls=$(sed -n 's/.*<pre id="controls-check">\([^<]*\)<.*/\1/p' "$work/controls-dom.html")
[ "$controls" = "result, reference, result, zoom 2" ] ||
  fail "flip and zoom saw '$controls', not 'result, reference, result, zoom 2'"

open_page --screenshot="$work/report.png" --window-size=1200,900 "file://$work/report.html" > /dev/null ||
  fail "chromium exited $? on --screenshot (log: $work/chromium.log)"
[ -s "$work/report.png" ] || fail "no screenshot"
echo "check_html_in_chromium: OK ($counts; $decoded images decoded; flip and zoom work;" \
     "report.html $(wc -c < "$work/report.html") bytes; screenshot $work/report.png)"
