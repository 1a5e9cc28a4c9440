// The check's split of a frame into edges and interiors (check/pixel_classes.h) on synthetic
// geometry, whose edges are known: a tiltedGround plane has none, a step, a crease, a silhouette, a
// plant and the water's outline each make a band of edges one pixel wide on either side; and the
// interior rule (check/check_judge.h) judges interior pixels only.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "check/check_judge.h"
#include "check/pixel_classes.h"

namespace oasis {
namespace {

constexpr int kClassWidth = 32, kClassHeight = 24;

// A plane seen by a pinhole camera: distance along each pixel's ray to the plane n.p = d.
float rayToPlane(int x, int y, double nx, double ny, double nz, double d) {
    double rx = (x + 0.5 - kClassWidth / 2.0) / kClassWidth, ry = (y + 0.5 - kClassHeight / 2.0) / kClassWidth, rz = 1.0;
    double length = std::sqrt(rx * rx + ry * ry + rz * rz);
    return float(d / ((nx * rx + ny * ry + nz * rz) / length));
}

// Geometry filled by `at(x, y, surface, distance, normal)`.
PixelGeometry geometryOf(const std::function<void(int, int, uint8_t&, float&, float*)>& at) {
    PixelGeometry g;
    g.width = kClassWidth;
    g.height = kClassHeight;
    g.surface.assign(kClassWidth * kClassHeight, 0);
    g.distance.assign(kClassWidth * kClassHeight, 0.0f);
    g.normal.assign(3 * kClassWidth * kClassHeight, 0.0f);
    for (int y = 0; y < kClassHeight; ++y)
        for (int x = 0; x < kClassWidth; ++x) {
            size_t p = size_t(y) * kClassWidth + size_t(x);
            at(x, y, g.surface[p], g.distance[p], &g.normal[3 * p]);
        }
    return g;
}

void tiltedGround(int x, int y, uint8_t&, float& distance, float* normal) {
    distance = rayToPlane(x, y, 0.0, 0.8, 0.6, 10.0);  // a ground plane seen at a slant
    normal[1] = 0.8f;
    normal[2] = 0.6f;
}

long interiorCount(const std::vector<uint8_t>& classes) {
    long count = 0;
    for (uint8_t c : classes) count += c == 0;
    return count;
}

uint8_t classAt(const std::vector<uint8_t>& classes, int x, int y) { return classes[size_t(y) * kClassWidth + size_t(x)]; }

TEST(PixelClasses, ATiltedPlaneIsAllInterior) {
    std::vector<uint8_t> classes = classifyPixels(geometryOf(tiltedGround));
    EXPECT_EQ(interiorCount(classes), long(kClassWidth) * kClassHeight) << pixelClassSummary(classes);
}

TEST(PixelClasses, ADepthStepIsAnEdgeOnePixelEitherSide) {
    // Two parallel planes facing the camera, the right half 30% further: a step at x = 16.
    std::vector<uint8_t> classes = classifyPixels(geometryOf([](int x, int, uint8_t&, float& distance, float* normal) {
        distance = x < 16 ? 10.0f : 13.0f;
        normal[2] = 1.0f;
    }));
    for (int y = 0; y < kClassHeight; ++y) {
        EXPECT_TRUE(classAt(classes, 15, y) & kEdgeDepth) << y;
        EXPECT_TRUE(classAt(classes, 16, y) & kEdgeDepth) << y;
        EXPECT_EQ(classAt(classes, 14, y), kEdgeNear) << y;  // the dilation
        EXPECT_EQ(classAt(classes, 17, y), kEdgeNear) << y;
        EXPECT_EQ(classAt(classes, 13, y), 0) << y;
        EXPECT_EQ(classAt(classes, 18, y), 0) << y;
    }
    EXPECT_EQ(interiorCount(classes), long(kClassWidth - 4) * kClassHeight);
}

TEST(PixelClasses, ACreaseIsAnEdgeAndAGentleBendIsNot) {
    // A roof: the left half's normal leans 30 degrees one way, the right half's the other way (a crease
    // of 60 degrees); then the same with 10 degrees between them, under the crease angle.
    for (double degrees : {30.0, 5.0}) {
        double s = std::sin(degrees * M_PI / 180.0), c = std::cos(degrees * M_PI / 180.0);
        std::vector<uint8_t> classes = classifyPixels(geometryOf([&](int x, int, uint8_t&, float& distance, float* normal) {
            distance = 10.0f;
            normal[0] = float(x < 16 ? -s : s);
            normal[2] = float(c);
        }));
        if (degrees > 20.0) {
            EXPECT_TRUE(classAt(classes, 15, 5) & kEdgeNormal);
            EXPECT_TRUE(classAt(classes, 16, 5) & kEdgeNormal);
            EXPECT_EQ(interiorCount(classes), long(kClassWidth - 4) * kClassHeight);
        } else {
            EXPECT_EQ(interiorCount(classes), long(kClassWidth) * kClassHeight) << pixelClassSummary(classes);
        }
    }
}

TEST(PixelClasses, TheSkyMeetingTheGroundIsASilhouetteAndTheSkyItselfInterior) {
    std::vector<uint8_t> classes = classifyPixels(geometryOf([](int x, int y, uint8_t& surface, float& distance, float* normal) {
        if (y < 10) {
            surface = kPixelSky;
            return;
        }
        tiltedGround(x, y, surface, distance, normal);
    }));
    EXPECT_TRUE(classAt(classes, 3, 9) & kEdgeSilhouette);
    EXPECT_TRUE(classAt(classes, 3, 10) & kEdgeSilhouette);
    EXPECT_EQ(classAt(classes, 3, 8), kEdgeNear);
    EXPECT_EQ(classAt(classes, 3, 11), kEdgeNear);
    EXPECT_EQ(classAt(classes, 3, 7), 0);  // the sky away from the horizon: interior, where a sky too bright shows
    EXPECT_EQ(interiorCount(classes), long(kClassWidth) * (kClassHeight - 4));
}

TEST(PixelClasses, APlantIsEdgeWholeAndTheWatersOutlineIsAnEdge) {
    std::vector<uint8_t> classes = classifyPixels(geometryOf([](int x, int y, uint8_t& surface, float& distance, float* normal) {
        tiltedGround(x, y, surface, distance, normal);
        if (x >= 4 && x < 7 && y >= 4 && y < 8) surface |= kPixelPlant;  // a leaf drawn on the same plane
        if (x >= 16 && y >= 12) surface |= kPixelWater;                 // a lake in the lower right
    }));
    for (int y = 4; y < 8; ++y)
        for (int x = 4; x < 7; ++x) EXPECT_TRUE(classAt(classes, x, y) & kEdgePlant) << x << "," << y;
    EXPECT_EQ(classAt(classes, 3, 4), kEdgeNear);
    EXPECT_EQ(classAt(classes, 2, 4), 0);
    EXPECT_TRUE(classAt(classes, 15, 20) & kEdgeWater);
    EXPECT_TRUE(classAt(classes, 16, 20) & kEdgeWater);
    EXPECT_TRUE(classAt(classes, 20, 11) & kEdgeWater);
    EXPECT_EQ(classAt(classes, 20, 16), 0);  // the water's own interior
    EXPECT_EQ(classAt(classes, 13, 20), 0);
}

TEST(PixelClasses, AShadowsStepAndPenumbraAreEdgesButTheTerminatorIsNot) {
    // Facing the sun: x < 8 lit, 8..15 shadowed, 16 a penumbra pixel; x > 16 faces away from the
    // sun, with no shadow bit: the step from the penumbra's neighbours on to it is the terminator.
    std::vector<uint8_t> classes = classifyPixels(geometryOf([](int x, int y, uint8_t& surface, float& distance, float* normal) {
        tiltedGround(x, y, surface, distance, normal);
        if (x <= 16) surface |= kPixelSunFacing;
        if (x >= 8 && x < 16) surface |= kPixelShadowed;
        if (x == 16) surface |= kPixelPenumbra;
        if (x == 24) surface |= kPixelSunFacing | kPixelShadowed;  // alone, beside faces turned away
    }));
    EXPECT_TRUE(classAt(classes, 7, 3) & kEdgeShadow);
    EXPECT_TRUE(classAt(classes, 8, 3) & kEdgeShadow);
    EXPECT_EQ(classAt(classes, 5, 3), 0);
    EXPECT_EQ(classAt(classes, 11, 3), 0);  // inside the shadow: interior
    EXPECT_TRUE(classAt(classes, 16, 3) & kEdgeShadow);
    EXPECT_TRUE(classAt(classes, 15, 3) & kEdgeShadow);  // shadowed beside the penumbra's partial light
    EXPECT_EQ(classAt(classes, 17, 3), kEdgeNear);
    EXPECT_EQ(classAt(classes, 18, 3), 0);  // past the terminator
    EXPECT_EQ(classAt(classes, 24, 3), 0);  // its neighbours face away: no step to see
}

TEST(PixelClasses, MismatchedSizesAreRefused) {
    PixelGeometry g = geometryOf(tiltedGround);
    g.distance.pop_back();
    EXPECT_THROW(classifyPixels(g), std::invalid_argument);
}

TEST(PixelClasses, ClassesSurviveTheirPicture) {
    std::vector<uint8_t> classes(kClassWidth * kClassHeight, 0);
    classes[7] = kEdgeDepth | kEdgePlant;
    classes[8] = kEdgeNear;
    EXPECT_EQ(pixelClassesOf(pixelClassImage(classes, kClassWidth, kClassHeight)), classes);
}

Image greyFrame(int value) {
    Image image(kClassWidth, kClassHeight);
    for (size_t i = 0; i < image.rgba.size(); ++i) image.rgba[i] = uint8_t(i % 4 == 3 ? 255 : value);
    return image;
}

TEST(InteriorRule, JudgesInteriorPixelsOnly) {
    const ImageRule& rule = imageRule("cross-driver-interior");
    ASSERT_TRUE(rule.interiorOnly);
    std::vector<uint8_t> classes(kClassWidth * kClassHeight, 0);
    for (int y = 0; y < kClassHeight; ++y) classes[size_t(y) * kClassWidth + 5] = kEdgeDepth;  // one column of edges
    Image reference = greyFrame(100), result = reference;
    for (int y = 0; y < kClassHeight; ++y) result.pixel(5, y)[0] = 255;  // a rasteriser's edge: the rule does not look
    InteriorJudgement clean = judgeInterior(result, reference, classes, rule);
    EXPECT_TRUE(clean.pass) << clean.summary;
    EXPECT_EQ(clean.pixels, long(kClassWidth - 1) * kClassHeight);
    EXPECT_EQ(clean.maxAbs, 0);
    // One interior pixel far off: above the level, over the pixels allowed at this size.
    result.pixel(9, 9)[1] = 200;
    InteriorJudgement one = judgeInterior(result, reference, classes, rule);
    EXPECT_EQ(one.maxAbs, 100);
    EXPECT_EQ(one.pixelsOver, 1);
    EXPECT_EQ(one.meanSigned, 0.0);  // an outlier is the count's, not the mean's
    // Every interior pixel a level brighter: no pixel over the level, the mean shifted by 1.
    Image brighter = greyFrame(101);
    InteriorJudgement shifted = judgeInterior(brighter, reference, classes, rule);
    EXPECT_EQ(shifted.pixelsOver, 0);
    EXPECT_NEAR(shifted.meanSigned, 1.0, 1e-12);
    EXPECT_GT(std::fabs(shifted.meanSigned), rule.maxMeanSigned);
    EXPECT_FALSE(shifted.pass) << shifted.summary;
    EXPECT_THROW(judgeInterior(result, reference, std::vector<uint8_t>(3, 0), rule), std::invalid_argument);
}

}  // namespace
}  // namespace oasis
