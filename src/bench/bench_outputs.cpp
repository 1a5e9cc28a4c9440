// `oasis bench`'s outputs from its results: the table, bench.json and bench.svg.
#include "bench/bench_outputs.h"

#include <algorithm>
#include <map>
#include <set>

#include "cli/options.h"
#include "bench/svg_plot.h"
#include "render/gbuffer_layout.h"
#include "render/image.h"

namespace oasis {

std::string timingNote(const TimingClock& clock) {
    return "frames: wall clock around glFinish; passes: " + clock.describe();
}

std::string sizeName(int width, int height) { return std::to_string(width) + "x" + std::to_string(height); }

std::string layoutLabel(const BenchConfig& config) {
    // A non-default depth or light method follows the layout: "standard+reversed-z", "full+tiled".
    std::string label = config.depth == standardDepthConvention().name ? config.layout : config.layout + "+" + config.depth;
    return config.lightMethod == LightMethod::Volumes ? label : label + "+" + lightMethodName(config.lightMethod);
}

std::string tableText(const std::vector<BenchResult>& results) {
    // The text columns as wide as their longest entry, so a long variation ("lights=4096
    // reflections=off") shifts no column after it.
    int layoutWidth = 6, variationWidth = 9;
    for (const BenchResult& r : results) {
        layoutWidth = std::max(layoutWidth, int(layoutLabel(r.config).size()));
        variationWidth = std::max(variationWidth, int(r.variation.size()));
    }
    std::string text;
    char line[512];
    std::snprintf(line, sizeof(line), "%-9s %6s %-8s %-*s %-*s %8s %-19s %5s %6s %7s %7s %4s %6s %7s %5s %6s %8s %s\n",
                  "size", "lights", "pipeline", layoutWidth, "layout", variationWidth, "variation", "ms med",
                  "95% interval", "CV%", "xfloor", "PSNR dB", "RMSE", "max", "SSIM", "own dB", "B/px", "MiB", "moved/px",
                  "pareto");
    text += line;
    for (const BenchResult& r : results) {
        const BenchConfig& c = r.config;
        const char* pareto = r.pareto ? "yes" : r.paretoInPipeline ? "in pipeline" : "";
        std::snprintf(line, sizeof(line), "%-9s %6d %-8s %-*s %-*s %8.2f %-19s %5.1f %6.2f %7.2f %7.3f %4d %6.4f %7.2f %5d %6.1f %8.1f %s\n",
                      sizeName(c.width, c.height).c_str(), c.lights, pipelineName(c.pipeline), layoutWidth,
                      layoutLabel(c).c_str(), variationWidth, r.variation.c_str(), r.msMedian,
                      (intervalText(r.ms.low, r.ms.high) + (r.ms.confidence < kIntervalConfidence ? "*" : "")).c_str(),
                      100.0 * r.ms.cv, r.msOverFloor(), r.psnrDb, r.rmse,
                      r.maxAbs, r.ssim, r.sameKnobsPsnrDb, r.bytesPerPixel, r.targetMiB, r.trafficBytesPerPixel, pareto);
        text += line;
    }
    return text;
}

namespace {

std::string lightCountsJson(const std::vector<int>& counts) {
    std::string text;
    for (int count : counts) text += (text.empty() ? "" : ", ") + std::to_string(count);
    return text;
}

}  // namespace

std::string benchJson(const std::vector<BenchResult>& results, const std::vector<Floor>& floors,
                      const std::vector<BenchFrame>& frames, const BenchPlan& plan, const Options& options,
                      const std::string& renderer, const std::string& referenceLayout,
                      const std::vector<DepthPrecision>& depthPrecision) {
    const std::vector<QualityKnob>& knobs = qualityKnobs();
    std::string json = "{\"renderer\": " + jsonString(renderer) + ", \"timing\": \"wall clock around glFinish\"" +
                       ", \"timing_note\": " + jsonString(timingNote(plan.clock)) +
                       ", \"frame_clock\": \"wall-glfinish\", \"pass_clock\": " + jsonString(plan.clock.name()) +
                       ", \"pass_clock_reason\": " + jsonString(plan.clock.reason) +
                       ", \"workarounds\": " + jsonString(plan.workarounds) +
                       ", \"quick\": " + (options.quick ? "true" : "false") + ", \"seed\": " + std::to_string(plan.seed) +
                       ", \"round_order\": \"random\"" +
                       ", \"timed_frames_per_frame\": " + std::to_string(plan.timedFrames) +
                       ", \"pass_frames_per_frame\": " + std::to_string(plan.passFrames) + ", \"frames\": [";
    for (size_t i = 0; i < frames.size(); ++i) {
        const CameraPose& p = frames[i].pose;
        json += std::string(i ? ", " : "") + "{\"time\": " + jsonNumber(frames[i].time, 2) + ", \"camera\": [" +
                jsonNumber(p.position.x, 3) + ", " + jsonNumber(p.position.y, 3) + ", " + jsonNumber(p.position.z, 3) +
                ", " + jsonNumber(p.yawDegrees, 3) + ", " + jsonNumber(p.pitchDegrees, 3) + "]}";
    }
    json += "], \"reference\": {\"pipeline\": \"deferred\", \"layout\": " + jsonString(referenceLayout) +
            ", \"knobs\": " + jsonString(BenchConfig{PipelineKind::Deferred, referenceLayout, 0, 0, highestLevels(knobs), -1}
                                             .knobSettings(knobs)) +
            ", \"lights\": \"the configuration's\"}, \"light_counts\": [" + lightCountsJson(plan.lightCounts) +
            "], \"error\": \"against the reference at the same frame, size and light count, pooled over the frames: PSNR and RMSE "
            "from the mean squared error of 8-bit RGB, max_abs the worst, ssim the mean over frames (luminance, "
            "11x11 Gaussian windows)\", \"floor\": \"full-screen G-buffer write + read with the default layout (" +
            defaultGBufferLayout().name + "), per size (floors: alone, every layout); a config's floor_ms is the median of "
            "the floors timed in turn with its frames, its floor_ratio the median of each frame's ms over its round's "
            "floor\", \"default_layout\": " +
            jsonString(defaultGBufferLayout().name) + ", \"knobs\": [";
    for (size_t k = 0; k < knobs.size(); ++k) {
        json += std::string(k ? ", " : "") + "{\"name\": " + jsonString(knobs[k].name) +
                ", \"description\": " + jsonString(knobs[k].description) + ", \"levels\": [";
        for (size_t l = 0; l < knobs[k].levels.size(); ++l)
            json += std::string(l ? ", " : "") + jsonString(knobs[k].levels[l].label);
        json += "], \"default\": " + jsonString(knobs[k].levels[size_t(knobs[k].defaultLevel)].label) + "}";
    }
    json += "], \"floors\": [";
    for (size_t i = 0; i < floors.size(); ++i)
        json += std::string(i ? ", " : "") + "{\"width\": " + std::to_string(floors[i].width) + ", \"height\": " +
                std::to_string(floors[i].height) + ", \"layout\": " + jsonString(floors[i].layout) +
                ", \"floor_ms\": " + jsonNumber(floors[i].ms) + "}";
    json += "], \"configs\": [\n";
    for (size_t i = 0; i < results.size(); ++i) json += (i ? ",\n  " : "  ") + benchConfigJson(results[i]);
    return json + "\n], " + depthPrecisionJsonFields(depthPrecision) + "}\n";
}

std::string benchSvg(const std::vector<BenchResult>& results, const std::string& renderer) {
    std::vector<PlotPanel> panels;
    std::map<std::string, size_t> panelOf;
    for (const BenchResult& r : results) {
        // One panel per frontier: a size and a light count.
        std::string size = sizeName(r.config.width, r.config.height) + ", " + std::to_string(r.config.lights) +
                           (r.config.lights == 1 ? " light" : " lights");
        if (!panelOf.count(size)) {
            panelOf[size] = panels.size();
            panels.push_back({size, {}});
        }
        std::string label = (r.config.layout == kNoLayout ? std::string() : layoutLabel(r.config) + " ") + r.variation;
        PlotPoint point{r.msMedian, r.rmse, pipelineName(r.config.pipeline), label, r.pareto, r.paretoInPipeline};
        if (r.ms.count > 0) point.xLow = r.ms.low, point.xHigh = r.ms.high;
        panels[panelOf[size]].points.push_back(point);
    }
    PlotText text{"oasis bench: time against error (Pareto frontiers per size and light count, and per pipeline)",
                  "median ms per frame (wall time around glFinish), bars: its 95% interval",
                  "RMSE against the reference (8-bit RGB)",
                  "reference: deferred, full layout, every knob at its highest, the same lights; " + renderer};
    std::set<int> lightCounts;  // a row per size, a column per light count
    for (const BenchResult& r : results) lightCounts.insert(r.config.lights);
    text.columns = int(lightCounts.size());
    return scatterPlotSvg(panels, text);
}

}  // namespace oasis
