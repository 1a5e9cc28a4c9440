// What `compare` measured of one frame pair: the two images and their difference, the pipelines'
// times against the floor, and with --passes each pass's time, traffic, graph and target memory.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "commands/session.h"
#include "frame/frame_traffic.h"
#include "frame/gpu_timer.h"
#include "render/image.h"
#include "stats/timing_stats.h"

namespace oasis {

struct Comparison {
    ImageDifference difference;
    DifferingPixels differing;  // how many pixels differ by more than 0, 1, 4, 16 levels
    PipelineTimes times;  // both pipelines and the floor, timed in turn
    Image forward, deferred;
    using PassTimes = std::vector<std::pair<std::string, double>>;
    PassTimes forwardPasses, deferredPasses;  // only with --passes
    using PassStats = std::vector<std::pair<std::string, SampleStats>>;
    PassStats forwardPassStats, deferredPassStats;  // their intervals, in the same order
    TimingClock clock;                        // how the passes were timed (measured with --passes)
    std::string forwardGraph, deferredGraph;  // each frame's graph as JSON (frame/frame_graph.h)
    FrameTraffic forwardTraffic, deferredTraffic, floorTraffic;  // counted with --passes
    double forwardTargetBytes = 0, deferredTargetBytes = 0;     // each frame's targets, as allocated
};

}  // namespace oasis
