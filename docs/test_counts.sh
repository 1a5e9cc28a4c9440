#!/bin/sh
# The number of tests under each ctest label of the normal tree, as `ctest -N` counts them now
# (docs/tests.md's table; tests/docs/test_counts_current.sh holds the page to it).
# usage: docs/test_counts.sh BUILD_DIR
build=${1:-build}
echo "| label | tests |"
echo "| --- | --- |"
for label in unit shaders gpu cli capture window soak gpu-zink gpu-softpipe gpu-no-ssbo-compute gpu-gles gpu-gles31; do
    count=$(ctest --test-dir "$build" -N -L "^$label\$" | grep -c ' Test  *#')
    echo "| \`$label\` | $count |"
done
