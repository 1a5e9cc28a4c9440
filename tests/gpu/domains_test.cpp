// The far ends of the input domains (src/cli/input_domains.h) render right: for each boundary a
// small frame with plants in both pipelines has no NaN/Inf in any buffer, forward and deferred
// agree (>= 45 dB, the stability tests' threshold) and the frame has content; where the boundary
// moves the camera far from the origin, the plants' bases (CPU heights) still lie on the terrain
// the GPU draws, which is what breaks first beyond the horizontal domain (noise cells past 2^24).
// The values come from the table, so moving a bound moves its test.
#include "frame/frame_readback.h"
#include "gpu_test.h"

#include "cli/input_domains.h"

namespace oasis::gputest {
namespace {


struct DomainCase {
    std::string name;
    SceneSettings scene;
    bool expectContent = true;  // false where the boundary's frame is rightly one smooth colour
    bool checkBases = false;    // the plants' bases against the GPU's terrain (far from the origin)
};

double low(const char* name) { return inputDomain(name).low; }
double high(const char* name) { return inputDomain(name).high; }

SceneSettings overGround(double x, double z, double height, double yaw, double pitch) {
    SceneSettings scene;
    scene.camera = CameraPose{glm::dvec3(x, groundAt(x, z) + height, z), float(yaw), float(pitch)};
    return scene;
}

std::vector<DomainCase> domainCases() {
    std::vector<DomainCase> cases;
    // Horizontal position: the corners of the square (both coordinates at their bounds: the noise
    // cells grow fastest along the diagonal).
    double xs[] = {low("--camera X"), high("--camera X")}, zs[] = {low("--camera Z"), high("--camera Z")};
    const char* names[] = {"Low", "High"};
    for (int i = 0; i < 2; ++i)
        for (int k = 0; k < 2; ++k)
            cases.push_back({std::string("cameraX") + names[i] + "Z" + names[k], overGround(xs[i], zs[k], 20.0, 45.0, -8.0),
                             true, true});
    // Time: the default flight at both ends (its position and the drifting detail noise).
    for (double t : {low("--time"), high("--time")}) {
        SceneSettings scene;
        scene.timeSeconds = t;
        cases.push_back({t < 0 ? "timeLow" : "timeHigh", scene, true, true});
    }
    // Height: the highest camera looking down, the lowest looking level.
    cases.push_back({"cameraYHigh", [] {
                         SceneSettings scene;
                         scene.camera = CameraPose{glm::dvec3(210.0, high("--camera Y"), -120.0), 90.0f, -89.9f};
                         return scene;
                     }()});
    cases.push_back({"cameraYLow", [] {
                         SceneSettings scene;
                         scene.camera = CameraPose{glm::dvec3(500.0, low("--camera Y"), 130.0), 0.0f, 0.0f};
                         return scene;
                     }(), false});
    // Angles: pitch at both ends (straight up is a smooth sky), yaw at the ends of its wrap.
    cases.push_back({"pitchLow", overGround(210.0, -120.0, 20.0, 90.0, low("--camera PITCH"))});
    cases.push_back({"pitchHigh", overGround(210.0, -120.0, 20.0, 90.0, high("--camera PITCH")), false});
    cases.push_back({"yawLow", overGround(210.0, -120.0, 20.0, low("--camera YAW"), -5.0)});
    cases.push_back({"yawHigh", overGround(210.0, -120.0, 20.0, std::nextafter(high("--camera YAW"), 0.0), -5.0)});
    // The water and the plants' knobs at their highest, seen across the lake from its western shore.
    auto lakeside = [] { return overGround(435.0, 140.0, 5.0, 30.0, -3.0); };
    for (double level : {low("--water-level"), high("--water-level")}) {
        SceneSettings scene = lakeside();
        scene.water.level = float(level);
        cases.push_back({level < 0 ? "waterLevelLow" : "waterLevelHigh", scene, level < 0});
    }
    {
        SceneSettings scene = lakeside();
        scene.water.rippleStrength = float(high("--ripples"));
        cases.push_back({"ripplesHigh", scene});
    }
    {
        SceneSettings scene = lakeside();
        scene.water.absorption = float(high("--absorption"));
        cases.push_back({"absorptionHigh", scene});
    }
    {
        SceneSettings scene = lakeside();
        scene.vegetation.density = float(high("--vegetation-density"));
        scene.vegetation.windStrength = float(high("--wind"));
        scene.timeSeconds = 3.0;
        cases.push_back({"densityAndWindHigh", scene});
    }
    {
        SceneSettings scene = lakeside();
        scene.water.rippleStrength = float(low("--ripples"));
        scene.water.absorption = float(low("--absorption"));
        scene.vegetation.density = float(low("--vegetation-density"));
        scene.vegetation.windStrength = float(low("--wind"));
        scene.lights.count = int(low("--lights"));
        cases.push_back({"knobsLow", scene});
    }
    for (double hour : {low("--hour"), high("--hour")}) {
        SceneSettings scene = lakeside();
        scene.hour = hour;
        scene.lights.count = int(high("--lights"));
        cases.push_back({hour == 0.0 ? "hourLowMostLights" : "hourHighMostLights", scene});
    }
    return cases;
}

void PrintTo(const DomainCase& c, std::ostream* out) { *out << c.name; }

class DomainEnds : public GpuTest, public ::testing::WithParamInterface<DomainCase> {};

TEST_P(DomainEnds, FiniteAgreeingAndPlantsOnTheTerrain) {
    const DomainCase& c = GetParam();
    Renderer renderer(*shaders_, c.scene);
    auto atlas = attachPlantAtlas(*shaders_, renderer);
    renderer.configure(kSmallWidth, kSmallHeight, layoutNamed("standard"));
    Image forward = renderFinal(renderer, c.scene, PipelineKind::Forward);
    // Where the frame wrote them (countNonFiniteWritten: nothing clears the rest).
    for (Target target : {Target::Radiance, Target::Reflection, Target::Final})
        EXPECT_EQ(countNonFiniteWritten(readTarget(renderer, target), target, readStencil(renderer),
                                        renderer.lastFrame().setup.reflectionsActive), 0)
            << "forward " << targetName(target);
    Image deferred = renderFinal(renderer, c.scene, PipelineKind::Deferred);
    dumpImage("domain-" + c.name + "-forward", forward);
    dumpImage("domain-" + c.name + "-deferred", deferred);
    for (Target target : {Target::Albedo, Target::Normal, Target::Position, Target::Info, Target::Radiance,
                          Target::Reflection, Target::Final})
        EXPECT_EQ(countNonFiniteWritten(readTarget(renderer, target), target, readStencil(renderer),
                                        renderer.lastFrame().setup.reflectionsActive), 0)
            << "deferred " << targetName(target);
    EXPECT_EQ(countNonFinite(readDepth(renderer)), 0) << "depth";
    ImageDifference difference = compareImages(forward, deferred);
    const glm::dvec3 camera = renderer.lastFrame().setup.view.pose.position;
    std::printf("[domains] %s: camera (%.6g, %.2f, %.6g), forward vs deferred %.2f dB, plants placed %zu drawn %zu\n",
                c.name.c_str(), camera.x, camera.y, camera.z, difference.psnrDb, renderer.lastFrame().vegetation.stats().plantsPlaced,
                renderer.lastFrame().vegetation.stats().plantsDrawn);
    EXPECT_GE(difference.psnrDb, 45.0) << "forward and deferred disagree";
    if (c.expectContent) EXPECT_TRUE(hasContent(deferred));
    if (!c.checkBases) return;
    std::vector<PlantInstance> plants = renderer.lastFrame().vegetation.placedPlants();
    ASSERT_GT(plants.size(), 1000u) << "plants placed around the far camera";
    std::vector<glm::dvec2> points;
    std::vector<float> bases;
    for (size_t i = 0; i < plants.size(); i += 13) {
        points.emplace_back(plants[i].base.x, plants[i].base.z);
        bases.push_back(plants[i].base.y);
    }
    std::vector<glm::vec3> gpu = probeGpuHeights(*shaders_, renderer, points);
    double worst = 0.0;
    for (size_t i = 0; i < gpu.size(); ++i) worst = std::max(worst, std::fabs(double(gpu[i].x) - double(bases[i])));
    std::printf("[domains]   %zu bases: worst |base - GPU terrain| %.2e\n", points.size(), worst);
    EXPECT_LE(worst, 1e-3) << "plants float over or sink into the GPU's terrain";
}

INSTANTIATE_TEST_SUITE_P(Boundaries, DomainEnds, ::testing::ValuesIn(domainCases()),
                         [](const auto& info) { return info.param.name; });

}  // namespace
}  // namespace oasis::gputest
