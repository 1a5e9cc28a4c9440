// The camera: a pose (position, yaw, pitch), the default time-driven flight over the terrain,
// and the matrices the passes use. Positions on the GPU are camera-relative, so the view matrix
// here has no translation: large world coordinates never enter a float matrix.
#pragma once
#include <array>
#include <optional>

#include <glm/glm.hpp>

#include "scene/terrain.h"

namespace oasis {

struct CameraPose {
    glm::dvec3 position{0.0};  // world units; double so far-away poses keep their precision
    float yawDegrees = 0.0f;   // 0 looks towards -Z, 90 towards +X
    float pitchDegrees = 0.0f; // positive looks up, clamped to [-89.9, 89.9]

    float yawRadians() const;
    float pitchRadians() const;
    glm::vec3 forward() const;
};

struct Projection {
    float verticalFovDegrees = 60.0f;
    float nearPlane = 0.25f;
    float farPlane = 6000.0f;
};

// A pose plus projection for a given aspect ratio.
struct CameraView {
    CameraPose pose;
    Projection projection;
    float aspect = 16.0f / 9.0f;

    glm::mat4 rotationOnlyView() const;  // world directions -> view space
    glm::mat4 projectionMatrix() const;
    glm::mat4 viewProjection() const;    // camera-relative world -> clip
    std::array<glm::vec3, 4> cornerRays() const;  // world directions through the frustum corners
};

// The default flight: eastwards over the hills, heading swaying, always above ground and water.
CameraPose defaultCameraPath(const TerrainShape& shape, double timeSeconds);

}  // namespace oasis
