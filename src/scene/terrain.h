// The terrain: a fractal-noise heightfield (shape parameters shared with the GPU through FrameData)
// and the screen-following polar grid it is drawn on (rings that widen with distance, a wedge
// that covers only the azimuths the camera can see).
#pragma once
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scene/noise.h"

namespace oasis {

struct TerrainShape {
    float frequency = 1.0f / 650.0f;  // noise units per world unit
    float amplitude = 40.0f;          // world units per noise unit
    float baseHeight = 18.0f;         // added to every height; about a fifth of the land is below 0
    int octaves = 7;
};

// Height (y) at world (x, z) and its derivatives: (h, dh/dx, dh/dz). Same maths as terrain.glsl,
// with the noise coordinates taken in double: as precise 1e5 units out as at the origin.
glm::vec3 terrainHeight(const TerrainShape& shape, glm::dvec2 worldXZ);
glm::vec3 terrainNormal(const TerrainShape& shape, glm::dvec2 worldXZ);
// The terrain noise's octave origins around a camera at worldXZ (FrameData.terrainNoiseOrigins).
NoiseOrigins terrainNoiseOrigins(const TerrainShape& shape, glm::dvec2 worldXZ);
// The GPU's arithmetic step for step (terrain.glsl terrainHeightFromCamera): the height at
// `relativeXZ` from a camera whose origins are given, the offset in float. It departs from
// terrainHeight by float rounding that grows with the offset (not with the camera's distance
// from the world's origin): measured 1.5e-3 at 4000 units, below 1e-4 within 500.
glm::vec3 terrainHeightFromCamera(const TerrainShape& shape, const NoiseOrigins& origins, glm::vec2 relativeXZ);
// The lowest and highest height anywhere (x low, y high): the fractal noise stays within +-2 (its
// octaves' amplitudes 1, 1/2, ... sum below 2, each octave within +-1), widened by a unit for the
// GPU's float rounding. The shadow pass culls the terrain's casters with it.
glm::vec2 terrainHeightBounds(const TerrainShape& shape);

// How finely the grid follows the screen: the grid's density knob.
struct TerrainGridDensity {
    int rings = 150;        // the centre point, then geometric rings from firstRingRadius to the view distance
    int segments = 128;     // angular segments across the wedge
    float firstRingRadius = 0.25f;
};
inline bool sameGridDensity(const TerrainGridDensity& a, const TerrainGridDensity& b) {
    return a.rings == b.rings && a.segments == b.segments && a.firstRingRadius == b.firstRingRadius;
}

// The wedge of azimuths the grid spans this frame: centred on the camera's heading,
// widened to the frustum's footprint, or a full circle when looking steeply up or down.
struct TerrainWedge {
    float centralAzimuth = 0.0f;  // radians, 0 = -Z, pi/2 = +X (same convention as Camera yaw)
    float halfWidth = 0.0f;       // radians, at most pi
    float ringRatio = 1.0f;       // radius of ring i+1 over ring i
};

struct CameraView;
TerrainWedge computeTerrainWedge(const CameraView& view, const TerrainGridDensity& density,
                                 float viewDistance);

// Grid vertices are (ring fraction, segment fraction) in [0,1]^2; the vertex shader maps them
// to world positions. Indices are ordered near to far so early depth testing culls overdraw.
struct GridMesh {
    std::vector<glm::vec2> vertices;
    std::vector<uint32_t> indices;
};
GridMesh buildTerrainGrid(const TerrainGridDensity& density);

}  // namespace oasis
