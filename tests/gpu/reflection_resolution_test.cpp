// The reflection drawn at a reduced resolution (--reflection-resolution half|quarter): only water
// pixels change, within a stated error, and some do; the frame's Reflection target is the reduced
// target read bilinearly at each water pixel's centre (checked on the CPU from the reduced texels);
// the water rectangle's widening covers the upsample's taps (bounded and unbounded frames are the
// same bit for bit); forward and deferred still agree; odd frame sizes round the targets up.
#include "frame/frame_readback.h"
#include "gpu_test.h"

#include "render/pixel_readback.h"

namespace oasis::gputest {
namespace {


SceneSettings atResolution(SceneSettings scene, int divisor) {
    scene.water.reflectionDivisor = divisor;
    return scene;
}

std::vector<NamedPose> posesWithWater() { return {defaultPose(), vegetationPoses()[0], waterPoses()[1]}; }

// The reduced Reflection (the frame's Reflection at its scale) as floats (RGBA, bottom row first)
// at its own size.
std::vector<float> readReducedReflection(const Renderer& renderer) {
    const FrameTargets& targets = renderer.targets();
    const int divisor = renderer.lastFrame().setup.reflectionDivisor;
    std::vector<float> pixels(size_t(targets.width(divisor)) * size_t(targets.height(divisor)) * 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, targets.framebuffer({Target::Reflection}, std::nullopt, divisor));
    readColourFloats(targets.width(divisor), targets.height(divisor), pixels.data());
    return pixels;
}

// GL's bilinear filter at a texture coordinate (clamped to the edge), on the CPU in double.
glm::dvec3 bilinear(const std::vector<float>& rgba, int width, int height, glm::dvec2 uv) {
    glm::dvec2 at = uv * glm::dvec2(width, height) - 0.5;
    glm::dvec2 base = glm::floor(at), f = at - base;
    auto texelAt = [&](int x, int y) {
        x = std::clamp(x, 0, width - 1);
        y = std::clamp(y, 0, height - 1);
        return glm::dvec3(rgbAt(rgba, width, x, y));
    };
    int x0 = int(base.x), y0 = int(base.y);
    return glm::mix(glm::mix(texelAt(x0, y0), texelAt(x0 + 1, y0), f.x),
                    glm::mix(texelAt(x0, y0 + 1), texelAt(x0 + 1, y0 + 1), f.x), f.y);
}

class ReflectionResolution : public GpuTest {};

// Both pipelines, three poses with water, half and quarter against full: every pixel the water
// stencil does not mark is the same bit for bit; the water's pixels differ (the knob does
// something) within a PSNR over the frame of 30 dB at half and 27 dB at quarter (measured at
// 320x180 on llvmpipe: 33.4-49.7 and 30.7-42.9 dB; the grazing view of the lake is the worst).
TEST_F(ReflectionResolution, OnlyTheWaterChangesWithinBoundedError) {
    Renderer renderer(*shaders_, defaultPose().scene);
    renderer.configure(kMediumWidth, kMediumHeight, layoutNamed("compact"));
    auto atlas = attachPlantAtlas(*shaders_, renderer);
    for (const NamedPose& pose : posesWithWater())
        for (PipelineKind kind : {PipelineKind::Forward, PipelineKind::Deferred}) {
            const Image full = renderFinal(renderer, pose.scene, kind);
            ASSERT_TRUE(hasContent(full));
            const std::vector<uint8_t> stencil = readStencil(renderer);
            const long long water = std::count(stencil.begin(), stencil.end(), uint8_t(kStencilWater));
            ASSERT_GT(water, 100) << pose.name << ": too little water in view to test the reflection";
            for (auto [divisor, minimumPsnr] : {std::pair{2, 30.0}, std::pair{4, 27.0}}) {
                SCOPED_TRACE(pose.name + ", " + pipelineName(kind) + ", 1/" + std::to_string(divisor));
                const Image reduced = renderFinal(renderer, atResolution(pose.scene, divisor), kind);
                int changedWater = 0, changedElsewhere = 0;
                for (int y = 0; y < kMediumHeight; ++y)
                    for (int x = 0; x < kMediumWidth; ++x) {
                        bool changed = maxChannelDifference(displayPixel(full, x, y), displayPixel(reduced, x, y)) > 0;
                        bool isWater = stencil[size_t(y) * kMediumWidth + size_t(x)] == kStencilWater;
                        (isWater ? changedWater : changedElsewhere) += changed ? 1 : 0;
                    }
                const ImageDifference difference = compareImages(full, reduced);
                std::printf("[reflection resolution] %s %s 1/%d: %.2f dB, max abs %d, %d of %lld water pixels changed\n",
                            pose.name.c_str(), pipelineName(kind), divisor, difference.psnrDb, difference.maxAbs,
                            changedWater, water);
                EXPECT_EQ(changedElsewhere, 0);
                EXPECT_GT(changedWater, 0) << "the reduced reflection changed nothing: the knob does nothing";
                EXPECT_GE(difference.psnrDb, minimumPsnr);
            }
        }
}

// The frame's Reflection at each water pixel is the reduced target filtered bilinearly at that
// pixel's centre, within RGBA16F's rounding of the result; outside the water nothing writes it.
TEST_F(ReflectionResolution, ReflectionTargetIsTheReducedTargetReadBilinearly) {
    for (const std::string layout : {"standard", "compact"})
        for (PipelineKind kind : {PipelineKind::Forward, PipelineKind::Deferred})
            for (int divisor : {2, 4}) {
                SCOPED_TRACE(layout + ", " + pipelineName(kind) + ", 1/" + std::to_string(divisor));
                Renderer renderer(*shaders_, defaultPose().scene);
                renderer.configure(kMediumWidth, kMediumHeight, layoutNamed(layout));
                auto atlas = attachPlantAtlas(*shaders_, renderer);
                renderer.setPipeline(kind);
                // Nothing clears Reflection: zeroed first, what is not 0 outside the water after
                // the frame was written there.
                zeroTarget(renderer.targets(), Target::Reflection);
                renderer.renderFrame(atResolution(defaultPose().scene, divisor));
                ASSERT_NE(renderer.targets().heldTexture(Target::Reflection, divisor), 0u);
                const int reducedWidth = renderer.targets().width(divisor);
                const int reducedHeight = renderer.targets().height(divisor);
                EXPECT_EQ(reducedWidth, kMediumWidth / divisor);
                EXPECT_EQ(reducedHeight, kMediumHeight / divisor);
                const std::vector<uint8_t> stencil = readStencil(renderer);
                const std::vector<float> reduced = readReducedReflection(renderer);
                const std::vector<float> frame = readTarget(renderer, Target::Reflection);
                EXPECT_EQ(countNonFinite(reduced), 0);
                int water = 0, off = 0, lit = 0, outsideNotCleared = 0;
                double worst = 0.0;
                for (int y = 0; y < kMediumHeight; ++y)
                    for (int x = 0; x < kMediumWidth; ++x) {
                        glm::dvec3 stored(rgbAt(frame, kMediumWidth, x, y));
                        if (stencil[size_t(y) * kMediumWidth + size_t(x)] != kStencilWater) {
                            outsideNotCleared += glm::length(stored) > 0.0 ? 1 : 0;
                            continue;
                        }
                        ++water;
                        glm::dvec2 uv((x + 0.5) / kMediumWidth, (y + 0.5) / kMediumHeight);
                        glm::dvec3 expected = bilinear(reduced, reducedWidth, reducedHeight, uv);
                        lit += glm::length(expected) > 0.01 ? 1 : 0;
                        // RGBA16F keeps 11 significant bits; the filter's weights may be 8-bit on
                        // some rasterisers (GL's minimum): 1/256 of the larger neighbour's value.
                        double error = glm::length(stored - expected) / std::max(glm::length(expected), 1e-3);
                        worst = std::max(worst, error);
                        off += error > 1.0 / 256.0 ? 1 : 0;
                    }
                std::printf("[reflection resolution] %s %s 1/%d: %d water pixels, %d lit, worst relative error %.5f\n",
                            layout.c_str(), pipelineName(kind), divisor, water, lit, worst);
                EXPECT_GT(lit, water / 2) << "the reduced reflection is mostly dark: the test shows nothing";
                EXPECT_EQ(off, 0);
                EXPECT_EQ(outsideNotCleared, 0);
            }
}

// The water rectangle, scaled to the reduced targets and widened by a pixel, holds every texel the
// upsample reads: bounded and unbounded frames are the same bit for bit (both layouts, pipelines,
// resolutions; the default pose and the eye at and just above the water plane).
TEST_F(ReflectionResolution, BoundedFrameIsTheUnboundedOne) {
    std::vector<NamedPose> poses = posesWithWater();
    poses.push_back(waterPoses()[0]);  // a still mirror
    poses.push_back({"eyeAtWater", sceneAtHeight(470.0, 0.0, 150.0, 30.0f, -1.0f), true, true, false});
    Renderer renderer(*shaders_, defaultPose().scene);
    renderer.configure(kMediumWidth, kMediumHeight, layoutNamed("compact"));
    auto atlas = attachPlantAtlas(*shaders_, renderer);
    if (!renderer.paths().waterBoundsAvailable) GTEST_SKIP() << renderer.paths().waterBoundsReason;
    for (const NamedPose& pose : poses)
        for (PipelineKind kind : {PipelineKind::Forward, PipelineKind::Deferred})
            for (int divisor : {2, 4}) {
                SCOPED_TRACE(pose.name + ", " + pipelineName(kind) + ", 1/" + std::to_string(divisor));
                SceneSettings bounded = atResolution(pose.scene, divisor), unbounded = bounded;
                unbounded.water.reflectionBounds = false;
                const Image reference = renderFinal(renderer, unbounded, kind);
                EXPECT_TRUE(hasContent(reference));
                EXPECT_EQ(compareImages(reference, renderFinal(renderer, bounded, kind)).maxAbs, 0);
            }
}

// Forward against deferred at each resolution: the agreement the full-resolution frame has
// (Agreement's 45 dB for the compact layout) holds, and is never 0.5 dB worse than full's (both
// pipelines read the same reduced reflection; measured: within 0.02 dB, 0.5 dB better grazing).
TEST_F(ReflectionResolution, PipelinesAgreeAtEveryResolution) {
    Renderer renderer(*shaders_, defaultPose().scene);
    renderer.configure(kMediumWidth, kMediumHeight, layoutNamed("compact"));
    auto atlas = attachPlantAtlas(*shaders_, renderer);
    for (const NamedPose& pose : posesWithWater()) {
        double fullPsnr = 0.0;
        for (int divisor : {1, 2, 4}) {
            SCOPED_TRACE(pose.name + ", 1/" + std::to_string(divisor));
            SceneSettings scene = atResolution(pose.scene, divisor);
            const double psnr = compareImages(renderFinal(renderer, scene, PipelineKind::Forward),
                                              renderFinal(renderer, scene, PipelineKind::Deferred)).psnrDb;
            std::printf("[reflection resolution] %s 1/%d: forward vs deferred %.2f dB\n", pose.name.c_str(), divisor, psnr);
            EXPECT_GE(psnr, 45.0);
            if (divisor == 1) fullPsnr = psnr;
            else EXPECT_GE(psnr, fullPsnr - 0.5);
        }
    }
}

// Sizes that do not divide: the reduced targets round up (161x91 and 81x46 for 321x181), the
// frame has no non-finite value in its reflection, and the error stays within bounds; back at
// full resolution the reduced targets are released.
TEST_F(ReflectionResolution, OddSizesRoundTheTargetsUp) {
    constexpr int width = 321, height = 181;
    Renderer renderer(*shaders_, defaultPose().scene);
    renderer.configure(width, height, layoutNamed("compact"));
    auto atlas = attachPlantAtlas(*shaders_, renderer);
    const Image full = renderFinal(renderer, defaultPose().scene, PipelineKind::Deferred);
    for (auto [divisor, reducedWidth, reducedHeight] : {std::tuple{2, 161, 91}, std::tuple{4, 81, 46}}) {
        SCOPED_TRACE("1/" + std::to_string(divisor));
        const Image reduced = renderFinal(renderer, atResolution(defaultPose().scene, divisor), PipelineKind::Deferred);
        ASSERT_NE(renderer.targets().heldTexture(Target::Reflection, divisor), 0u);
        EXPECT_EQ(renderer.targets().width(divisor), reducedWidth);
        EXPECT_EQ(renderer.targets().height(divisor), reducedHeight);
        EXPECT_EQ(countNonFiniteWritten(readTarget(renderer, Target::Reflection), Target::Reflection,
                                        readStencil(renderer), renderer.lastFrame().setup.reflectionsActive),
                  0);
        EXPECT_GE(compareImages(full, reduced).psnrDb, 27.0);
    }
    // Back at full resolution the reduced targets are given back (and the frame is the full one again).
    const Image again = renderFinal(renderer, defaultPose().scene, PipelineKind::Deferred);
    for (int divisor : {2, 4})
        for (int t = 0; t < int(Target::Count); ++t) EXPECT_EQ(renderer.targets().heldTexture(Target(t), divisor), 0u);
    EXPECT_EQ(compareImages(full, again).maxAbs, 0);
}

}  // namespace
}  // namespace oasis::gputest
