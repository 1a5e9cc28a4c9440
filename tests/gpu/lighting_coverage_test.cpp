// Which pixels the deferred lighting shades (LightingPass::testsSurfaces): where the depth-stencil
// target can be attached, a far-plane triangle depth-tested to the surfaces, SkyPass.deferred
// drawing exactly the rest; where it cannot (the compact layout reading depth in place on a
// context without read-only depth), every pixel, the sky's black until SkyPass draws over them.
// Both give the same frame bit for bit, and a frame stopped between the two shows black sky.
#include "frame/frame_readback.h"
#include "gpu_test.h"

#include <algorithm>
#include <cmath>

#include "common/shared_constants.glsl"
#include "passes/lighting_pass.h"

namespace oasis::gputest {
namespace {

constexpr long long kPixels = (long long)kSmallWidth * kSmallHeight;

struct CoverageRun {
    Image final;
    std::vector<float> radiance, reflection;
    long long lightingSamples = -1, skySamples = -1;  // -1: not counted (OpenGL ES has no GL_SAMPLES_PASSED)
};

CoverageRun renderWith(Renderer& renderer, const SceneSettings& scene, bool readOnlyDepth) {
    RendererCapabilities caps = renderer.paths().capabilities;
    caps.readOnlyDepth = {readOnlyDepth, readOnlyDepth ? "test: on" : "test: off"};
    renderer.setCapabilities(caps);
    CoverageRun run;
    // The samples LightingPass and SkyPass.deferred let through their tests (llvmpipe's
    // fragment-shader statistics count whole 4x4 blocks before the depth test, so they cannot
    // tell). A query spans just those two: the water mask's own occlusion query comes later.
    bool counted = epoxy_is_desktop_gl();
    GLuint query = 0;
    if (counted) glGenQueries(1, &query);
    bool open = false;
    const std::string before[] = {"VegetationPass.gbuffer", "DepthCopyPass", "LightTilingPass", "LightingPass"};
    renderer.renderFrame(scene, FrameRequest::observed([&](const Pass& pass) {
        if (!counted) return;
        if (open) {
            glEndQuery(GL_SAMPLES_PASSED);
            open = false;
            GLuint64 count = 0;
            glGetQueryObjectui64v(query, GL_QUERY_RESULT, &count);
            if (pass.name() == "LightingPass") run.lightingSamples = (long long)count;
            if (pass.name() == "SkyPass.deferred") run.skySamples = (long long)count;
        }
        if (std::find(std::begin(before), std::end(before), pass.name()) != std::end(before)) {
            glBeginQuery(GL_SAMPLES_PASSED, query);
            open = true;
        }
    }));
    if (counted) glDeleteQueries(1, &query);
    run.radiance = readTarget(renderer, Target::Radiance);
    // Where the frame wrote it: nothing clears Reflection outside the water (fresh NaNs on zink).
    run.reflection = writtenTexels(readTarget(renderer, Target::Reflection), Target::Reflection, readStencil(renderer),
                                   renderer.lastFrame().setup.reflectionsActive);
    renderer.views().render("final");
    run.final = readDisplay(renderer);
    return run;
}

class LightingCoverage : public GpuTest {};

// Every pose, the compact layout (in place and copied) and one that stores positions: the frame,
// Radiance and Reflection are the same whichever way the lighting is kept off the sky; tested,
// the lighting and the sky pass complementary pixels, untested the lighting passes every pixel.
TEST_F(LightingCoverage, SurfacesOnlyEqualsEveryPixelAndTheSkyShadesTheRest) {
    struct Setup {
        const char* layout;
        bool inPlace;
        const char* depth;
    };
    const Setup setups[] = {{"compact", true, "standard"}, {"compact", true, "reversed-z"}, {"compact", false, "standard"},
                            {"standard", true, "standard"}, {"standard", false, "reversed-z"}};
    for (auto [layout, inPlace, depth] : setups) {
        Renderer renderer(*shaders_, defaultPose().scene);
        renderer.setDepthConvention(*findDepthConvention(depth));
        renderer.configure(kSmallWidth, kSmallHeight, layoutNamed(layout));
        if (renderer.paths().depth->name != depth) GTEST_SKIP() << renderer.paths().depthReason;
        renderer.setPipeline(PipelineKind::Deferred);
        auto atlas = attachPlantAtlas(*shaders_, renderer);
        for (const NamedPose& pose : allPoses()) {
            SCOPED_TRACE(pose.name + ", " + layout + (inPlace ? ", in place, " : ", copied, ") + depth);
            SceneSettings scene = pose.scene;
            scene.work.depthReadInPlace = inPlace;
            const CoverageRun tested = renderWith(renderer, scene, true);
            LightingPass lighting;
            EXPECT_TRUE(lighting.testsSurfaces(renderer.lastFrame().setup));
            const CoverageRun untested = renderWith(renderer, scene, false);
            bool samplesTarget = inPlace && std::string(layout) == "compact";
            EXPECT_EQ(lighting.testsSurfaces(renderer.lastFrame().setup), !samplesTarget);
            EXPECT_TRUE(hasContent(tested.final));
            ImageDifference difference = compareImages(tested.final, untested.final);
            EXPECT_EQ(difference.maxAbs, 0) << difference.psnrDb << " dB";
            EXPECT_TRUE(tested.radiance == untested.radiance);
            EXPECT_TRUE(tested.reflection == untested.reflection);
            if (tested.lightingSamples < 0) continue;
            std::printf("[lighting coverage] %s %s%s %s: lighting %lld + sky %lld of %lld pixels; untested lighting %lld\n",
                        pose.name.c_str(), layout, inPlace ? " in place" : " copied", depth, tested.lightingSamples,
                        tested.skySamples, kPixels, untested.lightingSamples);
            EXPECT_EQ(tested.lightingSamples + tested.skySamples, kPixels);
            EXPECT_EQ(untested.lightingSamples, samplesTarget ? kPixels : tested.lightingSamples);
        }
    }
}

// The default frame shows sky: the surfaces-only lighting shades fewer than every pixel there.
TEST_F(LightingCoverage, TheDefaultFrameLeavesItsSkyToSkyPass) {
    Renderer renderer(*shaders_, defaultPose().scene);
    renderer.configure(kSmallWidth, kSmallHeight, layoutNamed("compact"));
    renderer.setPipeline(PipelineKind::Deferred);
    auto atlas = attachPlantAtlas(*shaders_, renderer);
    const CoverageRun run = renderWith(renderer, defaultPose().scene, true);
    if (run.lightingSamples < 0) GTEST_SKIP() << "OpenGL ES: no GL_SAMPLES_PASSED";
    EXPECT_GT(run.skySamples, kPixels / 10);
    EXPECT_LT(run.lightingSamples, kPixels * 9 / 10);
}

// Stopped before SkyPass.deferred, Radiance is black wherever the sky will be and lit elsewhere,
// whichever way the lighting kept off the sky, even after a whole frame drew the sky there.
TEST_F(LightingCoverage, AFrameStoppedBeforeTheSkyShowsItBlack) {
    Renderer renderer(*shaders_, defaultPose().scene);
    renderer.configure(kSmallWidth, kSmallHeight, layoutNamed("compact"));
    renderer.setPipeline(PipelineKind::Deferred);
    auto atlas = attachPlantAtlas(*shaders_, renderer);
    SceneSettings scene = defaultPose().scene;
    for (bool readOnlyDepth : {true, false}) {
    SCOPED_TRACE(readOnlyDepth ? "surfaces only" : "every pixel");
    RendererCapabilities caps = renderer.paths().capabilities;
    caps.readOnlyDepth = {readOnlyDepth, "test"};
    renderer.setCapabilities(caps);
    renderer.renderFrame(scene);
    std::vector<float> whole = readTarget(renderer, Target::Radiance);
    renderer.renderFrame(scene, "SkyPass.deferred");
    std::vector<float> stopped = readTarget(renderer, Target::Radiance);
    // The compact layout tells the sky by depth at the far plane (its Info is not cleared).
    std::vector<float> depth = readDepth(renderer);
    const float farPlane = renderer.targets().depth().farPlaneWindowDepth;
    int sky = 0, skyBefore = 0, litSurfaces = 0, wrong = 0;
    for (size_t pixel = 0; pixel < size_t(kPixels); ++pixel) {
        bool isSky = depth[pixel] == farPlane;
        glm::vec3 stoppedRgb(stopped[pixel * 4], stopped[pixel * 4 + 1], stopped[pixel * 4 + 2]);
        glm::vec3 wholeRgb(whole[pixel * 4], whole[pixel * 4 + 1], whole[pixel * 4 + 2]);
        bool finite = std::isfinite(stoppedRgb.r) && std::isfinite(stoppedRgb.g) && std::isfinite(stoppedRgb.b);
        if (isSky) {
            ++sky;
            skyBefore += wholeRgb != glm::vec3(0.0f) ? 1 : 0;
            wrong += stoppedRgb != glm::vec3(0.0f) ? 1 : 0;
        } else {
            litSurfaces += finite && stoppedRgb != glm::vec3(0.0f) ? 1 : 0;
        }
    }
    EXPECT_GT(sky, int(kPixels / 10));
    EXPECT_EQ(skyBefore, sky);  // the whole frame left sky there, which the stopped one must not show
    EXPECT_EQ(wrong, 0);
    EXPECT_EQ(litSurfaces, int(kPixels) - sky);
    }
}

}  // namespace
}  // namespace oasis::gputest
