// Coverage-preserving mip levels (render/coverage_mips.h) on synthetic cells: plain box filtering
// loses thin detail at a fixed threshold; the scaled levels keep each cell's coverage.
#include <gtest/gtest.h>

#include <cmath>

#include "render/coverage_mips.h"

namespace oasis {
namespace {

// Two cells of 128 texels side by side: sparse single-texel specks (about 8 % of the texels, like
// a plant's twigs: thin detail that box filtering averages away) and a filled disc off centre.
MipImage twoCells() {
    MipImage image;
    image.width = 256;
    image.height = 128;
    image.rgba.assign(size_t(image.width) * size_t(image.height) * 4, 0);
    for (int y = 0; y < 128; ++y)
        for (int x = 0; x < 256; ++x) {
            unsigned hash = (unsigned(x) * 73856093u) ^ (unsigned(y) * 19349663u);
            hash = (hash ^ (hash >> 13)) * 0x5bd1e995u;
            bool speck = x < 128 && (hash >> 8) % 100u < 8u;
            bool disc = x >= 128 && std::hypot(x - 190.3, y - 61.7) < 40.0;
            if (!speck && !disc) continue;
            // Specks of varied alpha, all passing at level 0 (as antialiased twigs would be), so
            // their averages vary too; premultiplied colour.
            int alpha = disc ? 255 : 128 + int((hash >> 3) % 128u);
            uint8_t* p = &image.rgba[(size_t(y) * 256 + size_t(x)) * 4];
            p[0] = uint8_t(40 * alpha / 255); p[1] = uint8_t(160 * alpha / 255); p[2] = uint8_t(30 * alpha / 255);
            p[3] = uint8_t(alpha);
        }
    return image;
}

TEST(CoverageMips, BoxFilteringLosesThinDetailAndScalingKeepsEveryCellsCoverage) {
    const float threshold = 0.5f;
    // Down to cells of 16 texels: coarser levels hold too few texels to match a coverage closely.
    std::vector<MipImage> plain = boxFilteredMips(twoCells(), 4);
    ASSERT_EQ(plain.size(), 4u);
    EXPECT_EQ(plain[3].width, 32);
    std::vector<MipImage> kept = plain;
    preserveCoverage(kept, 128, threshold);
    const double specks0 = alphaCoverage(plain[0], 0, 0, 128, threshold);
    const double disc0 = alphaCoverage(plain[0], 1, 0, 128, threshold);
    EXPECT_NEAR(specks0, 0.08, 0.02);
    for (size_t level = 1; level < plain.size(); ++level) {
        const int size = 128 >> level;
        // A 2x2 block reaches alpha 0.5 only with two specks (3 % of blocks): the threshold drops most.
        EXPECT_LT(alphaCoverage(plain[level], 0, 0, size, threshold), 0.5 * specks0) << level;
        EXPECT_NEAR(alphaCoverage(kept[level], 0, 0, size, threshold) / specks0, 1.0, 0.1) << level;
        EXPECT_NEAR(alphaCoverage(kept[level], 1, 0, size, threshold) / disc0, 1.0, 0.1) << level;
    }
    // The premultiplied colour follows the scaled alpha: colour / alpha is unchanged.
    for (size_t i = 0; i < kept[2].rgba.size(); i += 4) {
        if (kept[2].rgba[i + 3] < 32) continue;
        double before = double(plain[2].rgba[i + 1]) / plain[2].rgba[i + 3];
        double after = double(kept[2].rgba[i + 1]) / kept[2].rgba[i + 3];
        ASSERT_NEAR(after, before, 0.1);
    }
}

}  // namespace
}  // namespace oasis
