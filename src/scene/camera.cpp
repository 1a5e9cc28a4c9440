// Camera maths and the default flight path.
#include "scene/camera.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace oasis {

// Wrapped in double first: a float of 1e9 degrees in radians would keep no precision at all.
float CameraPose::yawRadians() const { return float(glm::radians(std::remainder(double(yawDegrees), 360.0))); }
float CameraPose::pitchRadians() const {
    return glm::radians(std::clamp(pitchDegrees, -89.9f, 89.9f));
}

glm::vec3 CameraPose::forward() const {
    float yaw = yawRadians(), pitch = pitchRadians();
    return {std::sin(yaw) * std::cos(pitch), std::sin(pitch), -std::cos(yaw) * std::cos(pitch)};
}

glm::mat4 CameraView::rotationOnlyView() const {
    return glm::lookAt(glm::vec3(0.0f), pose.forward(), glm::vec3(0.0f, 1.0f, 0.0f));
}

glm::mat4 CameraView::projectionMatrix() const {
    float fovy = glm::radians(projection.verticalFovDegrees);
    // Reversed: the 0..1 projection with near and far swapped puts the near plane at 1, the far at 0.
    if (depthMapping == DepthMapping::Reversed)
        return glm::perspectiveRH_ZO(fovy, aspect, projection.farPlane, projection.nearPlane);
    return glm::perspectiveRH_NO(fovy, aspect, projection.nearPlane, projection.farPlane);
}

glm::mat4 CameraView::viewProjection() const { return projectionMatrix() * rotationOnlyView(); }

std::array<glm::vec3, 4> CameraView::cornerRays() const {
    glm::mat4 toWorld = glm::inverse(rotationOnlyView());
    float tanY = std::tan(glm::radians(projection.verticalFovDegrees) * 0.5f);
    float tanX = tanY * aspect;
    std::array<glm::vec3, 4> rays;
    int i = 0;
    for (float sy : {-1.0f, 1.0f})
        for (float sx : {-1.0f, 1.0f})
            rays[i++] = glm::normalize(glm::vec3(toWorld * glm::vec4(sx * tanX, sy * tanY, -1.0f, 0.0f)));
    return rays;
}

std::array<glm::vec4, 6> frustumPlanes(const glm::mat4& viewProjection, DepthMapping mapping) {
    auto row = [&](int r) { return glm::vec4(viewProjection[0][r], viewProjection[1][r], viewProjection[2][r],
                                             viewProjection[3][r]); };
    glm::vec4 w = row(3), z = row(2);
    // Standard: -w <= z <= w. Reversed: 0 <= z <= w, the near plane at z = w and the far at z = 0.
    bool reversed = mapping == DepthMapping::Reversed;
    return {w + row(0), w - row(0), w + row(1), w - row(1), reversed ? w - z : w + z, reversed ? z : w - z};
}

CameraPose defaultCameraPath(const TerrainShape& shape, double timeSeconds) {
    const double speed = 7.0;  // world units per second eastwards
    const double swayPeriod = 90.0, swayAmplitude = 160.0;
    // The flight starts over a lake, so the default frame (time 0) shows the water.
    const double startOffset = 25.0;
    double t = timeSeconds + startOffset;
    CameraPose pose;
    double x = speed * t + 210.0;
    double z = swayAmplitude * std::sin(t / swayPeriod * 2.0 * M_PI) - 120.0;
    double dzdt = swayAmplitude * std::cos(t / swayPeriod * 2.0 * M_PI) * 2.0 * M_PI / swayPeriod;
    float yaw = float(std::atan2(speed, -dzdt));
    // Clear the highest ground just ahead so the flight never dips into a hill.
    double ground = 0.0;
    for (double ahead : {0.0, 20.0, 50.0, 100.0, 160.0}) {
        glm::dvec2 probe(x + ahead * std::sin(yaw), z - ahead * std::cos(yaw));
        ground = std::max(ground, double(terrainHeight(shape, probe).x));
    }
    pose.position = glm::dvec3(x, ground + 26.0, z);
    pose.yawDegrees = glm::degrees(yaw);
    pose.pitchDegrees = -9.0f;
    return pose;
}

}  // namespace oasis
