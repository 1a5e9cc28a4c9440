// `oasis bench`'s outputs from its results: the table on stdout, bench.json and bench.svg (the
// time against error plot), and the words and labels they share.
#pragma once
#include <string>
#include <vector>

#include "bench/bench.h"
#include "bench/bench_depth.h"
#include "bench/bench_report.h"
#include "frame/gpu_timer.h"
#include "scene/camera.h"

namespace oasis {

struct Options;

// A fixed frame of the run: its clock and camera.
struct BenchFrame {
    double time = 0.0;
    CameraPose pose;
};

// A floor timed alone: per size and layout.
struct Floor {
    int width, height;
    std::string layout;
    double ms;
};


// How the run was timed, in words: whole frames and the floor by wall time around glFinish on
// every driver (ratios compare like with like); passes by the clock the start-up check chose.
std::string timingNote(const TimingClock& clock);
std::string sizeName(int width, int height);  // "1280x720"
// The layout, and the depth convention and light method where they are not the defaults:
// "standard+reversed-z", "full+tiled".
std::string layoutLabel(const BenchConfig& config);
std::string tableText(const std::vector<BenchResult>& results);  // the table printed on stdout
std::string benchJson(const std::vector<BenchResult>& results, const std::vector<Floor>& floors,
                      const std::vector<BenchFrame>& frames, const BenchPlan& plan, const Options& options,
                      const std::string& renderer, const std::string& referenceLayout,
                      const std::vector<DepthPrecision>& depthPrecision);
std::string benchSvg(const std::vector<BenchResult>& results, const std::string& renderer);

}  // namespace oasis
