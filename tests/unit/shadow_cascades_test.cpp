// The shadow cascades' fit without GL (render/shadow_cascades.h): the quality table, slices that
// cover the view distance in order, maps that hold every visible point of their slice, texel
// snapping that keeps a fixed world point on the same sub-texel position as the camera moves
// (no shimmering), also 1e5 units out, and a size that does not change as the camera turns.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_access.hpp>

#include "render/frame_setup.h"
#include "render/shadow_cascades.h"

namespace oasis {
namespace {

CameraView viewAt(glm::dvec3 position, float yaw, float pitch) {
    CameraView view;
    view.pose = CameraPose{position, yaw, pitch};
    view.aspect = 16.0f / 9.0f;
    return view;
}

const glm::vec3 kLowSun = glm::normalize(glm::vec3(0.9f, 0.06f, 0.3f));

TEST(ShadowCascades, TableHasTheDefaultAndValidSizes) {
    ASSERT_NE(findShadowQuality(ShadowSettings{}.quality), nullptr);
    EXPECT_EQ(findShadowQuality("ultra"), nullptr);
    for (const ShadowQuality& quality : shadowQualities()) {
        EXPECT_GE(quality.cascades, 1) << quality.name;
        EXPECT_LE(quality.cascades, OASIS_SHADOW_MAX_CASCADES) << quality.name;
        EXPECT_GE(quality.mapSize, 256) << quality.name;
    }
}

TEST(ShadowCascades, SlicesCoverTheViewDistanceInOrder) {
    for (const ShadowQuality& quality : shadowQualities()) {
        ShadowCascades c = fitShadowCascades(viewAt({0, 50, 0}, 30.0f, -5.0f), kLowSun, quality, 4000.0f);
        ASSERT_EQ(c.count, quality.cascades);
        for (int i = 1; i < c.count; ++i) {
            EXPECT_GT(c.sliceEnd[i], c.sliceEnd[i - 1]) << quality.name;
            EXPECT_GE(c.texel[i], c.texel[i - 1]) << quality.name;  // finer near the camera
        }
        EXPECT_FLOAT_EQ(c.sliceEnd[c.count - 1], 4000.0f) << quality.name;
        EXPECT_LT(c.fadeStart, c.fadeEnd);
        EXPECT_FLOAT_EQ(c.fadeEnd, 4000.0f);
    }
}

// Every point of a cascade's slice inside the view frustum lands inside its map (|xy| < 1).
TEST(ShadowCascades, EachMapHoldsItsSlice) {
    for (glm::dvec3 position : {glm::dvec3(0, 50, 0), glm::dvec3(1e5, 40, -1e5)}) {
        CameraView view = viewAt(position, 120.0f, -20.0f);
        ShadowCascades c = fitShadowCascades(view, kLowSun, defaultShadowQuality(), 4000.0f);
        glm::mat4 toWorld = glm::inverse(view.rotationOnlyView());
        double tanY = std::tan(glm::radians(30.0)), tanX = tanY * view.aspect;
        float start = 1.0f;
        for (int i = 0; i < c.count; ++i) {
            for (float depth : {start, c.sliceEnd[i]})
                for (float sx : {-1.0f, 0.0f, 1.0f})
                    for (float sy : {-1.0f, 0.0f, 1.0f}) {
                        glm::vec4 p = toWorld * glm::vec4(sx * float(tanX) * depth, sy * float(tanY) * depth, -depth, 1.0f);
                        glm::vec4 clip = c.matrices[size_t(i)] * glm::vec4(glm::vec3(p), 1.0f);
                        EXPECT_LE(std::fabs(clip.x), 1.0f + 1e-4f) << "cascade " << i << " depth " << depth;
                        EXPECT_LE(std::fabs(clip.y), 1.0f + 1e-4f) << "cascade " << i << " depth " << depth;
                    }
            start = c.sliceEnd[i];
        }
    }
}

// Moving the camera by fractions of a texel moves a fixed world point's map position by whole
// texels only: a shadow edge stays on the same texel boundary, so it does not crawl. Near the
// origin and 1e5 units out (where float camera-relative maths would have lost the fractions).
TEST(ShadowCascades, SnappedToTexelsAsTheCameraMoves) {
    const ShadowQuality& quality = defaultShadowQuality();
    for (glm::dvec3 origin : {glm::dvec3(10, 50, 20), glm::dvec3(1e5, 50, 1e5)}) {
        const glm::dvec3 world = origin + glm::dvec3(30.0, -40.0, -60.0);  // a point on the ground ahead
        ShadowCascades first = fitShadowCascades(viewAt(origin, 200.0f, -30.0f), kLowSun, quality, 4000.0f);
        for (double step : {0.013, 0.37, 1.91}) {
            glm::dvec3 moved = origin + glm::dvec3(step, 0.2 * step, -0.7 * step);
            ShadowCascades next = fitShadowCascades(viewAt(moved, 200.0f, -30.0f), kLowSun, quality, 4000.0f);
            for (int i = 0; i < first.count; ++i) {
                ASSERT_FLOAT_EQ(first.texel[i], next.texel[i]);
                auto texelsAt = [&](const ShadowCascades& c, glm::dvec3 camera) {
                    glm::vec4 clip = c.matrices[size_t(i)] * glm::vec4(glm::vec3(world - camera), 1.0f);
                    return glm::dvec2(clip.x, clip.y) * 0.5 * double(quality.mapSize);
                };
                glm::dvec2 shift = texelsAt(next, moved) - texelsAt(first, origin);
                EXPECT_NEAR(shift.x, std::round(shift.x), 0.02) << "cascade " << i << " step " << step;
                EXPECT_NEAR(shift.y, std::round(shift.y), 0.02) << "cascade " << i << " step " << step;
            }
        }
    }
}

// Turning the camera does not resize a cascade (a resize would move every edge).
TEST(ShadowCascades, SizeIndependentOfTheCameraDirection) {
    ShadowCascades a = fitShadowCascades(viewAt({0, 50, 0}, 0.0f, 0.0f), kLowSun, defaultShadowQuality(), 4000.0f);
    ShadowCascades b = fitShadowCascades(viewAt({0, 50, 0}, 137.0f, -41.0f), kLowSun, defaultShadowQuality(), 4000.0f);
    for (int i = 0; i < a.count; ++i) EXPECT_EQ(a.texel[i], b.texel[i]) << "cascade " << i;
}

// No shadow maps at night: the frame says the pass is inactive and the shaders read "off".
TEST(ShadowCascades, NoneAtNightOrWhenOff) {
    SceneSettings scene;
    scene.hour = 21.0;
    FrameSetup night = prepareFrame(scene, 320, 180);
    EXPECT_FALSE(night.shadowsActive);
    EXPECT_EQ(night.data.shadow.x, 0.0f);
    scene.hour = 10.0;
    FrameSetup day = prepareFrame(scene, 320, 180);
    EXPECT_TRUE(day.shadowsActive);
    EXPECT_EQ(day.data.shadow.x, 1.0f);
    EXPECT_EQ(day.data.shadow.y, float(defaultShadowQuality().cascades));
    scene.shadows.enabled = false;
    EXPECT_FALSE(prepareFrame(scene, 320, 180).shadowsActive);
}

}  // namespace
}  // namespace oasis

namespace oasis {
namespace {

// ShadowPass draws only the terrain rings within each cascade's caster reach: every point of the
// box's square swept towards the sun, at a height between the casters' bounds, must lie within
// it (else a caster would be dropped and the image change), and with a high sun cascade 0's reach
// must end well inside the view distance (else nothing is culled).
TEST(ShadowCascades, CasterReachHoldsEveryCasterThatCanShadowTheBox) {
    const glm::vec2 heights(-20.0f, 150.0f);
    const glm::vec3 highSun = glm::normalize(glm::vec3(0.3f, 0.8f, -0.4f));
    for (glm::vec3 sun : {kLowSun, highSun}) {
        CameraView view = viewAt({1000, 60, -300}, 40.0f, -10.0f);
        ShadowCascades c = fitShadowCascades(view, sun, *findShadowQuality("medium"), 4000.0f, heights);
        for (int k = 0; k < c.count; ++k) {
            glm::mat4 fromClip = glm::inverse(c.matrices[size_t(k)]);
            int inside = 0;
            for (float a = -1.0f; a <= 1.0f; a += 0.125f)
                for (float b = -1.0f; b <= 1.0f; b += 0.125f)
                    for (float z = 1.0f; z >= -40.0f; z -= 0.0625f) {  // from the back towards the sun, past the front
                        glm::vec4 p = fromClip * glm::vec4(a, b, z, 1.0f);
                        float worldY = p.y / p.w + 60.0f;
                        if (worldY < heights.x || worldY > heights.y) continue;
                        float distance = glm::length(glm::vec2(p.x, p.z) / p.w);
                        ++inside;
                        EXPECT_GE(distance, c.casterReach[size_t(k)].x * 0.999f - 0.01f) << "cascade " << k;
                        EXPECT_LE(distance, c.casterReach[size_t(k)].y * 1.001f + 0.01f) << "cascade " << k;
                    }
            EXPECT_GT(inside, 0) << "cascade " << k;
        }
        if (sun == highSun) EXPECT_LT(c.casterReach[0].y, 1000.0f) << "cascade 0 reaches the whole view";
    }
}

// Without depth clamp the box reaches towards the sun (ShadowCasterDepth::Contained): every point
// above the box's square at a caster's height lies inside its depth range, so no caster is
// flattened (with a low sun, the sphere's box leaves many out); the square and the texel are the
// sphere's; the sphere's front is where common/shadows.glsl computes it from the texel and the
// depth range (it asks a wider cascade nearer the sun, as the clamped box does).
TEST(ShadowCascades, AContainedBoxHoldsEveryCasterAboveItsSquare) {
    const glm::vec2 heights(-20.0f, 150.0f);
    const glm::vec3 highSun = glm::normalize(glm::vec3(0.3f, 0.8f, -0.4f));
    const ShadowQuality& quality = *findShadowQuality("medium");
    for (glm::vec3 sun : {kLowSun, highSun}) {
        CameraView view = viewAt({1000, 60, -300}, 40.0f, -10.0f);
        ShadowCascades clamped = fitShadowCascades(view, sun, quality, 4000.0f, heights, ShadowCasterDepth::Clamped);
        ShadowCascades contained = fitShadowCascades(view, sun, quality, 4000.0f, heights, ShadowCasterDepth::Contained);
        ASSERT_EQ(clamped.count, contained.count);
        int pastTheSphere = 0;
        for (int k = 0; k < clamped.count; ++k) {
            const glm::mat4 &sphere = clamped.matrices[size_t(k)], &box = contained.matrices[size_t(k)];
            EXPECT_EQ(clamped.texel[k], contained.texel[k]);
            EXPECT_GE(contained.depthRange[k], clamped.depthRange[k]);
            for (int row = 0; row < 4; ++row) {  // x and y: the same square
                EXPECT_EQ(glm::row(sphere, 0)[row], glm::row(box, 0)[row]);
                EXPECT_EQ(glm::row(sphere, 1)[row], glm::row(box, 1)[row]);
            }
            glm::mat4 fromSphere = glm::inverse(sphere);
            for (float a = -1.0f; a <= 1.0f; a += 0.25f)
                for (float b = -1.0f; b <= 1.0f; b += 0.25f)
                    for (float z = 1.0f; z >= -40.0f; z -= 0.125f) {
                        glm::vec4 p = fromSphere * glm::vec4(a, b, z, 1.0f);
                        if (p.y / p.w + 60.0f > heights.y || p.y / p.w + 60.0f < heights.x) continue;
                        if (z < -1.0f) ++pastTheSphere;
                        float boxZ = (box * p).z / (box * p).w;
                        EXPECT_GE(boxZ, -1.0f - 1e-4f) << "cascade " << k << " flattens a caster at sphere depth " << z;
                        EXPECT_LE(boxZ, 1.0f + 1e-4f) << "cascade " << k;
                    }
            float sphereFront = 1.0f - 2.0f * (contained.texel[k] * float(quality.mapSize)) / contained.depthRange[k];
            glm::vec4 front = box * (fromSphere * glm::vec4(0.0f, 0.0f, -1.0f, 1.0f));
            EXPECT_NEAR(front.z / front.w, sphereFront, 1e-4f) << "cascade " << k;
            EXPECT_EQ(1.0f - 2.0f * (clamped.texel[k] * float(quality.mapSize)) / clamped.depthRange[k], -1.0f);
        }
        if (sun == kLowSun) EXPECT_GT(pastTheSphere, 100) << "the low sun's casters all fit the sphere: nothing tested";
    }
}

}  // namespace
}  // namespace oasis
