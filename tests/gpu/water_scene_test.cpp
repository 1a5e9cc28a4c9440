// The views' water scene (frame/view_fill.h): at water pixels every view of one frame shows the
// same scene, the one asked for, in both pipelines and every layout. Direct is the deferred
// frame's own G-buffer and depth before the water is marked (stopped before LightingPass), mirrored
// is the deferred frame's state before the reflection is lit (stopped before LightingPass.mirrored),
// bit for bit; the depth and the G-buffer agree on where nothing was drawn; a mirrored scene
// asked for without reflections falls back to the direct one and says why.
#include "frame/frame_readback.h"
#include "gpu_test.h"

#include "passes/pass.h"

namespace oasis::gputest {
namespace {


// Across the lake from the western shore: water reflecting hills, plants and sky.
SceneSettings lakeScene() {
    SceneSettings scene = sceneAtHeight(435.0, 4.0, 140.0, 30.0f, -3.0f);
    scene.water.rippleStrength = 0.6f;
    return scene;
}

struct Surfaces {
    std::vector<float> albedo, info, depth;
    std::vector<uint8_t> stencil;
};

// Where nothing was drawn (depth at the far plane) the colour targets are not cleared (issue 30,
// item 6): they hold whatever an earlier frame left, which nothing reads. Those texels read 0 here,
// and Info's the SKY flag where the layout tells the sky by depth (compact); the layouts that store
// position keep Info's clear, read as stored.
Surfaces readSurfaces(Renderer& renderer) {
    Surfaces read{readTarget(renderer, Target::Albedo), readTarget(renderer, Target::Info), readDepth(renderer),
                  readStencil(renderer)};
    const GBufferLayout& layout = renderer.targets().layout();
    const float cleared = renderer.targets().depth().farPlaneWindowDepth;
    for (size_t i = 0; i < read.depth.size(); ++i) {
        if (read.depth[i] != cleared) continue;
        for (int c = 0; c < 4; ++c) read.albedo[i * 4 + size_t(c)] = 0.0f;
        if (layout.positionFromDepth())
            for (int c = 0; c < 4; ++c) read.info[i * 4 + size_t(c)] = layout.clearedInfo()[c];
    }
    return read;
}

class WaterSceneTest : public GpuTest, public ::testing::WithParamInterface<std::string> {
protected:
    // A whole frame of `pipeline`, then the views' fill of `waterScene`.
    Surfaces filled(Renderer& renderer, const SceneSettings& scene, PipelineKind pipeline, WaterScene waterScene) {
        renderer.setPipeline(pipeline);
        renderer.views().setWaterScene(waterScene);
        renderer.renderFrame(scene);
        renderer.views().ensureGBuffer();
        return readSurfaces(renderer);
    }
    // The deferred frame as it stood before `pass`.
    Surfaces deferredBefore(Renderer& renderer, const SceneSettings& scene, const std::string& pass) {
        renderer.setPipeline(PipelineKind::Deferred);
        renderer.renderFrame(scene, pass);
        return readSurfaces(renderer);
    }
};

TEST_P(WaterSceneTest, EachSceneIsTheDeferredFramesOwnAndBothPipelinesShowIt) {
    const SceneSettings scene = lakeScene();
    Renderer renderer(*shaders_, scene);
    auto atlas = attachPlantAtlas(*shaders_, renderer);
    const GBufferLayout& layout = layoutNamed(GetParam());
    renderer.configure(kSmallWidth, kSmallHeight, layout);

    const Surfaces beforeLighting = deferredBefore(renderer, scene, "LightingPass");
    const Surfaces beforeMirroredLighting = deferredBefore(renderer, scene, "LightingPass.mirrored");
    long water = 0, reflected = 0, reflectsSky = 0;
    for (WaterScene waterScene : {WaterScene::Direct, WaterScene::Mirrored}) {
        const Surfaces& expected = waterScene == WaterScene::Direct ? beforeLighting : beforeMirroredLighting;
        for (PipelineKind pipeline : {PipelineKind::Forward, PipelineKind::Deferred}) {
            SCOPED_TRACE(std::string(pipelineName(pipeline)) + ", water scene " + waterSceneName(waterScene));
            const Surfaces shown = filled(renderer, scene, pipeline, waterScene);
            ASSERT_TRUE(renderer.views().scene().scene.has_value());
            EXPECT_EQ(*renderer.views().scene().scene, waterScene);
            EXPECT_EQ(shown.albedo, expected.albedo);
            EXPECT_EQ(shown.info, expected.info);
            EXPECT_EQ(shown.depth, expected.depth);
            // Every view agrees on where nothing was drawn, the water pixels included: depth holds
            // its clear value exactly where info carries the sky flag (by construction in compact,
            // whose sky is that depth: readSurfaces).
            const float cleared = renderer.targets().depth().farPlaneWindowDepth;
            long disagree = 0;
            for (size_t i = 0; i < shown.depth.size(); ++i) {
                unsigned flags = layout.storedFlags(glm::vec4(shown.info[i * 4], shown.info[i * 4 + 1],
                                                              shown.info[i * 4 + 2], shown.info[i * 4 + 3]));
                if (((flags & kSurfaceSky) != 0) != (shown.depth[i] == cleared)) ++disagree;
                if ((shown.stencil[i] & 0x7f) != kStencilWater || pipeline != PipelineKind::Deferred) continue;
                if (waterScene == WaterScene::Direct) {
                    ++water;
                    EXPECT_EQ(flags & kSurfaceReflected, 0u) << "a mirrored surface in the direct scene at pixel " << i;
                } else if (flags & kSurfaceReflected) {
                    ++reflected;
                } else if (flags & kSurfaceSky) {
                    ++reflectsSky;
                }
            }
            EXPECT_EQ(disagree, 0) << "pixels where depth and the G-buffer disagree on a surface";
        }
    }
    EXPECT_GT(water, 100) << "the frame must show the lake";
    EXPECT_GT(reflected, 20) << "the lake must reflect surfaces";
    EXPECT_GT(reflectsSky, 20) << "the lake must reflect the sky somewhere";
}

TEST_P(WaterSceneTest, MirroredWithoutReflectionsShowsTheDirectSceneAndSaysWhy) {
    SceneSettings scene = lakeScene();
    Renderer renderer(*shaders_, scene);
    auto atlas = attachPlantAtlas(*shaders_, renderer);
    renderer.configure(kSmallWidth, kSmallHeight, layoutNamed(GetParam()));
    const Surfaces direct = filled(renderer, scene, PipelineKind::Deferred, WaterScene::Direct);
    scene.water.reflections = false;
    const Surfaces asked = filled(renderer, scene, PipelineKind::Deferred, WaterScene::Mirrored);
    EXPECT_EQ(*renderer.views().scene().scene, WaterScene::Direct);
    EXPECT_NE(renderer.views().scene().reason.find("reflections off"), std::string::npos) << renderer.views().scene().reason;
    EXPECT_EQ(asked.albedo, direct.albedo);
    EXPECT_EQ(asked.depth, direct.depth);
}

TEST_P(WaterSceneTest, AFrameStoppedEarlyIsShownAsItWasLeft) {
    const SceneSettings scene = lakeScene();
    Renderer renderer(*shaders_, scene);
    auto atlas = attachPlantAtlas(*shaders_, renderer);
    renderer.configure(kSmallWidth, kSmallHeight, layoutNamed(GetParam()));
    const Surfaces stopped = deferredBefore(renderer, scene, "WaterCompositePass");
    renderer.views().setWaterScene(WaterScene::Direct);
    renderer.views().render("albedo");
    EXPECT_FALSE(renderer.views().scene().scene.has_value());
    EXPECT_NE(renderer.views().scene().description.find("WaterCompositePass"), std::string::npos);
    EXPECT_EQ(readSurfaces(renderer).albedo, stopped.albedo);
}

INSTANTIATE_TEST_SUITE_P(Layouts, WaterSceneTest, ::testing::Values("full", "standard", "compact"));

}  // namespace
}  // namespace oasis::gputest
