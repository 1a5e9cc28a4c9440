// Edges and interiors of a frame from its own geometry (check/pixel_classes.h).
#include "check/pixel_classes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <utility>

namespace oasis {
namespace {

struct ClassifierGrid {
    const PixelGeometry& g;
    size_t at(int x, int y) const { return size_t(y) * size_t(g.width) + size_t(x); }
    bool sky(int x, int y) const { return (g.surface[at(x, y)] & kPixelSky) != 0; }
    double inverseDistance(int x, int y) const { return 1.0 / std::max(double(g.distance[at(x, y)]), 1e-30); }
    double cosine(int x, int y, int u, int v) const {
        const float *a = &g.normal[3 * at(x, y)], *b = &g.normal[3 * at(u, v)];
        return double(a[0]) * b[0] + double(a[1]) * b[1] + double(a[2]) * b[2];
    }
};

// Whether 1/distance bends across (x, y) along (dx, dy): its second difference against its value.
// Both neighbours must be surfaces: a neighbour in the sky is the silhouette's test.
bool bends(const ClassifierGrid& grid, int x, int y, int dx, int dy, double threshold) {
    int ax = x - dx, ay = y - dy, bx = x + dx, by = y + dy;
    if (ax < 0 || ay < 0 || bx >= grid.g.width || by >= grid.g.height) return false;
    if (grid.sky(ax, ay) || grid.sky(bx, by)) return false;
    double centre = grid.inverseDistance(x, y);
    double second = grid.inverseDistance(ax, ay) - 2.0 * centre + grid.inverseDistance(bx, by);
    return std::fabs(second) > threshold * centre;
}

}  // namespace

std::vector<uint8_t> classifyPixels(const PixelGeometry& geometry, const EdgeThresholds& thresholds) {
    const size_t count = size_t(geometry.width) * size_t(geometry.height);
    if (geometry.width < 0 || geometry.height < 0 || geometry.surface.size() != count || geometry.distance.size() != count ||
        geometry.normal.size() != 3 * count)
        throw std::invalid_argument("classifyPixels: the geometry's vectors do not match its size");
    ClassifierGrid grid{geometry};
    std::vector<uint8_t> edges(count, 0);
    const int w = geometry.width, h = geometry.height;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            uint8_t& e = edges[grid.at(x, y)];
            const uint8_t surface = geometry.surface[grid.at(x, y)];
            if (surface & kPixelPlant) e |= kEdgePlant;
            if (surface & kPixelPenumbra) e |= kEdgeShadow;
            // The right and lower neighbours: each pair is seen once and marks both sides.
            for (auto [u, v] : {std::pair{x + 1, y}, std::pair{x, y + 1}}) {
                if (u >= w || v >= h) continue;
                uint8_t& f = edges[grid.at(u, v)];
                const uint8_t other = geometry.surface[grid.at(u, v)];
                uint8_t bits = 0;
                if ((surface ^ other) & kPixelSky) bits |= kEdgeSilhouette;
                if ((surface ^ other) & kPixelWater) bits |= kEdgeWater;
                if (!((surface | other) & kPixelSky) && grid.cosine(x, y, u, v) < thresholds.creaseCosine) bits |= kEdgeNormal;
                // A shadow's step only where both face the sun: the terminator (N.L crossing 0)
                // is the shading's, and an interior there shows a wrong N.L.
                if ((surface & other & kPixelSunFacing) && ((surface ^ other) & kPixelShadowed)) bits |= kEdgeShadow;
                e |= bits;
                f |= bits;
            }
            if (!(surface & kPixelSky) &&
                (bends(grid, x, y, 1, 0, thresholds.depthBend) || bends(grid, x, y, 0, 1, thresholds.depthBend)))
                e |= kEdgeDepth;
        }
    // One pixel around every edge: a rasteriser may cover the pixel beside the one llvmpipe did.
    std::vector<uint8_t> classes = edges;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            if (edges[grid.at(x, y)]) continue;
            for (int v = std::max(0, y - 1); v <= std::min(h - 1, y + 1); ++v)
                for (int u = std::max(0, x - 1); u <= std::min(w - 1, x + 1); ++u)
                    if (edges[grid.at(u, v)]) classes[grid.at(x, y)] = kEdgeNear;
        }
    return classes;
}

Image pixelClassImage(const std::vector<uint8_t>& classes, int width, int height) {
    Image image(width, height);
    for (size_t p = 0; p < classes.size() && p < size_t(width) * size_t(height); ++p) {
        uint8_t* out = &image.rgba[4 * p];
        out[0] = classes[p];
        out[1] = classes[p] == 0 ? 255 : 0;
        out[3] = 255;
    }
    return image;
}

std::vector<uint8_t> pixelClassesOf(const Image& image) {
    std::vector<uint8_t> classes(size_t(image.width) * size_t(image.height));
    for (size_t p = 0; p < classes.size(); ++p) classes[p] = image.rgba[4 * p];
    return classes;
}

std::string pixelClassSummary(const std::vector<uint8_t>& classes) {
    long interior = 0, bits[7] = {};
    for (uint8_t c : classes) {
        interior += c == 0;
        for (int b = 0; b < 7; ++b) bits[b] += (c >> b) & 1;
    }
    char text[256];
    std::snprintf(text, sizeof text, "%ld interior of %zu (edges: %ld silhouette, %ld depth, %ld crease, %ld plant, %ld water, "
                  "%ld shadow, %ld beside one)", interior, classes.size(), bits[0], bits[1], bits[2], bits[3], bits[4], bits[6],
                  bits[5]);
    return text;
}

}  // namespace oasis
