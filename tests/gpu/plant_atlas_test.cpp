// The plant atlas: the compute-shader turtle against the CPU composition it mirrors (segments
// read back from the SSBO), the atlas's content and colours, and the CPU path's atlas against the
// GPU path's.
#include <algorithm>
#include <cmath>

#include "gpu_test.h"
#include "common/shared_constants.glsl"
#include "render/coverage_mips.h"
#include "render/plant_atlas.h"
#include "render/plant_interpreter.h"
#include "scene/lsystem.h"
#include "scene/turtle.h"

namespace oasis::gputest {
namespace {

class PlantAtlasTest : public GpuTest {};

bool bitIdentical(const Segment2D& a, const Segment2D& b) {
    return a.start == b.start && a.end == b.end && a.depth == b.depth && a.distanceFromRoot == b.distanceFromRoot;
}

float plantExtent(const std::vector<Segment2D>& segments) {
    float extent = 1.0f;
    for (const Segment2D& s : segments)
        extent = std::max({extent, std::fabs(s.start.x), std::fabs(s.start.y), std::fabs(s.end.x), std::fabs(s.end.y)});
    return extent;
}

TEST_F(PlantAtlasTest, GpuSegmentsEqualCpuCompositionForEveryPresetUpToSixRewrites) {
    std::string why;
    if (!gl::measureCapabilities().computeAvailable(&why)) GTEST_SKIP() << "this context has no compute path: " << why;
    GpuTurtleInterpreter gpu(*shaders_);
    size_t total = 0, identical = 0;
    for (const PlantPreset& preset : plantPresets()) {
        for (int iterations = 0; iterations <= std::max(6, preset.system.iterations); ++iterations) {
            TurtleProgram program = encodeTurtleProgram(rewrite(preset.system, iterations));
            std::vector<Segment2D> cpu = interpretTurtleByComposition(program, preset.system.angleDegrees);
            std::vector<Segment2D> fromGpu = readSegments(gpu.interpret(program, preset.system.angleDegrees));
            ASSERT_EQ(fromGpu.size(), countForwardSteps(program)) << preset.name << " x" << iterations;
            ASSERT_EQ(fromGpu.size(), cpu.size());
            const float tolerance = 1e-5f * plantExtent(cpu);  // relative to the plant's size
            for (size_t i = 0; i < cpu.size(); ++i) {
                const Segment2D &c = cpu[i], &g = fromGpu[i];
                ASSERT_LE(glm::length(g.start - c.start), tolerance) << preset.name << " x" << iterations << " #" << i;
                ASSERT_LE(glm::length(g.end - c.end), tolerance) << preset.name << " x" << iterations << " #" << i;
                ASSERT_EQ(g.depth, c.depth) << preset.name << " x" << iterations << " #" << i;
                ASSERT_EQ(g.distanceFromRoot, c.distanceFromRoot) << preset.name << " x" << iterations << " #" << i;
                identical += bitIdentical(g, c);
            }
            total += cpu.size();
        }
    }
    std::printf("[plants] %zu of %zu GPU segments bit-identical to the CPU composition\n", identical, total);
}

TEST_F(PlantAtlasTest, GpuRoundsMatchTheCpuComposition) {
    for (const PlantPreset& preset : plantPresets()) {
        TurtleProgram program = encodeTurtleProgram(rewrite(preset.system, preset.system.iterations));
        TurtleLinks links = linkTurtleInstructions(program);
        int cpuRounds = 0;
        composeAlongPredecessors(localTurtleTransforms(program, preset.system.angleDegrees), links.predecessor,
                                 &cpuRounds);
        GpuTurtleLinks gpuLinks = linkForGpu(program);
        EXPECT_EQ(gpuLinks.rounds, cpuRounds) << preset.name;
        EXPECT_EQ(gpuLinks.segmentCount, countForwardSteps(program)) << preset.name;
    }
}

TEST_F(PlantAtlasTest, PathChoiceFollowsTheContextAndTheFlag) {
    std::string reason;
    gl::Capabilities caps = gl::measureCapabilities();
    EXPECT_EQ(choosePlantInterpretation(caps, true, reason), PlantInterpretation::Cpu);
    EXPECT_NE(reason.find("--no-compute"), std::string::npos) << reason;
    PlantInterpretation automatic = choosePlantInterpretation(caps, false, reason);
    EXPECT_EQ(automatic, contextHasComputeShaders() ? PlantInterpretation::Gpu : PlantInterpretation::Cpu) << reason;
    if (automatic != PlantInterpretation::Gpu) return;  // nothing to switch off on this context
    for (gl::ForcedFallbacks forced : {gl::ForcedFallbacks{true}, gl::ForcedFallbacks{false, true}}) {
        caps.forced = forced;  // --force no-ssbo, --force no-compute
        EXPECT_EQ(choosePlantInterpretation(caps, false, reason), PlantInterpretation::Cpu) << forced.list();
        EXPECT_NE(reason.find("--force " + forced.list()), std::string::npos) << reason;
    }
}

// Mean colour of the plant's pixels in a band of rows of one cell (rows counted from the top).
struct Band { double red = 0, green = 0; int pixels = 0; };
Band bandColour(const Image& image, int x0, int rowFrom, int rowTo, int cellSize) {
    Band band;
    for (int y = rowFrom; y <= rowTo; ++y)
        for (int x = x0; x < x0 + cellSize; ++x) {
            const uint8_t* p = image.pixel(x, y);
            if (p[3] == 0) continue;
            band.red += p[0];
            band.green += p[1];
            ++band.pixels;
        }
    if (band.pixels) { band.red /= band.pixels; band.green /= band.pixels; }
    return band;
}

TEST_F(PlantAtlasTest, EveryCellHasAPlantBrownAtTheBaseAndGreenAtTheTips) {
    PlantAtlas atlas(*shaders_, contextHasComputeShaders() ? PlantInterpretation::Gpu : PlantInterpretation::Cpu);
    Image image = atlas.read();
    ASSERT_EQ(image.width, atlas.width());
    const auto& variants = plantAtlasVariants();
    for (size_t v = 0; v < variants.size(); ++v) {
        std::string name = variants[v].preset + " x" + std::to_string(variants[v].iterations);
        int x0 = atlas.cellX(v), y0 = atlas.cellY(v), size = atlas.cellSize();
        int top = -1, bottom = -1, drawn = 0;
        for (int y = y0; y < y0 + size; ++y)
            for (int x = x0; x < x0 + size; ++x) {
                const uint8_t* p = image.pixel(x, y);
                if (p[3] == 0) {
                    EXPECT_TRUE(p[0] == 0 && p[1] == 0 && p[2] == 0) << name << ": transparent but coloured";
                    continue;
                }
                EXPECT_EQ(p[3], 255) << name;
                ++drawn;
                if (top < 0) top = y;
                bottom = y;
            }
        ASSERT_GT(drawn, 200) << name << ": too few plant pixels";
        int band = std::max(2, (bottom - top) / 10);
        Band base = bandColour(image, x0, bottom - band, bottom, size);
        Band tips = bandColour(image, x0, top, top + band, size);
        EXPECT_GT(base.red, base.green + 10) << name << ": the base is not brown";
        EXPECT_GT(tips.green, tips.red + 10) << name << ": the tips are not green";
    }
}

TEST_F(PlantAtlasTest, CpuPathDrawsTheSameAtlasAsTheGpuPath) {
    std::string why;
    if (!gl::measureCapabilities().computeAvailable(&why)) GTEST_SKIP() << "this context has no compute path: " << why;
    PlantAtlas gpu(*shaders_, PlantInterpretation::Gpu), cpu(*shaders_, PlantInterpretation::Cpu);
    ASSERT_EQ(gpu.segments().size(), cpu.segments().size());
    bool sameSegments = true;
    for (size_t v = 0; v < gpu.segments().size(); ++v) {
        ASSERT_EQ(gpu.segments()[v].size(), cpu.segments()[v].size());
        for (size_t i = 0; i < gpu.segments()[v].size(); ++i)
            sameSegments = sameSegments && bitIdentical(gpu.segments()[v][i], cpu.segments()[v][i]);
    }
    ImageDifference difference = compareImages(gpu.read(), cpu.read());
    // Start-up costs: the first GPU atlas compiles its programs; a second one, with them built, is
    // what the interpretation itself costs (the CPU atlas above already had the draw program).
    PlantAtlas gpuAgain(*shaders_, PlantInterpretation::Gpu);
    std::printf("[plants] atlas cpu vs gpu: segments %s, PSNR %.2f dB, max abs %d; start-up ms (segments ready / "
                "atlas drawn): gpu with compiles %.1f / %.1f, gpu %.1f / %.1f, cpu %.1f / %.1f\n",
                sameSegments ? "bit-identical" : "differ", difference.psnrDb, difference.maxAbs, gpu.interpretMs(),
                gpu.totalMs(), gpuAgain.interpretMs(), gpuAgain.totalMs(), cpu.interpretMs(), cpu.totalMs());
    // The same segments through the same draw give the same pixels.
    if (sameSegments) EXPECT_EQ(difference.maxAbs, 0);
    // Otherwise (a driver that rounds differently) the lines move by at most a pixel here and there.
    EXPECT_GE(difference.psnrDb, 40.0);
}

// The billboards test alpha against one threshold at every mip level, so each cell's coverage (the
// fraction of its texels that pass) must hold level to level, or far plants thin out or swell and
// their edges crawl as the level changes. Plain box-filtered levels (glGenerateMipmap's, built
// here from the same level 0) lose a plant's thin branches level by level and fail the bound.
TEST_F(PlantAtlasTest, AlphaCoverageHoldsAcrossMipLevels) {
    PlantAtlas atlas(*shaders_, PlantInterpretation::Cpu);
    const float threshold = float(OASIS_PLANT_ALPHA_THRESHOLD);
    // The most a level's coverage may differ from level 0's, relatively. One scale per cell and
    // level cannot split texels of equal alpha, and level 0 is drawn opaque or empty, so level 1
    // holds only the alphas 0, 1/4, 1/2, 3/4 and 1: 15 % down to cells of 32 texels (measured at
    // most 11.6 %); 20 % at 16 and 8 texels, where one texel is 1/256 and 1/64 of a cell (measured
    // at most 17.7 %). Plain box filtering loses all of a plant's coverage by the last level.
    auto boundAt = [](int level) { return level <= 3 ? 0.15 : 0.20; };
    std::vector<MipImage> stored;
    for (int level = 0; level < PlantAtlas::kMipLevels; ++level) stored.push_back(atlas.readLevel(level));
    const std::vector<MipImage> plain = boxFilteredMips(stored[0], PlantAtlas::kMipLevels);
    ASSERT_EQ(plain.size(), stored.size());
    double worstStored = 0.0, worstPlain = 0.0;
    bool plainOutside = false;
    for (int row = 0; row < atlas.rows(); ++row)
        for (int column = 0; column < atlas.columns(); ++column) {
            const double base = alphaCoverage(stored[0], column, row, atlas.cellSize(), threshold);
            ASSERT_GT(base, 0.005) << "cell " << column << "," << row << " is nearly empty";
            for (int level = 1; level < PlantAtlas::kMipLevels; ++level) {
                const int size = atlas.cellSize() >> level;
                const double kept = alphaCoverage(stored[size_t(level)], column, row, size, threshold) / base;
                const double boxed = alphaCoverage(plain[size_t(level)], column, row, size, threshold) / base;
                EXPECT_NEAR(kept, 1.0, boundAt(level)) << "cell " << column << "," << row << " level " << level;
                worstStored = std::max(worstStored, std::fabs(kept - 1.0));
                worstPlain = std::max(worstPlain, std::fabs(boxed - 1.0));
                plainOutside = plainOutside || std::fabs(boxed - 1.0) > boundAt(level);
            }
        }
    std::printf("[plants] alpha coverage at %.2f across %d mip levels, worst relative change from level 0: "
                "stored %.3f, plain box filter %.3f\n", threshold, PlantAtlas::kMipLevels, worstStored, worstPlain);
    EXPECT_TRUE(plainOutside) << "plain box filtering would pass too: the bound tests nothing";
}

TEST_F(PlantAtlasTest, AtlasViewShowsTheAtlas) {
    PlantAtlas atlas(*shaders_, PlantInterpretation::Cpu);
    Renderer renderer(*shaders_, SceneSettings{});
    renderer.configure(atlas.width(), atlas.height(), layoutNamed("standard"));
    renderer.views().setPlantAtlas(&atlas);
    Image view = renderView(renderer, SceneSettings{}, PipelineKind::Deferred, "atlas");
    Image expected = atlas.read();
    for (size_t i = 0; i < expected.rgba.size(); i += 4) expected.rgba[i + 3] = 255;  // shown on black
    EXPECT_EQ(compareImages(view, expected).maxAbs, 0);
    renderer.views().setPlantAtlas(nullptr);
    EXPECT_EQ(rgbStats(renderView(renderer, SceneSettings{}, PipelineKind::Deferred, "atlas"), wholeImage(view)).maxMean(), 0.0)
        << "with no atlas the view is black";
}

}  // namespace
}  // namespace oasis::gputest
