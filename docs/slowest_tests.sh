#!/bin/sh
# The 20 slowest tests, from ctest's own record of the runs in each build tree
# (Testing/Temporary/CTestCostData.txt: a line per test with its run count and average seconds),
# as the Markdown table docs/tests.md shows; .ci/test prints it at the end of every run.
# usage: docs/slowest_tests.sh BUILD_DIR...   (a tree without a record is left out)
set -u
for tree in "$@"; do
    record=$tree/Testing/Temporary/CTestCostData.txt
    [ -f "$record" ] || continue
    # Lines "NAME RUNS SECONDS" until the "---" that starts the list of failed tests.
    awk -v tree="$(basename "$tree")" '$0 == "---" { exit } NF == 3 { printf "%.1f %s %s\n", $3, tree, $1 }' "$record"
done | sort -g -r | head -n 20 | awk 'BEGIN { print "| seconds | tree | test |"; print "| ---: | --- | --- |" }
                                        { printf "| %s | %s | `%s` |\n", $1, $2, $3 }'
