// The reflection bounded to the visible water (shaders/common/water_bounds.glsl): the rectangle
// the water mask records holds every water pixel and is tight, the frame is the unbounded frame's
// bit for bit, the reflection's full-screen passes shade fewer fragments (none without water),
// a frame with no water in view runs no vertex or fragment of any reflection pass (conditional
// rendering on the water mask's occlusion query), and where storage blocks are missing the passes
// fall back to the whole screen and say why.
#include "frame/frame_readback.h"
#include "gpu_test.h"

namespace oasis::gputest {
namespace {


// Shader invocations (`statistic`: GL_VERTEX_SHADER_INVOCATIONS_ARB, ...) of every pass that only
// draws the reflection (Pass::reflectionWork: mirrored surfaces, copies, lighting, sky; the
// reflection clear's draw is conditional inside its pass, and draws nothing without water anyway),
// or of the passes `counted` picks; -1 where the context has no pipeline statistics query. A query
// spans each pass: it is ended and restarted after every pass that ran.
long long reflectionWorkInvocations(Renderer& renderer, const SceneSettings& scene, GLenum statistic,
                                    const std::function<bool(const Pass&)>& counted = [](const Pass& pass) {
                                        return pass.reflectionWork();
                                    }) {
    if (epoxy_gl_version() < 46 && !epoxy_has_gl_extension("GL_ARB_pipeline_statistics_query")) return -1;
    GLuint query = 0;
    glGenQueries(1, &query);
    long long reflection = 0;
    glBeginQuery(statistic, query);
    renderer.renderFrame(scene, FrameRequest::observed([&](const Pass& pass) {
        glEndQuery(statistic);
        GLuint64 count = 0;
        glGetQueryObjectui64v(query, GL_QUERY_RESULT, &count);
        if (counted(pass)) reflection += (long long)count;
        glBeginQuery(statistic, query);
    }));
    glEndQuery(statistic);
    glDeleteQueries(1, &query);
    return reflection;
}

// Fragment shader invocations of the reflection's full-screen passes (its clear, the mirrored depth
// copy, lighting and sky) in one frame; -1 where the context has no pipeline statistics query.
long long reflectionFragments(Renderer& renderer, const SceneSettings& scene) {
    return reflectionWorkInvocations(renderer, scene, GL_FRAGMENT_SHADER_INVOCATIONS_ARB, [](const Pass& pass) {
        const std::string name = pass.name();
        return name == "DepthCopyPass.mirrored" || name == "LightingPass.mirrored" ||
               name == "SkyPass.forward.mirrored" || name.rfind("ReflectionClearPass", 0) == 0;
    });
}

class ReflectionBounds : public GpuTest {};

// Water below all terrain: none in view. Bounded, the reflection's passes draw nothing at all (not
// a vertex); unbounded they run as before; the frames are the same bit for bit. With water in view
// the same passes do run.
TEST_F(ReflectionBounds, FrameWithoutWaterInViewPaysNothingForTheReflection) {
    NamedPose pose = vegetationPoses()[0];
    Renderer renderer(*shaders_, pose.scene);
    renderer.configure(kMediumWidth, kMediumHeight, layoutNamed("compact"));
    auto atlas = attachPlantAtlas(*shaders_, renderer);
    if (!renderer.paths().waterBoundsAvailable) GTEST_SKIP() << renderer.paths().waterBoundsReason;
    if (reflectionWorkInvocations(renderer, pose.scene, GL_VERTEX_SHADER_INVOCATIONS_ARB) < 0)
        GTEST_SKIP() << "no pipeline statistics queries";
    SceneSettings dry = pose.scene;
    dry.water.level = -150.0f;  // the terrain's lowest point is far above
    ASSERT_TRUE(dry.water.reflections);
    for (PipelineKind kind : {PipelineKind::Forward, PipelineKind::Deferred}) {
        SCOPED_TRACE(pipelineName(kind));
        renderer.setPipeline(kind);
        SceneSettings unbounded = dry;
        unbounded.water.reflectionBounds = false;
        renderer.renderFrame(unbounded);
        renderer.views().render("final");
        const Image reference = readDisplay(renderer);
        ASSERT_TRUE(hasContent(reference));
        const long long verticesUnbounded =
            reflectionWorkInvocations(renderer, unbounded, GL_VERTEX_SHADER_INVOCATIONS_ARB);

        renderer.renderFrame(dry);
        renderer.views().render("final");
        EXPECT_EQ(compareImages(reference, readDisplay(renderer)).maxAbs, 0);
        std::vector<uint8_t> stencil = readStencil(renderer);
        ASSERT_EQ(std::count(stencil.begin(), stencil.end(), uint8_t(kStencilWater)), 0) << "water in view";
        const long long vertices = reflectionWorkInvocations(renderer, dry, GL_VERTEX_SHADER_INVOCATIONS_ARB);
        const long long fragments = reflectionWorkInvocations(renderer, dry, GL_FRAGMENT_SHADER_INVOCATIONS_ARB);
        std::printf("[reflection bounds] no water in view, %s: reflection passes' vertex invocations %lld bounded, "
                    "%lld whole screen; fragments %lld bounded\n",
                    pipelineName(kind), vertices, verticesUnbounded, fragments);
        EXPECT_GT(verticesUnbounded, 1000) << "the unbounded reflection drew nothing: the test shows nothing";
        EXPECT_EQ(vertices, 0);
        EXPECT_EQ(fragments, 0);

        // Water in view: the same passes run.
        EXPECT_GT(reflectionWorkInvocations(renderer, pose.scene, GL_VERTEX_SHADER_INVOCATIONS_ARB), 1000);
    }
}

TEST_F(ReflectionBounds, RectangleHoldsEveryWaterPixelAndTheFrameIsTheUnboundedOne) {
    std::vector<NamedPose> poses = {defaultPose(), vegetationPoses()[0], waterPoses()[1]};
    for (const NamedPose& pose : hardPoses())
        if (pose.name == "down" || pose.name == "up") poses.push_back(pose);
    for (const std::string layout : {"standard", "compact"}) {
        Renderer renderer(*shaders_, defaultPose().scene);
        renderer.configure(kMediumWidth, kMediumHeight, layoutNamed(layout));
        auto atlas = attachPlantAtlas(*shaders_, renderer);
        if (!renderer.paths().waterBoundsAvailable) GTEST_SKIP() << renderer.paths().waterBoundsReason;
        for (const NamedPose& pose : poses)
            for (PipelineKind kind : {PipelineKind::Forward, PipelineKind::Deferred}) {
                SCOPED_TRACE(pose.name + ", " + pipelineName(kind) + ", " + layout);
                renderer.setPipeline(kind);
                SceneSettings unbounded = pose.scene;
                unbounded.water.reflectionBounds = false;
                renderer.renderFrame(unbounded);
                renderer.views().render("final");
                const Image reference = readDisplay(renderer);
                const long long fragmentsUnbounded = reflectionFragments(renderer, unbounded);

                renderer.renderFrame(pose.scene);
                renderer.views().render("final");
                const Image bounded = readDisplay(renderer);
                EXPECT_TRUE(hasContent(bounded));
                const glm::ivec4 rect = readWaterBounds(renderer);  // x0, y0, x1, y1, rows bottom-up
                const std::vector<uint8_t> stencil = readStencil(renderer);  // rows bottom-up
                const long long fragmentsBounded = reflectionFragments(renderer, pose.scene);

                // Every water pixel inside, and each edge of the rectangle on a water pixel.
                long water = 0, outside = 0;
                glm::ivec4 seen(kMediumWidth, kMediumHeight, -1, -1);
                for (int y = 0; y < kMediumHeight; ++y)
                    for (int x = 0; x < kMediumWidth; ++x) {
                        if (stencil[size_t(y) * kMediumWidth + size_t(x)] != kStencilWater) continue;
                        ++water;
                        if (x < rect.x || x > rect.z || y < rect.y || y > rect.w) ++outside;
                        seen = glm::ivec4(std::min(seen.x, x), std::min(seen.y, y), std::max(seen.z, x),
                                          std::max(seen.w, y));
                    }
                EXPECT_EQ(outside, 0) << water << " water pixels";
                if (water > 0)
                    EXPECT_EQ(rect, seen) << "the rectangle is not the water's own";
                else
                    EXPECT_GT(rect.x, rect.z) << "no water in view, yet a rectangle";

                ImageDifference difference = compareImages(reference, bounded);
                EXPECT_EQ(difference.maxAbs, 0);
                if (fragmentsBounded < 0) continue;
                std::string size = rect.x > rect.z ? "no rectangle"
                                                   : std::to_string(rect.z - rect.x + 1) + "x" +
                                                         std::to_string(rect.w - rect.y + 1) + " rectangle";
                std::printf("[reflection bounds] %s %s %s: water %.1f%% of the frame, %s; reflection fragments "
                            "%lld bounded, %lld whole screen; frames %.2f dB apart (max abs %d)\n",
                            pose.name.c_str(), pipelineName(kind), layout.c_str(),
                            100.0 * double(water) / double(kMediumWidth * kMediumHeight), size.c_str(), fragmentsBounded,
                            fragmentsUnbounded, difference.psnrDb, difference.maxAbs);
                // The mirrored lighting or sky shades every water pixel: a count below that is a
                // driver's counter that does not count shaded fragments (zink over lavapipe's).
                if (fragmentsUnbounded < water) {
                    std::printf("[reflection bounds] this driver's fragment-shader invocation counts do not count "
                                "the fragments shaded (%lld for %ld water pixels): not compared\n",
                                fragmentsUnbounded, water);
                    continue;
                }
                EXPECT_LE(fragmentsBounded, fragmentsUnbounded);
                if (water == 0 && pose.scene.water.reflections) {
                    EXPECT_EQ(fragmentsBounded, 0) << "no water in view, yet the reflection shaded fragments";
                }
            }
    }
}

// The mirrored billboards whose image misses the water's rectangle are dropped whole: fewer of
// their fragments are shaded where the water is a small part of the frame, and the frame is the
// unbounded one bit for bit (the vertex shader's test is per billboard, never a partial clip).
TEST_F(ReflectionBounds, MirroredBillboardsMissingTheWaterAreDropped) {
    NamedPose pose = vegetationPoses()[0];
    Renderer renderer(*shaders_, pose.scene);
    renderer.configure(kMediumWidth, kMediumHeight, layoutNamed("standard"));
    auto atlas = attachPlantAtlas(*shaders_, renderer);
    if (!renderer.paths().waterBoundsAvailable) GTEST_SKIP() << renderer.paths().waterBoundsReason;
    auto mirroredPlants = [](const Pass& pass) {
        return pass.name().rfind("VegetationPass", 0) == 0 && pass.reflectionWork();
    };
    SceneSettings unbounded = pose.scene;
    unbounded.water.reflectionBounds = false;
    for (PipelineKind kind : {PipelineKind::Forward, PipelineKind::Deferred}) {
        SCOPED_TRACE(pipelineName(kind));
        renderer.setPipeline(kind);
        const long long whole = reflectionWorkInvocations(renderer, unbounded, GL_FRAGMENT_SHADER_INVOCATIONS_ARB, mirroredPlants);
        if (whole < 0) GTEST_SKIP() << "no pipeline statistics queries";
        renderer.views().render("final");
        const Image reference = readDisplay(renderer);
        const long long bounded = reflectionWorkInvocations(renderer, pose.scene, GL_FRAGMENT_SHADER_INVOCATIONS_ARB, mirroredPlants);
        renderer.views().render("final");
        const Image frame = readDisplay(renderer);
        EXPECT_TRUE(hasContent(frame));
        EXPECT_EQ(compareImages(reference, frame).maxAbs, 0);
        std::printf("[reflection bounds] %s %s: mirrored plant fragments %lld bounded, %lld whole screen\n",
                    pose.name.c_str(), pipelineName(kind), bounded, whole);
        if (whole == 0) continue;  // a driver whose counter does not count them (zink's)
        EXPECT_GT(whole, 1000) << "no mirrored plants drawn: the test shows nothing";
        EXPECT_LT(bounded, whole);
    }
}

// Without storage blocks (the GL 3.3 tier, --force no-ssbo) the reflection's passes cover the
// whole screen, stencil-masked, as before; they say why, and draw the same frame.
TEST_F(ReflectionBounds, WithoutStorageBlocksTheWholeScreenIsUsedAndSaysWhy) {
    NamedPose pose = defaultPose();
    Renderer renderer(*shaders_, pose.scene);
    renderer.configure(kMediumWidth, kMediumHeight, layoutNamed("compact"));
    auto atlas = attachPlantAtlas(*shaders_, renderer);
    if (!renderer.paths().waterBoundsAvailable) GTEST_SKIP() << renderer.paths().waterBoundsReason;
    renderer.setPipeline(PipelineKind::Deferred);
    renderer.renderFrame(pose.scene);
    renderer.views().render("final");
    const Image bounded = readDisplay(renderer);
    EXPECT_TRUE(hasContent(bounded));

    RendererCapabilities caps = renderer.paths().capabilities;
    caps.ssbo = {false, "switched off by the test"};
    caps.forcedLightsPath = std::nullopt;
    renderer.setCapabilities(caps);
    EXPECT_FALSE(renderer.paths().waterBoundsAvailable);
    EXPECT_NE(renderer.paths().waterBoundsReason.find("switched off by the test"), std::string::npos)
        << renderer.paths().waterBoundsReason;
    renderer.renderFrame(pose.scene);
    renderer.views().render("final");
    const Image whole = readDisplay(renderer);
    EXPECT_EQ(compareImages(bounded, whole).maxAbs, 0);
}

}  // namespace
}  // namespace oasis::gputest
