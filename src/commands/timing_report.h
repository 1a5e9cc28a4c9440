// compare's and the main job's times as text and JSON: each stream's median with its 95% interval,
// CV and outliers, the ratios with their intervals and the verdict in words (issue 44), from
// PipelineTimes (commands/session.h). GL-free, so tests/unit/timing_report_test.cpp reads it.
#pragma once
#include <string>

#include "commands/session.h"

namespace oasis {

// The summary's timing lines, each ending in '\n'; `terrainTriangles` is named in the method line.
std::string timesText(const PipelineTimes& times, int terrainTriangles);
// The JSON keys added by issue 44, each followed by ", ": forward_stats, deferred_stats,
// floor_stats, deferred_over_forward, forward_over_floor_ci, deferred_over_floor_ci, seed,
// round_order, until_ci (only with --until-ci).
std::string timesStatsJson(const PipelineTimes& times);

}  // namespace oasis
