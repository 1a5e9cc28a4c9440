// `compare --json` (commands/compare_json.h): the frame pair's numbers, times with their intervals,
// and with --passes each pass's times, traffic, the frames' graphs and target memory.
#include "commands/compare_json.h"

#include <cstdio>

#include "commands/timing_report.h"
#include "commands/traffic_report.h"
#include "context/gl_context.h"
#include "debug/debug_view_pass.h"
#include "frame/renderer.h"
#include "io/json_text.h"
#include "render/depth_convention.h"
#include "render/light_method.h"
#include "render/light_paths.h"
#include "render/plant_atlas.h"

namespace oasis {
namespace {

// Each pass's interval: {"TerrainPass.forward": [lo, hi], ...} under `key` (with --passes).
std::string passIntervalsJson(const char* key, const Comparison::PassStats& passes) {
    if (passes.empty()) return {};
    std::string json = std::string(", \"") + key + "\": {";
    char numbers[64];
    for (size_t i = 0; i < passes.size(); ++i) {
        std::snprintf(numbers, sizeof(numbers), "[%.4f, %.4f]", passes[i].second.low, passes[i].second.high);
        json += (i ? ", \"" : "\"") + passes[i].first + "\": " + numbers;
    }
    return json + "}";
}

std::string passTimesJson(const char* key, const Comparison::PassTimes& passes) {
    if (passes.empty()) return {};
    std::string json = std::string(", \"") + key + "\": {";
    char number[32];
    for (size_t i = 0; i < passes.size(); ++i) {
        std::snprintf(number, sizeof(number), "%.4f", passes[i].second);
        json += (i ? ", \"" : "\"") + passes[i].first + "\": " + number;
    }
    return json + "}";
}

// Beside the per-round ratios' medians (kept): the ratios of the medians, each stream's lowest and
// highest round, the largest spread and whether it is over the noise threshold (issue 31, defect 5).
std::string timingSpreadJson(const PipelineTimes& t) {
    char text[512];
    std::snprintf(text, sizeof(text),
                  "\"forward_over_floor\": %.4f, \"deferred_over_floor\": %.4f, \"forward_ms_lowest\": %.4f, "
                  "\"forward_ms_highest\": %.4f, \"deferred_ms_lowest\": %.4f, \"deferred_ms_highest\": %.4f, "
                  "\"floor_ms_lowest\": %.4f, \"floor_ms_highest\": %.4f, \"rounds_spread\": %.4f, "
                  "\"noise_threshold\": %.2f, \"noisy\": %s, ",
                  t.forwardOverFloor, t.deferredOverFloor, t.forwardLowest, t.forwardHighest, t.deferredLowest,
                  t.deferredHighest, t.floorLowest, t.floorHighest, t.spread, PipelineTimes::kNoiseSpread,
                  t.noisy() ? "true" : "false");
    return text;
}

// Which clock timed the passes and why (only with --passes: the check costs frames).
std::string passClockJson(const Comparison& c) {
    if (c.forwardPasses.empty()) return {};
    return ", \"pass_clock\": " + jsonString(c.clock.name()) + ", \"pass_clock_reason\": " + jsonString(c.clock.reason);
}

// The passes of each pipeline's frame in order, culled ones with their reason (with --passes).
std::string graphJson(const Comparison& c) {
    if (c.forwardPasses.empty()) return {};
    return ",\n \"graph\": {\"forward\": " + c.forwardGraph + ",\n  \"deferred\": " + c.deferredGraph + "}";
}

}  // namespace

void printCompareJson(const Options& options, const RenderSession& session, const Comparison& c) {
    const FrameTargets& targets = session.renderer->targets();
    ContextInfo info = queryContextInfo();
    const VegetationStats& plants = session.renderer->lastFrame().vegetation.stats();
    std::printf("{\"vegetation\": %s, \"vegetation_density\": %.3f, \"plants_placed\": %zu, \"plants_drawn\": %zu, "
                "\"plants_drawn_mirrored\": %zu, ",
                session.renderer->lastFrame().setup.vegetationEnabled ? "true" : "false", session.scene.vegetation.density,
                plants.plantsPlaced, plants.plantsDrawn, plants.plantsDrawnMirrored);
    std::printf("\"pixels_differing\": %s, ", c.differing.json().c_str());
    std::printf("\"psnr_db\": %.4f, \"max_abs\": %d, \"rmse\": %.6f, \"forward_ms\": %.4f, \"deferred_ms\": %.4f, "
                "\"floor_ms\": %.4f, \"forward_floor_ratio\": %.4f, \"deferred_floor_ratio\": %.4f, "
                "\"deferred_floor_ratio_lowest\": %.4f, \"deferred_floor_ratio_highest\": %.4f, %s%s\"width\": %d, \"height\": %d, \"gbuffer\": \"%s\", \"bytes_per_pixel\": %d, "
                "\"depth\": \"%s\", \"depth_reason\": \"%s\", \"gbuffer_bytes_per_pixel\": %d, "
                "\"time\": %.4f, \"frames\": %d, \"renderer\": \"%s\", \"stencil_view\": \"%s\", "
                "\"shader_dir\": \"%s\", \"plant_interpretation\": \"%s\", \"plant_atlas_ms\": %.4f, "
                "\"lights\": %d, \"lights_path\": \"%s\", \"lights_path_reason\": \"%s\", \"lights_dropped\": %d, "
                "\"light_method\": \"%s\", \"light_method_reason\": \"%s\", "
                "\"frame_order\": \"rounds\", \"frame_clock\": \"wall-glfinish\"%s%s%s%s%s%s%s%s%s%s}\n",
                c.difference.psnrDb, c.difference.maxAbs, c.difference.rmse, c.times.forwardMs, c.times.deferredMs,
                c.times.floorMs, c.times.forwardRatio, c.times.deferredRatio, c.times.deferredRatioLowest,
                c.times.deferredRatioHighest, timingSpreadJson(c.times).c_str(), timesStatsJson(c.times).c_str(),
                targets.width(), targets.height(), targets.layout().name.c_str(),
                gbufferBytesPerPixel(targets.layout(), targets.depth()), targets.depth().name.c_str(),
                session.renderer->paths().depthReason.c_str(), gbufferBytesPerPixel(targets.layout(), targets.depth()),
                options.scene.timeSeconds, c.times.rounds, info.renderer.c_str(),
                stencilViewPathName(session.renderer->views().stencilPath()), session.shaders->directory().c_str(),
                plantInterpretationName(session.plantAtlas->path()), session.plantAtlas->totalMs(),
                session.renderer->paths().lightsDrawn, lightsPathName(session.renderer->paths().lights.path),
                session.renderer->paths().lights.reason.c_str(), session.renderer->paths().lightsDropped,
                lightMethodName(session.renderer->paths().lightMethod.method), session.renderer->paths().lightMethod.reason.c_str(),
                passClockJson(c).c_str(), passTimesJson("forward_passes_ms", c.forwardPasses).c_str(),
                passTimesJson("deferred_passes_ms", c.deferredPasses).c_str(),
                passIntervalsJson("forward_passes_ci_ms", c.forwardPassStats).c_str(),
                passIntervalsJson("deferred_passes_ci_ms", c.deferredPassStats).c_str(),
                pipelineTrafficJson("forward", c.forwardTraffic).c_str(),
                pipelineTrafficJson("deferred", c.deferredTraffic).c_str(), floorTrafficJson(c.floorTraffic).c_str(),
                (c.forwardPasses.empty() ? std::string()
                                         : targetMemoryJson(c.forwardTargetBytes, c.deferredTargetBytes)).c_str(),
                graphJson(c).c_str());
}

}  // namespace oasis
