// The window's live comparison: sides, rolling medians, the split image.
#include "window/window_compare.h"

#include <algorithm>
#include <stdexcept>

namespace oasis {

const char* compareModeName(CompareMode mode) {
    switch (mode) {
        case CompareMode::Off: return "off";
        case CompareMode::SplitPipelines: return "split: forward | deferred";
        case CompareMode::SplitLayouts: return "split: layout A | layout B (deferred)";
        case CompareMode::DifferencePipelines: return "difference: forward - deferred";
        case CompareMode::DifferenceLayouts: return "difference: layout A - layout B (deferred)";
    }
    return "?";
}

void RollingMedian::add(double sample) {
    samples_.push_back(sample);
    while (samples_.size() > capacity_) samples_.pop_front();
}

double RollingMedian::median() const { return oasis::median(samples()); }

RatioStats WindowComparison::bOverA() const {
    std::vector<double> a = msA.samples(), b = msB.samples();
    if (a.empty() || a.size() != b.size()) return {};
    // A fixed seed per call: the interval of the same frames does not flicker from frame to frame.
    return pairedMedianRatio(b, a, seed, 500);
}

void WindowComparison::chooseSides(PipelineKind chosenPipeline, size_t chosenLayout) {
    const auto& layouts = gbufferLayouts();
    if (comparesLayouts(mode)) {
        a = {"deferred, " + layouts[chosenLayout].name, PipelineKind::Deferred, chosenLayout};
        b = {"deferred, " + layouts[layoutB].name, PipelineKind::Deferred, layoutB};
    } else {
        a = {"forward", PipelineKind::Forward, chosenLayout};
        b = {"deferred, " + layouts[chosenLayout].name, PipelineKind::Deferred, chosenLayout};
    }
    (void)chosenPipeline;  // both pipelines are drawn; the chosen one is side A or B
}

void WindowComparison::noteSettings(const std::string& key) {
    if (key == settingsKey) return;
    settingsKey = key;
    msA.reset();
    msB.reset();
}

Image splitImage(const Image& a, const Image& b, int dividerX) {
    if (a.width != b.width || a.height != b.height) throw std::invalid_argument("split: the sides differ in size");
    Image out = a;
    dividerX = std::clamp(dividerX, 0, a.width);
    for (int y = 0; y < a.height; ++y)
        for (int x = dividerX; x < a.width; ++x) std::copy_n(b.pixel(x, y), 4, out.pixel(x, y));
    for (int y = 0; y < a.height; ++y)
        for (int x = std::max(0, dividerX - 1); x < std::min(a.width, dividerX + 1); ++x) {
            uint8_t* p = out.pixel(x, y);
            p[0] = p[1] = p[2] = 255;
        }
    return out;
}

}  // namespace oasis
