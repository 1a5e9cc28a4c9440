// Mip levels for an alpha-tested atlas that keep each cell's alpha-test coverage: box-filtered
// levels (premultiplied RGBA8) whose alpha is then scaled, cell by cell, so that the fraction of
// texels at or above the test's threshold is the same at every level as at level 0 (Castaño,
// "Computing Alpha Mipmaps", 2010). Plain box filtering thins a plant's branches level by level
// until a fixed threshold drops them. No GL here: src/render/plant_atlas.cpp uploads the levels.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace oasis {

// One level, RGBA8 premultiplied, rows in any order (every function keeps it).
struct MipImage {
    int width = 0, height = 0;
    std::vector<uint8_t> rgba;
    uint8_t alpha(int x, int y) const { return rgba[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4 + 3]; }
};

// Levels 0..levels-1: level 0 is `base`, each next one the 2x2 box average of the one before.
// Stops early where a side would fall below 1 texel.
std::vector<MipImage> boxFilteredMips(const MipImage& base, int levels);

// The fraction of the square cell (cellX, cellY) of `cellSize` texels of this level whose alpha
// reaches `threshold` (alpha / 255 >= threshold).
double alphaCoverage(const MipImage& level, int cellX, int cellY, int cellSize, float threshold);

// Scales the alpha (and the premultiplied colour with it) of every cell of every level past 0 so
// that its coverage at `threshold` is as close as a scale can bring it to the cell's coverage at
// level 0. Cells are a grid of `cellSize` texels at level 0 (cellSize >> level at each level).
void preserveCoverage(std::vector<MipImage>& levels, int cellSize, float threshold);

}  // namespace oasis
