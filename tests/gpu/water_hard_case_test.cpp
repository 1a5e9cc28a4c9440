// Water at hard camera poses (at, just above and under the water, straight down, grazing): every
// target finite, the reflection only inside the water, and the pipelines agreeing there.
#include "water_support.h"

namespace oasis::gputest {
namespace {

// ---------------------------------------------------------------------------------------------
// Hard cases, each in both layouts and both pipelines: no NaN/Inf in any target, Reflection zero
// outside the water, sky reflections equal the sky along the mirrored ray, forward and deferred
// agree (full >= 55 dB, standard >= 45 dB).
struct HardWaterPose {
    std::string name;
    SceneSettings scene;
};
std::vector<HardWaterPose> hardWaterPoses() {
    // Over the lake's deep part (bed about -11.8 at (490, 100)), water level 0.
    auto at = [](double y, float pitch) { return sceneAtHeight(490.0, y, 100.0, 30.0f, pitch); };
    return {
        {"atLevel", at(0.0, -5.0f)},          // the plane edge-on through the eye
        {"justAbove", at(1e-4, -5.0f)},       // 0.1 mm above it
        {"below", at(-3.0, -10.0f)},          // under water: no reflection work
        {"straightDown", at(5.0, -89.9f)},    // nothing but water
        {"grazing", at(0.5, -1.0f)},          // 0.5 above, 1 degree down
    };
}

class WaterHardCase : public GpuTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(WaterHardCase, FiniteReflectionOnlyInWaterAndPipelinesAgree) {
    HardWaterPose hard;
    for (const HardWaterPose& c : hardWaterPoses())
        if (c.name == GetParam()) hard = c;
    ASSERT_FALSE(hard.name.empty());
    Renderer renderer(*shaders_, hard.scene);
    for (const auto& [layout, minPsnr] : {std::make_pair("full", 55.0), std::make_pair("standard", 45.0)}) {
        SCOPED_TRACE(hard.name + " " + layout);
        renderer.configure(320, 180, layoutNamed(layout));
        // Reflection zeroed before each frame: nothing clears it, so what is not 0 after the
        // frame outside the water was written there.
        zeroTarget(renderer.targets(), Target::Reflection);
        FrameReadback forward = renderAndRead(renderer, hard.scene, PipelineKind::Forward);
        renderer.views().render("final");
        Image forwardImage = readDisplay(renderer);
        zeroTarget(renderer.targets(), Target::Reflection);
        FrameReadback deferred = renderAndRead(renderer, hard.scene, PipelineKind::Deferred);
        renderer.views().render("final");
        Image deferredImage = readDisplay(renderer);
        dumpImage("water-" + hard.name + "-" + layout + "-forward", forwardImage);
        dumpImage("water-" + hard.name + "-" + layout + "-deferred", deferredImage);
        const FrameSetup& frame = deferred.frame;

        const std::pair<const char*, const std::vector<float>*> targets[] = {
            {"albedo", &deferred.albedo}, {"normal", &deferred.normal}, {"position", &deferred.position},
            {"info", &deferred.info}, {"radiance", &deferred.radiance}, {"reflection", &deferred.reflection},
            {"final", &deferred.final}, {"depth", &deferred.depth}, {"forward radiance", &forward.radiance},
            {"forward reflection", &forward.reflection}, {"forward final", &forward.final}, {"forward depth", &forward.depth}};
        // The G-buffer's colour targets count where a surface was drawn (nothing clears the rest).
        const Target gbufferOf[] = {Target::Albedo, Target::Normal, Target::Position, Target::Info};
        for (size_t t = 0; t < std::size(targets); ++t) {
            const auto& [label, values] = targets[t];
            int nonFinite = t < 4 ? countNonFiniteWritten(*values, gbufferOf[t], deferred.stencil, frame.reflectionsActive)
                                  : countNonFinite(*values);
            EXPECT_EQ(nonFinite, 0) << label;
        }
        EXPECT_TRUE(forward.stencil == deferred.stencil) << "forward and deferred water masks differ";
        EXPECT_EQ(reflectionOutsideWater(deferred), 0) << "deferred: reflection outside the water";
        EXPECT_EQ(reflectionOutsideWater(forward), 0) << "forward: reflection outside the water";

        int water = countStencil(deferred, kStencilWater), skyInWater = 0, reflectedFlags = 0;
        for (int y = 0; y < deferred.height; ++y)
            for (int x = 0; x < deferred.width; ++x) {
                skyInWater += deferred.stencilAt(x, y) == kStencilWater && deferred.flags(x, y) == kSurfaceSky ? 1 : 0;
                reflectedFlags += deferred.flags(x, y) == kSurfaceReflected ? 1 : 0;
            }
        if (frame.reflectionsActive) {
            // The sky seen in the water, in both pipelines (forward draws it with sky.forward.mirrored).
            auto showsSky = [&](int x, int y) { return deferred.flags(x, y) == kSurfaceSky; };
            for (const FrameReadback* r : {&deferred, &forward}) {
                SkyReflectionStats sky = checkSkyReflection(*r, showsSky);
                EXPECT_EQ(sky.wrong, 0) << (r == &forward ? "forward" : "deferred")
                                        << ": sky reflection is not the sky along the mirrored ray; first " << sky.first;
            }
        } else {
            EXPECT_EQ(reflectedFlags, 0) << "mirrored surfaces drawn with reflections inactive";
        }

        ImageDifference difference = compareImages(forwardImage, deferredImage);
        std::printf("[water] hard case %s %s: water %d px (sky in it %d, reflected surfaces %d), reflections %s, "
                    "PSNR %.2f dB, max %d\n",
                    hard.name.c_str(), layout, water, skyInWater, reflectedFlags,
                    frame.reflectionsActive ? "active" : "inactive", difference.psnrDb, difference.maxAbs);
        EXPECT_GE(difference.psnrDb, minPsnr) << "forward and deferred disagree";

        if (hard.name == "straightDown") {
            EXPECT_EQ(water, deferred.width * deferred.height) << "straight down over the lake shows only water";
            EXPECT_EQ(skyInWater, water) << "straight down the water mirrors only the sky";
        }
        if (hard.name == "grazing") {
            EXPECT_GT(water, deferred.width * deferred.height / 4);
        }
        if (hard.name == "below") {
            EXPECT_FALSE(frame.cameraAboveWater);
            EXPECT_FALSE(frame.reflectionsActive);
            for (const FrameReadback* r : {&deferred, &forward}) {
                size_t nonZero = countNonZero(r->reflection);
                EXPECT_EQ(nonZero, 0u) << (r == &forward ? "forward" : "deferred") << ": Reflection not zero under water";
            }
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Water, WaterHardCase,
                         ::testing::Values("atLevel", "justAbove", "below", "straightDown", "grazing"),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace oasis::gputest
