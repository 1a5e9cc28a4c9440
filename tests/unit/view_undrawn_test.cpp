// The view controls with a drawn-pixel mask (issue 31, defect 1): pixels where nothing was drawn
// (the sky) count for nothing — not in the values, the range or the negatives — are drawn black
// in the values image and never overlaid.
#include <gtest/gtest.h>

#include <vector>

#include "debug/view_controls.h"

namespace oasis {
namespace {

// Two pixels: a drawn surface (g 0.25) and the sky's cleared texel (g -1: what a cleared or
// never-written target may hold there).
const std::vector<float> kValues = {0.1f, 0.25f, 0.3f, 1.0f, 0.0f, -1.0f, 0.0f, 0.0f};
const DrawnPixels kSurfaceThenSky = {1, 0};

TEST(ViewUndrawn, StatisticsAndRangeCountOnlyDrawnPixels) {
    ValueStatistics all = valueStatistics(kValues, ViewChannel::G);
    EXPECT_EQ(all.negative, 1);  // today's count without a mask: the sky's pixel
    ValueStatistics drawn = valueStatistics(kValues, ViewChannel::G, &kSurfaceThenSky);
    EXPECT_EQ(drawn.values, 1);
    EXPECT_EQ(drawn.negative, 0);
    EXPECT_EQ(drawn.undrawn, 1);
    EXPECT_DOUBLE_EQ(drawn.min, 0.25);
    EXPECT_DOUBLE_EQ(drawn.max, 0.25);
    const DrawnPixels none;  // an empty mask: every pixel counts
    EXPECT_EQ(valueStatistics(kValues, ViewChannel::G, &none).negative, 1);
}

TEST(ViewUndrawn, TheSkyIsBlackAndNeverOverlaid) {
    Image image = mapViewValues(kValues, 2, 1, ViewChannel::G, {-1.0, 1.0}, kOverlayNegative, &kSurfaceThenSky);
    const uint8_t* sky = image.pixel(1, 0);
    EXPECT_EQ(sky[0], 0);
    EXPECT_EQ(sky[1], 0);
    EXPECT_EQ(sky[2], 0);
    Image painted(2, 1);
    paintOverlay(painted, kValues, ViewChannel::G, kOverlayNegative, &kSurfaceThenSky);
    EXPECT_EQ(painted.pixel(1, 0)[0], Image(2, 1).pixel(1, 0)[0]);  // untouched
    Image unmasked(2, 1);
    paintOverlay(unmasked, kValues, ViewChannel::G, kOverlayNegative);
    EXPECT_EQ(unmasked.pixel(1, 0)[0], 255);  // the negative checker's magenta, without the mask
}

}  // namespace
}  // namespace oasis
