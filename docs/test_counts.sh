#!/bin/sh
# The number of tests under each ctest label of the normal tree, as `ctest -N` counts them now
# (docs/tests.md's table; tests/docs/test_counts_current.sh holds the page to it).
# usage: docs/test_counts.sh BUILD_DIR
# ctest -N runs on a copy of the tree's test files: run inside the suite, a ctest in the tree itself
# writes its Testing/Temporary/LastTest.log anew, under the running suite's (.ci/run reads that log).
build=${1:-build}
listing=$(mktemp -d) || exit 1
trap 'rm -rf "$listing"' EXIT
(cd "$build" && find . -name CTestTestfile.cmake) | while read -r file; do
    mkdir -p "$listing/$(dirname "$file")" && cp "$build/$file" "$listing/$file"
done
echo "| label | tests |"
echo "| --- | --- |"
for label in unit shaders gpu cli capture window soak gpu-zink gpu-softpipe gpu-no-ssbo-compute gpu-gles gpu-gles31; do
    count=$(ctest --test-dir "$listing" -N -L "^$label\$" | grep -c ' Test  *#')
    echo "| \`$label\` | $count |"
done
