// `oasis bench`: time against error over pipeline x G-buffer layout x quality knob x size, on fixed
// frames of the camera path, with the floor measured in the same run; table, CSV, JSON and SVG.
#pragma once
#include <cstdint>
#include <utility>
#include <vector>

#include "cli/options.h"
#include "frame/gpu_timer.h"

namespace oasis {

// What a run measures: sizes, the fixed frames (times along the default camera path) and how many
// frames it times. --quick: one frame at 320x180, each knob's cheapest level only, the default and
// the most lights, few timed frames.
struct BenchPlan {
    std::vector<std::pair<int, int>> sizes;
    std::vector<int> lightCounts;    // bench_report.h: benchLightCounts()
    std::vector<double> frameTimes;  // seconds along defaultCameraPath; the pose is fixed per frame
    int timedFrames = 7;             // per fixed frame, after warm-up
    int passFrames = 3;              // per fixed frame, by `clock`: timer queries or glFinish after every pass
    int floorFrames = 9;
    bool cheapestOnly = false;
    TimingClock clock;               // how passes are timed: measured at the run's start
    bool captureFirstTimedFrame = false;  // --capture: RenderDoc captures the run's first timed frame
    std::uint64_t seed = 0;  // each round's order of the configurations and the floor (--seed; printed)
    std::string workarounds;  // the driver workarounds in effect ("a,b"; "" none): bench.json records them
};
BenchPlan benchPlan(const Options& options);

// Returns the exit code: 0 done, 1 a runtime failure (message printed).
int runBenchCommand(const Options& options);

}  // namespace oasis
