// Splitting a frame's pixels into edges, where two correct rasterisers may differ (silhouettes,
// depth steps, creases, plants' alpha-tested leaves, the water's outline, one pixel around each),
// and interiors, where they should draw the same value to a level or two (issue 40, item 4). GL-free:
// the case's child fills PixelGeometry from the surfaces it read back (check/case_geometry.h); the
// unit tests fill it by hand.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "render/image.h"

namespace oasis {

// What one pixel's surface is, from the frame's own G-buffer (or forward's surfaces drawn again).
enum PixelSurface : uint8_t {
    kPixelSky = 1,    // nothing drawn: the sky behind every surface
    kPixelPlant = 2,  // an alpha-tested billboard (OASIS_SURFACE_PLANT)
    kPixelWater = 4,  // the water mask's stencil mark: the water and the mirrored scene in it
    // The sun's shadow, where the frame draws one: the surface faces the sun (elsewhere its
    // visibility multiplies nothing), and there it is wholly shadowed, or its visibility is the
    // driver's to filter (a penumbra, a depth tie, a cascade's edge: check/oracle_shadow.h).
    kPixelSunFacing = 8,
    kPixelShadowed = 16,
    kPixelPenumbra = 32,
};

// Rows top row first, as Image holds them.
struct PixelGeometry {
    int width = 0, height = 0;
    std::vector<uint8_t> surface;  // PixelSurface bits, one byte a pixel
    std::vector<float> distance;   // from the camera, any unit; ignored at sky pixels
    std::vector<float> normal;     // xyz a pixel, unit length; ignored at sky pixels
};

// Why a pixel is an edge (bits; 0: an interior pixel).
enum PixelEdge : uint8_t {
    kEdgeSilhouette = 1,  // the sky meets a surface here
    kEdgeDepth = 2,       // the distance bends or steps here: not one smooth surface across the pixel
    kEdgeNormal = 4,      // the normal turns by more than the crease angle to a neighbour
    kEdgePlant = 8,       // a plant's pixel: its alpha test's coverage is the rasteriser's to decide
    kEdgeWater = 16,      // the water's outline (its stencil mark changes)
    kEdgeNear = 32,       // within one pixel of any of the above (the dilation)
    // A shadow's edge: a penumbra, or a step between shadowed and lit. The shadow map is a
    // rasterisation of its own, and its compare filter's precision is the driver's (softpipe
    // parts from llvmpipe there by up to 48 levels at 256x144).
    kEdgeShadow = 64,
};

// The classifier's thresholds (docs/check.md, "Edges and interiors", says how they were chosen).
struct EdgeThresholds {
    // A pixel bends when 1/distance's second difference across it, along a row or a column,
    // exceeds this fraction of 1/distance there: on any plane it is all but 0 (1/z is affine in
    // screen space), across a step between two surfaces it is the step.
    double depthBend = 0.02;
    double creaseCosine = 0.9063;  // cos 25 degrees: neighbours' normals further apart are a crease
};

// One byte a pixel, top row first: 0 interior, else PixelEdge bits. Throws std::invalid_argument
// when the vectors do not match the size.
std::vector<uint8_t> classifyPixels(const PixelGeometry& geometry, const EdgeThresholds& thresholds = {});

// The classes as a picture and back, for the child's file and the report's pictures: the red
// channel holds the PixelEdge bits; green is 255 at interior pixels, so that it can be looked at.
Image pixelClassImage(const std::vector<uint8_t>& classes, int width, int height);
std::vector<uint8_t> pixelClassesOf(const Image& image);

// "12,345 interior of 36,864 (edges: 2,001 silhouette, ...)" for people.
std::string pixelClassSummary(const std::vector<uint8_t>& classes);

}  // namespace oasis
