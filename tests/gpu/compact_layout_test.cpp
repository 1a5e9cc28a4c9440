// The compact G-buffer layout against the full one (float targets: the reference), frame for
// frame, after whole frames: inside the water both G-buffers hold the mirrored scene, and
// compact's depth copy (DepthCopyPass.mirrored) its depth. Same surfaces (flags, specular power and intensity
// exactly), albedo within 8-bit rounding, normals within 1e-4 rad (16-bit octahedral), and the
// positions lighting reconstructs from D24 depth within the depth-step tolerance of gpu_test.h
// of the stored ones, direct and mirrored. Then the whole frame: compact's deferred image agrees
// with full's, and the targets compact does not store are neither allocated nor readable.
#include "frame/frame_readback.h"
#include "gpu_test.h"

#include <algorithm>

#include "render/depth_convention.h"

namespace oasis::gputest {
namespace {


struct GBufferRead {
    std::vector<float> albedo, normal, info, position;
};

GBufferRead renderGBuffer(Renderer& renderer, const SceneSettings& scene, const std::string& layout) {
    renderer.configure(kMediumWidth, kMediumHeight, layoutNamed(layout));
    renderer.setPipeline(PipelineKind::Deferred);
    renderer.renderFrame(scene);
    return {readTarget(renderer, Target::Albedo), readTarget(renderer, Target::Normal),
            readTarget(renderer, Target::Info), readSurfacePositions(renderer)};
}

class CompactLayout : public GpuTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(CompactLayout, ReconstructsTheFullLayoutsSurfaces) {
    const NamedPose pose = poseNamed(GetParam());
    Renderer renderer(*shaders_, pose.scene);
    auto atlas = attachPlantAtlas(*shaders_, renderer);
    const GBufferLayout& full = layoutNamed("full");
    const GBufferLayout& compact = layoutNamed("compact");
    const GBufferRead reference = renderGBuffer(renderer, pose.scene, "full");
    const GBufferRead packed = renderGBuffer(renderer, pose.scene, "compact");
    const float nearPlane = renderer.lastFrame().setup.data.depthRange.x, farPlane = renderer.lastFrame().setup.data.depthRange.y;

    int surfaces = 0, mirrored = 0, flagsDiffer = 0, materialDiffers = 0, albedoOff = 0, normalOff = 0, positionOff = 0;
    double worstAngle = 0.0, worstSteps = 0.0, worstFraction = 0.0, worstAlbedo = 0.0;
    // Round to nearest into the 8-bit target: llvmpipe's conversion, within half a level. A GPU's
    // full and compact variants compile separately and may convert its own way (H100: 2,370-4,493
    // pixels past half a level): one level there, which still catches a wrong channel or encoding.
    const float albedoTolerance = (cpuRasteriser() ? 0.5f : 1.0f) / 255.0f + 1e-6f;
    std::string firstPositionOff;
    for (int y = 0; y < kMediumHeight; ++y)
        for (int x = 0; x < kMediumWidth; ++x) {
            glm::vec4 infoFull = texel(reference.info, kMediumWidth, x, y), infoCompact = texel(packed.info, kMediumWidth, x, y);
            unsigned flags = full.storedFlags(infoFull);
            // Where nothing was drawn compact's info is not cleared: its sky is the depth at the far
            // plane, which its rebuilt positions mark with w = 0 (gbuffer_positions.frag).
            if (flags & kSurfaceSky) {
                if (texel(packed.position, kMediumWidth, x, y).w != 0.0f) ++flagsDiffer;
                continue;
            }
            if (compact.storedFlags(infoCompact) != flags) ++flagsDiffer;
            ++surfaces;
            mirrored += (flags & kSurfaceReflected) ? 1 : 0;
            // Power and intensity are multiples of 1/255 from the material: exact in both.
            glm::vec4 albedoFull = texel(reference.albedo, kMediumWidth, x, y), albedoCompact = texel(packed.albedo, kMediumWidth, x, y);
            if (std::lround(infoFull.r * 255.0f) != std::lround(infoCompact.r * 255.0f) ||
                std::fabs(infoFull.g - albedoCompact.a) > 1e-6f)
                ++materialDiffers;
            glm::vec3 albedoError = glm::abs(glm::vec3(albedoFull) - glm::vec3(albedoCompact));
            float albedoWorstChannel = std::max({albedoError.x, albedoError.y, albedoError.z});
            worstAlbedo = std::max(worstAlbedo, double(albedoWorstChannel));
            if (albedoWorstChannel > albedoTolerance) ++albedoOff;

            glm::dvec3 n(full.storedNormal(texel(reference.normal, kMediumWidth, x, y)));
            glm::dvec3 m(compact.storedNormal(texel(packed.normal, kMediumWidth, x, y)));
            double angle = std::atan2(glm::length(glm::cross(n, m)), glm::dot(n, m));
            worstAngle = std::max(worstAngle, angle);
            normalOff += angle > 1e-4 ? 1 : 0;

            glm::dvec3 stored(texel(reference.position, kMediumWidth, x, y)), rebuilt(texel(packed.position, kMediumWidth, x, y));
            double distance = glm::length(stored), error = glm::length(rebuilt - stored);
            double tolerance = reconstructionTolerance(distance, nearPlane, farPlane);
            worstSteps = std::max(worstSteps, error / depthStep(distance, nearPlane, farPlane));
            worstFraction = std::max(worstFraction, error / tolerance);
            if (error > tolerance && positionOff++ == 0)
                firstPositionOff = "pixel (" + std::to_string(x) + ", " + std::to_string(y) + "): error " +
                                   std::to_string(error) + " at distance " + std::to_string(distance);
        }
    std::printf("[compact] %s: %d surface pixels (%d mirrored), worst normal %.2e rad, worst position %.2f depth "
                "steps (%.0f%% of the tolerance), worst albedo %.2f levels\n",
                pose.name.c_str(), surfaces, mirrored, worstAngle, worstSteps, 100.0 * worstFraction, worstAlbedo * 255.0);
    EXPECT_GT(surfaces, kMediumWidth * kMediumHeight / 10);
    EXPECT_EQ(flagsDiffer, 0) << "surface flags differ from the full layout's";
    EXPECT_EQ(materialDiffers, 0) << "specular power or intensity differ";
    EXPECT_EQ(albedoOff, 0) << "albedo beyond 8-bit rounding (worst " << worstAlbedo * 255.0 << " levels)";
    EXPECT_EQ(normalOff, 0) << "normals more than 1e-4 rad off (worst " << worstAngle << ")";
    EXPECT_EQ(positionOff, 0) << "reconstructed positions beyond the depth tolerance; first " << firstPositionOff;
    if (pose.name == "lakeMirror") EXPECT_GT(mirrored, kMediumWidth * kMediumHeight / 20) << "the lake's mirrored scene";
}

INSTANTIATE_TEST_SUITE_P(Poses, CompactLayout, ::testing::Values("default", "meadow", "lakeMirror", "down", "sunset"),
                         [](const auto& info) { return info.param; });

// With reversed-z float depth the reconstruction error no longer grows with distance: compact's
// positions stay within float rounding of full's stored ones (relative error; D24 reaches 2e-3
// in the far band, see the bench's depth-precision table).
TEST_F(GpuTest, CompactWithReversedDepthReconstructsToFloatPrecision) {
    const NamedPose pose = defaultPose();
    Renderer renderer(*shaders_, pose.scene);
    auto atlas = attachPlantAtlas(*shaders_, renderer);
    renderer.configure(kMediumWidth, kMediumHeight, layoutNamed("full"));
    renderer.setDepthConvention(*findDepthConvention("reversed-z"));
    ASSERT_EQ(renderer.targets().depth().name, "reversed-z");
    const GBufferRead reference = renderGBuffer(renderer, pose.scene, "full");
    const GBufferRead packed = renderGBuffer(renderer, pose.scene, "compact");
    std::vector<double> relative;
    for (int y = 0; y < kMediumHeight; ++y)
        for (int x = 0; x < kMediumWidth; ++x) {
            if (layoutNamed("full").storedFlags(texel(reference.info, kMediumWidth, x, y)) & kSurfaceSky) continue;
            glm::dvec3 stored(texel(reference.position, kMediumWidth, x, y)), rebuilt(texel(packed.position, kMediumWidth, x, y));
            relative.push_back(glm::length(rebuilt - stored) / glm::length(stored));
        }
    ASSERT_GT(relative.size(), size_t(kMediumWidth * kMediumHeight / 10));
    std::sort(relative.begin(), relative.end());
    double median = relative[relative.size() / 2], worst = relative.back();
    std::printf("[compact] reversed-z: %zu surface pixels, relative position error median %.1e, worst %.1e\n",
                relative.size(), median, worst);
    // A GPU interpolates window depth with less than float precision (H100: median 5.3e-6, worst
    // 1.5e-5): 2e-5 there, still 40x finer than the standard convention's far band.
    EXPECT_LT(median, cpuRasteriser() ? 1e-6 : 2e-5);
    EXPECT_LT(worst, 1e-4);
}

TEST_F(GpuTest, CompactFrameAgreesWithTheFullLayoutAndStoresNoPosition) {
    const NamedPose pose = poseNamed("meadow");
    Renderer renderer(*shaders_, pose.scene);
    auto atlas = attachPlantAtlas(*shaders_, renderer);
    renderer.configure(kMediumWidth, kMediumHeight, layoutNamed("full"));
    Image full = renderFinal(renderer, pose.scene, PipelineKind::Deferred);
    renderer.configure(kMediumWidth, kMediumHeight, layoutNamed("compact"));
    Image compact = renderFinal(renderer, pose.scene, PipelineKind::Deferred);
    dumpImage("compact-meadow-deferred", compact);
    ImageDifference difference = compareImages(full, compact);
    std::printf("[compact] meadow: deferred compact vs full PSNR %.2f dB, max %d\n", difference.psnrDb,
                difference.maxAbs);
    EXPECT_GE(difference.psnrDb, 45.0);
    EXPECT_TRUE(hasContent(compact));
    EXPECT_EQ(renderer.targets().texture(Target::Position), 0u) << "compact allocates no position target";
    EXPECT_THROW(readTarget(renderer, Target::Position), std::invalid_argument);
}

// Without 16-bit unorm colour targets (OpenGL ES without EXT_texture_norm16) the renderer draws
// the standard layout for compact, says why, draws standard's frame bit for bit, keeps the request
// through a resize with its own layout, and draws compact again when the capability comes back.
TEST_F(GpuTest, CompactWithoutNorm16TargetsFallsBackToTheStandardFrame) {
    SceneSettings scene;
    Renderer standard(*shaders_, scene), fallback(*shaders_, scene);
    RendererCapabilities caps = fallback.paths().capabilities;
    caps.norm16Targets = {false, "no GL_EXT_texture_norm16 on this OpenGL ES driver"};
    fallback.setCapabilities(caps);
    fallback.configure(160, 90, layoutNamed("compact"));
    standard.configure(160, 90, layoutNamed("standard"));
    EXPECT_EQ(fallback.targets().layout().name, "standard");
    EXPECT_EQ(fallback.paths().gbuffer->name, "standard");
    EXPECT_EQ(fallback.paths().gbufferRequested, "compact");
    EXPECT_TRUE(fallback.paths().gbufferFellBack);
    EXPECT_NE(fallback.paths().gbufferReason.find("compact was asked for but its 16-bit unorm target is not "
                                                  "colour-renderable: no GL_EXT_texture_norm16"),
              std::string::npos) << fallback.paths().gbufferReason;
    for (PipelineKind kind : {PipelineKind::Forward, PipelineKind::Deferred})
        EXPECT_EQ(compareImages(renderFinal(standard, scene, kind), renderFinal(fallback, scene, kind)).maxAbs, 0);
    // A resize with the layout in use (the web page's frame loop) keeps the request and its reason.
    fallback.configure(96, 54, fallback.targets().layout());
    EXPECT_EQ(fallback.paths().gbufferRequested, "compact");
    EXPECT_TRUE(fallback.paths().gbufferFellBack);
    // Standard and full need no 16-bit unorm target: no fallback.
    fallback.configure(96, 54, layoutNamed("full"));
    EXPECT_FALSE(fallback.paths().gbufferFellBack);
    EXPECT_EQ(fallback.targets().layout().name, "full");
    // The capability coming back switches to compact (targets reallocated).
    fallback.configure(96, 54, layoutNamed("compact"));
    caps.norm16Targets = {true, "16-bit unorm colour-renderable"};
    fallback.setCapabilities(caps);
    EXPECT_EQ(fallback.targets().layout().name, "compact") << "targets not reallocated";
    EXPECT_FALSE(fallback.paths().gbufferFellBack);
}

}  // namespace
}  // namespace oasis::gputest
