// `oasis bench` without GL: the quality-knob table, the light-count workloads, the configurations a
// run measures, the Pareto frontiers of time against error, and one configuration's CSV row and JSON.
#pragma once
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "frame/pipeline.h"
#include "io/json_text.h"
#include "render/frame_setup.h"
#include "stats/timing_stats.h"

namespace oasis {

// One level of a quality knob: its label and how it changes the scene.
struct KnobLevel {
    std::string label;
    std::function<void(SceneSettings&)> apply;
};

// A quality knob: levels ordered from cheapest to highest quality; the reference render uses the
// last level of every knob; `defaultLevel` is what SceneSettings holds by default.
struct QualityKnob {
    std::string name;
    std::string description;
    std::vector<KnobLevel> levels;
    int defaultLevel = 0;
};

// The one table of knobs the bench varies (a new knob is one entry here).
const std::vector<QualityKnob>& qualityKnobs();

// The light counts the bench renders: a workload, not a quality knob. More lights make a different
// picture, not a more accurate one, so each count has its own reference (every knob at its highest,
// the same lights) and its own Pareto frontiers: error keeps measuring what the pipeline, layout and
// knobs lose, and time compares like with like. The default scene's count is one of them.
const std::vector<int>& benchLightCounts();
int defaultLightCount();  // SceneSettings' own
// --quick: the default count and the most.
std::vector<int> quickLightCounts();
// Forward is timed up to this many lights only: it shades every light in every fragment (about 21 ms
// per light per frame at 1280x720 on llvmpipe, docs/lights.md), so 256 lights take seconds a frame
// and 4096 over a minute; above it the counts compare the deferred light methods.
inline constexpr int kForwardBenchMaxLights = 32;

// The layout name of a forward configuration: forward writes no G-buffer, so no layout applies.
constexpr const char* kNoLayout = "none";

struct BenchConfig {
    PipelineKind pipeline = PipelineKind::Deferred;
    std::string layout;      // a gbufferLayouts() name, or kNoLayout for forward
    int width = 0, height = 0;
    std::vector<int> levels;  // one level index per knob of `knobs`
    int variedKnob = -1;      // the knob set away from its default, -1 for every knob at its default
    int lights = defaultLightCount();  // point lights in every frame (and in its reference)
    // Deferred's light method (the reference is volumes); rows with lights come in both methods.
    LightMethod lightMethod = LightMethod::Volumes;

    // "default" or e.g. "grid=coarse" or "lights=32": what this configuration changes.
    std::string variation(const std::vector<QualityKnob>& knobs) const;
    // Every knob's level, e.g. "grid=medium octaves=7 vegetation=1 reflections=on".
    std::string knobSettings(const std::vector<QualityKnob>& knobs) const;

    std::string depth = "standard";  // a depthConventions() name (bench/bench_depth.h adds reversed-z)
};

// Every knob at its highest level: the reference's settings.
std::vector<int> highestLevels(const std::vector<QualityKnob>& knobs);
std::vector<int> defaultLevels(const std::vector<QualityKnob>& knobs);
// The scene with each knob's chosen level applied in table order.
SceneSettings applyKnobs(SceneSettings scene, const std::vector<QualityKnob>& knobs, const std::vector<int>& levels);

// Per size and light count (in the order given): at the default light count, every knob at its
// default, then each knob alone at each other level (`cheapestOnly`: only its cheapest level); at
// any other count, every knob at its default only (a count is a workload, not crossed with every
// knob). For each of those, deferred with every layout (in the order given), each layout with the
// volumes and, with lights, the tiled light method, then forward once (it writes no G-buffer, so
// the layout does not change it; up to kForwardBenchMaxLights).
std::vector<BenchConfig> benchConfigs(const std::vector<QualityKnob>& knobs, const std::vector<std::string>& layouts,
                                      const std::vector<std::pair<int, int>>& sizes, bool cheapestOnly,
                                      const std::vector<int>& lightCounts = {defaultLightCount()});

// Minimise both: a point is off the frontier when another is at most as wrong and cheaper beyond
// the noise: the other's whole cost interval at or below this one's (and better in one of the two).
// Without intervals (low = high = cost) that is the plain rule: at most as costly and as wrong,
// better in one. Identical points are all on it (none beats another).
struct ParetoPoint {
    double cost = 0.0;
    double error = 0.0;
    double costLow = -1.0, costHigh = -1.0;  // the cost's 95% interval; negative: none (the cost itself)
    double low() const { return costLow >= 0.0 ? costLow : cost; }
    double high() const { return costHigh >= 0.0 ? costHigh : cost; }
};
std::vector<bool> paretoFrontier(const std::vector<ParetoPoint>& points);

struct BenchResult {
    BenchConfig config;
    std::string variation, knobSettings;
    double msMedian = 0.0, msMin = 0.0, msMax = 0.0;
    SampleStats ms;  // the timed frames' median with its 95% interval, CV and outliers (stats/timing_stats.h)
    double floorMs = 0.0;   // the floor (default layout, this size), median of the rounds timed with it
    double pairedFloorRatio = 0.0;  // median of its frames' ratios to their round's floor (0: not timed so)
    double psnrDb = 0.0, rmse = 0.0, ssim = 0.0;
    int maxAbs = 0;
    // Against the reference layout's deferred frame with the same knobs (the pipeline and layout's
    // own error, without the knobs'): pooled PSNR and the worst max abs.
    double sameKnobsPsnrDb = 0.0;
    int sameKnobsMaxAbs = 0;
    int bytesPerPixel = 0;         // render targets the pipeline's frame writes
    int gbufferBytesPerPixel = 0;  // of those, the G-buffer colour targets and depth-stencil (0 forward)
    double targetMiB = 0.0;        // bytesPerPixel x width x height
    std::vector<std::pair<std::string, double>> passesMs;  // median ms of each pass, in order
    // Memory traffic per pixel of the first frame, counted by the driver (frame/frame_traffic.h;
    // -1: this context cannot count it), its clears' share, and the floor's counted the same way.
    double trafficBytesPerPixel = -1.0, clearedBytesPerPixel = -1.0, floorTrafficBytesPerPixel = -1.0;
    bool pareto = false;            // on the frontier of every configuration of its size and light count
    bool paretoInPipeline = false;  // on the frontier of its size, light count and pipeline

    double floorRatio() const {
        if (pairedFloorRatio > 0.0) return pairedFloorRatio;
        return floorMs > 0.0 ? msMedian / floorMs : 0.0;
    }
    // What the table prints as xfloor: the median ms over this configuration's floor_ms, so the two
    // numbers a reader divides agree (the paired median above can differ from it by the noise:
    // 46.3x printed for 304.9 ms over a floor of 8.52, issue 31, defect 5).
    double msOverFloor() const { return floorMs > 0.0 ? msMedian / floorMs : 0.0; }
    // (ms max - ms min) / ms median of its timed frames; over kNoiseSpread the row is marked noisy.
    static constexpr double kNoiseSpread = 0.10;
    double msSpread() const { return msMedian > 0.0 ? (msMax - msMin) / msMedian : 0.0; }
    bool noisy() const { return msSpread() > kNoiseSpread; }
};

// Marks `pareto` and `paretoInPipeline` (cost: median ms with its interval; error: RMSE, which
// orders like PSNR).
void markParetoFrontiers(std::vector<BenchResult>& results);

std::string benchCsvHeader();
std::string benchCsvRow(const BenchResult& result);
std::string benchConfigJson(const BenchResult& result);

// The table's footer lines after the floors alone: per size the range of the floors timed in turn
// with the configurations (what xfloor divides by), and the rows marked noisy.
std::string floorsInTurnText(const std::vector<BenchResult>& results);

}  // namespace oasis
