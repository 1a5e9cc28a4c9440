// The window's live comparison: both sides (forward | deferred, or layout A | layout B) rendered
// every frame, shown split at a movable divider or as their difference heat map, with PSNR / max
// abs / RMSE of the displayed frame and each side's rolling median frame time with its 95% interval,
// and B over A with its paired interval and verdict (reset whenever the configuration or the
// scene's settings change); each frame draws the two sides in a random order. GL-free but for the renderer it drives.
#pragma once
#include <cstdint>
#include <deque>
#include <optional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "frame/gpu_timer.h"
#include "frame/renderer.h"
#include "render/image.h"

namespace oasis {

enum class CompareMode { Off, SplitPipelines, SplitLayouts, DifferencePipelines, DifferenceLayouts };
const char* compareModeName(CompareMode mode);
inline constexpr int kCompareModeCount = 5;
inline bool comparesLayouts(CompareMode mode) {
    return mode == CompareMode::SplitLayouts || mode == CompareMode::DifferenceLayouts;
}
inline bool showsDifference(CompareMode mode) {
    return mode == CompareMode::DifferencePipelines || mode == CompareMode::DifferenceLayouts;
}

// The median of the last `capacity` samples; cleared by reset().
class RollingMedian {
public:
    explicit RollingMedian(size_t capacity = 15) : capacity_(capacity) {}
    void add(double sample);
    void reset() { samples_.clear(); }
    double median() const;  // 0 with no samples
    size_t count() const { return samples_.size(); }
    std::vector<double> samples() const { return {samples_.begin(), samples_.end()}; }
    SampleStats stats() const { return describeSamples(samples()); }  // the median's interval, CV, outliers

private:
    size_t capacity_;
    std::deque<double> samples_;
};

// One side of the comparison: how to set the renderer up for it.
struct CompareSide {
    std::string label;  // "forward", "deferred (compact)"
    PipelineKind pipeline;
    size_t layoutIndex;
};

struct WindowComparison {
    CompareMode mode = CompareMode::Off;
    float divider = 0.5f;       // split: where side B starts, 0..1 of the width
    size_t layoutB = 0;         // layouts modes: the second layout (gbufferLayouts() index)
    bool passTimes = false;     // time each pass for the table, by `clock`
    std::optional<TimingClock> clock;  // measured when the table is first asked for
    PassTimerQueries queriesA, queriesB;  // the sides' non-stalling queries, where `clock` trusts them
    RollingMedian msA, msB;     // added to together: sample i of each is one frame's pair
    // Each frame's order of the two sides (a slow drift falls on neither side alone); the seed is shown.
    std::uint64_t seed = std::random_device{}() % 1000000;
    std::mt19937_64 order{seed};
    // B's median over A's with its bootstrap interval over the paired frames (0 rounds: none yet).
    RatioStats bOverA() const;
    std::string settingsKey;    // what the medians were measured for
    ImageDifference difference; // of the displayed sides
    std::vector<std::pair<std::string, double>> passesA, passesB;
    CompareSide a, b;

    // The two sides for the window's chosen pipeline and layout.
    void chooseSides(PipelineKind chosenPipeline, size_t chosenLayout);
    // Clears the medians when `key` (the configuration and the scene's settings) changed.
    void noteSettings(const std::string& key);
};

// Side B right of the divider (a column `dividerX`), with a 2-pixel white line between.
Image splitImage(const Image& a, const Image& b, int dividerX);

}  // namespace oasis
