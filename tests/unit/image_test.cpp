// Covers src/render/image.h: compareImages metrics (PSNR, RMSE, max abs), differenceHeatmap, flipRows,
// encodePng and writePng (decoded back with stb_image).
#include <gtest/gtest.h>
#include <stdlib.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "render/image.h"

#include <stb_image.h>

#include "unit_support.h"

namespace oasis {
namespace {

using namespace unittest;

// An image with every pixel (r, g, b, a).
Image solid(int w, int h, uint8_t r, uint8_t g, uint8_t b, uint8_t a = 255) {
    Image image(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            uint8_t* p = image.pixel(x, y);
            p[0] = r; p[1] = g; p[2] = b; p[3] = a;
        }
    return image;
}

TEST(CompareImages, IdenticalImagesHaveCappedPsnrAndZeroError) {
    for (Image a : {pattern(17, 9), solid(3, 3, 0, 0, 0), solid(1, 1, 255, 255, 255)}) {
        ImageDifference d = compareImages(a, a);
        EXPECT_EQ(kPsnrIdentical, 100.0);
        EXPECT_EQ(d.psnrDb, kPsnrIdentical);
        EXPECT_EQ(d.rmse, 0.0);
        EXPECT_EQ(d.maxAbs, 0);
    }
    ImageDifference empty = compareImages(Image(0, 0), Image(0, 0));
    EXPECT_EQ(empty.psnrDb, kPsnrIdentical);
    EXPECT_EQ(empty.rmse, 0.0);
}

TEST(CompareImages, UniformDifferenceOfOneInOneChannel) {
    // Every pixel differs by 1 in exactly one of the three channels: MSE = 1/3 over RGB.
    for (int channel = 0; channel < 3; ++channel) {
        Image a = pattern(32, 16), b = a;
        for (int y = 0; y < b.height; ++y)
            for (int x = 0; x < b.width; ++x) {
                uint8_t& v = b.pixel(x, y)[channel];
                v = v == 255 ? 254 : uint8_t(v + 1);
            }
        ImageDifference d = compareImages(a, b);
        EXPECT_EQ(d.maxAbs, 1);
        EXPECT_NEAR(d.rmse * d.rmse, 1.0 / 3.0, 1e-12);
        EXPECT_NEAR(d.psnrDb, 10.0 * std::log10(255.0 * 255.0 * 3.0), 1e-9) << "channel " << channel;
    }
}

TEST(CompareImages, KnownExtremesAndSymmetry) {
    Image black = solid(4, 4, 0, 0, 0), white = solid(4, 4, 255, 255, 255);
    ImageDifference d = compareImages(black, white);
    EXPECT_EQ(d.maxAbs, 255);
    EXPECT_NEAR(d.rmse, 255.0, 1e-12);
    EXPECT_NEAR(d.psnrDb, 0.0, 1e-12);  // MSE = 255^2
    // Half the pixels differ by 10 in all channels: MSE = 50, PSNR = 10 log10(255^2 / 50).
    Image a = solid(4, 2, 100, 100, 100), b = a;
    for (int x = 0; x < 4; ++x)
        for (int c = 0; c < 3; ++c) b.pixel(x, 1)[c] = 110;
    ImageDifference half = compareImages(a, b), reverse = compareImages(b, a);
    EXPECT_EQ(half.maxAbs, 10);
    EXPECT_NEAR(half.rmse, std::sqrt(50.0), 1e-12);
    EXPECT_NEAR(half.psnrDb, 10.0 * std::log10(255.0 * 255.0 / 50.0), 1e-9);
    EXPECT_EQ(half.psnrDb, reverse.psnrDb);
    EXPECT_EQ(half.rmse, reverse.rmse);
    EXPECT_EQ(half.maxAbs, reverse.maxAbs);
}

TEST(CompareImages, AlphaIsIgnored) {
    Image a = solid(5, 5, 10, 20, 30, 255), b = solid(5, 5, 10, 20, 30, 0);
    ImageDifference d = compareImages(a, b);
    EXPECT_EQ(d.maxAbs, 0);
    EXPECT_EQ(d.rmse, 0.0);
    EXPECT_EQ(d.psnrDb, kPsnrIdentical);
}

TEST(CompareImages, PsnrNeverExceedsTheCap) {
    // One channel of one pixel off by 1 in 65536 pixels: uncapped PSNR would be ~100.7 dB.
    Image a = solid(256, 256, 50, 50, 50), b = a;
    b.pixel(3, 4)[2] = 51;
    ImageDifference d = compareImages(a, b);
    EXPECT_GT(10.0 * std::log10(255.0 * 255.0 * 3.0 * 65536.0), kPsnrIdentical);
    EXPECT_EQ(d.psnrDb, kPsnrIdentical);
    EXPECT_EQ(d.maxAbs, 1);  // the difference is still visible in the other metrics
    EXPECT_GT(d.rmse, 0.0);
}

TEST(CompareImages, SizeMismatchThrows) {
    EXPECT_THROW(compareImages(Image(4, 4), Image(5, 4)), std::invalid_argument);
    EXPECT_THROW(compareImages(Image(4, 4), Image(4, 5)), std::invalid_argument);
    EXPECT_THROW(compareImages(Image(8, 2), Image(2, 8)), std::invalid_argument);  // same pixel count
    EXPECT_THROW(compareImages(Image(0, 0), Image(1, 1)), std::invalid_argument);
}

TEST(DifferenceHeatmap, ZeroDifferenceIsOpaqueBlack) {
    Image a = pattern(9, 7);
    Image heat = differenceHeatmap(a, a);
    ASSERT_EQ(heat.width, 9);
    ASSERT_EQ(heat.height, 7);
    for (int y = 0; y < 7; ++y)
        for (int x = 0; x < 9; ++x) {
            const uint8_t* p = heat.pixel(x, y);
            ASSERT_EQ(p[0], 0);
            ASSERT_EQ(p[1], 0);
            ASSERT_EQ(p[2], 0);
            ASSERT_EQ(p[3], 255);
        }
}

TEST(DifferenceHeatmap, SaturatedDifferenceIsWhite) {
    Image a = solid(3, 2, 0, 0, 0);
    for (int d : {16, 17, 100, 255}) {
        Image b = solid(3, 2, 0, uint8_t(d), 0);  // the largest channel difference counts
        Image heat = differenceHeatmap(a, b);
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 3; ++x) {
                const uint8_t* p = heat.pixel(x, y);
                ASSERT_EQ(p[0], 255) << d;
                ASSERT_EQ(p[1], 255) << d;
                ASSERT_EQ(p[2], 255) << d;
                ASSERT_EQ(p[3], 255) << d;
            }
    }
}

TEST(DifferenceHeatmap, BlackRedYellowWhiteScale) {
    // With fullScale 3, differences 0, 1, 2, 3 land on the scale's four stops.
    Image a = solid(4, 1, 100, 100, 100), b = a;
    for (int x = 0; x < 4; ++x) b.pixel(x, 0)[x % 3] = uint8_t(100 - x);
    Image heat = differenceHeatmap(a, b, 3);
    const uint8_t expected[4][3] = {{0, 0, 0}, {255, 0, 0}, {255, 255, 0}, {255, 255, 255}};
    for (int x = 0; x < 4; ++x)
        for (int c = 0; c < 3; ++c) EXPECT_EQ(heat.pixel(x, 0)[c], expected[x][c]) << "difference " << x;
    // Brightness never decreases as the difference grows (default scale).
    int previous = -1;
    for (int d = 0; d <= 40; ++d) {
        Image heatD = differenceHeatmap(solid(1, 1, 0, 0, 0), solid(1, 1, uint8_t(d), 0, 0));
        const uint8_t* p = heatD.pixel(0, 0);
        int sum = p[0] + p[1] + p[2];
        ASSERT_GE(sum, previous) << d;
        previous = sum;
    }
}

TEST(DifferenceHeatmap, IgnoresAlpha) {
    Image heat = differenceHeatmap(solid(2, 2, 5, 5, 5, 0), solid(2, 2, 5, 5, 5, 255));
    EXPECT_EQ(heat.pixel(1, 1)[0], 0);
    EXPECT_EQ(heat.pixel(1, 1)[1], 0);
    EXPECT_EQ(heat.pixel(1, 1)[2], 0);
}

// compareImages rejects images of different sizes; differenceHeatmap does not check and reads
// `b` with `a`'s dimensions (out of bounds when b is smaller).
TEST(DifferenceHeatmap, SizeMismatchThrowsLikeCompareImages) {
    Image a = pattern(4, 4), b = pattern(2, 2);
    EXPECT_THROW(differenceHeatmap(a, b), std::invalid_argument);
}

TEST(FlipRows, MirrorsRowsForOddAndEvenHeights) {
    for (int h : {1, 2, 3, 6, 7}) {
        Image original = pattern(5, h), flipped = original;
        flipped.flipRows();
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < 5; ++x)
                ASSERT_EQ(std::memcmp(flipped.pixel(x, y), original.pixel(x, h - 1 - y), 4), 0)
                    << "height " << h << " at " << x << "," << y;
        flipped.flipRows();
        EXPECT_EQ(flipped.rgba, original.rgba) << "flipping twice restores the image, height " << h;
    }
}

class WritePng : public ::testing::Test {
protected:
    void SetUp() override {
        std::string pattern = (std::filesystem::temp_directory_path() / "oasis-image-test-XXXXXX").string();
        std::vector<char> buffer(pattern.begin(), pattern.end());
        buffer.push_back('\0');
        ASSERT_NE(mkdtemp(buffer.data()), nullptr);
        dir = buffer.data();
    }
    void TearDown() override {
        if (!dir.empty()) std::filesystem::remove_all(dir);
    }
    std::string dir;
};

uint32_t bigEndian32(const unsigned char* p) {
    return (uint32_t(p[0]) << 24) | (uint32_t(p[1]) << 16) | (uint32_t(p[2]) << 8) | uint32_t(p[3]);
}

TEST_F(WritePng, WritesAValidPngHeader) {
    std::string path = dir + "/frame.png";
    std::string error;
    ASSERT_TRUE(writePng(path, pattern(13, 5), error)) << error;
    ASSERT_TRUE(std::filesystem::exists(path));
    std::ifstream in(path, std::ios::binary);
    std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_GE(bytes.size(), 33u);
    const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    EXPECT_EQ(std::memcmp(bytes.data(), signature, 8), 0);
    // The first chunk is IHDR with the image's width and height, 8-bit RGBA (colour type 6).
    EXPECT_EQ(std::string(bytes.begin() + 12, bytes.begin() + 16), "IHDR");
    EXPECT_EQ(bigEndian32(&bytes[16]), 13u);
    EXPECT_EQ(bigEndian32(&bytes[20]), 5u);
    EXPECT_EQ(bytes[24], 8);
    EXPECT_EQ(bytes[25], 6);
}

// The file decodes (stb_image) to the very pixels written, and the directory holds only it.
TEST_F(WritePng, DecodesToTheSamePixelsAndLeavesOnlyTheTarget) {
    Image image = pattern(37, 21);
    std::string path = dir + "/frame.png", error;
    ASSERT_TRUE(writePng(path, image, error)) << error;
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) names.push_back(entry.path().filename());
    EXPECT_EQ(names, std::vector<std::string>{"frame.png"});
    std::ifstream in(path, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::string encoded;
    ASSERT_TRUE(encodePng(image, encoded));
    EXPECT_EQ(bytes, encoded);
    int w = 0, h = 0, channels = 0;
    stbi_uc* decoded = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()), int(bytes.size()), &w, &h,
                                             &channels, 4);
    ASSERT_NE(decoded, nullptr) << stbi_failure_reason();
    EXPECT_EQ(w, 37);
    EXPECT_EQ(h, 21);
    EXPECT_EQ(channels, 4);
    EXPECT_EQ(std::memcmp(decoded, image.rgba.data(), image.rgba.size()), 0);
    stbi_image_free(decoded);
}

TEST_F(WritePng, AnEmptyImageIsRefusedAndNothingIsWritten) {
    std::string path = dir + "/empty.png", error;
    EXPECT_FALSE(writePng(path, Image(0, 0), error));
    EXPECT_NE(error.find("cannot write " + path), std::string::npos) << error;
    EXPECT_FALSE(std::filesystem::exists(path));
}

TEST_F(WritePng, FailsWithAMessageForAMissingDirectory) {
    std::string error;
    EXPECT_FALSE(writePng("/nonexistent/dir/x.png", pattern(2, 2), error));
    EXPECT_NE(error.find("/nonexistent/dir/x.png"), std::string::npos) << error;
    EXPECT_NE(error.find(std::strerror(ENOENT)), std::string::npos) << error;
    EXPECT_FALSE(std::filesystem::exists("/nonexistent/dir/x.png"));
}

// Issue 31, defect 6: a one-level difference shows (five such pixels were black-red 47 at the
// default scale of 16), and the counts over 0, 1, 4 and 16 levels say how many differ.
TEST(DifferenceHeatmap, OneLevelIsVisible) {
    Image heat = differenceHeatmap(solid(1, 1, 100, 100, 100), solid(1, 1, 101, 100, 100));
    EXPECT_GE(heat.pixel(0, 0)[0], 128);
}

TEST(DifferingPixels, CountsOverEachLevel) {
    Image a = solid(5, 1, 100, 100, 100), b = a;
    const int differences[5] = {0, 1, 2, 5, 17};
    for (int x = 0; x < 5; ++x) b.pixel(x, 0)[2] = uint8_t(100 + differences[x]);
    DifferingPixels counts = countDifferingPixels(a, b);
    EXPECT_EQ(counts.pixels, 5);
    EXPECT_EQ(counts.over[0], 4);  // > 0
    EXPECT_EQ(counts.over[1], 3);  // > 1
    EXPECT_EQ(counts.over[2], 2);  // > 4
    EXPECT_EQ(counts.over[3], 1);  // > 16
    EXPECT_EQ(counts.describe(), "pixels differing by more than 0: 4, 1: 3, 4: 2, 16: 1 levels (of 5)");
    EXPECT_EQ(counts.json(), "{\"0\": 4, \"1\": 3, \"4\": 2, \"16\": 1}");
}

}  // namespace
}  // namespace oasis
