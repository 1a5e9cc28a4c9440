// LFSR113 and per-chunk plant placement on the terrain height function.
#include "scene/placement.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace oasis {
namespace {

// SplitMix64's finaliser: a bijective mixer, so distinct keys give distinct seed material.
uint64_t splitMix64(uint64_t& state) {
    uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

uint64_t chunkKey(uint32_t worldSeed, glm::ivec2 chunk) {
    // Packing both 32-bit coordinates keeps every chunk's key distinct; the seed shifts the lot.
    uint64_t packed = (uint64_t(uint32_t(chunk.x)) << 32) | uint64_t(uint32_t(chunk.y));
    uint64_t seedState = worldSeed;
    return packed ^ splitMix64(seedState);
}

constexpr float kTwoPi = float(2.0 * M_PI);

uint32_t presetIndex(const char* name) {
    const std::vector<PlantPreset>& presets = plantPresets();
    for (size_t i = 0; i < presets.size(); ++i)
        if (presets[i].name == name) return uint32_t(i);
    throw std::logic_error(std::string("the plant placement table names no preset: ") + name);
}

// All random draws of one candidate, taken in a fixed order whether or not it is kept.
PlantInstance drawCandidate(Lfsr113& random, const PlantPlacementSettings& settings,
                            glm::ivec2 chunk) {
    PlantInstance plant;
    // Corner plus offset (not (chunk + u) * size) keeps precision far from the origin.
    float x = float(chunk.x) * settings.chunkSize + random.nextUnit() * settings.chunkSize;
    float z = float(chunk.y) * settings.chunkSize + random.nextUnit() * settings.chunkSize;
    plant.base = {x, 0.0f, z};
    const PlantKind& kind = plantKindAt(random.nextUnit());
    plant.size = random.uniform(kind.minSize, kind.maxSize);
    float brightness = random.uniform(0.85f, 1.15f);
    float dryness = random.uniform(0.0f, 1.0f);
    dryness *= dryness;  // most plants fresh, a few dry
    plant.tint = brightness * glm::mix(glm::vec3(1.0f), glm::vec3(1.25f, 1.1f, 0.6f), dryness);
    uint32_t variants = settings.variantCount > 0 ? settings.variantCount : 1u;
    uint32_t fewerRewrites = random.nextU32() & 1u;  // the atlas's top (default) or bottom row
    plant.variant = (presetIndex(kind.preset) + fewerRewrites * uint32_t(plantPresets().size())) % variants;
    plant.windPhase = random.uniform(0.0f, kTwoPi);
    return plant;
}

// The ground rules on one height sample (h, dh/dx, dh/dz); the normal is terrainNormal's.
bool groundAllowsPlant(const PlantPlacementSettings& settings, glm::vec3 heightSample) {
    float aboveWater = heightSample.x - settings.waterLevel;
    if (aboveWater < 0.0f || aboveWater > settings.maxHeightAboveWater) return false;
    glm::vec3 normal = glm::normalize(glm::vec3(-heightSample.y, 1.0f, -heightSample.z));
    return normal.y >= settings.minNormalY;
}

}  // namespace

Lfsr113::Lfsr113(std::array<uint32_t, 4> seeds) : z_(seeds) {
    for (std::size_t k = 0; k < 4; ++k)
        if (seeds[k] < kMinimumSeed[k])
            throw std::invalid_argument("LFSR113 seed " + std::to_string(k + 1) + " is " +
                                        std::to_string(seeds[k]) + ", below its minimum " +
                                        std::to_string(kMinimumSeed[k]));
}

Lfsr113 Lfsr113::fromKey(uint64_t key) {
    std::array<uint32_t, 4> seeds;
    uint64_t state = key;
    for (std::size_t k = 0; k < 4; ++k)
        // Setting the minimum's bit guarantees the constraint at the cost of one bit of entropy.
        seeds[k] = uint32_t(splitMix64(state) >> 32) | kMinimumSeed[k];
    return Lfsr113(seeds);
}

uint32_t Lfsr113::nextU32() {
    // L'Ecuyer's shifts (q, s) and masks (k = 31, 29, 28, 25 bits) for the four components.
    uint32_t b;
    b = ((z_[0] << 6) ^ z_[0]) >> 13;
    z_[0] = ((z_[0] & 0xFFFFFFFEu) << 18) ^ b;
    b = ((z_[1] << 2) ^ z_[1]) >> 27;
    z_[1] = ((z_[1] & 0xFFFFFFF8u) << 2) ^ b;
    b = ((z_[2] << 13) ^ z_[2]) >> 21;
    z_[2] = ((z_[2] & 0xFFFFFFF0u) << 7) ^ b;
    b = ((z_[3] << 3) ^ z_[3]) >> 12;
    z_[3] = ((z_[3] & 0xFFFFFF80u) << 13) ^ b;
    return z_[0] ^ z_[1] ^ z_[2] ^ z_[3];
}

float Lfsr113::nextUnit() {
    // The top 24 bits fit a float exactly, so the result can never round up to 1.
    return float(nextU32() >> 8) * (1.0f / 16777216.0f);
}

float Lfsr113::uniform(float low, float high) { return low + (high - low) * nextUnit(); }

const std::vector<PlantKind>& plantPlacementTable() {
    // Sizes from the presets' shapes: "weed" and "grass" are single stalks, "fractal-plant" a
    // fern-like shrub, "sprig" a small conifer-like tree, "bush" a broad crown on a trunk.
    static const std::vector<PlantKind> table = {
        {"grass", 0.4f, 0.9f, 0.30f},
        {"weed", 0.5f, 1.1f, 0.25f},
        {"fractal-plant", 1.2f, 2.6f, 0.20f},
        {"sprig", 3.0f, 6.0f, 0.13f},
        {"bush", 6.0f, 11.0f, 0.12f},
    };
    return table;
}

const PlantKind& plantKindAt(float unit) {
    const std::vector<PlantKind>& table = plantPlacementTable();
    float cumulative = 0.0f;
    for (const PlantKind& kind : table) {
        cumulative += kind.share;
        if (unit < cumulative) return kind;
    }
    return table.back();  // rounding in the shares' sum
}

glm::ivec2 chunkContaining(const PlantPlacementSettings& settings, glm::vec2 worldXZ) {
    return glm::ivec2(glm::floor(worldXZ / settings.chunkSize));
}

bool plantCanGrowAt(const TerrainShape& shape, const PlantPlacementSettings& settings,
                    glm::vec2 worldXZ) {
    return groundAllowsPlant(settings, terrainHeight(shape, worldXZ));
}

std::vector<PlantInstance> placePlantsInChunk(const TerrainShape& shape,
                                              const PlantPlacementSettings& settings,
                                              glm::ivec2 chunk) {
    Lfsr113 random = Lfsr113::fromKey(chunkKey(settings.worldSeed, chunk));
    std::vector<PlantInstance> plants;
    for (int i = 0; i < settings.candidatesPerChunk; ++i) {
        PlantInstance plant = drawCandidate(random, settings, chunk);
        glm::vec3 ground = terrainHeight(shape, glm::vec2(plant.base.x, plant.base.z));
        if (!groundAllowsPlant(settings, ground)) continue;
        plant.base.y = ground.x;
        plants.push_back(plant);
    }
    return plants;
}

std::vector<PlantInstance> placePlantsInChunks(const TerrainShape& shape,
                                               const PlantPlacementSettings& settings,
                                               glm::ivec2 firstChunk, glm::ivec2 chunkCount) {
    std::vector<PlantInstance> plants;
    for (int dz = 0; dz < chunkCount.y; ++dz)
        for (int dx = 0; dx < chunkCount.x; ++dx) {
            std::vector<PlantInstance> chunkPlants =
                placePlantsInChunk(shape, settings, firstChunk + glm::ivec2(dx, dz));
            plants.insert(plants.end(), chunkPlants.begin(), chunkPlants.end());
        }
    return plants;
}

}  // namespace oasis
