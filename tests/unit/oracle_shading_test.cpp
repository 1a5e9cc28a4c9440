// The shading oracle's CPU shading (check/oracle_shading.h) and sun shadow
// (check/oracle_shadow.h) on values worked out by hand: the sun overhead on a flat surface, a
// specular lobe at 22.5 degrees, the point lights' falloff, water and fog, and the shadow maps'
// answers (lit, shadowed, and the penumbra and depth tie the oracle leaves out).
#include <gtest/gtest.h>

#include <cmath>

#include "check/oracle_shading.h"
#include "check/oracle_shadow.h"

namespace oasis {
namespace {

// A frame with the sun overhead, grey sky, the camera 10 above the water, fog far away.
FrameData overheadSun() {
    FrameData f{};
    f.cameraPosition = glm::vec4(0.0f, 10.0f, 0.0f, 0.0f);
    f.sunDirection = glm::vec4(0.0f, 1.0f, 0.0f, 1.0f);
    f.sunRadiance = glm::vec4(2.0f, 2.0f, 2.0f, 0.0f);
    f.skyZenith = glm::vec4(0.2f, 0.4f, 0.8f, 0.0f);
    f.skyHorizon = glm::vec4(0.6f, 0.6f, 0.6f, 0.0f);
    f.groundAmbient = glm::vec4(0.1f, 0.1f, 0.1f, 0.0f);
    f.terrainGridCounts = glm::vec4(0.0f, 0.0f, 1000.0f, 2000.0f);
    f.water = glm::vec4(0.0f, 0.09f, 1.0f, 0.0f);
    return f;
}

OracleSurface flatGround() {
    OracleSurface s;
    s.albedo = glm::dvec3(0.5);
    s.normal = glm::dvec3(0.0, 1.0, 0.0);
    s.relativePosition = glm::dvec3(0.0, -5.0, -5.0);  // 5 below the eye, above the water
    s.specularPower = 1.0;
    s.specularIntensity = 0.0;
    return s;
}

TEST(OracleShading, SunOverheadOnFlatGround) {
    SurfaceTerms t = oracleShadeSurface(overheadSun(), flatGround(), 1.0, 0);
    EXPECT_DOUBLE_EQ(t.diffuse, 1.0);
    EXPECT_DOUBLE_EQ(t.diffusePart.x, 1.0);  // 0.5 x 2 x 1
    // n.y = 1: the ambient is the sky's alone, halfway between horizon and zenith.
    EXPECT_NEAR(t.ambient.x, 0.4, 1e-7);
    EXPECT_NEAR(t.ambient.z, 0.7, 1e-7);
    EXPECT_DOUBLE_EQ(t.specular, 0.0);
    EXPECT_DOUBLE_EQ(t.underLength, 0.0);
    EXPECT_DOUBLE_EQ(t.fog, 0.0);
    EXPECT_NEAR(t.surface.x, 1.0 + 0.5 * 0.4, 1e-7);
    EXPECT_NEAR(t.surface.z, 1.0 + 0.5 * 0.7, 1e-7);
}

TEST(OracleShading, ShadowScalesTheSunOnly) {
    SurfaceTerms t = oracleShadeSurface(overheadSun(), flatGround(), 0.0, 0);
    EXPECT_DOUBLE_EQ(t.diffusePart.x, 0.0);
    EXPECT_NEAR(t.surface.x, 0.5 * 0.4, 1e-7);
}

TEST(OracleShading, SpecularLobeAtTwentyTwoAndAHalfDegrees) {
    OracleSurface s = flatGround();
    s.specularIntensity = 1.0;
    // The eye 45 degrees above the surface, the sun overhead: the halfway vector is 22.5 degrees off.
    SurfaceTerms t = oracleShadeSurface(overheadSun(), s, 1.0, 0);
    EXPECT_NEAR(t.nDotH, std::cos(M_PI / 8.0), 1e-12);
    EXPECT_NEAR(t.normalisation, 9.0 / 25.13274, 1e-12);
    EXPECT_NEAR(t.specular, 9.0 / 25.13274 * std::cos(M_PI / 8.0), 1e-12);
    EXPECT_NEAR(t.specularPart.y, 2.0 * t.specular, 1e-12);
}

TEST(OracleShading, FogAndWater) {
    FrameData f = overheadSun();
    OracleSurface s = flatGround();
    s.relativePosition = glm::dvec3(0.0, -20.0, 0.0);  // 10 under the water, straight down
    SurfaceTerms t = oracleShadeSurface(f, s, 1.0, 0);
    EXPECT_NEAR(t.underLength, 10.0, 1e-12);
    EXPECT_NEAR(t.waterCrossed.x, std::exp(-0.09 * 10.0), 1e-7);
    EXPECT_NEAR(t.waterCrossed.z, std::exp(-0.09 * 10.0 * 0.3), 1e-7);
    s.relativePosition = glm::dvec3(0.0, -5.0, -1500.0);  // halfway through the fog
    t = oracleShadeSurface(f, s, 1.0, 0);
    EXPECT_NEAR(t.fog, 0.5, 1e-4);
}

TEST(OracleShading, PointLightFalloffAndShare) {
    EXPECT_DOUBLE_EQ(oraclePointLightFalloff(0.0, 10.0), 1.0);
    EXPECT_DOUBLE_EQ(oraclePointLightFalloff(5.0, 10.0), 0.9375 * 0.9375 / 26.0);
    EXPECT_DOUBLE_EQ(oraclePointLightFalloff(10.0, 10.0), 0.0);
    FrameData f = overheadSun();
    OracleSurface s = flatGround();
    PointLight above{glm::vec4(0.0f, -3.0f, -5.0f, 10.0f), glm::vec4(1.0f, 0.5f, 0.25f, 4.0f)};  // 2 above the surface
    glm::dvec3 share = oraclePointLightRadiance(f, s, above);
    double irradiance = 4.0 * oraclePointLightFalloff(2.0, 10.0);
    EXPECT_NEAR(share.x, 0.5 * 1.0 * irradiance, 1e-6);
    EXPECT_NEAR(share.z, 0.5 * 0.25 * irradiance, 1e-6);
    PointLight below{glm::vec4(0.0f, -7.0f, -5.0f, 10.0f), glm::vec4(1.0f)};  // under the surface: no light
    EXPECT_EQ(oraclePointLightRadiance(f, s, below), glm::dvec3(0.0));
    PixelShading pixel = oracleShadePixel(f, s, 1.0, 0, {below, above});
    ASSERT_EQ(pixel.lights.size(), 1u);
    EXPECT_EQ(pixel.lights[0].index, 1);
    std::vector<NamedTerm> terms = oracleNamedTerms(pixel);
    EXPECT_EQ(terms.back().name, "radiance");
    EXPECT_EQ(terms[terms.size() - 2].name, "light 1");
    EXPECT_NEAR(terms.back().values[0], pixel.surface.surface.x + share.x, 1e-12);
}

// One 8x8 cascade over the clip cube scaled by 10: the point (0, 0, 0) with normal +z lands at the
// map's centre at depth 0.575 - 0.125 (the depth bias).
struct OneCascade {
    FrameData frame = overheadSun();
    ShadowMapDepths maps;
    OneCascade(float left, float right) {
        frame.shadow = glm::vec4(1.0f, 1.0f, 1000.0f, 2000.0f);
        frame.shadowMatrices[0] = glm::mat4(0.1f);
        frame.shadowMatrices[0][3][3] = 1.0f;
        frame.shadowTexel = glm::vec4(1.0f);
        frame.shadowDepthRange = glm::vec4(8.0f);
        maps.size = 8;
        maps.layers = 1;
        for (int t = 0; t < 8; ++t)
            for (int s = 0; s < 8; ++s) maps.depths.push_back(s < 4 ? left : right);
    }
    OracleSunShadow at(glm::dvec3 position) const { return oracleSunShadow(frame, maps, position, glm::dvec3(0.0, 0.0, 1.0)); }
};

TEST(OracleShadow, LitShadowedPenumbraAndTie) {
    OracleSunShadow lit = OneCascade(1.0f, 1.0f).at(glm::dvec3(0.0));
    EXPECT_TRUE(lit.leftOut.empty());
    EXPECT_DOUBLE_EQ(lit.lit, 1.0);
    EXPECT_EQ(lit.cascade, 0);
    OracleSunShadow shadowed = OneCascade(0.2f, 0.2f).at(glm::dvec3(0.0));
    EXPECT_TRUE(shadowed.leftOut.empty());
    EXPECT_DOUBLE_EQ(shadowed.lit, 0.0);
    EXPECT_EQ(OneCascade(0.2f, 1.0f).at(glm::dvec3(0.0)).leftOut, kShadowPenumbra);
    EXPECT_EQ(OneCascade(0.45f, 0.45f).at(glm::dvec3(0.0)).leftOut, kShadowDepthTie);
    // Past the cascade's margin (clip x beyond 1 - 4/8) no cascade holds it: full sun.
    OracleSunShadow outside = OneCascade(0.2f, 0.2f).at(glm::dvec3(8.0, 0.0, 0.0));
    EXPECT_EQ(outside.cascade, -1);
    EXPECT_DOUBLE_EQ(outside.lit, 1.0);
    EXPECT_EQ(OneCascade(0.2f, 0.2f).at(glm::dvec3(5.0, 0.0, 0.0)).leftOut, kShadowCascadeEdge);
}

}  // namespace
}  // namespace oasis
