// The vegetation field: plants placed chunk by chunk (scene/placement.h) over every chunk within
// the draw distance of the camera, kept between frames, and each frame's draw lists: chunks culled
// against the view (and, for the water's reflection, against the view of their mirror image),
// plants thinned with distance. No GL here; src/render/vegetation_buffers.h uploads the lists.
#pragma once
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "scene/camera.h"
#include "scene/placement.h"
#include "scene/terrain.h"
#include "scene/visible_water.h"

namespace oasis {

// The run-time knobs (panel and CLI).
struct VegetationSettings {
    bool enabled = true;
    float density = 1.0f;         // multiplies the candidates per chunk; 0..kMaxDensity
    float windStrength = 1.0f;    // 0 = still air; 0..kMaxWindStrength
    float drawDistance = 600.0f;  // no plant further from the camera is drawn (world units, horizontal)
    // Every plant is drawn out to this distance; beyond it the drawn fraction falls as start / d,
    // which keeps the number of plants per unit of screen height roughly constant.
    float thinningStart = 120.0f;
    // Billboards trimmed to their atlas cell's drawn bounds (PlantAtlas::drawnBounds), or whole
    // cells (the reference for what the trim saves and changes).
    bool trimmedBillboards = true;
    static constexpr float kMaxDensity = 4.0f;
    static constexpr float kMaxWindStrength = 3.0f;
};

// One billboard as the vertex shader reads it: positions relative to the camera (subtracted in
// double on the CPU, so a far-away camera keeps full precision), 36 bytes.
struct PlantDrawInstance {
    glm::vec4 baseSize;   // xyz base minus camera, w world height of the billboard
    glm::vec4 tintPhase;  // rgb tint, w wind phase (radians)
    float variant;        // atlas cell index
};
static_assert(sizeof(PlantDrawInstance) == 36, "PlantDrawInstance is read as tightly packed attributes");

// Both draw lists of a frame in one array: the direct view first, then the mirror images.
struct VegetationDrawList {
    std::vector<PlantDrawInstance> instances;
    size_t directCount = 0;    // instances [0, directCount)
    size_t mirroredCount = 0;  // instances [directCount, directCount + mirroredCount)
};

// What a frame's lists came from, for the summary, the panel and the tests.
struct VegetationStats {
    size_t chunksInRange = 0;   // chunks within the draw distance (their plants are placed)
    size_t plantsPlaced = 0;    // plants in those chunks
    size_t chunksVisible = 0;   // chunks whose bounds meet the view
    size_t chunksMirrored = 0;  // chunks whose mirrored bounds meet the view (and may land on water)
    size_t chunksMirroredOnLand = 0;  // mirrored bounds in view, culled: their image lands only on dry land
    size_t plantsDrawn = 0;
    size_t plantsDrawnMirrored = 0;
    size_t plantsMirroredOnLand = 0;  // in the mirrored chunks drawn, culled alone: their image lands on dry land
};

// The world-space box a chunk's billboards can reach (wind sway included).
struct ChunkBounds {
    glm::dvec3 low{0.0}, high{0.0};
};
// The box one plant's billboard can reach: facing any way, bent by any wind up to kMaxWindStrength.
// A chunk's bounds are its plants' reaches together.
ChunkBounds plantReach(const PlantInstance& plant);

// Whether a box, given relative to the camera, meets the frustum of a camera-relative
// view-projection matrix built with `mapping` (conservative: a box that only meets the planes'
// corners may pass).
bool boxMeetsFrustum(const glm::mat4& viewProjection, DepthMapping mapping, glm::vec3 low, glm::vec3 high);

// The chunks whose squares the draw distance around the camera can reach, inclusive. False (nothing
// to place) when an index would leave +-kMaxChunkIndex (chunk + 1 must not overflow an int) or the
// range would be kMaxChunksAcross or wider: the CLI's domains keep the camera far inside both, and
// a NaN camera fails too, so the chunk loops always end.
struct ChunkRange {
    glm::ivec2 first{0}, last{-1};
};
constexpr double kMaxChunkIndex = double(1 << 30);
constexpr double kMaxChunksAcross = 4096.0;
bool chunkRangeAround(const glm::dvec3& camera, double distance, double chunkSize, ChunkRange& range);

// The fraction of a chunk's plants drawn at horizontal distance `distance` from the camera.
float drawnFraction(const VegetationSettings& settings, float distance);

class VegetationField {
public:
    // Placement rules that follow the scene; the water level and terrain shape come per frame.
    explicit VegetationField(PlantPlacementSettings placement = defaultPlacement());
    static PlantPlacementSettings defaultPlacement();

    // Makes sure every chunk within the draw distance of `camera` is placed (placing new ones,
    // forgetting far ones); a change of shape, water level, density or variant count re-places all.
    void update(const TerrainShape& shape, float waterLevel, const VegetationSettings& settings,
                uint32_t variantCount, const glm::dvec3& camera);
    // Fills `list` for a camera-relative view-projection: chunks that meet the view, thinned with
    // distance; with `withReflection` also the chunks whose mirror image in the water meets it and,
    // given `visibleWater` (prepared for this frame), may land on water that can be seen.
    void buildDrawList(const VegetationSettings& settings, const glm::dvec3& camera,
                       const glm::mat4& viewProjection, DepthMapping mapping, bool withReflection, float waterLevel,
                       VegetationDrawList& list, VisibleWaterBound* visibleWater = nullptr);

    const VegetationStats& stats() const { return stats_; }
    // For a frame that draws no plants (vegetation off, no atlas): nothing placed or drawn.
    void clearStats() { stats_ = VegetationStats{}; }
    const PlantPlacementSettings& placement() const { return placement_; }
    // Every placed plant, chunk by chunk (for tests and the summary).
    std::vector<PlantInstance> placedPlants() const;

private:
    struct Chunk {
        std::vector<PlantInstance> plants;
        ChunkBounds bounds;
    };
    using ChunkMap = std::map<std::pair<int, int>, Chunk>;
    ChunkMap::iterator placeChunk(const TerrainShape& shape, glm::ivec2 chunk);
    bool inRange(glm::ivec2 chunk, const glm::dvec3& camera, float distance) const;

    PlantPlacementSettings basePlacement_, placement_;
    ChunkMap chunks_;
    // What the placed chunks were placed with; a change re-places them all.
    TerrainShape placedShape_;
    float placedWaterLevel_ = 0.0f, placedDensity_ = -1.0f;
    uint32_t placedVariants_ = 0;
    VegetationStats stats_;
};

}  // namespace oasis
