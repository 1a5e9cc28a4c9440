// LFSR113 (reference outputs, statistics, seed rules) and per-chunk plant placement (determinism,
// plants sitting on the terrain, the ground rules).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>
#include <string>

#include "scene/lsystem.h"
#include "scene/placement.h"

namespace oasis {
namespace {

// Seeds 12345 x 4 (the defaults of L'Ecuyer's lfsr113.c). First step by hand, 12345 = 0x3039:
//   z1: b = ((0x3039 << 6) ^ 0x3039) >> 13 = 0xC3079 >> 13 = 0x61
//       z1 = ((0x3039 & ~1) << 18) ^ b = 0xC0E00000 ^ 0x61         = 0xC0E00061
//   z2: b = ((0x3039 << 2) ^ 0x3039) >> 27 = 0xF0DD >> 27 = 0;  z2 = 0x3038 << 2      = 0x0000C0E0
//   z3: b = ((0x3039 << 13) ^ 0x3039) >> 21 = 0x6075039 >> 21 = 0x30
//       z3 = ((0x3039 & ~15) << 7) ^ b = 0x181800 ^ 0x30           = 0x00181830
//   z4: b = ((0x3039 << 3) ^ 0x3039) >> 12 = 0x1B1F1 >> 12 = 0x1B
//       z4 = ((0x3039 & ~127) << 13) ^ b = 0x6000000 ^ 0x1B        = 0x0600001B
//   output = z1 ^ z2 ^ z3 ^ z4 = 0xC6F8D8AA (0.77723 as L'Ecuyer's double).
// The later outputs come from an independent transcription of the C code (Python, masked to 32 bits).
TEST(Lfsr113, FirstOutputsForTheReferenceSeeds) {
    Lfsr113 random({12345u, 12345u, 12345u, 12345u});
    EXPECT_EQ(random.nextU32(), 0xC6F8D8AAu);
    const std::array<uint32_t, 4> afterFirst = {0xC0E00061u, 0x0000C0E0u, 0x00181830u, 0x0600001Bu};
    EXPECT_EQ(random.state(), afterFirst);
    EXPECT_EQ(random.nextU32(), 0x0D8BBC98u);
    EXPECT_EQ(random.nextU32(), 0x7603004Eu);
    EXPECT_EQ(random.nextU32(), 0x08C62223u);
    EXPECT_EQ(random.nextU32(), 0x83A312ABu);
}

TEST(Lfsr113, SeedsBelowTheirMinimumAreRejected) {
    EXPECT_NO_THROW(Lfsr113({2u, 8u, 16u, 128u}));
    EXPECT_THROW(Lfsr113({1u, 8u, 16u, 128u}), std::invalid_argument);
    EXPECT_THROW(Lfsr113({2u, 7u, 16u, 128u}), std::invalid_argument);
    EXPECT_THROW(Lfsr113({2u, 8u, 15u, 128u}), std::invalid_argument);
    EXPECT_THROW(Lfsr113({2u, 8u, 16u, 127u}), std::invalid_argument);
}

TEST(Lfsr113, KeyedSeedsAlwaysSatisfyTheConstraints) {
    for (uint64_t key = 0; key < 2000; ++key) {
        std::array<uint32_t, 4> state = Lfsr113::fromKey(key).state();
        for (std::size_t k = 0; k < 4; ++k) ASSERT_GE(state[k], Lfsr113::kMinimumSeed[k]);
    }
    EXPECT_NE(Lfsr113::fromKey(1).state(), Lfsr113::fromKey(2).state());
}

TEST(Lfsr113, UniformStatisticsAndNoShortPeriod) {
    Lfsr113 random = Lfsr113::fromKey(7);
    const std::array<uint32_t, 4> initial = random.state();
    const int samples = 1000000;
    double sum = 0.0, sumSquares = 0.0;
    std::array<int, 32> bitSet{};
    std::array<int, 10> decile{};
    for (int i = 0; i < samples; ++i) {
        uint32_t word = random.nextU32();
        ASSERT_NE(random.state(), initial) << "period " << i + 1;
        for (int b = 0; b < 32; ++b) bitSet[b] += (word >> b) & 1u;
        double u = double(word) / 4294967296.0;
        sum += u;
        sumSquares += u * u;
        ++decile[int(u * 10.0)];
    }
    // Standard error of the mean is sqrt(1/12 / 1e6) ~ 2.9e-4: 5 sigma bounds.
    double mean = sum / samples;
    EXPECT_NEAR(mean, 0.5, 1.5e-3);
    EXPECT_NEAR(sumSquares / samples - mean * mean, 1.0 / 12.0, 1e-3);
    for (int b = 0; b < 32; ++b) EXPECT_NEAR(bitSet[b] / double(samples), 0.5, 2.5e-3) << "bit " << b;
    for (int d = 0; d < 10; ++d) EXPECT_NEAR(decile[d] / double(samples), 0.1, 1.5e-3) << d;
}

TEST(Lfsr113, UnitFloatsStayBelowOne) {
    Lfsr113 random = Lfsr113::fromKey(3);
    for (int i = 0; i < 100000; ++i) {
        float u = random.nextUnit();
        ASSERT_GE(u, 0.0f);
        ASSERT_LT(u, 1.0f);
    }
}

PlantPlacementSettings testSettings() {
    PlantPlacementSettings settings;
    settings.worldSeed = 42;
    settings.variantCount = uint32_t(2 * plantPresets().size());  // the atlas: two rows of presets
    return settings;
}

bool samePlants(const std::vector<PlantInstance>& a, const std::vector<PlantInstance>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i].base != b[i].base || a[i].size != b[i].size || a[i].tint != b[i].tint ||
            a[i].variant != b[i].variant || a[i].windPhase != b[i].windPhase)
            return false;
    return true;
}

// The placement table's row of a placed plant, from its atlas cell's preset.
const PlantKind& kindOf(const PlantInstance& plant) {
    const std::string& preset = plantPresets()[plant.variant % plantPresets().size()].name;
    for (const PlantKind& kind : plantPlacementTable())
        if (preset == kind.preset) return kind;
    throw std::logic_error("a placed plant whose preset is not in the table: " + preset);
}

// Sizes run from shrub to tree in one table, every row a real preset, and the placed plants
// follow it: each within its row's sizes, each row placed in its share, the whole span covered.
TEST(Placement, PlantSizesSpanShrubToTreePerTheTable) {
    const std::vector<PlantKind>& table = plantPlacementTable();
    float shares = 0.0f, lowest = INFINITY, highest = 0.0f;
    for (const PlantKind& kind : table) {
        ASSERT_NE(findPlantPreset(kind.preset), nullptr) << kind.preset;
        ASSERT_GT(kind.minSize, 0.0f);
        ASSERT_LE(kind.minSize, kind.maxSize);
        shares += kind.share;
        lowest = std::min(lowest, kind.minSize);
        highest = std::max(highest, kind.maxSize);
    }
    EXPECT_NEAR(shares, 1.0f, 1e-5f);
    EXPECT_LE(lowest, 1.0f) << "no plant as low as a shrub or herb";
    EXPECT_GE(highest, 8.0f) << "no plant as tall as a tree";

    TerrainShape shape;
    PlantPlacementSettings settings = testSettings();
    std::vector<PlantInstance> plants = placePlantsInChunks(shape, settings, {-8, -8}, {16, 16});
    ASSERT_GT(plants.size(), 4000u);
    std::map<std::string, std::size_t> placed;
    float smallest = INFINITY, tallest = 0.0f;
    for (const PlantInstance& plant : plants) {
        const PlantKind& kind = kindOf(plant);
        ASSERT_GE(plant.size, kind.minSize) << kind.preset;
        ASSERT_LE(plant.size, kind.maxSize) << kind.preset;
        placed[kind.preset]++;
        smallest = std::min(smallest, plant.size);
        tallest = std::max(tallest, plant.size);
    }
    // The ground rules do not look at the kind, so each row keeps its share (binomial: 3 sigma of
    // a share near 0.3 over 4000 plants is 0.022).
    for (const PlantKind& kind : table)
        EXPECT_NEAR(double(placed[kind.preset]) / double(plants.size()), kind.share, 0.03) << kind.preset;
    EXPECT_LE(smallest, lowest + 0.1f);
    EXPECT_GE(tallest, highest - 0.5f);
    std::printf("[placement] %zu plants, sizes %.2f to %.2f world units\n", plants.size(), smallest, tallest);
}

TEST(Placement, ChunksAreDeterministicAndIndependent) {
    TerrainShape shape;
    PlantPlacementSettings settings = testSettings();
    // The first chunk along a diagonal that has ground for plants (not all water or rock).
    glm::ivec2 chunk(0, 0);
    std::vector<PlantInstance> once;
    for (int i = 0; i < 64 && once.empty(); ++i) {
        chunk = glm::ivec2(3 + i, -2 - i);
        once = placePlantsInChunk(shape, settings, chunk);
    }
    ASSERT_FALSE(once.empty());
    EXPECT_TRUE(samePlants(once, placePlantsInChunk(shape, settings, chunk)));
    EXPECT_FALSE(samePlants(once, placePlantsInChunk(shape, settings, chunk + glm::ivec2(1, 0))));
    EXPECT_FALSE(samePlants(once, placePlantsInChunk(shape, settings, glm::ivec2(chunk.y, chunk.x))));
    settings.worldSeed = 43;
    EXPECT_FALSE(samePlants(once, placePlantsInChunk(shape, settings, chunk)));

    // A chunk generated inside a block is the same as the chunk generated alone.
    settings = testSettings();
    // A 2x2 block whose last chunk (in x-fastest order) is `chunk`.
    glm::ivec2 origin = chunk - glm::ivec2(1, 1);
    std::vector<PlantInstance> block = placePlantsInChunks(shape, settings, origin, {2, 2});
    std::size_t before = placePlantsInChunk(shape, settings, origin).size() +
                         placePlantsInChunk(shape, settings, origin + glm::ivec2(1, 0)).size() +
                         placePlantsInChunk(shape, settings, origin + glm::ivec2(0, 1)).size();
    ASSERT_GE(block.size(), before + once.size());
    std::vector<PlantInstance> fromBlock(block.begin() + long(before),
                                         block.begin() + long(before + once.size()));
    EXPECT_TRUE(samePlants(once, fromBlock));
}

TEST(Placement, EveryPlantSitsOnAllowedGroundInsideItsChunk) {
    TerrainShape shape;
    PlantPlacementSettings settings = testSettings();
    const glm::ivec2 first(-6, -6), count(12, 12);
    std::vector<PlantInstance> plants = placePlantsInChunks(shape, settings, first, count);
    const std::size_t candidates = std::size_t(settings.candidatesPerChunk) * 144;
    EXPECT_GT(plants.size(), candidates / 10);  // the rules thin, not empty, the land
    EXPECT_LT(plants.size(), candidates);       // and the region has water or rock to avoid
    for (const PlantInstance& plant : plants) {
        glm::vec2 xz(plant.base.x, plant.base.z);
        glm::vec3 height = terrainHeight(shape, xz);
        ASSERT_NEAR(plant.base.y, height.x, 1e-4f);
        ASSERT_GE(plant.base.y, settings.waterLevel);
        ASSERT_LE(plant.base.y - settings.waterLevel, settings.maxHeightAboveWater);
        ASSERT_GE(terrainNormal(shape, xz).y, settings.minNormalY);
        glm::ivec2 chunk = chunkContaining(settings, xz);
        ASSERT_GE(chunk.x, first.x);
        ASSERT_LE(chunk.x, first.x + count.x);  // a plant may round onto its chunk's far edge
        ASSERT_GE(chunk.y, first.y);
        ASSERT_LE(chunk.y, first.y + count.y);
        const PlantKind& kind = kindOf(plant);
        ASSERT_GE(plant.size, kind.minSize) << kind.preset;
        ASSERT_LE(plant.size, kind.maxSize) << kind.preset;
        ASSERT_LT(plant.variant, settings.variantCount);
        ASSERT_GE(plant.windPhase, 0.0f);
        ASSERT_LT(plant.windPhase, float(2.0 * M_PI));
        ASSERT_GT(plant.tint.g, 0.5f);
    }
}

TEST(Placement, StricterRulesOnlyRemovePlants) {
    TerrainShape shape;
    PlantPlacementSettings loose = testSettings(), strict = testSettings();
    strict.waterLevel = 8.0f;
    // The rock line sits at a height above the water: lower it with the rising water.
    strict.maxHeightAboveWater = loose.maxHeightAboveWater - 8.0f;
    strict.minNormalY = 0.9f;
    std::vector<PlantInstance> all = placePlantsInChunks(shape, loose, {-3, -3}, {6, 6});
    std::vector<PlantInstance> kept = placePlantsInChunks(shape, strict, {-3, -3}, {6, 6});
    ASSERT_LT(kept.size(), all.size());
    std::size_t matched = 0;  // `kept` is a subsequence of `all`
    for (const PlantInstance& plant : all)
        if (matched < kept.size() && samePlants({plant}, {kept[matched]})) ++matched;
    EXPECT_EQ(matched, kept.size());
    for (const PlantInstance& plant : kept) {
        EXPECT_GE(plant.base.y, strict.waterLevel);
        EXPECT_TRUE(plantCanGrowAt(shape, strict, {plant.base.x, plant.base.z}));
    }
}

TEST(Placement, EverythingUnderWaterMeansNoPlants) {
    TerrainShape shape;
    PlantPlacementSettings settings = testSettings();
    settings.waterLevel = 1e6f;
    EXPECT_TRUE(placePlantsInChunks(shape, settings, {0, 0}, {3, 3}).empty());
}

}  // namespace
}  // namespace oasis
