// The depth convention table (render/depth_convention.h) against the camera's projection and the
// GLSL reconstruction it feeds (shaders/common/depth.glsl), without GL.
#include <gtest/gtest.h>

#include <cmath>

#include "cli/options.h"
#include "render/depth_convention.h"
#include "render/frame_setup.h"

namespace oasis {
namespace {

CameraView viewWith(const DepthConvention& depth) {
    CameraView view;
    view.pose.yawDegrees = 30.0f;
    view.pose.pitchDegrees = -9.0f;
    view.depthMapping = depth.mapping;
    return view;
}

glm::vec3 relativeToNdc(const glm::mat4& viewProjection, glm::vec3 relative) {
    glm::vec4 clip = viewProjection * glm::vec4(relative, 1.0f);
    return glm::vec3(clip) / clip.w;
}

// Window depth from NDC z under the row's clip control (glDepthRange 0..1).
float windowDepth(const DepthConvention& depth, float ndcZ) {
    return depth.clipDepthMode == GL_ZERO_TO_ONE ? ndcZ : ndcZ * 0.5f + 0.5f;
}

// The CPU twin of eyeDepthFromWindowDepth (shaders/common/depth.glsl), in double.
double eyeDepth(const DepthConvention& depth, double window, double n, double f) {
    if (depth.reversed()) return n * f / (window * (f - n) + n);
    double ndc = window * 2.0 - 1.0;
    return 2.0 * n * f / (f + n - ndc * (f - n));
}

TEST(DepthConventionTable, NamesFindableStandardFirst) {
    for (const DepthConvention& depth : depthConventions()) EXPECT_EQ(findDepthConvention(depth.name), &depth);
    EXPECT_EQ(standardDepthConvention().name, "standard");
    EXPECT_FALSE(standardDepthConvention().needsClipControl()) << "the fallback must need nothing";
    EXPECT_EQ(depthConventionNames(), "standard, reversed-z");
    EXPECT_EQ(findDepthConvention("nonsense"), nullptr);
}

TEST(DepthConventionTable, NearAndFarPlanesWhereTheRowSays) {
    for (const DepthConvention& depth : depthConventions()) {
        SCOPED_TRACE(depth.name);
        CameraView view = viewWith(depth);
        glm::mat4 vp = view.viewProjection();
        glm::vec3 forward = view.pose.forward();
        float nearZ = relativeToNdc(vp, forward * view.projection.nearPlane).z;
        float farZ = relativeToNdc(vp, forward * view.projection.farPlane).z;
        EXPECT_NEAR(nearZ, depth.nearPlaneNdcZ, 1e-4f);
        EXPECT_NEAR(farZ, depth.farPlaneNdcZ, 1e-4f);
        EXPECT_FLOAT_EQ(windowDepth(depth, depth.farPlaneNdcZ), depth.farPlaneWindowDepth);
        // The comparison that keeps the nearer fragment follows the direction depth grows in.
        bool nearIsLarger = depth.nearPlaneNdcZ > depth.farPlaneNdcZ;
        EXPECT_EQ(depth.nearerFunc, GLenum(nearIsLarger ? GL_GREATER : GL_LESS));
        EXPECT_EQ(depth.nearerOrEqualFunc, GLenum(nearIsLarger ? GL_GEQUAL : GL_LEQUAL));
        glm::vec4 frame = depth.frameData();
        EXPECT_EQ(frame.x, depth.reversed() ? 1.0f : 0.0f);
        EXPECT_EQ(frame.y, depth.nearPlaneNdcZ);
        EXPECT_EQ(frame.z, depth.farPlaneWindowDepth);
        EXPECT_EQ(frame.w, depth.farPlaneNdcZ);
        // prepareFrame hands the row to the shaders and the camera.
        FrameSetup setup = prepareFrame(SceneSettings{}, 320, 180, depth);
        EXPECT_EQ(setup.view.depthMapping, depth.mapping);
        EXPECT_EQ(setup.data.depthConvention, frame);
    }
}

TEST(DepthConventionTable, ReconstructionFormulaInvertsTheProjection) {
    for (const DepthConvention& depth : depthConventions()) {
        SCOPED_TRACE(depth.name);
        CameraView view = viewWith(depth);
        glm::dmat4 vp(view.viewProjection());
        double n = view.projection.nearPlane, f = view.projection.farPlane;
        for (double distance : {0.5, 3.0, 40.0, 700.0, 5000.0}) {
            glm::dvec4 clip = vp * glm::dvec4(glm::dvec3(view.pose.forward()) * distance, 1.0);
            double window = windowDepth(depth, float(clip.z / clip.w));
            EXPECT_NEAR(eyeDepth(depth, window, n, f), distance, distance * 1e-3) << distance;
        }
    }
}

TEST(DepthConventionTable, BytesAndFormats) {
    const DepthConvention& standard = standardDepthConvention();
    const DepthConvention& reversed = *findDepthConvention("reversed-z");
    EXPECT_EQ(standard.depthStencil.internalFormat, GLenum(GL_DEPTH24_STENCIL8));
    EXPECT_EQ(standard.depthStencil.bytesPerPixel, 4);
    EXPECT_EQ(reversed.depthStencil.internalFormat, GLenum(GL_DEPTH32F_STENCIL8));
    EXPECT_EQ(reversed.depthStencil.bytesPerPixel, 8);  // as drivers allocate it: float + stencil + 24 unused bits
    EXPECT_TRUE(reversed.needsClipControl());
    EXPECT_EQ(reversed.clipDepthMode, GLenum(GL_ZERO_TO_ONE));
    for (const GBufferLayout& layout : gbufferLayouts()) {
        EXPECT_EQ(gbufferBytesPerPixel(layout, standard), layout.bytesPerPixel());
        // +4 for the depth-stencil, and +4 again for the depth copy of a layout that keeps one.
        EXPECT_EQ(gbufferBytesPerPixel(layout, reversed), layout.bytesPerPixel() + (layout.positionFromDepth() ? 8 : 4));
        if (layout.positionFromDepth())
            EXPECT_EQ(targetFormat(layout, reversed, Target::SceneDepth).internalFormat, GLenum(GL_DEPTH32F_STENCIL8));
        EXPECT_EQ(targetFormat(layout, reversed, Target::DepthStencil).internalFormat, GLenum(GL_DEPTH32F_STENCIL8));
        EXPECT_EQ(targetFormat(layout, reversed, Target::Albedo).internalFormat, layout.albedo.internalFormat);
    }
}

TEST(FrustumPlanes, SameFrustumUnderEitherMapping) {
    // Points inside one frustum are inside the other: the planes differ only in how z is scaled.
    CameraView standard = viewWith(standardDepthConvention());
    CameraView reversed = viewWith(*findDepthConvention("reversed-z"));
    auto inside = [](const CameraView& view, glm::vec3 p) {
        for (const glm::vec4& plane : frustumPlanes(view.viewProjection(), view.depthMapping))
            if (glm::dot(glm::vec3(plane), p) + plane.w < 0.0f) return false;
        return true;
    };
    glm::vec3 forward = standard.pose.forward();
    for (float distance : {0.1f, 0.3f, 10.0f, 5990.0f, 6010.0f, -5.0f}) {
        glm::vec3 p = forward * distance;
        EXPECT_EQ(inside(standard, p), inside(reversed, p)) << distance;
        EXPECT_EQ(inside(reversed, p), distance > 0.25f && distance < 6000.0f) << distance;
    }
}

TEST(DepthOption, ParsedCheckedAndLeftToTheBench) {
    ParseResult ok = parseCommandLine({"render", "--depth", "reversed-z"});
    ASSERT_TRUE(ok.ok) << ok.error;
    EXPECT_EQ(ok.options.scene.depth, "reversed-z");
    EXPECT_EQ(parseCommandLine({"render"}).options.scene.depth, "standard");
    ParseResult bad = parseCommandLine({"render", "--depth", "nonsense"});
    EXPECT_FALSE(bad.ok);
    EXPECT_EQ(bad.error, "--depth: unknown convention 'nonsense' (one of: standard, reversed-z)");
    EXPECT_FALSE(parseCommandLine({"bench", "--depth", "reversed-z"}).ok) << "the bench compares them itself";
    ParseResult forced = parseCommandLine({"caps", "--force", "no-clip-control"});
    ASSERT_TRUE(forced.ok) << forced.error;
    EXPECT_TRUE(forced.options.scene.force.noClipControl);
    EXPECT_EQ(forced.options.scene.force.list(), "no-clip-control");
    EXPECT_NE(usage(Command::Render).find("--depth"), std::string::npos);
}

TEST(DepthOption, ClipControlFromVersionOrExtension) {
    gl::Capabilities caps;
    caps.major = 3;
    caps.minor = 3;
    std::string why;
    EXPECT_FALSE(caps.clipControlAvailable(&why));
    EXPECT_EQ(why, "no GL 4.5 / GL_ARB_clip_control");
    caps.extensions.insert("GL_ARB_clip_control");
    EXPECT_TRUE(caps.clipControlAvailable(&why));
    caps.major = 4;
    caps.minor = 5;
    caps.extensions.clear();
    EXPECT_TRUE(caps.clipControlAvailable(&why));
    EXPECT_EQ(why, "clip control present (GL 4.5)");
    caps.forced.noClipControl = true;
    EXPECT_FALSE(caps.clipControlAvailable(&why));
    EXPECT_EQ(why, "switched off by --force no-clip-control");
}

}  // namespace
}  // namespace oasis
