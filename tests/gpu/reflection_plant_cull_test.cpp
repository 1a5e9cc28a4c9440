// The reflection's plants culled on the CPU where their mirror image can land only on dry land
// (--reflection-plant-cull, scene/visible_water.h): the frames and the Reflection target are the
// same bit for bit with and without the cull, in both pipelines, over poses with water near and
// far, low and grazing, along the flight and far from the origin; and the cull does cull (the
// default frame loses more than a third of its mirrored plants). At a reduced reflection
// resolution it stands aside; by default (auto) it culls only while the camera stands still.
#include "frame/frame_readback.h"
#include "gpu_test.h"

namespace oasis::gputest {
namespace {


std::vector<NamedPose> culledPoses() {
    std::vector<NamedPose> poses{defaultPose(), vegetationPoses()[0]};
    for (const NamedPose& pose : waterPoses()) poses.push_back(pose);
    for (double time : {25.0, 70.0}) {
        SceneSettings scene;
        scene.timeSeconds = time;
        poses.push_back({"flight " + std::to_string(int(time)) + " s", scene, true, true, false});
    }
    // Far out: 1e5 units east, 15 units over the ground, looking down a little.
    poses.push_back({"far", sceneAt(100000.0, 300.0, 15.0, 60.0f, -6.0f), true, true, false});
    // Low over the shore: 1.2 units above the ground by the lake, looking across it.
    poses.push_back({"shore", sceneAtHeight(440.0, 1.2, 150.0, 35.0f, -2.0f), true, true, false});
    return poses;
}

SceneSettings withCull(SceneSettings scene, bool cull) {
    scene.work.mirroredPlantCull = cull ? MirroredPlantCull::On : MirroredPlantCull::Off;
    return scene;
}

class ReflectionPlantCull : public GpuTest {};

TEST_F(ReflectionPlantCull, SameFramesBitForBitWithFewerMirroredPlants) {
    Renderer renderer(*shaders_, defaultPose().scene);
    renderer.configure(kMediumWidth, kMediumHeight, layoutNamed("compact"));
    auto atlas = attachPlantAtlas(*shaders_, renderer);
    size_t culledPlants = 0, mirroredWithout = 0;
    for (const NamedPose& pose : culledPoses()) {
        for (PipelineKind kind : {PipelineKind::Forward, PipelineKind::Deferred}) {
            SCOPED_TRACE(pose.name + (kind == PipelineKind::Forward ? " forward" : " deferred"));
            const Image without = renderFinal(renderer, withCull(pose.scene, false), kind);
            ASSERT_TRUE(hasContent(without));
            // Where the frame wrote it (writtenTexels: nothing clears Reflection outside the water).
            auto reflection = [&] {
                return writtenTexels(readTarget(renderer, Target::Reflection), Target::Reflection,
                                     readStencil(renderer), renderer.lastFrame().setup.reflectionsActive);
            };
            const std::vector<float> reflectionWithout = reflection();
            const VegetationStats statsWithout = renderer.lastFrame().vegetation.stats();
            EXPECT_FALSE(renderer.lastFrame().setup.mirroredPlantsCulled);

            const Image with = renderFinal(renderer, withCull(pose.scene, true), kind);
            const std::vector<float> reflectionWith = reflection();
            const VegetationStats stats = renderer.lastFrame().vegetation.stats();
            EXPECT_EQ(renderer.lastFrame().setup.mirroredPlantsCulled, renderer.lastFrame().setup.reflectionsActive);

            ImageDifference difference = compareImages(without, with);
            EXPECT_EQ(difference.maxAbs, 0) << difference.psnrDb << " dB";
            EXPECT_TRUE(reflectionWith == reflectionWithout) << "the Reflection target changed";
            // The cull only removes: the direct list is untouched, the mirrored one shrinks by what it counts.
            EXPECT_EQ(stats.plantsDrawn, statsWithout.plantsDrawn);
            EXPECT_LE(stats.plantsDrawnMirrored + stats.plantsMirroredOnLand, statsWithout.plantsDrawnMirrored);
            EXPECT_EQ(stats.chunksMirrored + stats.chunksMirroredOnLand, statsWithout.chunksMirrored);
            if (kind == PipelineKind::Deferred) {
                culledPlants += statsWithout.plantsDrawnMirrored - stats.plantsDrawnMirrored;
                mirroredWithout += statsWithout.plantsDrawnMirrored;
            }
            if (pose.name == "default") {
                // Measured: 5,293 mirrored plants without, 2,303 with (1280x720 and here alike).
                EXPECT_LT(double(stats.plantsDrawnMirrored), 0.66 * double(statsWithout.plantsDrawnMirrored));
            }
        }
    }
    EXPECT_GT(culledPlants, mirroredWithout / 4) << "of " << mirroredWithout;
}

TEST_F(ReflectionPlantCull, StandsAsideAtReducedResolutionAndWithoutReflections) {
    Renderer renderer(*shaders_, defaultPose().scene);
    renderer.configure(kMediumWidth, kMediumHeight, layoutNamed("compact"));
    auto atlas = attachPlantAtlas(*shaders_, renderer);
    SceneSettings scene = defaultPose().scene;
    scene.water.reflectionDivisor = 2;
    renderFinal(renderer, scene, PipelineKind::Deferred);
    EXPECT_FALSE(renderer.lastFrame().setup.mirroredPlantsCulled);
    EXPECT_EQ(renderer.lastFrame().vegetation.stats().plantsMirroredOnLand, 0u);
    EXPECT_EQ(renderer.lastFrame().vegetation.stats().chunksMirroredOnLand, 0u);
    scene = defaultPose().scene;
    scene.water.reflections = false;
    renderFinal(renderer, scene, PipelineKind::Deferred);
    EXPECT_FALSE(renderer.lastFrame().setup.mirroredPlantsCulled);
    EXPECT_EQ(renderer.lastFrame().vegetation.stats().plantsDrawnMirrored, 0u);
}

// Auto (the default) culls once the camera stands still: not on a frame whose grid moved, from
// the next frame of the same view on; and stops when it moves again.
TEST_F(ReflectionPlantCull, AutoCullsWhileTheCameraStandsStill) {
    Renderer renderer(*shaders_, defaultPose().scene);
    renderer.configure(kMediumWidth, kMediumHeight, layoutNamed("compact"));
    auto atlas = attachPlantAtlas(*shaders_, renderer);
    SceneSettings scene = defaultPose().scene;
    ASSERT_EQ(scene.work.mirroredPlantCull, MirroredPlantCull::Auto);
    const Image first = renderFinal(renderer, scene, PipelineKind::Deferred);
    EXPECT_FALSE(renderer.lastFrame().setup.mirroredPlantsCulled) << "the first frame has no last grid";
    const Image still = renderFinal(renderer, scene, PipelineKind::Deferred);
    EXPECT_TRUE(renderer.lastFrame().setup.mirroredPlantsCulled);
    EXPECT_GT(renderer.lastFrame().vegetation.stats().plantsMirroredOnLand, 0u);
    EXPECT_EQ(compareImages(first, still).maxAbs, 0);
    scene.timeSeconds = 0.5;  // the flight moves on
    renderFinal(renderer, scene, PipelineKind::Deferred);
    EXPECT_FALSE(renderer.lastFrame().setup.mirroredPlantsCulled);
    renderFinal(renderer, scene, PipelineKind::Forward);
    EXPECT_TRUE(renderer.lastFrame().setup.mirroredPlantsCulled) << "the other pipeline, the same view";
}

}  // namespace
}  // namespace oasis::gputest
