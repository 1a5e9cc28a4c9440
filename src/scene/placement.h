// Deterministic plant placement: L'Ecuyer's LFSR113 generator and plants scattered per terrain
// chunk, each chunk seeded from its own coordinates so any chunk regenerates on its own.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scene/lsystem.h"
#include "scene/terrain.h"

namespace oasis {

// LFSR113 (P. L'Ecuyer, "Tables of maximally equidistributed combined LFSR generators", Math. Comp.
// 68 (1999)): four Tausworthe components of 31, 29, 28 and 25 bits XORed together, period ~2^113.
class Lfsr113 {
public:
    // The components recur on the bits above their lowest 1, 3, 4 and 7; a seed below 2, 8, 16 or
    // 128 is zero there, and that component would stay zero forever.
    static constexpr std::array<uint32_t, 4> kMinimumSeed = {2u, 8u, 16u, 128u};

    // Throws std::invalid_argument if any seed is below its minimum.
    explicit Lfsr113(std::array<uint32_t, 4> seeds);
    // Mixes an arbitrary 64-bit key into four valid seeds (neighbouring keys give unrelated streams).
    static Lfsr113 fromKey(uint64_t key);

    uint32_t nextU32();
    float nextUnit();                 // uniform in [0, 1), 24 bits
    float uniform(float low, float high);
    std::array<uint32_t, 4> state() const { return z_; }

private:
    std::array<uint32_t, 4> z_;
};

// One billboard's worth of plant. The base sits on the terrain: base.y == terrainHeight(x, z).x.
struct PlantInstance {
    glm::vec3 base{0.0f};
    float size = 1.0f;         // world height of the billboard
    glm::vec3 tint{1.0f};      // multiplies the atlas colour: brightness and a dry, yellow shift
    uint32_t variant = 0;      // index into the plant presets / atlas layers
    float windPhase = 0.0f;    // radians in [0, 2 pi)
};

struct PlantPlacementSettings {
    uint32_t worldSeed = 1;
    float chunkSize = 64.0f;        // world units along each side of a chunk
    int candidatesPerChunk = 96;    // drawn per chunk; the ground rules below reject some
    // Ground rules (every placed plant satisfies all three):
    float waterLevel = 0.0f;        // bases below the water plane are skipped
    // Steeper ground is skipped: terrain.glsl's rock band reaches down to slope 1 - normal.y =
    // 0.33 minus up to 0.075 of noise minus its half-width 0.012 (0.243), so 0.76 keeps plants off
    // anything that can show rock.
    float minNormalY = 0.76f;
    // terrain.glsl turns high ground to rock from 48 - 8 = 40 units above the water.
    float maxHeightAboveWater = 40.0f;
    // Atlas cells (render/plant_atlas.h): a preset's cell is its index in plantPresets() in the
    // top row, one row down for its variant of one rewrite fewer; wrapped to this count.
    uint32_t variantCount = 1;
};

// One row of the placement table: an L-system preset (scene/lsystem.h) at its natural size. A
// plant's size is its billboard's world height (the atlas cell's: the plant fills 90 % of it, less
// where a wide plant is fitted to the cell's width).
struct PlantKind {
    const char* preset;
    float minSize, maxSize;  // world units, drawn uniformly between them
    float share;             // fraction of the candidates; the table's shares sum to 1
};
// Shrub to tree, in one table: low weeds and grass, ferny shrubs, young trees and broad trees.
const std::vector<PlantKind>& plantPlacementTable();
// The table row a candidate drawn with `unit` in [0, 1) falls in (by the cumulative shares).
const PlantKind& plantKindAt(float unit);

// The chunk whose square [c, c + 1) * chunkSize holds worldXZ.
glm::ivec2 chunkContaining(const PlantPlacementSettings& settings, glm::vec2 worldXZ);

// Whether the ground rules allow a plant at worldXZ, judged on terrainHeight (the terrain shader's
// height function) and the normal it implies.
bool plantCanGrowAt(const TerrainShape& shape, const PlantPlacementSettings& settings,
                    glm::vec2 worldXZ);

// The plants of one chunk, in a fixed order. Each candidate draws all its random numbers before
// the ground rules are applied, so changing a rule removes plants without moving the others.
std::vector<PlantInstance> placePlantsInChunk(const TerrainShape& shape,
                                              const PlantPlacementSettings& settings,
                                              glm::ivec2 chunk);
// The plants of a rectangle of chunks, chunk by chunk (rows of x within z).
std::vector<PlantInstance> placePlantsInChunks(const TerrainShape& shape,
                                               const PlantPlacementSettings& settings,
                                               glm::ivec2 firstChunk, glm::ivec2 chunkCount);

}  // namespace oasis
