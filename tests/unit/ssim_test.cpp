// Covers ssim() in src/render/image.h: identical images, shifts, noise, symmetry, sizes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "render/image.h"

namespace oasis {
namespace {

// A smooth, varied test card: gradients plus a few sine bands, grey (r = g = b).
Image card(int w, int h, int shiftX = 0) {
    Image image(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            int sx = x + shiftX;
            double v = 128.0 + 60.0 * std::sin(sx * 0.35) * std::cos(y * 0.22) + 0.4 * (sx - w / 2);
            uint8_t g = uint8_t(std::clamp(v, 0.0, 255.0));
            uint8_t* p = image.pixel(x, y);
            p[0] = p[1] = p[2] = g;
            p[3] = 255;
        }
    return image;
}

// Adds deterministic pseudo-random noise of the given amplitude to every channel.
Image noisy(Image image, int amplitude, uint32_t seed = 12345) {
    for (size_t i = 0; i < image.rgba.size(); ++i) {
        if (i % 4 == 3) continue;
        seed = seed * 1664525u + 1013904223u;
        int delta = int((seed >> 16) % uint32_t(2 * amplitude + 1)) - amplitude;
        image.rgba[i] = uint8_t(std::clamp(int(image.rgba[i]) + delta, 0, 255));
    }
    return image;
}

TEST(Ssim, IdenticalImagesScoreOne) {
    Image a = card(64, 48);
    EXPECT_DOUBLE_EQ(ssim(a, a), 1.0);
    Image flat(32, 32);
    EXPECT_DOUBLE_EQ(ssim(flat, flat), 1.0);  // constant images: the constants keep it defined
}

TEST(Ssim, ShiftsLowerItAndLargerShiftsLowerItMore) {
    Image a = card(64, 48);
    double one = ssim(a, card(64, 48, 1)), three = ssim(a, card(64, 48, 3));
    EXPECT_LT(one, 0.999);
    EXPECT_LT(three, one);
    EXPECT_GT(three, -1.0);
}

TEST(Ssim, NoiseLowersItMonotonically) {
    Image a = card(64, 48);
    double light = ssim(a, noisy(a, 4)), heavy = ssim(a, noisy(a, 40));
    EXPECT_LT(light, 1.0);
    EXPECT_GT(light, 0.8);
    EXPECT_LT(heavy, light);
    EXPECT_LT(heavy, 0.7);
}

TEST(Ssim, IsSymmetric) {
    Image a = card(50, 40), b = noisy(card(50, 40, 2), 10);
    EXPECT_DOUBLE_EQ(ssim(a, b), ssim(b, a));
}

TEST(Ssim, UsesLuminanceNotAlpha) {
    Image a = card(32, 32), b = a;
    for (size_t i = 3; i < b.rgba.size(); i += 4) b.rgba[i] = 0;
    EXPECT_DOUBLE_EQ(ssim(a, b), 1.0);
    // Swapping red and blue changes luminance where they differ: a coloured image then scores lower.
    Image c(32, 32), d(32, 32);
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) {
            uint8_t* p = c.pixel(x, y);
            p[0] = uint8_t(x * 8); p[1] = 50; p[2] = uint8_t(255 - y * 8); p[3] = 255;
            uint8_t* q = d.pixel(x, y);
            q[0] = p[2]; q[1] = p[1]; q[2] = p[0]; q[3] = 255;
        }
    EXPECT_LT(ssim(c, d), 0.99);
}

TEST(Ssim, BrightnessOffsetLowersItLessThanStructureLoss) {
    Image a = card(64, 48), brighter = a;
    for (size_t i = 0; i < brighter.rgba.size(); ++i)
        if (i % 4 != 3) brighter.rgba[i] = uint8_t(std::min(255, brighter.rgba[i] + 10));
    double offset = ssim(a, brighter);
    EXPECT_LT(offset, 1.0);
    EXPECT_GT(offset, ssim(a, noisy(a, 40)));
}

TEST(Ssim, ImagesSmallerThanAWindowStillCompare) {
    Image a = card(5, 4), b = noisy(card(5, 4), 30);
    EXPECT_DOUBLE_EQ(ssim(a, a), 1.0);
    EXPECT_LT(ssim(a, b), 1.0);
}

TEST(Ssim, RejectsMismatchedOrEmptyImages) {
    EXPECT_THROW(ssim(Image(4, 4), Image(4, 5)), std::invalid_argument);
    EXPECT_THROW(ssim(Image(), Image()), std::invalid_argument);
}

}  // namespace
}  // namespace oasis
