// Point light placement and animation.
#include "scene/point_lights.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace oasis {
namespace {

// A well-mixed hash of (index, salt) to [0, 1) (splitmix64's finaliser).
double unitHash(uint64_t index, uint64_t salt) {
    uint64_t z = index * 0x9E3779B97F4A7C15ull + salt * 0xBF58476D1CE4E5B9ull + 0x94D049BB133111EBull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return double(z >> 11) * (1.0 / 9007199254740992.0);
}

// Where the lights gather: the lake east of the default flight's start and its shores.
constexpr double kCentreX = 560.0, kCentreZ = 60.0, kSpread = 420.0;

}  // namespace

std::vector<WorldPointLight> scenePointLights(int count, double timeSeconds, const TerrainShape& terrain,
                                              float waterLevel) {
    std::vector<WorldPointLight> lights;
    lights.reserve(size_t(std::max(count, 0)));
    for (int i = 0; i < count; ++i) {
        uint64_t k = uint64_t(i);
        // Uniform over a disc (sqrt for equal area), each light on its own slow loop.
        double angle = 2.0 * M_PI * unitHash(k, 1), distance = kSpread * std::sqrt(unitHash(k, 2));
        double loopRadius = 2.0 + 4.0 * unitHash(k, 3), loopSpeed = 0.15 + 0.35 * unitHash(k, 4);
        double phase = 2.0 * M_PI * unitHash(k, 5);
        double x = kCentreX + distance * std::cos(angle) + loopRadius * std::cos(phase + loopSpeed * timeSeconds);
        double z = kCentreZ + distance * std::sin(angle) + loopRadius * std::sin(phase + loopSpeed * timeSeconds);
        double ground = std::max(double(terrainHeight(terrain, glm::vec2(float(x), float(z))).x), double(waterLevel));
        double hover = 1.5 + 4.5 * unitHash(k, 6) + 0.8 * std::sin(1.3 * timeSeconds + phase);
        WorldPointLight light;
        light.position = glm::dvec3(x, ground + hover, z);
        light.radius = float(9.0 + 9.0 * unitHash(k, 7));
        // Warm lanterns (orange to yellow) and a few greenish fireflies.
        double hue = unitHash(k, 8);
        light.colour = hue < 0.75 ? glm::vec3(1.0f, float(0.45 + 0.35 * hue / 0.75), float(0.12 + 0.1 * hue))
                                  : glm::vec3(0.55f, 1.0f, 0.25f);
        light.intensity = float(20.0 + 30.0 * unitHash(k, 9)) * float(0.85 + 0.15 * std::sin(3.1 * timeSeconds + 2.0 * phase));
        lights.push_back(light);
    }
    return lights;
}

std::vector<glm::vec3> lightVolumeMesh() {
    const double t = (1.0 + std::sqrt(5.0)) / 2.0;
    std::vector<glm::dvec3> v = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                                 {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    const int faces[20][3] = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                              {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
                              {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
    std::vector<glm::dvec3> triangles;
    for (const auto& f : faces) {
        glm::dvec3 a = glm::normalize(v[f[0]]), b = glm::normalize(v[f[1]]), c = glm::normalize(v[f[2]]);
        glm::dvec3 ab = glm::normalize(a + b), bc = glm::normalize(b + c), ca = glm::normalize(c + a);
        for (const glm::dvec3& p : {a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca}) triangles.push_back(p);
    }
    // The nearest face plane to the centre sets the scale that circumscribes the unit sphere.
    double inradius = 1.0;
    for (size_t i = 0; i < triangles.size(); i += 3) {
        glm::dvec3 n = glm::normalize(glm::cross(triangles[i + 1] - triangles[i], triangles[i + 2] - triangles[i]));
        inradius = std::min(inradius, glm::dot(n, triangles[i]));
    }
    std::vector<glm::vec3> mesh;
    for (const glm::dvec3& p : triangles) mesh.push_back(glm::vec3(p / inradius * 1.0001));
    return mesh;
}

}  // namespace oasis
