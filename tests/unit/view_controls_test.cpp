// The view controls on the CPU: channel choice per view, value statistics (NaN, infinities and
// negatives counted, the finite range), the fitted range, the linear mapping to grey and the
// overlay's checkers.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>

#include "debug/debug_views.h"
#include "debug/view_controls.h"

namespace oasis {
namespace {

constexpr float kNan = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

TEST(ViewControls, ChannelsParseAndEachViewOffersOnlyWhatItFills) {
    ViewChannel channel;
    for (const char* name : {"rgb", "r", "g", "b", "a", "luminance"}) {
        ASSERT_TRUE(parseViewChannel(name, channel)) << name;
        EXPECT_STREQ(viewChannelName(channel), name);
    }
    EXPECT_FALSE(parseViewChannel("alpha", channel));
    EXPECT_FALSE(parseViewChannel("", channel));
    const DebugView& stencil = *findDebugView("stencil");
    EXPECT_TRUE(viewHasChannel(stencil, ViewChannel::R));
    for (ViewChannel missing : {ViewChannel::G, ViewChannel::B, ViewChannel::A, ViewChannel::Rgb, ViewChannel::Luminance})
        EXPECT_FALSE(viewHasChannel(stencil, missing)) << viewChannelName(missing);
    EXPECT_TRUE(viewHasChannel(*findDebugView("position"), ViewChannel::A));
    EXPECT_EQ(describeChannel(*findDebugView("position"), ViewChannel::A), "a (distance)");
    EXPECT_EQ(defaultChannel(stencil), ViewChannel::R);
    EXPECT_EQ(defaultChannel(*findDebugView("normal")), ViewChannel::Rgb);
    // Every view names the values it fills, at most four.
    for (const DebugView& view : debugViews()) {
        EXPECT_GE(view.values.size(), 1u) << view.name;
        EXPECT_LE(view.values.size(), 4u) << view.name;
    }
}

TEST(ViewControls, OverlayListsParse) {
    unsigned bits = 0;
    ASSERT_TRUE(parseOverlay("nan,inf,negative", bits));
    EXPECT_EQ(bits, unsigned(kOverlayNan | kOverlayInfinity | kOverlayNegative));
    ASSERT_TRUE(parseOverlay("none", bits));
    EXPECT_EQ(bits, 0u);
    EXPECT_FALSE(parseOverlay("nan,", bits));
    EXPECT_FALSE(parseOverlay("", bits));
    EXPECT_FALSE(parseOverlay("zero", bits));
    EXPECT_EQ(overlayNames(kOverlayNan | kOverlayNegative), "nan,negative");
}

TEST(ViewControls, StatisticsCountNonFiniteAndNegativeValuesAndFitTheFiniteRange) {
    // Four pixels: (1, -2, 3, 9), (NaN, 4, inf, 9), (-inf, 0.5, 0, 9), (2, 2, 2, 9).
    std::vector<float> rgba = {1, -2, 3, 9, kNan, 4, kInf, 9, -kInf, 0.5f, 0, 9, 2, 2, 2, 9};
    ValueStatistics rgb = valueStatistics(rgba, ViewChannel::Rgb);
    EXPECT_EQ(rgb.values, 12);
    EXPECT_EQ(rgb.nan, 1);
    EXPECT_EQ(rgb.positiveInfinity, 1);
    EXPECT_EQ(rgb.negativeInfinity, 1);
    EXPECT_EQ(rgb.negative, 1);
    EXPECT_EQ(rgb.min, -2.0);
    EXPECT_EQ(rgb.max, 4.0);
    ValueStatistics alpha = valueStatistics(rgba, ViewChannel::A);
    EXPECT_EQ(alpha.values, 4);
    EXPECT_EQ(alpha.nan + alpha.positiveInfinity + alpha.negativeInfinity + alpha.negative, 0);
    // Flat values widen to a unit span; a given range wins.
    auto [low, high] = rangeInUse(ViewControls{}, alpha);
    EXPECT_EQ(low, 9.0);
    EXPECT_EQ(high, 10.0);
    ViewControls given;
    given.range = std::pair{-1.0, 1.0};
    EXPECT_EQ(rangeInUse(given, rgb), std::make_pair(-1.0, 1.0));
    // No finite value at all.
    ValueStatistics none = valueStatistics({kNan, kNan, kNan, kNan}, ViewChannel::R);
    EXPECT_FALSE(none.anyFinite);
    EXPECT_EQ(none.nan, 1);
}

TEST(ViewControls, MappingIsLinearInTheRangeAndTheOverlayPaintsCheckers) {
    // 4x2 values, bottom row first: r = 0, 0.25, 0.5, 1 (bottom), then NaN, inf, -inf, -0.5 (top).
    std::vector<float> rgba = {0, 0, 0, 1, 0.25f, 0, 0, 1, 0.5f, 0, 0, 1, 1, 0, 0, 1,
                               kNan, 0, 0, 1, kInf, 0, 0, 1, -kInf, 0, 0, 1, -0.5f, 0, 0, 1};
    Image image = mapViewValues(rgba, 4, 2, ViewChannel::R, {0.0, 1.0}, kOverlayNan | kOverlayInfinity | kOverlayNegative);
    // The image is top row first: the bottom GL row is image row 1.
    EXPECT_EQ(image.pixel(0, 1)[0], 0);
    EXPECT_EQ(image.pixel(1, 1)[0], 64);
    EXPECT_EQ(image.pixel(2, 1)[1], 128);  // grey: every channel the same
    EXPECT_EQ(image.pixel(3, 1)[2], 255);
    auto is = [&](int x, int y, std::array<uint8_t, 3> rgb) {
        const uint8_t* p = image.pixel(x, y);
        return p[0] == rgb[0] && p[1] == rgb[1] && p[2] == rgb[2];
    };
    // GL row 1 (image row 0), x / 2 + y / 2 = 0 for x < 2: the checker's first colour, magenta.
    EXPECT_TRUE(is(0, 0, {255, 0, 255}));  // NaN
    EXPECT_TRUE(is(1, 0, {255, 0, 255}));  // +Inf
    EXPECT_TRUE(is(2, 0, {128, 128, 128}));  // -Inf: second colour at x / 2 = 1
    EXPECT_TRUE(is(3, 0, {0, 255, 255}));    // negative: cyan
    // Without the overlay the same values map: NaN black, +Inf white, -Inf and -0.5 black.
    Image plain = mapViewValues(rgba, 4, 2, ViewChannel::R, {0.0, 1.0}, 0);
    EXPECT_EQ(plain.pixel(0, 0)[0], 0);
    EXPECT_EQ(plain.pixel(1, 0)[0], 255);
    EXPECT_EQ(plain.pixel(3, 0)[0], 0);
    // Luminance is Rec. 709.
    std::vector<float> white = {1, 1, 1, 1};
    EXPECT_NEAR(valueStatistics(white, ViewChannel::Luminance).max, 1.0, 1e-6);
}

}  // namespace
TEST(ViewControls, TheOverlayInARectanglePaintsWhereTheRectangleSamplesTheFrame) {
    // A 4x2 frame (bottom row first) with one NaN at texel (2, 1): the top row, third column.
    const int frameWidth = 4, frameHeight = 2;
    std::vector<float> rgba(size_t(frameWidth * frameHeight) * 4, 0.5f);
    rgba[(size_t(1) * frameWidth + 2) * 4] = std::numeric_limits<float>::quiet_NaN();
    Image image(12, 6);
    for (uint8_t& byte : image.rgba) byte = 7;
    // Shown at twice the size in the rectangle x 3..10, y 1..4 (from the top).
    paintOverlayIn(image, {3, 1, 8, 4}, rgba, frameWidth, frameHeight, ViewChannel::R, kOverlayNan);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            bool inTexel = x >= 3 + 4 && x < 3 + 6 && y >= 1 && y < 3;  // the texel's 2x2 pixels, top half
            const uint8_t* p = image.pixel(x, y);
            EXPECT_EQ(p[0] != 7 || p[1] != 7 || p[2] != 7, inTexel) << "pixel " << x << "," << y;
        }
}

}  // namespace oasis
