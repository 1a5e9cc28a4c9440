// The bench's knob table, light counts, configurations, Pareto frontier and CSV/JSON formatting (no GL).
#include "bench/bench_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "cli/option_table.h"
#include "cli/options.h"
#include "io/decimal_text.h"

namespace oasis {
namespace {

KnobLevel gridLevel(const char* label, int rings, int segments) {
    return {label, [rings, segments](SceneSettings& scene) {
                scene.grid.rings = rings;
                scene.grid.segments = segments;
            }};
}

KnobLevel octaveLevel(const char* label, int octaves) {
    return {label, [octaves](SceneSettings& scene) { scene.terrain.octaves = octaves; }};
}

KnobLevel vegetationLevel(const char* label, bool enabled, float density) {
    return {label, [enabled, density](SceneSettings& scene) {
                scene.vegetation.enabled = enabled;
                scene.vegetation.density = density;
            }};
}

// A knob made from an option's row (cli/option_table.h): its levels are values of the option,
// applied to the scene as the command line would set them.
QualityKnob optionKnob(const char* flag) {
    const OptionRow& row = *findOption(flag);
    QualityKnob knob{row.bench.knob, row.bench.description, {}, row.bench.defaultLevel};
    for (const char* level : row.bench.levels) {
        std::string value = level;
        knob.levels.push_back({level, [&row, value](SceneSettings& scene) {
                                   Options options;
                                   options.scene = sceneOptionsOf(scene);
                                   std::vector<std::string> notes;
                                   std::string error;
                                   readOption(row, value, options, notes, error);
                                   applySceneOptions(options.scene, scene);
                               }});
    }
    return knob;
}

// Sun shadows: off, then every level of the shadow quality table (render/shadow_cascades.cpp).
QualityKnob shadowKnob() {
    QualityKnob knob{"shadows", "sun shadows off, or the shadow quality table's cascades x map size:", {}, 0};
    knob.levels.push_back({"off", [](SceneSettings& scene) { scene.shadows.enabled = false; }});
    for (const ShadowQuality& quality : shadowQualities()) {
        std::string name = quality.name;
        knob.description += " " + name + " " + std::to_string(quality.cascades) + " x " +
                            std::to_string(quality.mapSize) + "^2";
        if (name == ShadowSettings{}.quality) knob.defaultLevel = int(knob.levels.size());
        knob.levels.push_back({quality.name, [name](SceneSettings& scene) {
                                   scene.shadows.enabled = true;
                                   scene.shadows.quality = name;
                               }});
    }
    return knob;
}

// The scene's own knobs, then every option row that has bench levels, in the rows' order (bench.csv
// and bench.json list them so), then the shadows.
std::vector<QualityKnob> makeKnobs() {
    std::vector<QualityKnob> knobs = {
        {"grid", "terrain grid rings x segments (38,400 triangles at medium)",
         {gridLevel("coarse", 75, 64), gridLevel("medium", 150, 128), gridLevel("fine", 300, 256)}, 1},
        {"octaves", "simplex-noise octaves of the terrain height", {octaveLevel("3", 3), octaveLevel("5", 5),
         octaveLevel("7", 7)}, 2},
        {"vegetation", "plant density (off, or times the default candidates per chunk)",
         {vegetationLevel("off", false, 1.0f), vegetationLevel("0.5", true, 0.5f), vegetationLevel("1", true, 1.0f)}, 2},
    };
    for (const OptionRow& row : optionTable())
        if (row.bench.knob) knobs.push_back(optionKnob(row.flag));
    knobs.push_back(shadowKnob());
    return knobs;
}
const std::vector<QualityKnob> kKnobs = makeKnobs();

// Light counts: none (the default scene), 4 (where deferred starts to win on llvmpipe: the README's
// lights table has the pipelines even at 1 and deferred ahead from 4) and 32. Not more: forward
// shades every light in every fragment and its cost grows with the count, deferred pays each
// volume's pixels. Measured in a full run on a loaded llvmpipe (2 cores) at 1280x720: forward 221,
// 643 and 2404 ms a frame at 0, 4 and 32 lights, deferred (standard) 293, 381 and 364 ms; the 4-
// and 32-light configurations took 222 s of the run's 660. 128 lights would add about 4x that.
// 256 and 4096 compare the deferred light methods (forward stops at kForwardBenchMaxLights).
const std::vector<int> kLightCounts = {0, 4, 32, 256, 4096};

std::string passesText(const BenchResult& result) {
    std::string text;
    for (const auto& [name, ms] : result.passesMs) text += (text.empty() ? "" : ";") + name + "=" + formatNumber("%.3f", ms);
    return text;
}

std::string csvField(const std::string& text) {
    if (text.find_first_of(",\"\n") == std::string::npos) return text;
    std::string quoted = "\"";
    for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

}  // namespace

const std::vector<QualityKnob>& qualityKnobs() { return kKnobs; }

const std::vector<int>& benchLightCounts() { return kLightCounts; }
int defaultLightCount() { return LightSettings{}.count; }
std::vector<int> quickLightCounts() {
    std::vector<int> counts = {defaultLightCount()};
    int most = *std::max_element(kLightCounts.begin(), kLightCounts.end());
    if (most != counts[0]) counts.push_back(most);
    return counts;
}

std::string BenchConfig::variation(const std::vector<QualityKnob>& knobs) const {
    std::string text = lights != defaultLightCount() ? "lights=" + std::to_string(lights) : "";
    if (variedKnob >= 0) {
        const QualityKnob& knob = knobs[size_t(variedKnob)];
        text += (text.empty() ? "" : " ") + knob.name + "=" + knob.levels[size_t(levels[size_t(variedKnob)])].label;
    }
    return text.empty() ? "default" : text;
}

std::string BenchConfig::knobSettings(const std::vector<QualityKnob>& knobs) const {
    std::string text;
    for (size_t i = 0; i < knobs.size(); ++i)
        text += (i ? " " : "") + knobs[i].name + "=" + knobs[i].levels[size_t(levels[i])].label;
    return text;
}

std::vector<int> highestLevels(const std::vector<QualityKnob>& knobs) {
    std::vector<int> levels;
    for (const QualityKnob& knob : knobs) levels.push_back(int(knob.levels.size()) - 1);
    return levels;
}

std::vector<int> defaultLevels(const std::vector<QualityKnob>& knobs) {
    std::vector<int> levels;
    for (const QualityKnob& knob : knobs) levels.push_back(knob.defaultLevel);
    return levels;
}

SceneSettings applyKnobs(SceneSettings scene, const std::vector<QualityKnob>& knobs, const std::vector<int>& levels) {
    for (size_t i = 0; i < knobs.size(); ++i) knobs[i].levels[size_t(levels[i])].apply(scene);
    return scene;
}

std::vector<BenchConfig> benchConfigs(const std::vector<QualityKnob>& knobs, const std::vector<std::string>& layouts,
                                      const std::vector<std::pair<int, int>>& sizes, bool cheapestOnly,
                                      const std::vector<int>& lightCounts) {
    std::vector<std::pair<int, std::vector<int>>> settings = {{-1, defaultLevels(knobs)}};
    for (size_t k = 0; k < knobs.size(); ++k)
        for (int level = 0; level < int(knobs[k].levels.size()); ++level) {
            if (level == knobs[k].defaultLevel || (cheapestOnly && level != 0)) continue;
            std::vector<int> levels = defaultLevels(knobs);
            levels[k] = level;
            settings.emplace_back(int(k), levels);
        }
    std::vector<BenchConfig> configs;
    for (const auto& [width, height] : sizes)
        for (int lights : lightCounts)
            for (const auto& [varied, levels] : settings) {
                if (lights != defaultLightCount() && varied >= 0) continue;
                BenchConfig config;
                config.width = width;
                config.height = height;
                config.levels = levels;
                config.variedKnob = varied;
                config.lights = lights;
                config.pipeline = PipelineKind::Deferred;
                for (const std::string& layout : layouts) {
                    config.layout = layout;
                    config.lightMethod = LightMethod::Volumes;
                    configs.push_back(config);
                    if (lights == 0) continue;  // without lights the methods draw the same passes
                    config.lightMethod = LightMethod::Tiled;
                    configs.push_back(config);
                }
                config.lightMethod = LightMethod::Volumes;
                if (lights > kForwardBenchMaxLights) continue;
                config.pipeline = PipelineKind::Forward;
                config.layout = kNoLayout;
                configs.push_back(config);
            }
    return configs;
}

std::vector<bool> paretoFrontier(const std::vector<ParetoPoint>& points) {
    std::vector<bool> frontier(points.size(), true);
    for (size_t i = 0; i < points.size(); ++i)
        for (size_t j = 0; j < points.size() && frontier[i]; ++j) {
            const ParetoPoint &a = points[i], &b = points[j];
            bool noWorse = b.high() <= a.low() && b.error <= a.error;
            bool better = b.high() < a.low() || b.error < a.error;
            if (j != i && noWorse && better) frontier[i] = false;
        }
    return frontier;
}

void markParetoFrontiers(std::vector<BenchResult>& results) {
    // Groups: a size and light count (every configuration), and those within one pipeline. Only
    // configurations of the same light count share a frontier: their errors are against the same
    // reference and their times are of the same work.
    std::map<std::string, std::vector<size_t>> bySize, byPipeline;
    for (size_t i = 0; i < results.size(); ++i) {
        const BenchConfig& c = results[i].config;
        std::string size = std::to_string(c.width) + "x" + std::to_string(c.height) + " " + std::to_string(c.lights);
        bySize[size].push_back(i);
        byPipeline[size + pipelineName(c.pipeline)].push_back(i);
    }
    auto mark = [&](const std::map<std::string, std::vector<size_t>>& groups, bool BenchResult::*flag) {
        for (const auto& [key, members] : groups) {
            std::vector<ParetoPoint> points;
            for (size_t i : members) {
                const BenchResult& r = results[i];
                bool interval = r.ms.count > 0;  // timed: its interval; else (tests' rows) the median alone
                points.push_back({r.msMedian, r.rmse, interval ? r.ms.low : -1.0, interval ? r.ms.high : -1.0});
            }
            std::vector<bool> frontier = paretoFrontier(points);
            for (size_t m = 0; m < members.size(); ++m) results[members[m]].*flag = frontier[m];
        }
    };
    mark(bySize, &BenchResult::pareto);
    mark(byPipeline, &BenchResult::paretoInPipeline);
}

std::string benchCsvHeader() {
    return "pipeline,layout,width,height,variation,knobs,lights,ms_median,ms_min,ms_max,floor_ms,floor_ratio,"
           "psnr_db,rmse,max_abs,ssim,same_knobs_psnr_db,same_knobs_max_abs,bytes_per_pixel,gbuffer_bytes_per_pixel,target_mib,pareto,"
           "pareto_in_pipeline,passes_ms,depth,light_method,traffic_bytes_per_pixel,cleared_bytes_per_pixel,"
           "floor_traffic_bytes_per_pixel,ms_ci_low,ms_ci_high,ms_cv,ms_outliers_mild,ms_outliers_severe";
}

std::string benchCsvRow(const BenchResult& r) {
    const BenchConfig& c = r.config;
    return std::string(pipelineName(c.pipeline)) + "," + csvField(c.layout) + "," + std::to_string(c.width) + "," +
           std::to_string(c.height) + "," + csvField(r.variation) + "," + csvField(r.knobSettings) + "," +
           std::to_string(c.lights) + "," + formatNumber("%.3f", r.msMedian) + "," + formatNumber("%.3f", r.msMin) + "," + formatNumber("%.3f", r.msMax) + "," +
           formatNumber("%.3f", r.floorMs) + "," + formatNumber("%.3f", r.floorRatio()) + "," + formatNumber("%.3f", r.psnrDb) + "," +
           formatNumber("%.4f", r.rmse) + "," + std::to_string(r.maxAbs) + "," + formatNumber("%.5f", r.ssim) + "," + formatNumber("%.3f", r.sameKnobsPsnrDb) + "," + std::to_string(r.sameKnobsMaxAbs) + "," +
           std::to_string(r.bytesPerPixel) + "," + std::to_string(r.gbufferBytesPerPixel) + "," +
           formatNumber("%.2f", r.targetMiB) + "," + (r.pareto ? "true" : "false") + "," +
           (r.paretoInPipeline ? "true" : "false") + "," + csvField(passesText(r)) + "," + csvField(c.depth) + "," +
           lightMethodName(c.lightMethod) + "," + formatNumber("%.4f", r.trafficBytesPerPixel) + "," +
           formatNumber("%.4f", r.clearedBytesPerPixel) + "," + formatNumber("%.4f", r.floorTrafficBytesPerPixel) + "," +
           formatNumber("%.3f", r.ms.low) + "," + formatNumber("%.3f", r.ms.high) + "," + formatNumber("%.4f", r.ms.cv) +
           "," + std::to_string(r.ms.outliers.mild) + "," + std::to_string(r.ms.outliers.severe);
}

std::string benchConfigJson(const BenchResult& r) {
    const BenchConfig& c = r.config;
    std::string passes;
    for (const auto& [name, ms] : r.passesMs) passes += (passes.empty() ? "" : ", ") + jsonString(name) + ": " + jsonNumber(ms);
    return "{\"pipeline\": " + jsonString(pipelineName(c.pipeline)) + ", \"layout\": " + jsonString(c.layout) +
           ", \"width\": " + std::to_string(c.width) + ", \"height\": " + std::to_string(c.height) +
           ", \"variation\": " + jsonString(r.variation) + ", \"knobs\": " + jsonString(r.knobSettings) +
           ", \"lights\": " + std::to_string(c.lights) +
           ", \"light_method\": " + jsonString(lightMethodName(c.lightMethod)) + ", \"ms_median\": " + jsonNumber(r.msMedian) + ", \"ms_min\": " + jsonNumber(r.msMin) +
           ", \"ms_max\": " + jsonNumber(r.msMax) + ", \"ms_ci\": [" + jsonNumber(r.ms.low) + ", " + jsonNumber(r.ms.high) +
           "], \"ms_cv\": " + jsonNumber(r.ms.cv) + ", \"ms_outliers\": {\"mild\": " + std::to_string(r.ms.outliers.mild) +
           ", \"severe\": " + std::to_string(r.ms.outliers.severe) + "}, \"ms_samples\": " + std::to_string(r.ms.count) +
           ", \"floor_ms\": " + jsonNumber(r.floorMs) +
           ", \"floor_ratio\": " + jsonNumber(r.floorRatio()) + ", \"ms_over_floor_ms\": " + jsonNumber(r.msOverFloor()) +
           ", \"ms_spread\": " + jsonNumber(r.msSpread()) + ", \"noisy\": " + (r.noisy() ? "true" : "false") +
           ", \"psnr_db\": " + jsonNumber(r.psnrDb) +
           ", \"rmse\": " + jsonNumber(r.rmse, 6) + ", \"max_abs\": " + std::to_string(r.maxAbs) +
           ", \"ssim\": " + jsonNumber(r.ssim, 6) + ", \"same_knobs_psnr_db\": " + jsonNumber(r.sameKnobsPsnrDb) +
           ", \"same_knobs_max_abs\": " + std::to_string(r.sameKnobsMaxAbs) + ", \"bytes_per_pixel\": " + std::to_string(r.bytesPerPixel) +
           ", \"gbuffer_bytes_per_pixel\": " + std::to_string(r.gbufferBytesPerPixel) +
           ", \"target_mib\": " + jsonNumber(r.targetMiB, 3) + ", \"passes_ms\": {" + passes + "}" +
           ", \"pareto\": " + (r.pareto ? "true" : "false") +
           ", \"pareto_in_pipeline\": " + (r.paretoInPipeline ? "true" : "false") + ", \"depth\": " + jsonString(c.depth) +
           ", \"traffic_bytes_per_pixel\": " + jsonNumber(r.trafficBytesPerPixel, 6) +
           ", \"cleared_bytes_per_pixel\": " + jsonNumber(r.clearedBytesPerPixel, 6) +
           ", \"floor_traffic_bytes_per_pixel\": " + jsonNumber(r.floorTrafficBytesPerPixel, 6) + "}";
}

// Per size, the range of the floors timed in turn with the configurations (what xfloor divides
// by), and the rows whose timed frames spread by more than BenchResult::kNoiseSpread.
std::string floorsInTurnText(const std::vector<BenchResult>& results) {
    std::map<std::string, std::pair<double, double>> ranges;
    std::vector<std::string> noisy;
    for (const BenchResult& r : results) {
        std::string size = std::to_string(r.config.width) + "x" + std::to_string(r.config.height);
        auto [it, added] = ranges.try_emplace(size, r.floorMs, r.floorMs);
        it->second = {std::min(it->second.first, r.floorMs), std::max(it->second.second, r.floorMs)};
        if (r.noisy()) noisy.push_back(size + " " + std::to_string(r.config.lights) + " lights " + pipelineName(r.config.pipeline) + " " +
                            r.config.layout + " " + r.variation);
    }
    std::string text;
    char line[256];
    for (const auto& [size, range] : ranges) {
        std::snprintf(line, sizeof(line), "floor %s timed in turn with the configurations (xfloor's divisor): %.2f to %.2f ms\n",
                      size.c_str(), range.first, range.second);
        text += line;
    }
    std::snprintf(line, sizeof(line), "noisy rows (ms max - ms min over %.0f%% of ms med; their xfloor is not a measured difference): %zu of %zu%s",
                  100.0 * BenchResult::kNoiseSpread, noisy.size(), results.size(), noisy.empty() ? "\n" : ":");
    text += line;
    for (size_t i = 0; i < noisy.size(); ++i) text += (i ? ", " : " ") + noisy[i] + (i + 1 == noisy.size() ? "\n" : "");
    return text;
}

}  // namespace oasis
