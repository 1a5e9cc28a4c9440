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

// How view depth maps to clip z: OpenGL's default (near plane at NDC z -1, far at 1), or reversed
// on a 0..1 clip range (near 1, far 0), which keeps a float depth buffer's precision where the
// distance is large (glClipControl ZERO_TO_ONE; render/depth_convention.h chooses it).
enum class DepthMapping { Standard, Reversed };

// A pose plus projection for a given aspect ratio.
struct CameraView {
    CameraPose pose;
    Projection projection;
    float aspect = 16.0f / 9.0f;
    DepthMapping depthMapping = DepthMapping::Standard;

    glm::mat4 rotationOnlyView() const;  // world directions -> view space
    glm::mat4 projectionMatrix() const;
    glm::mat4 viewProjection() const;    // camera-relative world -> clip
    std::array<glm::vec3, 4> cornerRays() const;  // world directions through the frustum corners
};

// The six planes of a camera-relative view-projection's frustum (Gribb and Hartmann): inside where
// dot(plane.xyz, p) + plane.w >= 0. Left, right, bottom, top, near, far; the near and far planes
// depend on the depth mapping the matrix was built with.
std::array<glm::vec4, 6> frustumPlanes(const glm::mat4& viewProjection, DepthMapping mapping);

// The default flight: eastwards over the hills, heading swaying, always above ground and water.
CameraPose defaultCameraPath(const TerrainShape& shape, double timeSeconds);

}  // namespace oasis
