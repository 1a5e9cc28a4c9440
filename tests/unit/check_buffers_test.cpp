// The buffers in the check's pass-by-pass search without GL (check/check_buffers.h): the tile
// lists checked against the lights that reach each pixel, decoded buffers compared in order or as
// a multiset, their trip between processes, and the first divergence naming a buffer before the
// targets of the passes that read it.
#include <gtest/gtest.h>

#include <cstring>

#include "check/check_buffers.h"
#include "check/check_snapshots.h"
#include "common/shared_constants.glsl"
#include "passes/light_tiling_pass.h"

namespace oasis {
namespace {

constexpr int kSliceStride = OASIS_LIGHT_TILE_MAX_LIGHTS + 1;
constexpr int kTileStride = 2 + OASIS_LIGHT_TILE_SLICES * kSliceStride;

uint32_t bitsOf(float value) {
    uint32_t bits;
    std::memcpy(&bits, &value, sizeof(bits));
    return bits;
}

// Two tiles side by side (a 32x16 frame), each with a surface range of 10..20 and `listed` in
// every slice of tile 0; tile 1 lists nothing.
std::vector<uint32_t> tileLists(const std::vector<uint32_t>& listed) {
    std::vector<uint32_t> words(LightTilingPass::listBytes(32, 16) / sizeof(uint32_t), 0u);
    for (int tile = 0; tile < 2; ++tile) {
        words[size_t(tile * kTileStride)] = bitsOf(10.0f);
        words[size_t(tile * kTileStride + 1)] = bitsOf(20.0f);
    }
    for (int slice = 0; slice < OASIS_LIGHT_TILE_SLICES; ++slice) {
        size_t base = size_t(2 + slice * kSliceStride);
        words[base] = uint32_t(listed.size());
        for (size_t k = 0; k < listed.size(); ++k) words[base + 1 + k] = listed[k];
    }
    return words;
}

// Every pixel a surface 15 units ahead; the sky at pixel (1, 0).
std::vector<float> surfaces() {
    std::vector<float> positions;
    for (int p = 0; p < 32 * 16; ++p) positions.insert(positions.end(), {0.0f, 0.0f, -15.0f, p == 1 ? 0.0f : 1.0f});
    return positions;
}

// Light 0 reaches every surface; light 1 is far away.
const std::vector<float> kLights = {0.0f, 0.0f, -14.0f, 5.0f, 1.0f, 1.0f, 1.0f, 3.0f,
                                    500.0f, 0.0f, 0.0f, 5.0f, 1.0f, 1.0f, 1.0f, 3.0f};

TEST(CheckBuffers, ALightMissingFromItsTilesListIsAFaultAtEveryPixelItReaches) {
    std::vector<float> faults = lightTileFaults(tileLists({0}), surfaces(), kLights, 32, 16);
    ASSERT_EQ(faults.size(), 32u * 16u);
    EXPECT_EQ(faults[0], 0.0f) << "tile 0 lists light 0";
    EXPECT_EQ(faults[1], 0.0f) << "the sky is lit by nothing";
    EXPECT_EQ(faults[16], 1.0f) << "tile 1 leaves light 0 out";
    EXPECT_EQ(faults[31 + 15 * 32], 1.0f);
    // The far light in the list, or more listed than reach, is no fault; leaving light 0 out is.
    EXPECT_EQ(lightTileFaults(tileLists({0, 1}), surfaces(), kLights, 32, 16)[0], 0.0f);
    EXPECT_EQ(lightTileFaults(tileLists({1}), surfaces(), kLights, 32, 16)[0], 1.0f);
}

TEST(CheckBuffers, ASliceOverItsMaximumUsesEveryLight) {
    std::vector<uint32_t> words = tileLists({});
    for (int slice = 0; slice < OASIS_LIGHT_TILE_SLICES; ++slice) words[size_t(2 + slice * kSliceStride)] = 100000u;
    EXPECT_EQ(lightTileFaults(words, surfaces(), kLights, 32, 16)[0], 0.0f);
}

TEST(CheckBuffers, DecodedBuffersCompareInOrderOrAsAMultiset) {
    BufferSnapshot a{"PlantInstances", 2, true, {1, 2, 3, 4, 5, 6}};
    BufferSnapshot shuffled{"PlantInstances", 2, true, {5, 6, 1, 2, 3, 4}};
    EXPECT_EQ(bufferDifferences(a, shuffled, 0), 0);
    shuffled.values[0] = 5.5f;
    EXPECT_EQ(bufferDifferences(a, shuffled, 0), 1);
    EXPECT_EQ(bufferDifferences(a, shuffled, 255), 0) << "within the level";
    BufferSnapshot ordered{"LightList", 2, false, {1, 2, 3, 4, 5, 6}}, reordered{"LightList", 2, false, {3, 4, 1, 2, 5, 6}};
    EXPECT_EQ(bufferDifferences(ordered, reordered, 0), 2);
    BufferSnapshot shorter{"LightList", 2, false, {1, 2}};
    EXPECT_EQ(bufferDifferences(ordered, shorter, 0), 2) << "the entries one path lacks";
}

TEST(CheckBuffers, SnapshotsCarryChecksAndBuffersBetweenProcesses) {
    std::vector<PassSnapshot> snapshots = {
        {kFrameInputsStep, {}, {}, {{"LightList", 8, false, {1, 2, 3, 4, 5, 6, 7, 8}}, {"PlantInstances", 9, true, {}}}},
        {"LightTilingPass", {}, {{"LightTiles", {0, 2, 1}}}, {}}};
    keepPixels(snapshots, {true, false, true});
    EXPECT_EQ(snapshots[1].pixelChecks[0].second, (std::vector<float>{0, 1}));
    EXPECT_EQ(snapshots[0].buffers[0].values.size(), 8u) << "a decoded buffer is kept whole";
    std::string bytes = encodeSnapshots(snapshots), error;
    std::vector<PassSnapshot> back;
    ASSERT_TRUE(decodeSnapshots(bytes, back, error)) << error;
    ASSERT_EQ(back.size(), 2u);
    EXPECT_EQ(back[0].buffers[1].name, "PlantInstances");
    EXPECT_TRUE(back[0].buffers[1].unordered);
    EXPECT_EQ(back[0].buffers[0].stride, 8u);
    EXPECT_EQ(back[0].buffers[0].values, snapshots[0].buffers[0].values);
    EXPECT_EQ(back[1].pixelChecks, snapshots[1].pixelChecks);
    for (size_t cut : {size_t(20), bytes.size() / 2, bytes.size() - 1})
        EXPECT_FALSE(decodeSnapshots(bytes.substr(0, cut), back, error)) << cut;
}

// The tiled path's lists miss a light that the volumes path (no tile lists) has no way to miss:
// the search names the tiling pass, before the lighting's Radiance that follows from it.
TEST(CheckBuffers, TheFirstDivergenceNamesTheTileListsBeforeTheRadiance) {
    std::vector<PassSnapshot> volumes = {{kFrameInputsStep, {}, {}, {{"LightList", 8, false, {1, 2, 3, 4, 5, 6, 7, 8}}}},
                                         {"LightTilingPass", {}},
                                         {"LightingPass", {{"Radiance", {0, 0, 0, 1, 0, 0, 0, 1}}}}};
    std::vector<PassSnapshot> tiled = volumes;
    tiled[1].pixelChecks.push_back({"LightTiles", {0, 3}});
    tiled[2].targets[0].second = {0, 0, 0, 1, 0.5f, 0, 0, 1};
    Divergence found;
    ASSERT_TRUE(firstDivergence(volumes, tiled, 0, {}, found));
    EXPECT_EQ(found.pass, "LightTilingPass");
    EXPECT_EQ(found.target, "LightTiles");
    EXPECT_EQ(found.pixels, 1);
    // Lists that miss nothing: the Radiance is where they part.
    tiled[1].pixelChecks[0].second = {0, 0};
    ASSERT_TRUE(firstDivergence(volumes, tiled, 0, {}, found));
    EXPECT_EQ(found.pass, "LightingPass");
    // A light decoded differently is named at the inputs, before any pass.
    tiled[0].buffers[0].values[7] = 32.0f;
    ASSERT_TRUE(firstDivergence(volumes, tiled, 0, {}, found));
    EXPECT_EQ(found.pass, kFrameInputsStep);
    EXPECT_EQ(found.target, "LightList");
    EXPECT_EQ(found.pixels, 1);
}

}  // namespace
}  // namespace oasis
