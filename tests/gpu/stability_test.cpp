// Numerical stability on hard cases, with plants and both pipelines: the camera 1e5 and 1e6 units
// from the origin, 1e6 s of animation (the default flight is then 7e6 units out), the sun exactly
// at the horizon at sunrise and sunset, the camera exactly at the water plane, and the most point
// lights (4096). In each: no NaN/Inf in any buffer, every surface normal unit length within 1e-3,
// forward and deferred agree (>= 45 dB, the standard layout's threshold), the frame has content.
#include "gpu_test.h"

namespace oasis::gputest {
namespace {

struct HardCase {
    std::string name;
    SceneSettings scene;
    int width = 320, height = 180;
};

SceneSettings above(double x, double z, double height, float yaw, float pitch) {
    SceneSettings scene;
    scene.camera = CameraPose{glm::dvec3(x, groundAt(x, z) + height, z), yaw, pitch};
    return scene;
}

std::vector<HardCase> hardCases() {
    std::vector<HardCase> cases;
    cases.push_back({"far1e5", above(1.0e5, -7.0e4, 30.0, 30.0f, -10.0f)});
    {
        SceneSettings scene = above(-6.0e5, 8.0e5, 30.0, -60.0f, -8.0f);
        scene.timeSeconds = 1.0e6;
        cases.push_back({"far1e6AfterMillionSeconds", scene});
    }
    {
        SceneSettings scene;  // the default flight, 7e6 units east after 1e6 s
        scene.timeSeconds = 1.0e6;
        cases.push_back({"flightAfterMillionSeconds", scene});
    }
    for (double hour : {6.0, 18.0}) {
        SceneSettings scene = above(210.0, -120.0, 30.0, hour < 12.0 ? 90.0f : -90.0f, -3.0f);
        scene.hour = hour;
        cases.push_back({hour < 12.0 ? "sunriseExactly" : "sunsetExactly", scene});
    }
    {
        SceneSettings scene;
        scene.camera = CameraPose{glm::dvec3(470.0, 0.0, 150.0), 30.0f, -2.0f};  // eye on the water plane
        cases.push_back({"eyeAtTheWaterPlane", scene});
    }
    {
        SceneSettings scene;
        scene.hour = 21.0;
        scene.lights.count = kMaxLights;
        cases.push_back({"mostLights", scene, 160, 90});
    }
    return cases;
}

class Stability : public GpuTest, public ::testing::WithParamInterface<HardCase> {};

TEST_P(Stability, FiniteUnitNormalsAndAgreement) {
    const HardCase& hard = GetParam();
    Renderer renderer(*shaders_, hard.scene);
    auto atlas = attachPlantAtlas(*shaders_, renderer);
    renderer.configure(hard.width, hard.height, layoutNamed("standard"));
    Image forward = renderFinal(renderer, hard.scene, PipelineKind::Forward);
    for (Target target : {Target::Radiance, Target::Reflection, Target::Final})
        EXPECT_EQ(countNonFinite(renderer.readTarget(target)), 0) << "forward " << targetName(target);
    Image deferred = renderFinal(renderer, hard.scene, PipelineKind::Deferred);
    for (Target target : {Target::Albedo, Target::Normal, Target::Position, Target::Info, Target::Radiance,
                          Target::Reflection, Target::Final})
        EXPECT_EQ(countNonFinite(renderer.readTarget(target)), 0) << "deferred " << targetName(target);
    EXPECT_EQ(countNonFinite(renderer.readDepth()), 0) << "depth";

    const std::vector<float> normal = renderer.readTarget(Target::Normal);
    const std::vector<float> info = renderer.readTarget(Target::Info);
    int surfaces = 0, notUnit = 0;
    double worst = 0.0;
    for (int y = 0; y < hard.height; ++y)
        for (int x = 0; x < hard.width; ++x) {
            if (infoFlags(texel(info, hard.width, x, y)) & kSurfaceSky) continue;
            ++surfaces;
            double error = std::fabs(glm::length(glm::dvec3(texel(normal, hard.width, x, y))) - 1.0);
            worst = std::max(worst, error);
            notUnit += error > 1e-3;
        }
    ImageDifference difference = compareImages(forward, deferred);
    std::printf("[stability] %s: camera (%.0f, %.1f, %.0f), %d surface pixels, worst |n|-1 %.1e, forward vs deferred "
                "%.2f dB, plants drawn %zu, lights %d\n",
                hard.name.c_str(), renderer.lastFrame().view.pose.position.x, renderer.lastFrame().view.pose.position.y,
                renderer.lastFrame().view.pose.position.z, surfaces, worst, difference.psnrDb,
                renderer.vegetationStats().plantsDrawn, renderer.lightsDrawn());
    EXPECT_GT(surfaces, 0);
    EXPECT_EQ(notUnit, 0) << "normals off unit length by more than 1e-3 (worst " << worst << ")";
    EXPECT_GE(difference.psnrDb, 45.0) << "forward and deferred disagree";
    EXPECT_TRUE(hasContent(deferred));
    EXPECT_TRUE(hasContent(forward));
}

INSTANTIATE_TEST_SUITE_P(HardCases, Stability, ::testing::ValuesIn(hardCases()),
                         [](const auto& info) { return info.param.name; });

}  // namespace
}  // namespace oasis::gputest
