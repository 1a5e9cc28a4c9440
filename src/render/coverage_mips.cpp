// Box-filtered mip levels and per-cell alpha scaling that keeps the alpha test's coverage.
#include "render/coverage_mips.h"

#include <algorithm>
#include <cmath>

namespace oasis {
namespace {

bool passes(int alphaByte, float threshold) { return float(alphaByte) >= threshold * 255.0f; }

// Coverage of a cell with its alpha scaled by `scale` (as preserveCoverage would store it).
double scaledCoverage(const MipImage& level, int x0, int y0, int size, float scale, float threshold) {
    long passing = 0;
    for (int y = y0; y < y0 + size; ++y)
        for (int x = x0; x < x0 + size; ++x) {
            int a = level.alpha(x, y);
            passing += a > 0 && passes(std::min(255, int(std::lround(float(a) * scale))), threshold);
        }
    return double(passing) / double(size * size);
}

void scaleCell(MipImage& level, int x0, int y0, int size, float scale) {
    for (int y = y0; y < y0 + size; ++y)
        for (int x = x0; x < x0 + size; ++x) {
            uint8_t* p = &level.rgba[(size_t(y) * size_t(level.width) + size_t(x)) * 4];
            if (p[3] == 0) continue;
            int scaled = std::min(255, int(std::lround(float(p[3]) * scale)));
            float ratio = float(scaled) / float(p[3]);  // premultiplied colour follows its alpha
            for (int c = 0; c < 3; ++c) p[c] = uint8_t(std::min(255, int(std::lround(float(p[c]) * ratio))));
            p[3] = uint8_t(scaled);
        }
}

}  // namespace

std::vector<MipImage> boxFilteredMips(const MipImage& base, int levels) {
    std::vector<MipImage> chain{base};
    while (int(chain.size()) < levels && chain.back().width >= 2 && chain.back().height >= 2) {
        const MipImage& above = chain.back();
        MipImage next;
        next.width = above.width / 2;
        next.height = above.height / 2;
        next.rgba.resize(size_t(next.width) * size_t(next.height) * 4);
        for (int y = 0; y < next.height; ++y)
            for (int x = 0; x < next.width; ++x)
                for (int c = 0; c < 4; ++c) {
                    int sum = 0;
                    for (int dy = 0; dy < 2; ++dy)
                        for (int dx = 0; dx < 2; ++dx)
                            sum += above.rgba[(size_t(2 * y + dy) * size_t(above.width) + size_t(2 * x + dx)) * 4 + size_t(c)];
                    next.rgba[(size_t(y) * size_t(next.width) + size_t(x)) * 4 + size_t(c)] = uint8_t((sum + 2) / 4);
                }
        chain.push_back(std::move(next));
    }
    return chain;
}

double alphaCoverage(const MipImage& level, int cellX, int cellY, int cellSize, float threshold) {
    return scaledCoverage(level, cellX * cellSize, cellY * cellSize, cellSize, 1.0f, threshold);
}

void preserveCoverage(std::vector<MipImage>& levels, int cellSize, float threshold) {
    if (levels.empty()) return;
    const int columns = levels[0].width / cellSize, rows = levels[0].height / cellSize;
    for (int row = 0; row < rows; ++row)
        for (int column = 0; column < columns; ++column) {
            const double target = alphaCoverage(levels[0], column, row, cellSize, threshold);
            for (size_t l = 1; l < levels.size(); ++l) {
                const int size = cellSize >> l;
                if (size < 1) break;
                MipImage& level = levels[l];
                const int x0 = column * size, y0 = row * size;
                // Coverage only grows with the scale: bisect for the smallest scale that reaches the
                // target, then keep whichever of it and the largest below lands nearer.
                float low = 0.0f, high = 64.0f;
                for (int step = 0; step < 24; ++step) {
                    float middle = 0.5f * (low + high);
                    (scaledCoverage(level, x0, y0, size, middle, threshold) >= target ? high : low) = middle;
                }
                double above = scaledCoverage(level, x0, y0, size, high, threshold);
                double below = scaledCoverage(level, x0, y0, size, low, threshold);
                float scale = std::fabs(above - target) <= std::fabs(below - target) ? high : low;
                scaleCell(level, x0, y0, size, scale);
            }
        }
}

}  // namespace oasis
