// Covers src/bench/bench_report.h and svg_plot.h: the knob table, the light counts, the
// configurations a run measures, the Pareto frontiers (per size and light count), a configuration's
// CSV row and JSON object, and the SVG plot.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "bench/bench_report.h"
#include "bench/svg_plot.h"
#include "render/gbuffer_layout.h"

namespace oasis {
namespace {

size_t count(const std::string& text, const std::string& part) {
    size_t n = 0;
    for (size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + part.size())) ++n;
    return n;
}

std::vector<std::string> splitCsv(const std::string& line) {
    std::vector<std::string> fields(1);
    bool quoted = false;
    for (size_t i = 0; i < line.size(); ++i) {
        char c = line[i];
        if (c == '"') {
            if (quoted && i + 1 < line.size() && line[i + 1] == '"') { fields.back() += '"'; ++i; }
            else quoted = !quoted;
        } else if (c == ',' && !quoted) {
            fields.emplace_back();
        } else {
            fields.back() += c;
        }
    }
    return fields;
}

TEST(BenchKnobs, DefaultLevelsAreTheDefaultSceneAndTheHighestAreLast) {
    const std::vector<QualityKnob>& knobs = qualityKnobs();
    std::set<std::string> names;
    for (const QualityKnob& knob : knobs) {
        EXPECT_TRUE(names.insert(knob.name).second) << "duplicate knob " << knob.name;
        ASSERT_GE(knob.levels.size(), 2u) << knob.name;
        ASSERT_GE(knob.defaultLevel, 0);
        ASSERT_LT(size_t(knob.defaultLevel), knob.levels.size());
    }
    for (const char* name : {"grid", "octaves", "vegetation", "reflections"}) EXPECT_TRUE(names.count(name)) << name;
    SceneSettings defaults;
    SceneSettings applied = applyKnobs(SceneSettings{}, knobs, defaultLevels(knobs));
    EXPECT_EQ(applied.grid.rings, defaults.grid.rings);
    EXPECT_EQ(applied.grid.segments, defaults.grid.segments);
    EXPECT_EQ(applied.terrain.octaves, defaults.terrain.octaves);
    EXPECT_EQ(applied.vegetation.enabled, defaults.vegetation.enabled);
    EXPECT_EQ(applied.vegetation.density, defaults.vegetation.density);
    EXPECT_EQ(applied.water.reflections, defaults.water.reflections);
    EXPECT_EQ(applied.shadows.enabled, defaults.shadows.enabled);
    EXPECT_EQ(applied.shadows.quality, defaults.shadows.quality);
    SceneSettings highest = applyKnobs(SceneSettings{}, knobs, highestLevels(knobs));
    EXPECT_GE(highest.grid.rings * highest.grid.segments, defaults.grid.rings * defaults.grid.segments);
    EXPECT_GE(highest.terrain.octaves, defaults.terrain.octaves);
    EXPECT_TRUE(highest.water.reflections);
    EXPECT_TRUE(highest.vegetation.enabled);
    SceneSettings cheapest = applyKnobs(SceneSettings{}, knobs, std::vector<int>(knobs.size(), 0));
    EXPECT_LT(cheapest.grid.rings * cheapest.grid.segments, defaults.grid.rings * defaults.grid.segments);
    EXPECT_LT(cheapest.terrain.octaves, defaults.terrain.octaves);
    EXPECT_FALSE(cheapest.water.reflections);
}

TEST(BenchLights, CountsAreAscendingAndHoldTheDefaultScenes) {
    const std::vector<int>& counts = benchLightCounts();
    ASSERT_GE(counts.size(), 2u);
    EXPECT_TRUE(std::is_sorted(counts.begin(), counts.end()));
    EXPECT_EQ(std::set<int>(counts.begin(), counts.end()).size(), counts.size()) << "a count twice";
    EXPECT_EQ(defaultLightCount(), SceneSettings{}.lights.count);
    EXPECT_NE(std::find(counts.begin(), counts.end(), defaultLightCount()), counts.end());
    for (int count : counts) {
        EXPECT_GE(count, 0);
        EXPECT_LE(count, kMaxLights);
    }
    // --quick: the default and the most.
    EXPECT_EQ(quickLightCounts(), (std::vector<int>{defaultLightCount(), counts.back()}));
}

TEST(BenchConfigs, DefaultFirstThenEachKnobAloneDeferredLayoutsThenForward) {
    const std::vector<QualityKnob>& knobs = qualityKnobs();
    std::vector<std::string> layouts = {"full", "standard"};
    std::vector<BenchConfig> configs = benchConfigs(knobs, layouts, {{640, 360}, {32, 18}}, false);
    size_t settings = 1;
    for (const QualityKnob& knob : knobs) settings += knob.levels.size() - 1;
    ASSERT_EQ(configs.size(), 2 * settings * (layouts.size() + 1));
    EXPECT_EQ(configs[0].variation(knobs), "default");
    EXPECT_EQ(configs[0].pipeline, PipelineKind::Deferred);
    EXPECT_EQ(configs[0].layout, "full");
    EXPECT_EQ(configs[1].layout, "standard");
    EXPECT_EQ(configs[2].pipeline, PipelineKind::Forward);
    EXPECT_EQ(configs[2].layout, kNoLayout);
    EXPECT_EQ(configs[0].width, 640);
    EXPECT_EQ(configs.back().width, 32);
    for (const BenchConfig& c : configs) {
        int away = 0;
        for (size_t k = 0; k < knobs.size(); ++k) away += c.levels[k] != knobs[k].defaultLevel;
        EXPECT_EQ(away, c.variedKnob < 0 ? 0 : 1) << c.variation(knobs);
    }
    EXPECT_EQ(configs[3].variation(knobs), knobs[0].name + "=" + knobs[0].levels[0].label);
    EXPECT_EQ(configs[0].knobSettings(knobs).find("grid=medium"), 0u);

    std::vector<BenchConfig> quick = benchConfigs(knobs, layouts, {{320, 180}}, true);
    size_t quickSettings = 1;
    for (const QualityKnob& knob : knobs) quickSettings += knob.defaultLevel != 0;
    EXPECT_EQ(quick.size(), quickSettings * 3);
    for (const BenchConfig& c : quick)
        if (c.variedKnob >= 0) EXPECT_EQ(c.levels[size_t(c.variedKnob)], 0);
    // Without light counts given, every configuration has the default scene's.
    for (const BenchConfig& c : configs) EXPECT_EQ(c.lights, defaultLightCount());
}

// Each further light count is a workload of the default knobs only (every layout, then forward),
// after every configuration of the default count at that size.
TEST(BenchConfigs, OtherLightCountsAtTheDefaultKnobsOnly) {
    const std::vector<QualityKnob>& knobs = qualityKnobs();
    std::vector<std::string> layouts = {"full", "standard"};
    const std::vector<int> counts = {0, 4, 32, 256};
    ASSERT_EQ(defaultLightCount(), 0);
    ASSERT_LT(32, kForwardBenchMaxLights + 1);
    ASSERT_GT(256, kForwardBenchMaxLights);
    std::vector<BenchConfig> configs = benchConfigs(knobs, layouts, {{640, 360}, {32, 18}}, false, counts);
    std::vector<BenchConfig> plain = benchConfigs(knobs, layouts, {{640, 360}, {32, 18}}, false);
    // With lights: each layout with volumes then tiled, then forward up to kForwardBenchMaxLights.
    const size_t withForward = 2 * layouts.size() + 1, deferredOnly = 2 * layouts.size();
    const size_t perSize = plain.size() / 2 + 2 * withForward + deferredOnly;
    ASSERT_EQ(configs.size(), 2 * perSize);
    for (size_t i = 0; i < configs.size(); ++i) {
        const BenchConfig& c = configs[i];
        size_t inSize = i % perSize;
        size_t lit = inSize - plain.size() / 2;
        int expectedLights = inSize < plain.size() / 2 ? 0 : lit < 2 * withForward ? counts[1 + lit / withForward] : 256;
        EXPECT_EQ(c.lights, expectedLights) << i;
        EXPECT_EQ(c.width, i < perSize ? 640 : 32) << i;
        if (c.lights == 0) EXPECT_EQ(c.lightMethod, LightMethod::Volumes) << "without lights the methods are the same";
        if (c.lights > kForwardBenchMaxLights) EXPECT_EQ(c.pipeline, PipelineKind::Deferred) << i;
        if (c.lights != defaultLightCount()) {
            EXPECT_EQ(c.variedKnob, -1) << "knobs are varied at the default light count only";
            EXPECT_EQ(c.levels, defaultLevels(knobs));
            EXPECT_EQ(c.variation(knobs), "lights=" + std::to_string(c.lights));
        }
    }
    // The first configurations at 4 lights: each layout with volumes, then tiled, then forward.
    const size_t first4 = plain.size() / 2;
    EXPECT_EQ(configs[first4].layout, "full");
    EXPECT_EQ(configs[first4].lightMethod, LightMethod::Volumes);
    EXPECT_EQ(configs[first4 + 1].layout, "full");
    EXPECT_EQ(configs[first4 + 1].lightMethod, LightMethod::Tiled);
    EXPECT_EQ(configs[first4 + 2].layout, "standard");
    EXPECT_EQ(configs[first4 + 4].pipeline, PipelineKind::Forward);
    EXPECT_EQ(configs[0].variation(knobs), "default");

    std::vector<BenchConfig> quick = benchConfigs(knobs, layouts, {{320, 180}}, true, quickLightCounts());
    EXPECT_EQ(quick.back().lights, benchLightCounts().back());
    // The most lights are past forward's limit: the quick run ends with deferred's tiled method.
    EXPECT_EQ(quick.back().pipeline, PipelineKind::Deferred);
    EXPECT_EQ(quick.back().lightMethod, LightMethod::Tiled);
}

TEST(Pareto, DominatedPointsAreOff) {
    // (cost, error): b beats a in both, c is cheaper but worse, d is dominated by c.
    std::vector<bool> f = paretoFrontier({{10, 5}, {8, 4}, {5, 9}, {6, 10}, {20, 1}});
    EXPECT_EQ(f, (std::vector<bool>{false, true, true, false, true}));
}

TEST(Pareto, TiesAndIdenticalPoints) {
    // Same cost, different error: the worse one is off. Same error, different cost: the dearer is off.
    EXPECT_EQ(paretoFrontier({{5, 3}, {5, 2}}), (std::vector<bool>{false, true}));
    EXPECT_EQ(paretoFrontier({{5, 3}, {4, 3}}), (std::vector<bool>{false, true}));
    // Identical points: neither beats the other, both are on; a third that beats both takes it.
    EXPECT_EQ(paretoFrontier({{5, 3}, {5, 3}}), (std::vector<bool>{true, true}));
    EXPECT_EQ(paretoFrontier({{5, 3}, {5, 3}, {4, 2}}), (std::vector<bool>{false, false, true}));
    EXPECT_EQ(paretoFrontier({{1, 1}}), (std::vector<bool>{true}));
    EXPECT_TRUE(paretoFrontier({}).empty());
}

BenchResult sampleResult(PipelineKind pipeline, const std::string& layout, int width, double ms, double rmse) {
    BenchResult r;
    r.config.pipeline = pipeline;
    r.config.layout = layout;
    r.config.width = width;
    r.config.height = width / 2;
    r.config.levels = defaultLevels(qualityKnobs());
    r.variation = "default";
    r.knobSettings = r.config.knobSettings(qualityKnobs());
    r.msMedian = ms;
    r.rmse = rmse;
    return r;
}

// Only configurations with the same light count share a frontier: a cheap frame with no lights
// must not push a frame with many lights off its own.
TEST(Pareto, MarkedPerLightCount) {
    std::vector<BenchResult> results = {
        sampleResult(PipelineKind::Forward, kNoLayout, 100, 10, 1.0),
        sampleResult(PipelineKind::Deferred, "standard", 100, 12, 1.1),
        sampleResult(PipelineKind::Forward, kNoLayout, 100, 200, 1.0),    // 32 lights: dearer, still on its own
        sampleResult(PipelineKind::Deferred, "standard", 100, 30, 1.5),   // 32 lights
        sampleResult(PipelineKind::Deferred, "full", 100, 40, 1.6),       // 32 lights: beaten by standard
    };
    for (size_t i = 2; i < results.size(); ++i) results[i].config.lights = 32;
    markParetoFrontiers(results);
    auto marks = [&](bool BenchResult::*flag) {
        std::vector<bool> marked;
        for (const BenchResult& r : results) marked.push_back(r.*flag);
        return marked;
    };
    EXPECT_EQ(marks(&BenchResult::pareto), (std::vector<bool>{true, false, true, true, false}));
    EXPECT_EQ(marks(&BenchResult::paretoInPipeline), (std::vector<bool>{true, true, true, true, false}));
}

TEST(Pareto, MarkedPerSizeAndPerPipeline) {
    std::vector<BenchResult> results = {
        sampleResult(PipelineKind::Forward, kNoLayout, 100, 10, 1.0),
        sampleResult(PipelineKind::Deferred, "full", 100, 20, 1.0),     // beaten by forward, best deferred error
        sampleResult(PipelineKind::Deferred, "standard", 100, 15, 1.1),  // beaten by forward, cheapest deferred
        sampleResult(PipelineKind::Deferred, "standard", 50, 30, 2.0),   // alone at its size
    };
    markParetoFrontiers(results);
    EXPECT_TRUE(results[0].pareto);
    EXPECT_FALSE(results[1].pareto);
    EXPECT_FALSE(results[2].pareto);
    EXPECT_TRUE(results[1].paretoInPipeline);
    EXPECT_TRUE(results[2].paretoInPipeline);
    EXPECT_TRUE(results[3].pareto);
}

TEST(BenchFormat, CsvRowMatchesTheHeader) {
    BenchResult r = sampleResult(PipelineKind::Deferred, "standard", 1280, 45.25, 3.5);
    r.msMin = 40.0;
    r.msMax = 50.0;
    r.floorMs = 15.0;
    r.psnrDb = 37.25;
    r.maxAbs = 120;
    r.ssim = 0.91234;
    r.bytesPerPixel = 56;
    r.passesMs = {{"ClearPass.gbuffer", 1.5}, {"LightingPass", 20.25}};
    r.pareto = true;
    r.config.lights = 32;
    std::vector<std::string> header = splitCsv(benchCsvHeader()), row = splitCsv(benchCsvRow(r));
    ASSERT_EQ(header.size(), row.size());
    auto field = [&](const std::string& name) {
        auto at = std::find(header.begin(), header.end(), name);
        EXPECT_NE(at, header.end()) << name;
        return at == header.end() ? std::string() : row[size_t(at - header.begin())];
    };
    EXPECT_EQ(field("pipeline"), "deferred");
    EXPECT_EQ(field("layout"), "standard");
    EXPECT_EQ(field("width"), "1280");
    EXPECT_EQ(field("ms_median"), "45.250");
    EXPECT_EQ(field("floor_ratio"), "3.017");
    EXPECT_EQ(field("psnr_db"), "37.250");
    EXPECT_EQ(field("bytes_per_pixel"), "56");
    EXPECT_EQ(field("pareto"), "true");
    EXPECT_EQ(field("knobs"), r.knobSettings);
    EXPECT_EQ(field("lights"), "32");
    EXPECT_EQ(field("passes_ms"), "ClearPass.gbuffer=1.500;LightingPass=20.250");
}

TEST(BenchFormat, JsonHasTheRequiredKeys) {
    BenchResult r = sampleResult(PipelineKind::Forward, kNoLayout, 640, 20.0, 0.0);
    r.floorMs = 4.0;
    r.psnrDb = 100.0;
    r.passesMs = {{"ToneMapPass", 1.25}};
    r.config.lights = 4;
    std::string json = benchConfigJson(r);
    for (const char* key : {"\"pipeline\": \"forward\"", "\"layout\": \"none\"", "\"width\": 640", "\"height\": 320",
                            "\"ms_median\": 20.0000", "\"floor_ratio\": 5.0000", "\"psnr_db\": 100.0000",
                            "\"bytes_per_pixel\": ", "\"ssim\": ", "\"rmse\": ", "\"max_abs\": ",
                            "\"passes_ms\": {\"ToneMapPass\": 1.2500}", "\"pareto\": false", "\"lights\": 4"})
        EXPECT_NE(json.find(key), std::string::npos) << key << " in " << json;
    EXPECT_EQ(json.front(), '{');
    EXPECT_EQ(json.back(), '}');
    EXPECT_EQ(count(json, "{"), count(json, "}"));
    r.floorMs = 0.0;
    r.msMedian = std::nan("");
    EXPECT_NE(benchConfigJson(r).find("\"ms_median\": null"), std::string::npos);
    EXPECT_EQ(jsonString("a\"b\\c\n"), "\"a\\\"b\\\\c\\u000a\"");
}

TEST(SvgPlot, NiceTicksCoverTheRange) {
    std::vector<double> ticks = niceTicks(3.2, 47.9, 5);
    ASSERT_FALSE(ticks.empty());
    EXPECT_GE(ticks.front(), 3.2);
    EXPECT_LE(ticks.back(), 47.9);
    EXPECT_EQ(ticks, (std::vector<double>{10, 20, 30, 40}));
    EXPECT_EQ(niceTicks(0.0, 1.0, 5).size(), 6u);
    EXPECT_TRUE(niceTicks(5.0, 5.0).empty());
}

TEST(SvgPlot, DrawsEveryPointTheFrontierAndTheLegend) {
    PlotPanel a{"1280x720", {{10, 3, "forward", "default", true, true}, {20, 1, "deferred", "full default", true, true},
                             {25, 2, "deferred", "standard x<y", false, true}, {30, 4, "deferred", "off", false, false}}};
    PlotPanel b{"640x360", {{5, 4, "forward", "default", true, true}}};
    std::string svg = scatterPlotSvg({a, b}, {"title", "ms", "RMSE", "note"});
    EXPECT_EQ(svg.rfind("<svg", 0), 0u);
    EXPECT_NE(svg.find("</svg>"), std::string::npos);
    EXPECT_EQ(count(svg, "<circle cx"), 5u + 2u);  // five points, two legend swatches
    EXPECT_EQ(count(svg, "class=\"pareto\""), 2u);
    EXPECT_EQ(count(svg, "class=\"pareto-series\""), 1u);  // deferred's own frontier in the first panel
    EXPECT_NE(svg.find(">standard x&lt;y</text>"), std::string::npos);  // on its series' frontier: labelled
    EXPECT_EQ(svg.find(">off</text>"), std::string::npos);              // on no frontier: not labelled
    EXPECT_NE(svg.find("1280x720"), std::string::npos);
    EXPECT_NE(svg.find("x&lt;y"), std::string::npos);  // labels are escaped
    EXPECT_EQ(svg.find("x<y"), std::string::npos);
    // Two panels in a row, or one per row with a column count of 1: the canvas follows.
    EXPECT_NE(svg.find("width=\"1120.0\" height=\"490.0\""), std::string::npos) << svg.substr(0, 120);
    PlotText stacked{"title", "ms", "RMSE", "note", 1};
    std::string tall = scatterPlotSvg({a, b}, stacked);
    EXPECT_NE(tall.find("width=\"560.0\" height=\"910.0\""), std::string::npos) << tall.substr(0, 120);
}

// Issue 31, defect 5: a row printed 46.3x for 304.9 ms over a floor_ms of 8.52: the table's xfloor
// is the median ms over the row's floor_ms, and a row whose frames spread over 10% is noisy.
TEST(BenchResult, TableRatioAgreesWithFloorMsAndNoiseIsMarked) {
    BenchResult r;
    r.msMedian = 304.9, r.msMin = 250.0, r.msMax = 320.0, r.floorMs = 8.52, r.pairedFloorRatio = 46.3;
    EXPECT_DOUBLE_EQ(r.msOverFloor(), 304.9 / 8.52);
    EXPECT_DOUBLE_EQ(r.floorRatio(), 46.3);  // bench.json's floor_ratio keeps its meaning
    EXPECT_TRUE(r.noisy());
    std::string footer = floorsInTurnText({r});
    EXPECT_NE(footer.find("timed in turn with the configurations (xfloor's divisor): 8.52 to 8.52 ms"), std::string::npos) << footer;
    EXPECT_NE(footer.find("noisy rows (ms max - ms min over 10% of ms med; their xfloor is not a measured difference): 1 of 1:"),
              std::string::npos) << footer;
    EXPECT_NE(benchConfigJson(r).find("\"ms_over_floor_ms\": 35.7864"), std::string::npos) << benchConfigJson(r);
}

}  // namespace
}  // namespace oasis
