// Where this frame's water can be seen, bounded on the CPU from the terrain grid's own vertices,
// so the reflection's plant chunks whose mirror image can only land on dry land are culled before
// they are drawn (VegetationField::buildDrawList). The argument, for an eye above the water:
// a pixel shows water only where its ray meets the water plane at a point W the drawn terrain does
// not rise above. If the terrain is above the water at W, the ray, which started above the ground,
// has crossed the ground's upper (front) face before reaching W, and that face's depth hides the
// water there. The drawn terrain is terrain.vert's polar grid, linear between its vertices, so a
// grid cell is certainly dry when all four of its vertices (their heights computed here as the
// GPU does) stand above the water by a margin that covers float and depth-buffer rounding.
// A mirrored point P' is seen where the ray from the eye to P' crosses the plane; the crossings of
// a box's mirror image lie in the hull of its corners' crossings, and the test asks whether any
// grid cell under that hull may be wet. Whenever the argument does not hold (eye at or below the
// water, ground within a near-plane's reach of the eye, an image beyond the grid or outside its
// wedge), the answer is "may show" and nothing is culled.
#pragma once
#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "scene/camera.h"
#include "scene/noise.h"
#include "scene/terrain.h"

namespace oasis {

// Where the terrain grid's vertices lie this frame: equal placements put them at the same points.
struct TerrainGridPlacement {
    TerrainShape shape;
    TerrainGridDensity density;
    TerrainWedge wedge;
    float viewDistance = 0.0f;
    glm::dvec2 cameraXZ{0.0};
    bool operator==(const TerrainGridPlacement& other) const;
};

class VisibleWaterBound {
public:
    // The frame's grid (the same numbers terrain.vert reads: FrameData.terrainGrid and its counts),
    // its view and the water level.
    void prepare(const TerrainShape& shape, const TerrainGridDensity& density, const TerrainWedge& wedge,
                 float viewDistance, const CameraView& view, float waterLevel);

    // False only when no part of the box's mirror image (of what is above the water) can be seen
    // on visible water. World coordinates.
    bool mirrorImageMayShow(const glm::dvec3& low, const glm::dvec3& high);

    // False when the frame's view gives the argument no hold: every box then may show.
    bool active() const { return active_; }
    // Grid vertices whose height was computed since prepare changed the grid (for the tests).
    size_t heightsComputed() const { return heightsComputed_; }

    // A cell is dry when its vertices are above the water by more than this at `radius` from the
    // eye: 0.1 for the GPU's float heights (measured 1.5e-3 at 4000 units) and positions, plus four
    // steps of a 24-bit depth buffer there, which reversed-z's float depth only betters.
    static float dryMargin(float radius, float nearPlane);

private:
    float ringRadius(int ring) const;
    float vertexHeight(int ring, int segment);
    float cellLowest(int ring, int segment);  // the lowest of the cell's four vertices
    bool anyCellWet(int firstRing, int lastRing, int firstSegment, int lastSegment);

    TerrainGridPlacement key_;
    bool keyValid_ = false, active_ = false;
    float waterLevel_ = 0.0f, nearPlane_ = 0.25f;
    glm::dvec3 camera_{0.0};
    NoiseOrigins origins_{};
    std::vector<float> heights_;     // (rings + 1) x (segments + 1), NaN until computed
    std::vector<float> cellLowest_;  // rings x segments, NaN until computed
    size_t heightsComputed_ = 0;
};

}  // namespace oasis
