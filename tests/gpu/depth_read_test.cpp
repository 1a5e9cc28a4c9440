// The compact layout's depth read in place (--depth-read in-place, FrameSetup::work):
// the direct lighting samples the depth-stencil target itself, drawn without it attached, so
// DepthCopyPass's direct copy runs only for the stencil light volumes. Against the frame that
// copies depth for every reader: the copy is not exact on llvmpipe (gl_FragDepth written back to
// 24 bits moves a few texels by one step), so the in-place frame may differ where, and only
// where, the copy was off; the displayed frame by at most one level of 255.
#include "frame/frame_readback.h"
#include "gpu_test.h"

#include <algorithm>

namespace oasis::gputest {
namespace {


struct DepthReadRun {
    std::vector<std::string> passes;
    Image final;
    std::vector<float> radiance, positions;
    std::vector<int> copyOff;  // per pixel: the copy's depth minus the target's, in 24-bit steps
};

// D24S8 depth as integers, bottom row first; the stencil byte dropped.
std::vector<uint32_t> depthSteps(GLuint framebuffer, int width, int height) {
    std::vector<uint32_t> packed(size_t(width) * size_t(height));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, width, height, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, packed.data());
    for (uint32_t& value : packed) value >>= 8;
    return packed;
}

DepthReadRun renderWith(Renderer& renderer, SceneSettings scene, bool inPlace) {
    DepthReadRun run;
    scene.work.depthReadInPlace = inPlace;
    const FrameTargets& targets = renderer.targets();
    renderer.renderFrame(scene, FrameRequest::observed([&](const Pass& pass) {
        run.passes.push_back(pass.name());
        // What the direct lighting read: the copy against the target it was made from (the water
        // mask writes the water's depth into the target after this).
        if (pass.name() != "LightingPass" || !targets.framebuffer({}, Target::SceneDepth) || inPlace) return;
        std::vector<uint32_t> target = depthSteps(targets.framebuffer({}, Target::DepthStencil), kSmallWidth, kSmallHeight);
        std::vector<uint32_t> copy = depthSteps(targets.framebuffer({}, Target::SceneDepth), kSmallWidth, kSmallHeight);
        for (size_t i = 0; i < target.size(); ++i) run.copyOff.push_back(int(copy[i]) - int(target[i]));
    }));
    EXPECT_EQ(renderer.lastFrame().setup.work.depthReadInPlace, inPlace);
    run.radiance = readTarget(renderer, Target::Radiance);
    run.positions = readSurfacePositions(renderer);
    renderer.views().render("final");
    run.final = readDisplay(renderer);
    return run;
}

bool ran(const DepthReadRun& run, const std::string& pass) {
    return std::find(run.passes.begin(), run.passes.end(), pass) != run.passes.end();
}

size_t differingValues(const std::vector<float>& a, const std::vector<float>& b) {
    if (a.size() != b.size()) return std::max(a.size(), b.size());
    size_t differing = 0;
    for (size_t i = 0; i < a.size(); ++i) differing += a[i] != b[i] ? 1 : 0;
    return differing;
}

// The displayed frames within one level, the positions the views rebuild (from the target in both)
// equal; with `copyWholeFrame` (no reflection drew over the direct lighting's pixels) every
// Radiance pixel that differs is one the copy moved, and the copy moved none by more than one step.
void expectSameFrame(const std::string& what, const DepthReadRun& copied, const DepthReadRun& inPlace,
                     bool copyWholeFrame) {
    EXPECT_TRUE(hasContent(inPlace.final));
    ImageDifference difference = compareImages(copied.final, inPlace.final);
    EXPECT_LE(difference.maxAbs, 1) << difference.psnrDb << " dB";
    EXPECT_EQ(differingValues(copied.positions, inPlace.positions), 0u);
    int moved = 0, worst = 0, unexplained = 0, radianceDiffers = 0;
    for (size_t pixel = 0; pixel < copied.copyOff.size(); ++pixel) {
        int off = std::abs(copied.copyOff[pixel]);
        moved += off ? 1 : 0;
        worst = std::max(worst, off);
        bool differs = false;
        for (size_t c = 0; c < 4; ++c) differs |= copied.radiance[pixel * 4 + c] != inPlace.radiance[pixel * 4 + c];
        radianceDiffers += differs ? 1 : 0;
        unexplained += differs && !off ? 1 : 0;
    }
    std::printf("[depth read] %s: the copy moved %d of %zu pixels (worst %d steps); Radiance differs at %d, "
                "frame max abs %d (%.1f dB)\n", what.c_str(), moved, copied.copyOff.size(), worst, radianceDiffers,
                difference.maxAbs, difference.psnrDb);
    if (!copyWholeFrame) return;
    EXPECT_LE(worst, 1);
    EXPECT_EQ(unexplained, 0);
}

class DepthReadInPlace : public GpuTest {};

TEST_F(DepthReadInPlace, EveryPoseEqualsTheCopiedDepthsFrameWithoutTheDirectCopy) {
    Renderer renderer(*shaders_, defaultPose().scene);
    renderer.configure(kSmallWidth, kSmallHeight, layoutNamed("compact"));
    renderer.setPipeline(PipelineKind::Deferred);
    auto atlas = attachPlantAtlas(*shaders_, renderer);
    for (const NamedPose& pose : allPoses())
        for (bool reflections : {false, true}) {
            SCOPED_TRACE(pose.name + (reflections ? ", reflections on" : ", reflections off"));
            SceneSettings scene = pose.scene;
            scene.water.reflections = reflections;
            const DepthReadRun copied = renderWith(renderer, scene, false);
            const DepthReadRun inPlace = renderWith(renderer, scene, true);
            EXPECT_TRUE(ran(copied, "DepthCopyPass"));
            EXPECT_FALSE(ran(inPlace, "DepthCopyPass"));
            // The reflection's lighting is stencil-tested: its copy stays wherever it runs.
            EXPECT_EQ(ran(inPlace, "DepthCopyPass.mirrored"), ran(copied, "DepthCopyPass.mirrored"));
            EXPECT_EQ(ran(inPlace, "LightingPass.mirrored"), ran(inPlace, "DepthCopyPass.mirrored"));
            expectSameFrame(pose.name, copied, inPlace, !ran(copied, "DepthCopyPass.mirrored"));
        }
}

// Tiled lights read depth in place (a compute pass and the lighting); the stencil volumes test
// against the target while they read it, so that frame copies depth in both settings.
TEST_F(DepthReadInPlace, LightsTiledReadInPlaceAndTheVolumesKeepTheCopy) {
    NamedPose pose = defaultPose();
    pose.scene.lights.count = 16;
    pose.scene.hour = 21.0;
    Renderer renderer(*shaders_, pose.scene);
    renderer.configure(kSmallWidth, kSmallHeight, layoutNamed("compact"));
    renderer.setPipeline(PipelineKind::Deferred);
    auto atlas = attachPlantAtlas(*shaders_, renderer);
    std::vector<LightMethod> methods = {LightMethod::Volumes};
    if (renderer.paths().capabilities.compute.available) methods.push_back(LightMethod::Tiled);
    for (LightMethod method : methods) {
        SCOPED_TRACE(lightMethodName(method));
        SceneSettings scene = pose.scene;
        scene.lights.method = method;
        const DepthReadRun copied = renderWith(renderer, scene, false);
        const DepthReadRun inPlace = renderWith(renderer, scene, true);
        EXPECT_EQ(renderer.lastFrame().setup.lightMethod, method);
        EXPECT_EQ(ran(inPlace, "DepthCopyPass"), method == LightMethod::Volumes);
        EXPECT_EQ(ran(inPlace, "LightVolumePass"), method == LightMethod::Volumes);
        expectSameFrame(std::string("16 lights, ") + lightMethodName(method), copied, inPlace,
                        !ran(copied, "DepthCopyPass.mirrored"));
    }
}

// A layout that stores positions never copies depth, in place or not.
TEST_F(DepthReadInPlace, LayoutsThatStorePositionsNeverCopy) {
    Renderer renderer(*shaders_, defaultPose().scene);
    renderer.configure(kSmallWidth, kSmallHeight, layoutNamed("standard"));
    renderer.setPipeline(PipelineKind::Deferred);
    auto atlas = attachPlantAtlas(*shaders_, renderer);
    for (bool inPlace : {false, true}) {
        const DepthReadRun run = renderWith(renderer, defaultPose().scene, inPlace);
        EXPECT_FALSE(ran(run, "DepthCopyPass"));
        EXPECT_FALSE(ran(run, "DepthCopyPass.mirrored"));
        EXPECT_TRUE(hasContent(run.final));
    }
}

}  // namespace
}  // namespace oasis::gputest
