// The vegetation field on the CPU: thinning and frustum maths, deterministic placement of at
// least 20,000 plants around the default camera, density adding plants without moving any, and
// the draw lists: inside the draw distance, nothing wholly behind the camera, every near plant in
// view drawn, far plants thinned to the stated fraction, and no reflection list when none is asked.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>

#include "render/frame_setup.h"
#include "scene/vegetation.h"

namespace oasis {
namespace {

TEST(VegetationThinning, FractionIsOneThenStartOverDistanceThenZero) {
    VegetationSettings settings;
    EXPECT_EQ(drawnFraction(settings, 0.0f), 1.0f);
    EXPECT_EQ(drawnFraction(settings, settings.thinningStart), 1.0f);
    EXPECT_FLOAT_EQ(drawnFraction(settings, 2.0f * settings.thinningStart), 0.5f);
    EXPECT_FLOAT_EQ(drawnFraction(settings, settings.drawDistance), settings.thinningStart / settings.drawDistance);
    EXPECT_EQ(drawnFraction(settings, settings.drawDistance + 0.01f), 0.0f);
}

TEST(VegetationFrustum, BoxesInFrontPassBehindAndBesideFail) {
    for (DepthMapping mapping : {DepthMapping::Standard, DepthMapping::Reversed}) {
        SCOPED_TRACE(mapping == DepthMapping::Reversed ? "reversed" : "standard");
        CameraView view;  // at the origin, looking along -Z
        view.depthMapping = mapping;
        glm::mat4 vp = view.viewProjection();
        EXPECT_TRUE(boxMeetsFrustum(vp, mapping, {-1, -1, -20}, {1, 1, -10}));
        EXPECT_TRUE(boxMeetsFrustum(vp, mapping, {-1, -1, -1}, {1, 1, 1})) << "a box around the camera";
        EXPECT_FALSE(boxMeetsFrustum(vp, mapping, {-1, -1, 10}, {1, 1, 20})) << "behind";
        EXPECT_FALSE(boxMeetsFrustum(vp, mapping, {500, -1, -20}, {510, 1, -10})) << "far to the right";
        EXPECT_FALSE(boxMeetsFrustum(vp, mapping, {-1, -1, -7000}, {1, 1, -6500})) << "beyond the far plane";
        EXPECT_TRUE(boxMeetsFrustum(vp, mapping, {-1, -1, -6100}, {1, 1, -5900})) << "across the far plane";
        EXPECT_FALSE(boxMeetsFrustum(vp, mapping, {-0.01f, -0.01f, -0.2f}, {0.01f, 0.01f, -0.1f}))
            << "between the eye and the near plane";
    }
}

struct FieldFixture {
    SceneSettings scene;
    FrameSetup frame;
    VegetationField field;
    VegetationDrawList list;
    explicit FieldFixture(float density = 1.0f) {
        scene.vegetation.density = density;
        frame = prepareFrame(scene, 1280, 720);
        field.update(scene.terrain, scene.water.level, scene.vegetation, 10, frame.view.pose.position);
        field.buildDrawList(scene.vegetation, frame.view.pose.position, frame.data.viewProjection,
                            frame.view.depthMapping, true, scene.water.level, list);
    }
};

using PlantKey = std::tuple<float, float, float, float, uint32_t>;
std::set<PlantKey> keysOf(const std::vector<PlantInstance>& plants) {
    std::set<PlantKey> keys;
    for (const PlantInstance& p : plants) keys.insert({p.base.x, p.base.y, p.base.z, p.size, p.variant});
    return keys;
}

TEST(VegetationField, AtLeast20000PlantsPlacedDeterministically) {
    FieldFixture a, b;
    std::vector<PlantInstance> plants = a.field.placedPlants();
    EXPECT_GE(a.field.stats().plantsPlaced, 20000u);
    EXPECT_EQ(keysOf(plants), keysOf(b.field.placedPlants()));
    TerrainShape shape;
    for (const PlantInstance& plant : plants) {
        ASSERT_TRUE(plantCanGrowAt(shape, a.field.placement(), {plant.base.x, plant.base.z}));
        ASSERT_EQ(plant.base.y, terrainHeight(shape, {plant.base.x, plant.base.z}).x);
        ASSERT_LT(plant.variant, 10u);
    }
}

TEST(VegetationField, DoublingTheDensityKeepsEveryPlant) {
    FieldFixture single(1.0f), twice(2.0f);
    std::set<PlantKey> one = keysOf(single.field.placedPlants()), two = keysOf(twice.field.placedPlants());
    EXPECT_TRUE(std::includes(two.begin(), two.end(), one.begin(), one.end())) << "a density change moved plants";
    EXPECT_GT(two.size(), one.size() * 19 / 10);
}

TEST(VegetationField, DrawListIsCulledAndThinned) {
    FieldFixture f;
    const VegetationSettings& settings = f.scene.vegetation;
    const glm::vec3 forward = f.frame.view.pose.forward();
    const glm::dvec3 camera = f.frame.view.pose.position;
    ASSERT_EQ(f.list.instances.size(), f.list.directCount + f.list.mirroredCount);
    ASSERT_GT(f.list.directCount, 1000u);
    const float chunkReach = f.field.placement().chunkSize * 1.5f + 20.0f;  // a chunk's diagonal and sway
    std::set<std::tuple<float, float, float>> drawn;
    for (size_t i = 0; i < f.list.directCount; ++i) {
        glm::vec3 offset(f.list.instances[i].baseSize);
        ASSERT_LE(std::hypot(offset.x, offset.z), settings.drawDistance);
        ASSERT_GT(glm::dot(offset, forward), -chunkReach) << "a plant wholly behind the camera was drawn";
        drawn.insert({offset.x, offset.y, offset.z});
    }
    // Every plant whose base is in view is drawn when near; far ones in the thinned share.
    size_t nearInView = 0, nearMissing = 0, farInView = 0, farDrawn = 0;
    double expectedFar = 0.0;
    for (const PlantInstance& plant : f.field.placedPlants()) {
        glm::vec3 offset(glm::dvec3(plant.base) - camera);
        glm::vec4 clip = f.frame.data.viewProjection * glm::vec4(offset, 1.0f);
        bool inView = clip.w > 0.0f && std::fabs(clip.x) < clip.w && std::fabs(clip.y) < clip.w && clip.z < clip.w;
        if (!inView) continue;
        float distance = std::hypot(offset.x, offset.z);
        bool isDrawn = drawn.count({offset.x, offset.y, offset.z}) > 0;
        if (distance < settings.thinningStart) {
            ++nearInView;
            nearMissing += !isDrawn;
        } else if (distance > 250.0f && distance < settings.drawDistance) {
            ++farInView;
            farDrawn += isDrawn;
            expectedFar += drawnFraction(settings, distance);
        }
    }
    EXPECT_GT(nearInView, 100u);
    EXPECT_EQ(nearMissing, 0u) << "near plants in view were culled or thinned";
    ASSERT_GT(farInView, 2000u);
    double share = double(farDrawn) / double(farInView), expected = expectedFar / double(farInView);
    std::printf("[vegetation] far plants in view drawn %.3f (expected %.3f of %zu)\n", share, expected, farInView);
    EXPECT_NEAR(share, expected, 0.15 * expected);
}

TEST(VegetationField, NoReflectionListWhenNotAsked) {
    FieldFixture f;
    EXPECT_GT(f.list.mirroredCount, 0u);
    f.field.buildDrawList(f.scene.vegetation, f.frame.view.pose.position, f.frame.data.viewProjection,
                          f.frame.view.depthMapping, false, f.scene.water.level, f.list);
    EXPECT_EQ(f.list.mirroredCount, 0u);
    EXPECT_EQ(f.list.instances.size(), f.list.directCount);
}

// The reversed-z projection culls exactly what the standard one does (the same frustum).
TEST(VegetationField, ReversedDepthCullsLikeStandard) {
    FieldFixture f;
    FrameSetup reversed = prepareFrame(f.scene, 1280, 720, *findDepthConvention("reversed-z"));
    ASSERT_EQ(reversed.view.depthMapping, DepthMapping::Reversed);
    VegetationDrawList list;
    f.field.buildDrawList(f.scene.vegetation, reversed.view.pose.position, reversed.data.viewProjection,
                          reversed.view.depthMapping, true, f.scene.water.level, list);
    EXPECT_EQ(list.directCount, f.list.directCount);
    EXPECT_EQ(list.mirroredCount, f.list.mirroredCount);
    EXPECT_GT(list.directCount, 1000u);
}

}  // namespace
}  // namespace oasis
