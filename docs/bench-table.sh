#!/usr/bin/env bash
# Turns `oasis bench`'s bench.csv into a markdown table (docs/bench-table.md; docs/bench.md the default rows).
# B/px counts every target the frame writes (compare's "bytes/pixel" the G-buffer alone).
# usage: docs/bench-table.sh [oasis-out/bench/bench.csv]
set -euo pipefail
csv=${1:-oasis-out/bench/bench.csv}
awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i;
  print "| size | lights | pipeline | layout | variation | ms median [95% interval] | x floor | PSNR dB | SSIM | max abs | own PSNR dB | B/px (all targets) | MiB | Pareto |"
  print "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"; next }
{ layout = $col["layout"] ($col["depth"] != "standard" ? "+" $col["depth"] : "")
  pareto = $col["pareto"] == "true" ? "**yes**" : ($col["pareto_in_pipeline"] == "true" ? "in pipeline" : "")
  # The interval of the median (issue 44); a CSV from before it has none: its range, so marked.
  interval = ("ms_ci_low" in col) ? sprintf("[%.1f, %.1f]", $col["ms_ci_low"], $col["ms_ci_high"]) \
                                   : sprintf("(range %.1f-%.1f)", $col["ms_min"], $col["ms_max"])
  printf "| %sx%s | %s | %s | %s | %s | %.1f %s | %.2f | %s | %s | %s | %.1f | %s | %.1f | %s |\n",
    $col["width"], $col["height"], $col["lights"], $col["pipeline"], layout, $col["variation"], $col["ms_median"],
    interval, $col["floor_ratio"], $col["psnr_db"], $col["ssim"], $col["max_abs"],
    $col["same_knobs_psnr_db"], $col["bytes_per_pixel"], $col["target_mib"], pareto }' "$csv"
