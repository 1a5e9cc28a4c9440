// Numerical stability on hard cases, with plants and both pipelines: the camera 1e5 and 1e6 units
// from the origin, 1e6 s of animation (the default flight is then 7e6 units out), grazing views
// over land and water, the camera 0.05 above the water, exactly at it and under it, the sun
// exactly at the horizon, below it at night and minutes before sunrise, no point lights and the
// most (4096). In each: no NaN/Inf in any buffer, every surface normal unit length within 1e-3,
// forward and deferred agree (>= 45 dB, the standard layout's threshold), the frame has content;
// some cases check what they are about on top (the camera under the water, the sun down, ...).
// The compact layout runs every case too (CompactLayoutFiniteAndAgrees).
#include "frame/frame_readback.h"
#include "gpu_test.h"

namespace oasis::gputest {
namespace {

// What a case's own checks see of its frame: the deferred frame's setup, G-buffer and stencil
// (bottom row first), both final images.
struct CaseFrame {
    const FrameSetup& frame;
    int width, height;
    const std::vector<float>& position;  // camera-relative, from the deferred G-buffer
    const std::vector<float>& info;
    const std::vector<uint8_t>& stencil;
    const Image& forward;
    const Image& deferred;
    int lightsDrawn;

    int countStencil(uint8_t mark) const {
        return int(std::count_if(stencil.begin(), stencil.end(), [&](uint8_t s) { return (s & 3) == mark; }));
    }
    unsigned flags(int x, int y) const { return infoFlags(texel(info, width, x, y)); }
    // The farthest surface (not sky) from the camera, in world units.
    double farthestSurface() const {
        double farthest = 0.0;
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x)
                if (!(flags(x, y) & kSurfaceSky))
                    farthest = std::max(farthest, glm::length(glm::dvec3(texel(position, width, x, y))));
        return farthest;
    }
};

struct HardCase {
    std::string name;
    SceneSettings scene;
    int width = 320, height = 180;
    std::function<void(const CaseFrame&)> check;  // what this case is about, beyond the common checks
};

SceneSettings above(double x, double z, double height, float yaw, float pitch) {
    SceneSettings scene;
    scene.camera = CameraPose{glm::dvec3(x, groundAt(x, z) + height, z), yaw, pitch};
    return scene;
}

// The lake east of the default flight's start: water level 0, bed about -7.6 at (500, 210) and
// -10.3 at (500, 130), shores about 170 units apart along z (z 40 to 220).
SceneSettings inTheLake(double y, double z, float yaw, float pitch) {
    SceneSettings scene;
    scene.camera = CameraPose{glm::dvec3(500.0, y, z), yaw, pitch};
    return scene;
}

// Looking level, the terrain is seen out to `minDistance` units (the fog starts at 350).
std::function<void(const CaseFrame&)> expectViewOut(double minDistance) {
    return [minDistance](const CaseFrame& c) {
        double farthest = c.farthestSurface();
        std::printf("[stability]   farthest surface %.0f units\n", farthest);
        EXPECT_GT(farthest, minDistance) << "a level view should see terrain far away";
    };
}

void expectUnderWater(const CaseFrame& c) {
    EXPECT_FALSE(c.frame.cameraAboveWater);
    EXPECT_FALSE(c.frame.reflectionsActive);
    // Everything is seen through the water: no pixel of the frame is left unmarked (stencil 0).
    EXPECT_EQ(c.countStencil(kStencilSky), 0) << "under water, pixels seen other than through the water";
    // Through a few units of clear-ish water by day the view is not dark (the mean of the brightest
    // channel, 8-bit).
    for (const Image* image : {&c.forward, &c.deferred}) {
        RgbStats stats = rgbStats(*image, wholeImage(*image));
        std::printf("[stability]   %s: %s\n", image == &c.forward ? "forward" : "deferred", describe(stats).c_str());
        EXPECT_GT(stats.maxMean(), 60.0) << "dark under water: " << describe(stats);
    }
}

void expectSunDown(const CaseFrame& c) {
    std::printf("[stability]   sun elevation %.4f (sin), radiance %.3g\n", c.frame.sky.sunDirection.y,
                c.frame.sky.sunRadiance.x + c.frame.sky.sunRadiance.y + c.frame.sky.sunRadiance.z);
    EXPECT_LT(c.frame.sky.sunDirection.y, 0.0f) << "the sun should be below the horizon";
    EXPECT_EQ(c.frame.sky.sunRadiance, glm::vec3(0.0f)) << "no direct sun below the horizon";
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
    // Grazing: 1 unit above the ground, looking level. Over a gentle slope west of the origin, the
    // one pose of a 50-unit scan of +-1500 units whose level ray clears the ground for over 1000
    // units (the ground within 60 units stays 1 to 4 units below the eye)...
    cases.push_back({"grazingLand", above(-700.0, 0.0, 1.0, -45.0f, 0.0f), 320, 180, expectViewOut(1000.0)});
    // ... and from the lake's western shore across the water (seen at grazing angles) to the hills
    // beyond its eastern shore (about 570 units).
    cases.push_back({"grazingShore", above(420.0, 100.0, 1.0, 60.0f, 0.0f), 320, 180, [](const CaseFrame& c) {
                         expectViewOut(400.0)(c);
                         std::printf("[stability]   water %d px\n", c.countStencil(kStencilWater));
                         EXPECT_GT(c.countStencil(kStencilWater), c.width * c.height / 10) << "the lake in view";
                     }});
    // 0.05 units above the water, looking level along the lake from its southern end: the plane
    // nearly edge-on, reflections on.
    cases.push_back({"skimmingTheLake", inTheLake(0.05, 210.0, 0.0f, 0.0f), 320, 180, [](const CaseFrame& c) {
                         EXPECT_TRUE(c.frame.cameraAboveWater);
                         EXPECT_TRUE(c.frame.reflectionsActive);
                         std::printf("[stability]   water %d px\n", c.countStencil(kStencilWater));
                         EXPECT_GT(c.countStencil(kStencilWater), c.width * c.height / 4) << "the lake fills the lower half";
                     }});
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
    // 3 units under the water (bed at -10.3), looking level along the lake and 30 degrees up at
    // the surface from below.
    cases.push_back({"underWaterLevel", inTheLake(-3.0, 130.0, 0.0f, 0.0f), 320, 180, expectUnderWater});
    cases.push_back({"underWaterLookingUp", inTheLake(-3.0, 130.0, 0.0f, 30.0f), 320, 180, [](const CaseFrame& c) {
                         expectUnderWater(c);
                         int skyInWater = 0;
                         for (int y = 0; y < c.height; ++y)
                             for (int x = 0; x < c.width; ++x) skyInWater += (c.flags(x, y) & kSurfaceSky) ? 1 : 0;
                         std::printf("[stability]   sky through the surface %d px\n", skyInWater);
                         EXPECT_GT(skyInWater, c.width * c.height / 2) << "the sky seen through the surface";
                     }});
    // The sun below the horizon: midnight (the lowest) and 3 minutes before sunrise, looking east
    // over the valley and the lake towards where it will rise.
    {
        SceneSettings scene = above(210.0, -120.0, 30.0, 90.0f, -3.0f);
        scene.hour = 0.0;
        cases.push_back({"midnight", scene, 320, 180, expectSunDown});
        scene.hour = 6.0 - 3.0 / 60.0;
        cases.push_back({"minutesBeforeSunrise", scene, 320, 180, expectSunDown});
    }
    // No point lights at night, where they would show: empty light lists on every path.
    {
        SceneSettings scene;
        scene.hour = 21.0;
        scene.lights.count = 0;
        cases.push_back({"noLightsAtNight", scene, 320, 180, [](const CaseFrame& c) {
                             expectSunDown(c);
                             EXPECT_EQ(c.lightsDrawn, 0);
                         }});
    }
    {
        SceneSettings scene;
        scene.hour = 21.0;
        scene.lights.count = kMaxLights;
        cases.push_back({"mostLights", scene, 160, 90});
    }
    return cases;
}

void PrintTo(const HardCase& hard, std::ostream* out) { *out << hard.name; }

class Stability : public GpuTest, public ::testing::WithParamInterface<HardCase> {};

TEST_P(Stability, FiniteUnitNormalsAndAgreement) {
    const HardCase& hard = GetParam();
    Renderer renderer(*shaders_, hard.scene);
    auto atlas = attachPlantAtlas(*shaders_, renderer);
    renderer.configure(hard.width, hard.height, layoutNamed("standard"));
    Image forward = renderFinal(renderer, hard.scene, PipelineKind::Forward);
    // Where the frame wrote each target: nothing clears the rest (NaNs in zink's fresh memory).
    auto nonFiniteWritten = [&](Target target) {
        return countNonFiniteWritten(readTarget(renderer, target), target, readStencil(renderer),
                                     renderer.lastFrame().setup.reflectionsActive);
    };
    for (Target target : {Target::Radiance, Target::Reflection, Target::Final})
        EXPECT_EQ(nonFiniteWritten(target), 0) << "forward " << targetName(target);
    Image deferred = renderFinal(renderer, hard.scene, PipelineKind::Deferred);
    dumpImage("stability-" + hard.name + "-forward", forward);
    dumpImage("stability-" + hard.name + "-deferred", deferred);
    for (Target target : {Target::Albedo, Target::Normal, Target::Position, Target::Info, Target::Radiance,
                          Target::Reflection, Target::Final})
        EXPECT_EQ(nonFiniteWritten(target), 0) << "deferred " << targetName(target);
    EXPECT_EQ(countNonFinite(readDepth(renderer)), 0) << "depth";

    const std::vector<float> normal = readTarget(renderer, Target::Normal);
    const std::vector<float> info = readTarget(renderer, Target::Info);
    const std::vector<uint8_t> stencil = readStencil(renderer);  // bottom row first, as the targets
    int surfaces = 0, notUnit = 0;
    double worst = 0.0;
    for (int y = 0; y < hard.height; ++y)
        for (int x = 0; x < hard.width; ++x) {
            if (!texelWritten(Target::Normal, stencil[size_t(y) * size_t(hard.width) + size_t(x)], false)) continue;
            ++surfaces;
            double error = std::fabs(glm::length(glm::dvec3(texel(normal, hard.width, x, y))) - 1.0);
            worst = std::max(worst, error);
            notUnit += error > 1e-3;
        }
    ImageDifference difference = compareImages(forward, deferred);
    std::printf("[stability] %s: camera (%.0f, %.2f, %.0f), %d surface pixels, worst |n|-1 %.1e, forward vs deferred "
                "%.2f dB, plants drawn %zu, lights %d\n",
                hard.name.c_str(), renderer.lastFrame().setup.view.pose.position.x, renderer.lastFrame().setup.view.pose.position.y,
                renderer.lastFrame().setup.view.pose.position.z, surfaces, worst, difference.psnrDb,
                renderer.lastFrame().vegetation.stats().plantsDrawn, renderer.paths().lightsDrawn);
    EXPECT_GT(surfaces, 0);
    EXPECT_EQ(notUnit, 0) << "normals off unit length by more than 1e-3 (worst " << worst << ")";
    EXPECT_GE(difference.psnrDb, 45.0) << "forward and deferred disagree";
    EXPECT_TRUE(hasContent(deferred));
    EXPECT_TRUE(hasContent(forward));
    if (hard.check) {
        const std::vector<float> position = readTarget(renderer, Target::Position);
        hard.check(CaseFrame{renderer.lastFrame().setup, hard.width, hard.height, position, info, stencil, forward,
                             deferred, renderer.paths().lightsDrawn});
    }
}

// The same cases with the compact layout: positions reconstructed from the depth copy and
// octahedral normals stay finite and unit, and deferred still agrees with forward.
TEST_P(Stability, CompactLayoutFiniteAndAgrees) {
    const HardCase& hard = GetParam();
    Renderer renderer(*shaders_, hard.scene);
    auto atlas = attachPlantAtlas(*shaders_, renderer);
    const GBufferLayout& compact = layoutNamed("compact");
    renderer.configure(hard.width, hard.height, compact);
    Image forward = renderFinal(renderer, hard.scene, PipelineKind::Forward);
    Image deferred = renderFinal(renderer, hard.scene, PipelineKind::Deferred);
    for (Target target : {Target::Albedo, Target::Normal, Target::Info, Target::Radiance, Target::Reflection,
                          Target::Final})
        EXPECT_EQ(countNonFiniteWritten(readTarget(renderer, target), target, readStencil(renderer),
                                        renderer.lastFrame().setup.reflectionsActive),
                  0)
            << "deferred " << targetName(target);
    const std::vector<float> positions = readSurfacePositions(renderer);
    EXPECT_EQ(countNonFinite(positions), 0) << "reconstructed positions";
    const std::vector<float> normal = readTarget(renderer, Target::Normal);
    const std::vector<float> info = readTarget(renderer, Target::Info);
    const std::vector<uint8_t> stencil = readStencil(renderer);  // bottom row first, as the targets
    int surfaces = 0, notUnit = 0;
    for (int y = 0; y < hard.height; ++y)
        for (int x = 0; x < hard.width; ++x) {
            if (!texelWritten(Target::Normal, stencil[size_t(y) * size_t(hard.width) + size_t(x)], false)) continue;
            ++surfaces;
            glm::vec3 n = compact.storedNormal(texel(normal, hard.width, x, y));
            notUnit += !(std::fabs(glm::length(glm::dvec3(n)) - 1.0) <= 1e-3);  // NaN counts
        }
    ImageDifference difference = compareImages(forward, deferred);
    std::printf("[stability] %s compact: %d surface pixels, forward vs deferred %.2f dB\n", hard.name.c_str(), surfaces,
                difference.psnrDb);
    EXPECT_GT(surfaces, 0);
    EXPECT_EQ(notUnit, 0);
    EXPECT_GE(difference.psnrDb, 45.0) << "forward and deferred disagree";
    EXPECT_TRUE(hasContent(deferred));
}

INSTANTIATE_TEST_SUITE_P(HardCases, Stability, ::testing::ValuesIn(hardCases()),
                         [](const auto& info) { return info.param.name; });

}  // namespace
}  // namespace oasis::gputest
