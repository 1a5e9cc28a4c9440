// The plant atlas: the compute-shader turtle against the CPU composition it mirrors (segments
// read back from the SSBO), the atlas's content and colours, and the CPU path's atlas against the
// GPU path's.
#include <algorithm>
#include <cmath>

#include "gpu_test.h"
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

TEST_F(PlantAtlasTest, AtlasViewShowsTheAtlas) {
    PlantAtlas atlas(*shaders_, PlantInterpretation::Cpu);
    Renderer renderer(*shaders_, SceneSettings{});
    renderer.configure(atlas.width(), atlas.height(), layoutNamed("standard"));
    renderer.setPlantAtlas(&atlas);
    Image view = renderView(renderer, SceneSettings{}, PipelineKind::Deferred, "atlas");
    Image expected = atlas.read();
    for (size_t i = 0; i < expected.rgba.size(); i += 4) expected.rgba[i + 3] = 255;  // shown on black
    EXPECT_EQ(compareImages(view, expected).maxAbs, 0);
    renderer.setPlantAtlas(nullptr);
    EXPECT_EQ(rgbStats(renderView(renderer, SceneSettings{}, PipelineKind::Deferred, "atlas"), wholeImage(view)).maxMean(), 0.0)
        << "with no atlas the view is black";
}

}  // namespace
}  // namespace oasis::gputest
