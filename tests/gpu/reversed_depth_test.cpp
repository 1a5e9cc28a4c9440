// The reversed-z depth convention (render/depth_convention.h): its frames agree with standard
// frames in both pipelines (plants, water reflections, hard poses); the sky lies at its far plane
// (depth 0, black in the depth view); the position reconstructed from its float depth is far more
// precise in the far band than standard's 24-bit depth; without clip control it falls back to the
// standard frame and says why; its clip control does not outlive the frame. (The light volumes
// under reversed-z: lights_test.cpp.)
#include "frame/frame_readback.h"
#include "gpu_test.h"

#include "bench/bench_depth.h"
#include "commands/session.h"

namespace oasis::gputest {
namespace {

const DepthConvention& reversedZ() { return *findDepthConvention("reversed-z"); }

class ReversedDepth : public GpuTest {};

// Measured on llvmpipe at 320x180, standard layout: 60.8 dB at the lowest (the default frame,
// both pipelines), 100 dB (identical) for the meadow and both lake poses; each is printed as
// [reversed-z]. The frames differ only where depth ties and near-ties resolve differently
// (plants against terrain and against each other, far silhouettes), a few pixels.
constexpr double kMinAgreementPsnrDb = 55.0;

TEST_F(ReversedDepth, FramesAgreeWithStandardInBothPipelines) {
    const int width = 320, height = 180;
    for (const char* poseName : {"default", "meadow", "sunset", "night", "lakeMirror", "lakeGrazing"}) {
        NamedPose pose = poseNamed(poseName);
        Renderer standard(*shaders_, pose.scene), reversed(*shaders_, pose.scene);
        auto standardAtlas = attachPlantAtlas(*shaders_, standard);
        auto reversedAtlas = attachPlantAtlas(*shaders_, reversed);
        reversed.setDepthConvention(reversedZ());
        ASSERT_EQ(reversed.paths().depth->name, "reversed-z") << reversed.paths().depthReason;
        standard.configure(width, height, layoutNamed("standard"));
        reversed.configure(width, height, layoutNamed("standard"));
        for (PipelineKind kind : {PipelineKind::Forward, PipelineKind::Deferred}) {
            SCOPED_TRACE(pose.name + " " + pipelineName(kind));
            Image a = renderFinal(standard, pose.scene, kind);
            Image b = renderFinal(reversed, pose.scene, kind);
            dumpImage("reversed-z-" + pose.name + "-" + pipelineName(kind), b);
            ImageDifference difference = compareImages(a, b);
            std::printf("[reversed-z] %s %s: PSNR %.2f dB against standard, max abs %d\n", pose.name.c_str(),
                        pipelineName(kind), difference.psnrDb, difference.maxAbs);
            EXPECT_TRUE(hasContent(b));
            EXPECT_GE(difference.psnrDb, kMinAgreementPsnrDb);
        }
    }
}

TEST_F(ReversedDepth, SkyIsAtTheFarPlaneAndBlackInTheDepthView) {
    const int width = 160, height = 90;
    NamedPose pose = defaultPose();
    Renderer renderer(*shaders_, pose.scene);
    renderer.setDepthConvention(reversedZ());
    renderer.configure(width, height, layoutNamed("full"));
    Image depthView = renderView(renderer, pose.scene, PipelineKind::Deferred, "depth");
    dumpImage("reversed-z-depth-view", depthView);
    std::vector<float> depth = readDepth(renderer);
    std::vector<float> info = readTarget(renderer, Target::Info);
    std::vector<uint8_t> stencil = readStencil(renderer);
    int sky = 0, ground = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            size_t i = size_t(y) * width + size_t(x);
            glm::ivec3 shown = displayPixel(depthView, x, y);
            if (stencil[i] == kStencilSky) {
                ++sky;
                ASSERT_EQ(depth[i], 0.0f) << "sky at " << x << "," << y << " is not at the far plane";
                ASSERT_TRUE(infoFlags(texel(info, width, x, y)) & OASIS_SURFACE_SKY);
                ASSERT_EQ(shown, glm::ivec3(0)) << "the depth view shows sky at " << x << "," << y;
            } else {
                ++ground;
                ASSERT_GT(depth[i], 0.0f);
                ASSERT_LT(depth[i], 1.0f);
                ASSERT_NE(shown, glm::ivec3(0)) << "the depth view shows a surface black at " << x << "," << y;
            }
        }
    EXPECT_GT(sky, width * height / 10);
    EXPECT_GT(ground, width * height / 2);
}

// The bench's depth-precision comparison on the default frame and two views of distant hills: in
// the far band (beyond the plants' draw distance) reversed-z's median error is a small fraction of
// standard's (measured on llvmpipe at 640x360: 0.002 on the default frame alone).
TEST_F(ReversedDepth, FarBandReconstructionFarMorePreciseThanStandard) {
    std::vector<SceneSettings> scenes = {defaultPose().scene, poseNamed("sunset").scene, poseNamed("lakeMirror").scene};
    std::map<std::string, DepthPrecision> far, near;
    for (const DepthConvention& depth : depthConventions()) {
        Renderer renderer(*shaders_, scenes[0]);
        auto atlas = attachPlantAtlas(*shaders_, renderer);
        renderer.setDepthConvention(depth);
        ASSERT_EQ(renderer.paths().depth->name, depth.name) << renderer.paths().depthReason;
        renderer.configure(640, 360, layoutNamed("full"));
        std::vector<DepthPrecision> rows = measureDepthPrecision(renderer, scenes, depthBands(scenes[0]));
        std::printf("%s", depthPrecisionTable(rows).c_str());
        ASSERT_EQ(rows.size(), 3u);
        near[depth.name] = rows[0];
        far[depth.name] = rows[2];
    }
    const DepthPrecision &standard = far["standard"], &reversed = far["reversed-z"];
    ASSERT_GT(standard.pixels, 1000u) << "too little of the frame in the far band";
    double ratio = reversed.medianAbs / standard.medianAbs;
    std::printf("[reversed-z] far band median error: reversed-z %.3e, standard %.3e (ratio %.4f)\n",
                reversed.medianAbs, standard.medianAbs, ratio);
    // H100: 0.034 (its depth interpolation is coarser than llvmpipe's float arithmetic): 0.05 there.
    EXPECT_LT(ratio, cpuRasteriser() ? 0.02 : 0.05);
    EXPECT_LT(reversed.maxAbs, 0.1 * standard.maxAbs);
    // Near the camera both are good: within a thousandth of the distance.
    EXPECT_LT(near["reversed-z"].maxRelative, 1e-3);
}

TEST_F(ReversedDepth, WithoutClipControlFallsBackToTheStandardFrame) {
    SceneSettings scene;
    Renderer standard(*shaders_, scene), fallback(*shaders_, scene);
    RendererCapabilities caps = fallback.paths().capabilities;
    caps.clipControl = {false, "switched off by --force no-clip-control"};
    fallback.setCapabilities(caps);
    fallback.setDepthConvention(reversedZ());
    EXPECT_EQ(fallback.paths().depth->name, "standard");
    EXPECT_TRUE(fallback.paths().depthFellBack);
    EXPECT_NE(fallback.paths().depthReason.find("reversed-z was asked for but switched off by --force no-clip-control"),
              std::string::npos) << fallback.paths().depthReason;
    standard.configure(160, 90, layoutNamed("standard"));
    fallback.configure(160, 90, layoutNamed("standard"));
    EXPECT_EQ(fallback.targets().depth().name, "standard");
    for (PipelineKind kind : {PipelineKind::Forward, PipelineKind::Deferred})
        EXPECT_EQ(compareImages(renderFinal(standard, scene, kind), renderFinal(fallback, scene, kind)).maxAbs, 0);
    // Clip control coming back (the panel's combo is asked again) switches to reversed-z.
    caps.clipControl = {true, "clip control present"};
    fallback.setCapabilities(caps);
    EXPECT_EQ(fallback.paths().depth->name, "reversed-z");
    EXPECT_EQ(fallback.targets().depth().name, "reversed-z") << "targets not reallocated";
}

TEST_F(ReversedDepth, SessionReportsTheForcedFallbackOnce) {
    ParseResult parsed = parseCommandLine({"render", "--depth", "reversed-z", "--force", "no-clip-control",
                                           "--size", "64x36", "--no-compute"});
    ASSERT_TRUE(parsed.ok) << parsed.error;
    RenderSession session(parsed.options);
    EXPECT_EQ(session.renderer->paths().depth->name, "standard");
    std::vector<std::string> lines = session.fallbacks();
    int clipLines = 0;
    for (const std::string& line : lines)
        if (line.rfind("clip-control: ", 0) == 0) {
            ++clipLines;
            EXPECT_NE(line.find("reversed-z was asked for but switched off by --force no-clip-control"),
                      std::string::npos) << line;
        }
    EXPECT_EQ(clipLines, 1);
    // Asked for and available: used, no fallback.
    ParseResult plain = parseCommandLine({"render", "--depth", "reversed-z", "--size", "64x36", "--no-compute"});
    RenderSession used(plain.options);
    EXPECT_EQ(used.renderer->paths().depth->name, "reversed-z");
    for (const std::string& line : used.fallbacks()) EXPECT_EQ(line.rfind("clip-control", 0), std::string::npos) << line;
}

TEST_F(ReversedDepth, ClipControlIsRestoredAfterEachFrame) {
    SceneSettings scene;
    Renderer renderer(*shaders_, scene);
    renderer.setDepthConvention(reversedZ());
    renderer.configure(64, 36, layoutNamed("standard"));
    for (PipelineKind kind : {PipelineKind::Forward, PipelineKind::Deferred}) {
        renderer.setPipeline(kind);
        renderer.renderFrame(scene);
        renderer.views().render("overview");  // forward fills the G-buffer for the views inside its own scope
        GLint origin = 0, mode = 0;
        glGetIntegerv(GL_CLIP_ORIGIN, &origin);
        glGetIntegerv(GL_CLIP_DEPTH_MODE, &mode);
        EXPECT_EQ(origin, GL_LOWER_LEFT);
        EXPECT_EQ(mode, GL_NEGATIVE_ONE_TO_ONE) << "the frame's clip control leaked";
    }
}

}  // namespace
}  // namespace oasis::gputest
