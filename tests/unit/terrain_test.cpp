// Covers src/scene/terrain.h: height derivatives and normals, the polar grid mesh and the view wedge (with camera.h).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>

#include "scene/camera.h"
#include "scene/terrain.h"

namespace oasis {
namespace {

// Five-point central difference along one world axis; p is an integer point and h a power of
// two, so every sample is exact in float and the divisor is exactly 12h.
double fivePoint(const TerrainShape& shape, glm::vec2 p, int axis, float h) {
    auto f = [&](glm::vec2 q) { return double(terrainHeight(shape, q).x); };
    glm::vec2 a = p, b = p, c = p, d = p;
    a[axis] += h;
    b[axis] -= h;
    c[axis] += 2.0f * h;
    d[axis] -= 2.0f * h;
    return (8.0 * (f(a) - f(b)) - (f(c) - f(d))) / (12.0 * double(h));
}

double wrapAngle(double a) {
    while (a > M_PI) a -= 2.0 * M_PI;
    while (a < -M_PI) a += 2.0 * M_PI;
    return a;
}

// Default shape: the finest octave has a period of ~10 world units; h = 0.5 resolves it. Over
// |x|,|z| < 3000 the observed error is < 8e-3 against slopes up to ~2.6 (float rounding of the
// octave coordinates dominates); tolerance 3e-2. A missing factor such as the valley
// flattening's (1 + 2kn) or the frequency would be off by up to ~1.
TEST(TerrainHeight, DerivativesMatchFiniteDifferences) {
    TerrainShape shape;
    std::mt19937 rng(21);
    std::uniform_real_distribution<float> coord(-3000.0f, 3000.0f);
    double steepest = 0.0;
    for (int i = 0; i < 4000; ++i) {
        glm::vec2 p = glm::round(glm::vec2(coord(rng), coord(rng)));
        glm::vec3 h = terrainHeight(shape, p);
        ASSERT_NEAR(h.y, fivePoint(shape, p, 0, 0.5f), 3e-2) << "dh/dx at " << p.x << "," << p.y;
        ASSERT_NEAR(h.z, fivePoint(shape, p, 1, 0.5f), 3e-2) << "dh/dz at " << p.x << "," << p.y;
        steepest = std::max(steepest, double(std::hypot(h.y, h.z)));
    }
    EXPECT_GT(steepest, 1.0);  // the sample includes real slopes, not only flat ground
}

TEST(TerrainHeight, DerivativesMatchForOtherShapes) {
    TerrainShape shape;
    shape.frequency = 1.0f / 128.0f;
    shape.amplitude = 10.0f;
    shape.baseHeight = -2.0f;
    shape.octaves = 3;
    std::mt19937 rng(22);
    std::uniform_real_distribution<float> coord(-500.0f, 500.0f);
    for (int i = 0; i < 4000; ++i) {
        glm::vec2 p = glm::round(glm::vec2(coord(rng), coord(rng)));
        glm::vec3 h = terrainHeight(shape, p);
        ASSERT_NEAR(h.y, fivePoint(shape, p, 0, 0.5f), 1e-2) << p.x << "," << p.y;
        ASSERT_NEAR(h.z, fivePoint(shape, p, 1, 0.5f), 1e-2) << p.x << "," << p.y;
    }
}

TEST(TerrainHeight, BaseHeightShiftsOnlyTheValue) {
    TerrainShape a, b;
    b.baseHeight = a.baseHeight + 17.0f;
    for (int i = 0; i < 100; ++i) {
        glm::vec2 p(37.0f * float(i) - 1500.0f, 11.0f * float(i));
        glm::vec3 ha = terrainHeight(a, p), hb = terrainHeight(b, p);
        EXPECT_NEAR(hb.x - ha.x, 17.0f, 1e-4f);
        EXPECT_EQ(ha.y, hb.y);
        EXPECT_EQ(ha.z, hb.z);
    }
}

TEST(TerrainNormal, UnitLengthAndPerpendicularToTheSurface) {
    TerrainShape shape;
    std::mt19937 rng(23);
    std::uniform_real_distribution<float> coord(-3000.0f, 3000.0f);
    for (int i = 0; i < 2000; ++i) {
        glm::vec2 p = glm::round(glm::vec2(coord(rng), coord(rng)));
        glm::vec3 n = terrainNormal(shape, p);
        glm::vec3 h = terrainHeight(shape, p);
        ASSERT_NEAR(glm::length(n), 1.0f, 1e-6f);
        ASSERT_GT(n.y, 0.0f);  // a heightfield's normal faces up
        // Perpendicular to both tangents (1, dh/dx, 0) and (0, dh/dz, 1) of the analytic gradient...
        ASSERT_NEAR(glm::dot(n, glm::vec3(1.0f, h.y, 0.0f)), 0.0f, 1e-6f);
        ASSERT_NEAR(glm::dot(n, glm::vec3(0.0f, h.z, 1.0f)), 0.0f, 1e-6f);
        // ...and of the finite-difference slopes (tolerance as in DerivativesMatchFiniteDifferences).
        glm::vec3 tx(1.0f, float(fivePoint(shape, p, 0, 0.5f)), 0.0f);
        glm::vec3 tz(0.0f, float(fivePoint(shape, p, 1, 0.5f)), 1.0f);
        ASSERT_NEAR(glm::dot(n, tx), 0.0f, 3e-2f) << p.x << "," << p.y;
        ASSERT_NEAR(glm::dot(n, tz), 0.0f, 3e-2f) << p.x << "," << p.y;
    }
}

TEST(TerrainGrid, ExactCountsAndRanges) {
    for (TerrainGridDensity density : {TerrainGridDensity{}, TerrainGridDensity{1, 1, 0.5f},
                                       TerrainGridDensity{7, 3, 1.0f}, TerrainGridDensity{40, 64, 0.25f}}) {
        GridMesh mesh = buildTerrainGrid(density);
        const size_t rings = size_t(density.rings), segments = size_t(density.segments);
        ASSERT_EQ(mesh.vertices.size(), (rings + 1) * (segments + 1));
        ASSERT_EQ(mesh.indices.size(), rings * segments * 6);
        for (uint32_t index : mesh.indices) ASSERT_LT(index, mesh.vertices.size());
        std::set<std::pair<float, float>> distinct;
        for (glm::vec2 v : mesh.vertices) {
            ASSERT_GE(v.x, 0.0f);
            ASSERT_LE(v.x, 1.0f);
            ASSERT_GE(v.y, 0.0f);
            ASSERT_LE(v.y, 1.0f);
            distinct.insert({v.x, v.y});
        }
        EXPECT_EQ(distinct.size(), mesh.vertices.size()) << "duplicate grid vertices";
        // The corners of the unit square are all present (the grid spans the full range).
        for (auto corner : {std::pair{0.0f, 0.0f}, {1.0f, 0.0f}, {0.0f, 1.0f}, {1.0f, 1.0f}})
            EXPECT_EQ(distinct.count(corner), 1u);
    }
}

TEST(TerrainGrid, TrianglesAreNonDegenerateCounterClockwiseFromAboveAndCoverEachCellOnce) {
    TerrainGridDensity density{12, 10, 0.25f};
    GridMesh mesh = buildTerrainGrid(density);
    // Map (ring fraction, segment fraction) to a flat polar layout the way terrain.vert does
    // (radius grows with ring, azimuth with segment; x = r sin(az), z = -r cos(az)), then check
    // orientation seen from +Y: counter-clockwise in (x, -z) means a positive cross product.
    auto place = [](glm::vec2 g) {
        float radius = 1.0f + g.x;
        float azimuth = (2.0f * g.y - 1.0f) * 0.8f;
        return glm::vec2(radius * std::sin(azimuth), -radius * std::cos(azimuth));
    };
    double area = 0.0;
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        glm::vec2 a = place(mesh.vertices[mesh.indices[t]]), b = place(mesh.vertices[mesh.indices[t + 1]]),
                  c = place(mesh.vertices[mesh.indices[t + 2]]);
        // Seen from above (+Y, looking down -Y) with x right: screen "up" is -z.
        glm::vec2 sa(a.x, -a.y), sb(b.x, -b.y), sc(c.x, -c.y);
        double cross = double(sb.x - sa.x) * double(sc.y - sa.y) - double(sb.y - sa.y) * double(sc.x - sa.x);
        ASSERT_GT(cross, 0.0) << "triangle " << t / 3 << " is clockwise or degenerate seen from above";
        area += 0.5 * cross;
    }
    // The triangles tile the annular sector exactly: area = 0.5 * (R^2 - r^2) * angle.
    double expected = 0.5 * (4.0 - 1.0) * 1.6;
    EXPECT_NEAR(area, expected, 0.02 * expected);
}

TEST(TerrainGrid, IndicesRunNearToFar) {
    GridMesh mesh = buildTerrainGrid(TerrainGridDensity{20, 16, 0.25f});
    float previousNearest = -1.0f;
    for (size_t t = 0; t < mesh.indices.size(); t += 3) {
        float nearest = std::min({mesh.vertices[mesh.indices[t]].x, mesh.vertices[mesh.indices[t + 1]].x,
                                  mesh.vertices[mesh.indices[t + 2]].x});
        ASSERT_GE(nearest, previousNearest) << "triangle " << t / 3;
        previousNearest = nearest;
    }
}

CameraView viewWith(float yaw, float pitch, float aspect = 16.0f / 9.0f, float fov = 60.0f) {
    CameraView view;
    view.pose.position = glm::dvec3(100.0, 50.0, -30.0);
    view.pose.yawDegrees = yaw;
    view.pose.pitchDegrees = pitch;
    view.aspect = aspect;
    view.projection.verticalFovDegrees = fov;
    return view;
}

TEST(TerrainWedge, FullCircleWhenLookingSteeplyUpOrDown) {
    TerrainGridDensity density;
    for (float yaw : {0.0f, 37.0f, 90.0f, -135.0f, 270.0f}) {
        for (float pitch : {-89.0f, 89.0f, -89.9f, 89.9f}) {
            TerrainWedge wedge = computeTerrainWedge(viewWith(yaw, pitch), density, 5000.0f);
            EXPECT_GE(wedge.halfWidth, float(M_PI)) << "yaw " << yaw << " pitch " << pitch;
            EXPECT_LE(wedge.halfWidth, float(M_PI)) << "documented as at most pi";
        }
    }
}

TEST(TerrainWedge, LevelViewWithDefaultProjectionIsNarrow) {
    TerrainGridDensity density;
    const double margin = 0.12;  // the slack the header's "widened to the frustum's footprint" allows
    for (float yaw : {0.0f, 45.0f, 90.0f, 180.0f, -60.0f}) {
        CameraView view = viewWith(yaw, 0.0f);
        TerrainWedge wedge = computeTerrainWedge(view, density, 5000.0f);
        // The frustum's half-angle across is atan(tan(30 deg) * 16/9) = 45.8 deg.
        double halfFov = std::atan(std::tan(M_PI / 6.0) * 16.0 / 9.0);
        EXPECT_GE(wedge.halfWidth, halfFov - 1e-5);
        EXPECT_LT(wedge.halfWidth, M_PI / 2.0 + margin);
        EXPECT_LE(wedge.halfWidth, halfFov + margin + 1e-5);
        EXPECT_NEAR(wrapAngle(wedge.centralAzimuth - view.pose.yawRadians()), 0.0, 1e-6);
    }
}

TEST(TerrainWedge, ContainsTheAzimuthOfEveryFrustumCorner) {
    TerrainGridDensity density;
    std::mt19937 rng(24);
    std::uniform_real_distribution<float> yaw(-360.0f, 360.0f), pitch(-89.9f, 89.9f), aspect(0.3f, 3.5f),
        fov(20.0f, 110.0f);
    int partial = 0;
    for (int i = 0; i < 20000; ++i) {
        CameraView view = viewWith(yaw(rng), pitch(rng), aspect(rng), fov(rng));
        TerrainWedge wedge = computeTerrainWedge(view, density, 6000.0f);
        ASSERT_GT(wedge.halfWidth, 0.0f);
        ASSERT_LE(wedge.halfWidth, float(M_PI));
        if (wedge.halfWidth < float(M_PI)) ++partial;
        for (glm::vec3 ray : view.cornerRays()) {
            if (std::hypot(ray.x, ray.z) < 1e-6f) continue;  // straight up or down: any azimuth
            // Azimuth convention: 0 = -Z, pi/2 = +X.
            double azimuth = std::atan2(double(ray.x), -double(ray.z));
            double relative = wrapAngle(azimuth - double(wedge.centralAzimuth));
            ASSERT_LE(std::fabs(relative), double(wedge.halfWidth) + 1e-5)
                << "yaw " << view.pose.yawDegrees << " pitch " << view.pose.pitchDegrees << " aspect "
                << view.aspect << " fov " << view.projection.verticalFovDegrees;
        }
    }
    EXPECT_GT(partial, 5000);  // most random views exercise the partial wedge, not only the full circle
}

// Ring 0 is the point under the camera; rings 1..rings sit at firstRingRadius * ratio^(ring - 1)
// (terrain.h, terrain.vert), so the outermost ring reaches the view distance when
// ratio^(rings - 1) = viewDistance / firstRingRadius.
TEST(TerrainWedge, RingRatioSpansFirstRingToViewDistance) {
    for (TerrainGridDensity density : {TerrainGridDensity{}, TerrainGridDensity{10, 8, 1.0f},
                                       TerrainGridDensity{300, 64, 0.1f}, TerrainGridDensity{2, 4, 3.0f}}) {
        for (float viewDistance : {500.0f, 3000.0f, 6000.0f}) {
            TerrainWedge wedge = computeTerrainWedge(viewWith(30.0f, -10.0f), density, viewDistance);
            ASSERT_GT(wedge.ringRatio, 1.0f);
            double outer = double(density.firstRingRadius) * std::pow(double(wedge.ringRatio), double(density.rings - 1));
            EXPECT_NEAR(outer / double(viewDistance), 1.0, 1e-3) << density.rings << " rings to " << viewDistance;
        }
    }
}

}  // namespace
}  // namespace oasis
