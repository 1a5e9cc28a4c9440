// The scene's point lights: lanterns and fireflies hovering above the ground and the water around
// the lake of the default flight, animated by time. GL-free, in world space (double positions).
#pragma once
#include <vector>

#include <glm/glm.hpp>

#include "scene/terrain.h"

namespace oasis {

struct WorldPointLight {
    glm::dvec3 position{0.0};
    float radius = 10.0f;           // influence ends here (the falloff reaches zero)
    glm::vec3 colour{1.0f};         // linear
    float intensity = 1.0f;
};

// Light i of `count` at `timeSeconds`: the same light for the same index whatever the count, so
// raising the count adds lights and keeps the others. Each sits 1.5 to 6 units above the ground or
// the water (the CPU terrain height), bobs and drifts on its own small loop.
std::vector<WorldPointLight> scenePointLights(int count, double timeSeconds, const TerrainShape& terrain,
                                              float waterLevel);

// A light's volume: an icosphere (80 triangles, counter-clockwise seen from outside) scaled so
// every face lies at least 1 from the centre: it contains the unit sphere. Scaled by a light's
// radius it covers every point the light reaches. Non-indexed triangle list.
std::vector<glm::vec3> lightVolumeMesh();

}  // namespace oasis
