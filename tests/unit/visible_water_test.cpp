// The CPU bound of visible water (scene/visible_water.h) on its own: it takes hold only for an eye
// above the water and clear of the ground; a box whose mirror image lands on water the grid leaves
// below the surface may show, one standing on high ground far from any water does not; heights
// are computed as the GPU's grid places its vertices and cached while the grid stays put; and a
// plant's reach holds its billboard bent by the strongest wind.
#include <gtest/gtest.h>

#include <cmath>

#include "render/frame_setup.h"
#include "scene/visible_water.h"
#include "scene/vegetation.h"

namespace oasis {
namespace {

struct Bound {
    SceneSettings scene;
    FrameSetup frame;
    VisibleWaterBound bound;
    explicit Bound(const CameraPose& pose) {
        scene.camera = pose;
        frame = prepareFrame(scene, 1280, 720);
        bound.prepare(scene.terrain, scene.grid, frame.wedge, scene.viewDistance, frame.view, scene.water.level);
    }
};

double groundAt(double x, double z) { return terrainHeight(TerrainShape{}, glm::dvec2(x, z)).x; }

// A plant-sized box (4 units wide, 6 tall) standing on the ground at (x, z).
bool boxMayShow(VisibleWaterBound& bound, double x, double z) {
    double ground = groundAt(x, z);
    return bound.mirrorImageMayShow({x - 2.0, ground - 0.3, z - 2.0}, {x + 2.0, ground + 6.0, z + 2.0});
}

TEST(VisibleWater, TakesHoldOnlyAboveTheWaterAndClearOfTheGround) {
    // Over the lake east of the flight's start (bed about -10 at (490, 100)).
    EXPECT_TRUE(Bound(CameraPose{{490.0, 5.0, 100.0}, 30.0f, -5.0f}).bound.active());
    EXPECT_FALSE(Bound(CameraPose{{490.0, -1.0, 100.0}, 30.0f, -5.0f}).bound.active()) << "under the water";
    EXPECT_FALSE(Bound(CameraPose{{490.0, 0.0, 100.0}, 30.0f, -5.0f}).bound.active()) << "at the water";
    double ground = groundAt(210.0, -120.0);
    ASSERT_GT(ground, 1.0);
    EXPECT_TRUE(Bound(CameraPose{{210.0, ground + 2.0, -120.0}, 90.0f, -5.0f}).bound.active());
    EXPECT_FALSE(Bound(CameraPose{{210.0, ground + 0.1, -120.0}, 90.0f, -5.0f}).bound.active())
        << "the near plane could clip the ground in front of the water";
    EXPECT_FALSE(Bound(CameraPose{{210.0, ground - 3.0, -120.0}, 90.0f, -5.0f}).bound.active()) << "under the ground";
    // Inactive: every box may show.
    Bound under(CameraPose{{490.0, -1.0, 100.0}, 30.0f, -5.0f});
    EXPECT_TRUE(boxMayShow(under.bound, 210.0, -120.0));
}

TEST(VisibleWater, ImagesOnTheLakeMayShowImagesOnDryHillsDoNot) {
    // From the lake's western shore looking east over it: a plant on the far shore, whose image
    // falls on the lake between, may show.
    Bound shore(CameraPose{{435.0, 5.0, 140.0}, 90.0f, -3.0f});
    ASSERT_TRUE(shore.bound.active());
    int shown = 0, hidden = 0;
    for (double x = 560.0; x <= 700.0; x += 20.0) {
        if (groundAt(x, 140.0) <= 0.5) continue;  // under water: nothing to mirror
        (boxMayShow(shore.bound, x, 140.0) ? shown : hidden)++;
    }
    EXPECT_GT(shown, 0);
    // High on a dry hill, looking along it: images of plants further up the slope land on the slope.
    double ground = groundAt(210.0, -120.0);
    Bound hill(CameraPose{{210.0, ground + 3.0, -120.0}, 90.0f, -5.0f});
    ASSERT_TRUE(hill.bound.active());
    int dry = 0, tried = 0;
    for (double x = 230.0; x <= 300.0; x += 10.0) {
        if (groundAt(x, -120.0) < ground) continue;  // only ground that rises away from the eye
        ++tried;
        dry += boxMayShow(hill.bound, x, -120.0) ? 0 : 1;
    }
    ASSERT_GT(tried, 0);
    EXPECT_EQ(dry, tried) << "images on rising dry ground, far from water";
    EXPECT_GT(hill.bound.heightsComputed(), 0u);
}

TEST(VisibleWater, EveryAnswerIsMayShowWhereTheGridDrawsNoGround) {
    Bound shore(CameraPose{{435.0, 5.0, 140.0}, 90.0f, -3.0f});
    ASSERT_TRUE(shore.bound.active());
    // Behind the camera (outside the wedge) and beyond the view distance.
    EXPECT_TRUE(boxMayShow(shore.bound, 300.0, 140.0));
    EXPECT_TRUE(shore.bound.mirrorImageMayShow({5000.0, 10.0, 130.0}, {5004.0, 16.0, 134.0}));
    // Nothing above the water: nothing mirrored, but no claim either.
    EXPECT_TRUE(shore.bound.mirrorImageMayShow({600.0, -5.0, 130.0}, {604.0, -1.0, 134.0}));
}

TEST(VisibleWater, HeightsAreCachedWhileTheGridStaysPut) {
    double ground = groundAt(210.0, -120.0);
    CameraPose pose{{210.0, ground + 3.0, -120.0}, 90.0f, -5.0f};
    Bound hill(pose);
    const size_t byPrepare = hill.bound.heightsComputed();  // the ground around the eye
    boxMayShow(hill.bound, 260.0, -120.0);
    size_t computed = hill.bound.heightsComputed();
    ASSERT_GT(computed, byPrepare);
    // The same grid (a new height only): nothing recomputed.
    CameraPose higher = pose;
    higher.position.y += 1.0;
    hill.frame = prepareFrame(hill.scene, 1280, 720);
    FrameSetup again = hill.frame;
    again.view.pose = higher;
    hill.bound.prepare(hill.scene.terrain, hill.scene.grid, hill.frame.wedge, hill.scene.viewDistance, again.view,
                       hill.scene.water.level);
    boxMayShow(hill.bound, 260.0, -120.0);
    EXPECT_EQ(hill.bound.heightsComputed(), computed);
    // Moved sideways: the grid moved with it, every height starts again (the ground around the eye first).
    again.view.pose.position.x += 0.5;
    hill.bound.prepare(hill.scene.terrain, hill.scene.grid, hill.frame.wedge, hill.scene.viewDistance, again.view,
                       hill.scene.water.level);
    EXPECT_EQ(hill.bound.heightsComputed(), byPrepare);
}

TEST(VisibleWater, DryMarginCoversFloatsAndDepthSteps) {
    EXPECT_FLOAT_EQ(VisibleWaterBound::dryMargin(0.0f, 0.25f), 0.1f);
    // Four 24-bit depth steps at 600 units with the near plane at 0.25: 4 * 600^2 / (0.25 * 2^24).
    EXPECT_NEAR(VisibleWaterBound::dryMargin(600.0f, 0.25f), 0.1f + 4.0f * 360000.0f / (0.25f * 16777216.0f), 1e-4f);
}

TEST(PlantReach, HoldsTheBillboardBentByTheStrongestWind) {
    PlantInstance plant;
    plant.base = {10.0f, 3.0f, -4.0f};
    plant.size = 5.0f;
    ChunkBounds reach = plantReach(plant);
    // vegetation.vert: corners at base + right (x - 0.5) size + up (y - root) size + bend size y,
    // |bend| <= 0.24 strength; right is any horizontal unit vector.
    const double strength = VegetationSettings::kMaxWindStrength, root = 0.05;
    for (int i = 0; i < 64; ++i) {
        double angle = 2.0 * M_PI * i / 64.0, bendAngle = 2.0 * M_PI * ((i * 7) % 64) / 64.0;
        glm::dvec2 right(std::cos(angle), std::sin(angle)), bend = 0.24 * strength * glm::dvec2(std::cos(bendAngle), std::sin(bendAngle));
        for (double cx : {0.0, 1.0})
            for (double cy : {0.0, 1.0}) {
                glm::dvec2 xz = glm::dvec2(plant.base.x, plant.base.z) + right * ((cx - 0.5) * plant.size) + bend * (plant.size * cy);
                double y = plant.base.y + (cy - root) * plant.size;
                EXPECT_GE(xz.x, reach.low.x); EXPECT_LE(xz.x, reach.high.x);
                EXPECT_GE(xz.y, reach.low.z); EXPECT_LE(xz.y, reach.high.z);
                EXPECT_GE(y, reach.low.y); EXPECT_LE(y, reach.high.y);
            }
    }
}

}  // namespace
}  // namespace oasis
