// The bench's depth-convention parts without GL (bench/bench_depth.h): reversed-z configurations
// beside the default layout's deferred ones, the distance bands, the CPU twin of
// relativePositionFromDepth, and the depth-precision CSV and JSON.
#include <gtest/gtest.h>

#include "bench/bench_depth.h"

namespace oasis {
namespace {

TEST(BenchDepth, ReversedConfigsFollowTheirLayoutsDeferredConfigs) {
    std::vector<BenchConfig> configs = benchConfigs(qualityKnobs(), {"full", "standard"}, {{320, 180}}, true);
    size_t before = configs.size();
    insertDepthConfigs(configs, "standard", {"reversed-z"});
    size_t settings = before / 3;  // deferred full, deferred standard, forward per knob setting
    ASSERT_EQ(configs.size(), before + settings);
    for (size_t i = 0; i < configs.size(); ++i) {
        if (configs[i].depth != "reversed-z") continue;
        ASSERT_GT(i, 0u);
        EXPECT_EQ(configs[i].pipeline, PipelineKind::Deferred);
        EXPECT_EQ(configs[i].layout, "standard");
        EXPECT_EQ(configs[i - 1].layout, "standard");
        EXPECT_EQ(configs[i - 1].depth, "standard");
        EXPECT_EQ(configs[i].levels, configs[i - 1].levels);  // the same knob setting: timed together
    }
    std::vector<BenchConfig> none = benchConfigs(qualityKnobs(), {"full"}, {{320, 180}}, true);
    size_t count = none.size();
    insertDepthConfigs(none, "standard", {});
    EXPECT_EQ(none.size(), count);
}

TEST(BenchDepth, BandsFromTheScene) {
    SceneSettings scene;
    std::vector<DepthBand> bands = depthBands(scene);
    ASSERT_EQ(bands.size(), 3u);
    EXPECT_EQ(bands[0].from, double(scene.projection.nearPlane));
    EXPECT_EQ(bands[0].to, double(scene.vegetation.thinningStart));
    EXPECT_EQ(bands[1].to, double(scene.vegetation.drawDistance));
    EXPECT_EQ(bands[2].to, double(scene.viewDistance));
    for (size_t i = 1; i < bands.size(); ++i) EXPECT_EQ(bands[i].from, bands[i - 1].to);
}

TEST(BenchDepth, CpuReconstructionInvertsTheProjection) {
    for (const DepthConvention& depth : depthConventions()) {
        SCOPED_TRACE(depth.name);
        FrameSetup frame = prepareFrame(SceneSettings{}, 320, 180, depth);
        glm::dvec4 relative(glm::dvec3(frame.view.pose.forward()) * 300.0 + glm::dvec3(20.0, -10.0, 5.0), 1.0);
        glm::dvec4 clip = glm::dmat4(frame.data.viewProjection) * relative;
        glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
        double window = depth.clipDepthMode == GL_ZERO_TO_ONE ? ndc.z : ndc.z * 0.5 + 0.5;
        glm::vec2 uv(float(ndc.x * 0.5 + 0.5), float(ndc.y * 0.5 + 0.5));
        glm::vec3 back = relativePositionFromDepth(frame.data, uv, float(window));
        EXPECT_LT(glm::length(glm::dvec3(back) - glm::dvec3(relative)), 300.0 * 1e-3);
    }
}

TEST(BenchDepth, CsvAndJsonCarryEveryRow) {
    DepthPrecision row;
    row.depth = "reversed-z";
    row.band = {"far", 600.0, 4000.0};
    row.pixels = 12;
    row.medianAbs = 1.5e-4;
    row.maxAbs = 2e-3;
    row.medianRelative = 2e-7;
    row.maxRelative = 3e-6;
    std::string csv = depthPrecisionCsv({row, row});
    EXPECT_EQ(csv.rfind("depth,band,from,to,pixels,median_abs,max_abs,median_relative,max_relative\n", 0), 0u);
    EXPECT_NE(csv.find("reversed-z,far,600.000,4000.000,12,1.500000e-04,2.000000e-03,2.000000e-07,3.000000e-06\n"),
              std::string::npos) << csv;
    std::string json = depthPrecisionJson({row});
    EXPECT_NE(json.find("{\"depth\": \"reversed-z\", \"band\": \"far\", \"from\": 600.000, \"to\": 4000.000, "
                        "\"pixels\": 12, \"median_abs\": 1.500000e-04"), std::string::npos) << json;
    EXPECT_EQ(depthPrecisionJson({}), "[\n]");
    EXPECT_NE(depthPrecisionTable({row}).find("600.00-4000"), std::string::npos);
}

}  // namespace
}  // namespace oasis
