// Noise and terrain on the CPU: range, continuity, determinism, analytic gradients against
// finite differences, and the polar grid's exact counts and coverage of the frustum.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/camera.h"
#include "scene/noise.h"
#include "scene/terrain.h"

namespace oasis {
namespace {

TEST(Noise, StaysWithinUnitRange) {
    float largest = 0.0f;
    for (int i = 0; i < 600; ++i)
        for (int j = 0; j < 600; ++j)
            largest = std::max(largest, std::fabs(simplexNoise({i * 0.0371f - 11.0f, j * 0.0413f + 3.0f}).x));
    EXPECT_LE(largest, 1.0f + 1e-6f);
    EXPECT_GT(largest, 0.8f);  // the scale uses the range, not a sliver of it
}

TEST(Noise, IsContinuousAcrossCells) {
    // |gradient| of this simplex is bounded (measured max about 7), so steps of 1e-3 move < 1e-2,
    // including across simplex cell edges (every 0.0371 step crosses many).
    float worst = 0.0f;
    for (int i = 0; i < 20000; ++i) {
        glm::vec2 p(i * 0.0371f - 300.0f, i * 0.0123f + 7.0f);
        worst = std::max(worst, std::fabs(simplexNoise(p + glm::vec2(1e-3f, 0)).x - simplexNoise(p).x));
    }
    EXPECT_LT(worst, 1e-2f);
}

TEST(Noise, IsDeterministic) {
    for (int i = 0; i < 100; ++i) {
        glm::vec2 p(i * 1.7f, -i * 2.3f);
        EXPECT_EQ(simplexNoise(p), simplexNoise(p));
        EXPECT_EQ(fractalNoise(p, 7), fractalNoise(p, 7));
    }
    EXPECT_NE(hashCell({0, 0}), hashCell({1, 0}));
    EXPECT_NE(hashCell({0, 0}), hashCell({0, 1}));
    EXPECT_NE(hashCell({1, 0}), hashCell({0, 1}));
}

// Central differences in double around a float evaluation: tolerance covers float rounding.
glm::vec2 numericGradient(glm::vec2 p, float h, float (*f)(glm::vec2)) {
    return {(f(p + glm::vec2(h, 0)) - f(p - glm::vec2(h, 0))) / (2 * h),
            (f(p + glm::vec2(0, h)) - f(p - glm::vec2(0, h))) / (2 * h)};
}

TEST(Noise, AnalyticGradientMatchesFiniteDifferences) {
    auto value = [](glm::vec2 p) { return simplexNoise(p).x; };
    auto fractal = [](glm::vec2 p) { return fractalNoise(p, 5).x; };
    for (int i = 0; i < 500; ++i) {
        glm::vec2 p(i * 0.173f - 40.0f, i * 0.091f + 5.0f);
        glm::vec3 n = simplexNoise(p);
        glm::vec2 numeric = numericGradient(p, 1e-3f, value);
        EXPECT_NEAR(n.y, numeric.x, 2e-2f) << "at " << p.x << "," << p.y;
        EXPECT_NEAR(n.z, numeric.y, 2e-2f);
        glm::vec3 f = fractalNoise(p, 5);
        glm::vec2 fractalNumeric = numericGradient(p, 1e-3f, fractal);
        // Octave 5 has frequency 2^4: the finite difference's truncation error grows with it.
        EXPECT_NEAR(f.y, fractalNumeric.x, 0.25f);
        EXPECT_NEAR(f.z, fractalNumeric.y, 0.25f);
    }
}

TEST(Terrain, HeightGradientAndNormalAgree) {
    TerrainShape shape;
    for (int i = 0; i < 200; ++i) {
        glm::vec2 p(i * 37.3f - 3000.0f, i * -21.7f + 1000.0f);
        glm::vec3 h = terrainHeight(shape, p);
        float step = 0.05f;
        float dx = (terrainHeight(shape, p + glm::vec2(step, 0)).x - terrainHeight(shape, p - glm::vec2(step, 0)).x) / (2 * step);
        float dz = (terrainHeight(shape, p + glm::vec2(0, step)).x - terrainHeight(shape, p - glm::vec2(0, step)).x) / (2 * step);
        EXPECT_NEAR(h.y, dx, 0.02f + 0.02f * std::fabs(dx));
        EXPECT_NEAR(h.z, dz, 0.02f + 0.02f * std::fabs(dz));
        glm::vec3 n = terrainNormal(shape, p);
        EXPECT_NEAR(glm::length(n), 1.0f, 1e-6f);
        EXPECT_NEAR(n.x / n.y, -h.y, 1e-4f + 1e-4f * std::fabs(h.y));
    }
}

TEST(TerrainGrid, HasExactCounts) {
    TerrainGridDensity density;
    density.rings = 17;
    density.segments = 9;
    GridMesh mesh = buildTerrainGrid(density);
    EXPECT_EQ(mesh.vertices.size(), size_t((17 + 1) * (9 + 1)));
    EXPECT_EQ(mesh.indices.size(), size_t(17 * 9 * 6));
    for (uint32_t index : mesh.indices) EXPECT_LT(index, mesh.vertices.size());
    for (glm::vec2 v : mesh.vertices) {
        EXPECT_GE(v.x, 0.0f); EXPECT_LE(v.x, 1.0f);
        EXPECT_GE(v.y, 0.0f); EXPECT_LE(v.y, 1.0f);
    }
}

CameraView viewWithPitch(float yaw, float pitch) {
    CameraView view;
    view.pose.yawDegrees = yaw;
    view.pose.pitchDegrees = pitch;
    return view;
}

TEST(TerrainGrid, WedgeCoversTheFrustumAndClosesWhenLookingSteeply) {
    TerrainGridDensity density;
    const float viewDistance = 4000.0f;
    for (float pitch : {-89.0f, 89.0f, -75.0f})
        EXPECT_GE(computeTerrainWedge(viewWithPitch(0, pitch), density, viewDistance).halfWidth, float(M_PI) - 1e-6f)
            << "pitch " << pitch;
    TerrainWedge level = computeTerrainWedge(viewWithPitch(0, 0), density, viewDistance);
    EXPECT_LT(level.halfWidth, float(M_PI) / 2 + 0.2f);
    for (float yaw : {-170.0f, -30.0f, 0.0f, 45.0f, 120.0f}) {
        for (float pitch : {-40.0f, -10.0f, 0.0f, 20.0f}) {
            CameraView view = viewWithPitch(yaw, pitch);
            TerrainWedge wedge = computeTerrainWedge(view, density, viewDistance);
            for (glm::vec3 ray : view.cornerRays()) {
                float azimuth = std::atan2(ray.x, -ray.z);  // same convention as yaw
                float offset = std::remainder(azimuth - wedge.centralAzimuth, 2.0f * float(M_PI));
                EXPECT_LE(std::fabs(offset), wedge.halfWidth) << "yaw " << yaw << " pitch " << pitch;
            }
        }
    }
    // Rings 1..rings-1 grow geometrically from the first radius to the view distance.
    EXPECT_NEAR(density.firstRingRadius * std::pow(level.ringRatio, float(density.rings - 1)), viewDistance,
                viewDistance * 1e-3f);
}

}  // namespace
}  // namespace oasis
