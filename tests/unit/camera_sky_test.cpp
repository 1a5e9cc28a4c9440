// Camera conventions and matrices, the default flight, and the sun over the day.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/camera.h"
#include "scene/sky.h"

namespace oasis {
namespace {

void expectNear(glm::vec3 a, glm::vec3 b, float tolerance) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(Camera, YawAndPitchConventions) {
    CameraPose pose;
    expectNear(pose.forward(), {0, 0, -1}, 1e-6f);
    pose.yawDegrees = 90;
    expectNear(pose.forward(), {1, 0, 0}, 1e-6f);
    pose.pitchDegrees = 90;  // clamped to 89.9: still finite, almost straight up
    EXPECT_GT(pose.forward().y, 0.9999f);
}

TEST(Camera, ProjectionMapsForwardToCentreAndCornerRaysToCorners) {
    CameraView view;
    view.pose.yawDegrees = 37;
    view.pose.pitchDegrees = -12;
    glm::vec4 ahead = view.viewProjection() * glm::vec4(view.pose.forward() * 100.0f, 1.0f);
    EXPECT_NEAR(ahead.x / ahead.w, 0.0f, 1e-5f);
    EXPECT_NEAR(ahead.y / ahead.w, 0.0f, 1e-5f);
    int i = 0;
    for (float sy : {-1.0f, 1.0f}) {
        for (float sx : {-1.0f, 1.0f}) {
            glm::vec4 clip = view.viewProjection() * glm::vec4(view.cornerRays()[i++] * 50.0f, 1.0f);
            EXPECT_NEAR(clip.x / clip.w, sx, 1e-4f);
            EXPECT_NEAR(clip.y / clip.w, sy, 1e-4f);
        }
    }
}

TEST(Camera, DefaultFlightIsDeterministicAboveGroundAndHeadsWhereItGoes) {
    TerrainShape shape;
    for (double t = 0.0; t <= 3000.0; t += 7.3) {
        CameraPose a = defaultCameraPath(shape, t), b = defaultCameraPath(shape, t);
        EXPECT_EQ(a.position, b.position);
        ASSERT_TRUE(std::isfinite(a.position.y));
        float ground = terrainHeight(shape, glm::vec2(a.position.x, a.position.z)).x;
        EXPECT_GE(a.position.y, ground + 10.0) << "t " << t;
        glm::dvec3 next = defaultCameraPath(shape, t + 0.01).position;
        glm::vec2 motion = glm::normalize(glm::vec2(next.x - a.position.x, next.z - a.position.z));
        glm::vec3 forward = a.forward();
        glm::vec2 heading = glm::normalize(glm::vec2(forward.x, forward.z));
        EXPECT_GT(glm::dot(motion, heading), 0.999f) << "t " << t;
    }
}

TEST(Sky, ClockStartsAtTenAndWraps) {
    EXPECT_DOUBLE_EQ(hourAtTime(0.0), 10.0);
    EXPECT_NEAR(hourAtTime(kDayLengthSeconds), 10.0, 1e-9);
    EXPECT_NEAR(hourAtTime(kDayLengthSeconds / 2), 22.0, 1e-9);
    double negative = hourAtTime(-kDayLengthSeconds * 0.75);
    EXPECT_GE(negative, 0.0);
    EXPECT_LT(negative, 24.0);
    EXPECT_NEAR(negative, 16.0, 1e-9);
}

TEST(Sky, SunRisesAtSixSetsAtEighteenAndIsDarkAtMidnight) {
    EXPECT_NEAR(skyAtHour(6.0).sunDirection.y, 0.0f, 1e-6f);
    EXPECT_NEAR(skyAtHour(18.0).sunDirection.y, 0.0f, 1e-6f);
    EXPECT_GT(skyAtHour(6.0).sunDirection.x, 0.99f);   // east
    EXPECT_LT(skyAtHour(18.0).sunDirection.x, -0.99f); // west
    EXPECT_GT(skyAtHour(12.0).sunDirection.y, 0.5f);
    EXPECT_EQ(skyAtHour(0.0).sunRadiance, glm::vec3(0.0f));
    EXPECT_GT(skyAtHour(12.0).sunRadiance.r, 1.0f);
    for (double hour = 0.0; hour < 24.0; hour += 0.37)
        EXPECT_NEAR(glm::length(skyAtHour(hour).sunDirection), 1.0f, 1e-6f);
}

}  // namespace
}  // namespace oasis
