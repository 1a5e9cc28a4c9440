// Covers src/scene/camera.h: pose conventions, the view-projection and frustum corner rays, and the default flight path.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>

#include "scene/camera.h"
#include "scene/terrain.h"

namespace oasis {
namespace {

void expectVecNear(glm::vec3 actual, glm::vec3 expected, float tolerance, const std::string& what) {
    EXPECT_NEAR(actual.x, expected.x, tolerance) << what;
    EXPECT_NEAR(actual.y, expected.y, tolerance) << what;
    EXPECT_NEAR(actual.z, expected.z, tolerance) << what;
}

CameraPose pose(float yaw, float pitch) {
    CameraPose p;
    p.position = glm::dvec3(1234.5, 67.0, -890.25);
    p.yawDegrees = yaw;
    p.pitchDegrees = pitch;
    return p;
}

double wrapAngle(double a) {
    while (a > M_PI) a -= 2.0 * M_PI;
    while (a < -M_PI) a += 2.0 * M_PI;
    return a;
}

TEST(CameraPose, ForwardConventions) {
    expectVecNear(pose(0, 0).forward(), {0, 0, -1}, 1e-6f, "yaw 0 looks towards -Z");
    expectVecNear(pose(90, 0).forward(), {1, 0, 0}, 1e-6f, "yaw 90 looks towards +X");
    expectVecNear(pose(180, 0).forward(), {0, 0, 1}, 1e-6f, "yaw 180 looks towards +Z");
    expectVecNear(pose(-90, 0).forward(), {-1, 0, 0}, 1e-6f, "yaw -90 looks towards -X");
    // Pitch is clamped to 89.9 degrees: sin(89.9 deg) = 0.9999985, so +Y within 2e-3 overall.
    expectVecNear(pose(0, 90).forward(), {0, 1, 0}, 2e-3f, "pitch 90 looks up");
    expectVecNear(pose(0, -90).forward(), {0, -1, 0}, 2e-3f, "pitch -90 looks down");
    EXPECT_GT(pose(0, 90).forward().y, 0.99999f);
    expectVecNear(pose(0, 30).forward(), {0, 0.5f, -std::sqrt(3.0f) / 2.0f}, 1e-6f, "pitch 30");
}

TEST(CameraPose, PitchIsClampedAndForwardIsUnit) {
    EXPECT_NEAR(pose(0, 120).pitchRadians(), glm::radians(89.9f), 1e-6f);
    EXPECT_NEAR(pose(0, -120).pitchRadians(), -glm::radians(89.9f), 1e-6f);
    EXPECT_NEAR(pose(200, 0).yawRadians(), glm::radians(-160.0f), 1e-6f);  // wrapped into [-180, 180]
    std::mt19937 rng(31);
    std::uniform_real_distribution<float> yaw(-720, 720), pitch(-100, 100);
    for (int i = 0; i < 1000; ++i) {
        glm::vec3 f = pose(yaw(rng), pitch(rng)).forward();
        ASSERT_NEAR(glm::length(f), 1.0f, 1e-6f);
        // Never exactly vertical, so lookAt with up = +Y stays well defined.
        ASSERT_GT(std::hypot(f.x, f.z), 1e-3f);
    }
}

CameraView view(float yaw, float pitch, float aspect = 16.0f / 9.0f) {
    CameraView v;
    v.pose = pose(yaw, pitch);
    v.aspect = aspect;
    return v;
}

glm::vec3 toNdc(const glm::mat4& m, glm::vec3 p) {
    glm::vec4 clip = m * glm::vec4(p, 1.0f);
    return glm::vec3(clip) / clip.w;
}

TEST(CameraView, PointStraightAheadMapsToNdcCentre) {
    std::mt19937 rng(32);
    std::uniform_real_distribution<float> yaw(-180, 180), pitch(-85, 85), aspect(0.5f, 3.0f);
    for (int i = 0; i < 500; ++i) {
        CameraView v = view(yaw(rng), pitch(rng), aspect(rng));
        glm::mat4 vp = v.viewProjection();
        for (float distance : {1.0f, 10.0f, 1000.0f}) {
            glm::vec3 ndc = toNdc(vp, v.pose.forward() * distance);
            ASSERT_NEAR(ndc.x, 0.0f, 1e-5f);
            ASSERT_NEAR(ndc.y, 0.0f, 1e-5f);
            ASSERT_GT(ndc.z, -1.0f);
            ASSERT_LT(ndc.z, 1.0f);
        }
        // Depth increases with distance, and points behind the camera get w < 0.
        EXPECT_LT(toNdc(vp, v.pose.forward() * 2.0f).z, toNdc(vp, v.pose.forward() * 20.0f).z);
        EXPECT_LT((vp * glm::vec4(-v.pose.forward(), 1.0f)).w, 0.0f);
    }
}

TEST(CameraView, NearAndFarPlanesMapToNdcDepthLimits) {
    CameraView v = view(10, -5);
    glm::mat4 vp = v.viewProjection();
    glm::vec3 f = v.pose.forward();
    EXPECT_NEAR(toNdc(vp, f * v.projection.nearPlane).z, -1.0f, 1e-4f);
    EXPECT_NEAR(toNdc(vp, f * v.projection.farPlane).z, 1.0f, 1e-4f);
}

TEST(CameraView, UpAndRightAreScreenUpAndRight) {
    // Level camera looking at -Z: +X is screen right, +Y is screen up.
    CameraView v = view(0, 0);
    glm::vec3 right = toNdc(v.viewProjection(), {1, 0, -10});
    glm::vec3 up = toNdc(v.viewProjection(), {0, 1, -10});
    EXPECT_GT(right.x, 0.0f);
    EXPECT_NEAR(right.y, 0.0f, 1e-6f);
    EXPECT_GT(up.y, 0.0f);
    EXPECT_NEAR(up.x, 0.0f, 1e-6f);
}

TEST(CameraView, CornerRaysMapToNdcCorners) {
    std::mt19937 rng(33);
    std::uniform_real_distribution<float> yaw(-180, 180), pitch(-89.9f, 89.9f), aspect(0.4f, 3.0f),
        fov(20.0f, 120.0f);
    for (int i = 0; i < 500; ++i) {
        CameraView v = view(yaw(rng), pitch(rng), aspect(rng));
        v.projection.verticalFovDegrees = fov(rng);
        glm::mat4 vp = v.viewProjection();
        std::set<std::pair<int, int>> corners;
        for (glm::vec3 ray : v.cornerRays()) {
            ASSERT_NEAR(glm::length(ray), 1.0f, 1e-5f);
            glm::vec4 clip = vp * glm::vec4(ray * 10.0f, 1.0f);
            ASSERT_GT(clip.w, 0.0f);
            glm::vec3 ndc = glm::vec3(clip) / clip.w;
            ASSERT_NEAR(std::fabs(ndc.x), 1.0f, 1e-4f) << "pitch " << v.pose.pitchDegrees;
            ASSERT_NEAR(std::fabs(ndc.y), 1.0f, 1e-4f) << "pitch " << v.pose.pitchDegrees;
            corners.insert({ndc.x > 0 ? 1 : -1, ndc.y > 0 ? 1 : -1});
        }
        ASSERT_EQ(corners.size(), 4u) << "the four rays must hit four different corners";
    }
}

TEST(DefaultCameraPath, Deterministic) {
    TerrainShape shape;
    for (double t : {0.0, 1.5, 100.0, 2999.0}) {
        CameraPose a = defaultCameraPath(shape, t), b = defaultCameraPath(shape, t);
        EXPECT_EQ(a.position.x, b.position.x);
        EXPECT_EQ(a.position.y, b.position.y);
        EXPECT_EQ(a.position.z, b.position.z);
        EXPECT_EQ(a.yawDegrees, b.yawDegrees);
        EXPECT_EQ(a.pitchDegrees, b.pitchDegrees);
    }
}

TEST(DefaultCameraPath, FiniteAndWellAboveTheGround) {
    TerrainShape shape;
    double lowestClearance = 1e9;
    for (double t = 0.0; t <= 3000.0; t += 0.25) {
        CameraPose p = defaultCameraPath(shape, t);
        ASSERT_TRUE(std::isfinite(p.position.x) && std::isfinite(p.position.y) && std::isfinite(p.position.z) &&
                    std::isfinite(p.yawDegrees) && std::isfinite(p.pitchDegrees))
            << "t = " << t;
        double ground = terrainHeight(shape, glm::vec2(p.position.x, p.position.z)).x;
        double clearance = p.position.y - ground;
        ASSERT_GE(clearance, 10.0) << "t = " << t;
        ASSERT_GE(p.position.y, 10.0) << "t = " << t << ": also above the water at height 0";
        ASSERT_GT(p.pitchDegrees, -89.9f);
        ASSERT_LT(p.pitchDegrees, 89.9f);
        lowestClearance = std::min(lowestClearance, clearance);
    }
    RecordProperty("lowest_clearance", std::to_string(lowestClearance));
}

TEST(DefaultCameraPath, MovesEastwards) {
    TerrainShape shape;
    double previousX = defaultCameraPath(shape, 0.0).position.x;
    for (double t = 1.0; t <= 3000.0; t += 1.0) {
        double x = defaultCameraPath(shape, t).position.x;
        ASSERT_GT(x, previousX) << "t = " << t;
        previousX = x;
    }
}

TEST(DefaultCameraPath, YawFollowsTheDirectionOfMotion) {
    TerrainShape shape;
    const double dt = 1e-3;
    for (double t = 0.0; t <= 3000.0; t += 3.7) {
        glm::dvec3 before = defaultCameraPath(shape, t - dt).position, after = defaultCameraPath(shape, t + dt).position;
        glm::dvec2 velocity(after.x - before.x, after.z - before.z);
        ASSERT_GT(glm::length(velocity), 0.0);
        // Same azimuth convention as yaw: 0 = -Z, pi/2 = +X. The central difference of the
        // sway (period 90 s) has relative error ~(2 pi dt / 90)^2 / 6; yaw is stored in float
        // degrees. Tolerance 1e-4 rad.
        double heading = std::atan2(velocity.x, -velocity.y);
        double yaw = glm::radians(double(defaultCameraPath(shape, t).yawDegrees));
        ASSERT_NEAR(wrapAngle(yaw - heading), 0.0, 1e-4) << "t = " << t;
    }
}

}  // namespace
}  // namespace oasis
