// Terrain heights on the CPU (for the camera path, tests and placement) and the polar grid.
#include "scene/terrain.h"

#include <algorithm>
#include <cmath>

#include "common/shared_constants.glsl"
#include "scene/camera.h"
#include "scene/noise.h"

namespace oasis {
namespace {
constexpr float kValleyFlattening = float(OASIS_TERRAIN_VALLEY_FLATTENING);
}  // namespace

NoiseOrigins terrainNoiseOrigins(const TerrainShape& shape, glm::dvec2 worldXZ) {
    return fractalNoiseOrigins(worldXZ * double(shape.frequency), shape.octaves);
}

namespace {
// h = amplitude * (n + k n^2) + base and its gradient, from the noise and its gradient.
glm::vec3 heightFromNoise(const TerrainShape& shape, glm::vec3 n) {
    const float k = kValleyFlattening;
    float slopeScale = shape.amplitude * shape.frequency * (1.0f + 2.0f * k * n.x);
    return {shape.amplitude * (n.x + k * n.x * n.x) + shape.baseHeight, slopeScale * n.y, slopeScale * n.z};
}
}  // namespace

glm::vec3 terrainHeight(const TerrainShape& shape, glm::dvec2 worldXZ) {
    return heightFromNoise(shape, fractalNoise(worldXZ * double(shape.frequency), shape.octaves));
}

glm::vec3 terrainHeightFromCamera(const TerrainShape& shape, const NoiseOrigins& origins, glm::vec2 relativeXZ) {
    return heightFromNoise(shape, fractalNoiseFrom(origins, relativeXZ * shape.frequency, shape.octaves));
}

glm::vec2 terrainHeightBounds(const TerrainShape& shape) {
    // h = amplitude * (n + k n^2) + base over |n| <= 2: highest at n = 2, lowest at the parabola's
    // vertex n = -1 / (2k) when that lies inside (it does for k >= 0.25), else at n = -2.
    const float k = kValleyFlattening, n = 2.0f;
    auto height = [&](float noise) { return shape.amplitude * (noise + k * noise * noise) + shape.baseHeight; };
    float vertex = k > 0.0f ? -1.0f / (2.0f * k) : -n;
    float lowest = std::min(height(-n), height(std::max(vertex, -n)));
    float highest = std::max(height(n), height(-n));
    return {lowest - 1.0f, highest + 1.0f};
}

glm::vec3 terrainNormal(const TerrainShape& shape, glm::dvec2 worldXZ) {
    glm::vec3 h = terrainHeight(shape, worldXZ);
    return glm::normalize(glm::vec3(-h.y, 1.0f, -h.z));
}

TerrainWedge computeTerrainWedge(const CameraView& view, const TerrainGridDensity& density,
                                 float viewDistance) {
    TerrainWedge wedge;
    // Ring 0 is the centre point; rings 1..rings go geometrically from firstRingRadius to viewDistance.
    wedge.ringRatio = std::pow(viewDistance / density.firstRingRadius, 1.0f / float(std::max(1, density.rings - 1)));
    wedge.centralAzimuth = view.pose.yawRadians();
    // Azimuth of each frustum corner relative to the heading; the extremes are at the corners
    // as long as every corner ray points forward horizontally.
    const float margin = 0.12f;  // radians: vertices beyond the edge keep border triangles whole
    float widest = 0.0f;
    for (glm::vec3 ray : view.cornerRays()) {
        glm::vec2 horizontal(ray.x, ray.z);
        glm::vec2 heading(std::sin(wedge.centralAzimuth), -std::cos(wedge.centralAzimuth));
        float ahead = glm::dot(horizontal, heading);
        float side = heading.x * horizontal.y - heading.y * horizontal.x;
        if (ahead <= 0.05f * glm::length(horizontal) + 1e-4f) {
            wedge.halfWidth = float(M_PI);
            return wedge;
        }
        widest = std::max(widest, std::atan2(std::fabs(side), ahead));
    }
    wedge.halfWidth = std::min(float(M_PI), widest + margin);
    return wedge;
}

GridMesh buildTerrainGrid(const TerrainGridDensity& density) {
    GridMesh mesh;
    const int columns = density.segments + 1;
    for (int ring = 0; ring <= density.rings; ++ring)
        for (int segment = 0; segment <= density.segments; ++segment)
            mesh.vertices.emplace_back(float(ring) / float(density.rings),
                                       float(segment) / float(density.segments));
    for (int ring = 0; ring < density.rings; ++ring) {
        for (int segment = 0; segment < density.segments; ++segment) {
            uint32_t a = uint32_t(ring * columns + segment);
            uint32_t b = a + 1, c = a + uint32_t(columns), d = c + 1;
            // Counter-clockwise seen from above (+Y), matching the sky-facing front face.
            mesh.indices.insert(mesh.indices.end(), {a, b, d, a, d, c});
        }
    }
    return mesh;
}

}  // namespace oasis
