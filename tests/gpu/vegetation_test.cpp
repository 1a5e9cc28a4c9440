// Vegetation on the GPU: plant bases on the terrain the GPU draws (CPU noise vs the shader's
// heights within 1e-3), the toggle changing only plant and water pixels, plants in the water's
// reflection in both pipelines, wind that moves plants (and does not in still air, nor jumps after
// days of animation), and the CPU-interpreted atlas giving the same frame as the compute one.
#include "frame/frame_readback.h"
#include "gpu_test.h"

#include <cstring>

namespace oasis::gputest {
namespace {


class Vegetation : public GpuTest {
protected:
    // A deferred frame of `scene` and its stencil.
    std::vector<uint8_t> stencilOf(Renderer& renderer, const SceneSettings& scene, PipelineKind kind) {
        renderer.setPipeline(kind);
        renderer.renderFrame(scene);
        return readStencil(renderer);
    }
};

size_t countValue(const std::vector<uint8_t>& values, uint8_t value) {
    return size_t(std::count(values.begin(), values.end(), value));
}

TEST_F(Vegetation, PlantBasesLieOnTheTerrainTheGpuDraws) {
    NamedPose pose = poseNamed("meadow");
    Renderer renderer(*shaders_, pose.scene);
    renderer.configure(kMediumWidth, kMediumHeight, layoutNamed("standard"));
    auto atlas = attachPlantAtlas(*shaders_, renderer);
    renderer.renderFrame(pose.scene);
    std::vector<PlantInstance> plants = renderer.lastFrame().vegetation.placedPlants();
    ASSERT_GE(plants.size(), 20000u) << "fewer plants than the issue asks for around the camera";
    // Every 7th plant: 5,000-odd bases spread over the whole field.
    std::vector<glm::vec2> points;
    std::vector<float> baseHeights;
    for (size_t i = 0; i < plants.size(); i += 7) {
        points.emplace_back(plants[i].base.x, plants[i].base.z);
        baseHeights.push_back(plants[i].base.y);
    }
    std::vector<glm::vec3> gpu = probeGpuHeights(*shaders_, renderer, points);
    ASSERT_EQ(gpu.size(), points.size());
    double worst = 0.0;
    size_t worstIndex = 0;
    for (size_t i = 0; i < gpu.size(); ++i) {
        double error = std::fabs(double(gpu[i].x) - double(baseHeights[i]));
        if (error > worst) { worst = error; worstIndex = i; }
    }
    std::printf("[vegetation] %zu bases checked of %zu placed: worst |base - GPU terrain| = %.2e at (%.1f, %.1f)\n",
                points.size(), plants.size(), worst, points[worstIndex].x, points[worstIndex].y);
    EXPECT_LE(worst, 1e-3);
}

TEST_F(Vegetation, ToggleChangesOnlyPlantAndWaterPixels) {
    NamedPose pose = poseNamed("meadow");
    SceneSettings off = pose.scene;
    off.vegetation.enabled = false;
    Renderer renderer(*shaders_, pose.scene);
    renderer.configure(kMediumWidth, kMediumHeight, layoutNamed("standard"));
    auto atlas = attachPlantAtlas(*shaders_, renderer);
    // The plants' sun shadows fall on the ground beside them (tests/gpu/shadows_test.cpp): without
    // them, everything but the plants and the water must stay the same.
    pose.scene.shadows.enabled = false;
    off.shadows.enabled = false;
    for (PipelineKind kind : {PipelineKind::Forward, PipelineKind::Deferred}) {
        SCOPED_TRACE(pipelineName(kind));
        std::vector<uint8_t> stencilOn = stencilOf(renderer, pose.scene, kind);
        renderer.views().render("final");
        Image on = readDisplay(renderer);
        EXPECT_GT(renderer.lastFrame().vegetation.stats().plantsDrawn, 1000u);
        EXPECT_GT(renderer.lastFrame().vegetation.stats().plantsDrawnMirrored, 0u);
        std::vector<uint8_t> stencilOff = stencilOf(renderer, off, kind);
        renderer.views().render("final");
        Image offImage = readDisplay(renderer);
        EXPECT_EQ(renderer.lastFrame().vegetation.stats().plantsDrawn, 0u) << "plants drawn with vegetation off";
        EXPECT_EQ(countValue(stencilOff, kStencilPlant), 0u) << "plant stencil marks with vegetation off";
        size_t plantPixels = countValue(stencilOn, kStencilPlant);
        EXPECT_GT(plantPixels, size_t(kMediumWidth * kMediumHeight / 20)) << "the meadow shows few plants";
        // Outside plants (and the water, which reflects them) the two frames are the same bit for bit.
        size_t changedElsewhere = 0, changedInWater = 0;
        for (int y = 0; y < kMediumHeight; ++y)
            for (int x = 0; x < kMediumWidth; ++x) {
                uint8_t s = stencilOn[size_t(y) * kMediumWidth + size_t(x)];
                bool differs = displayPixel(on, x, y) != displayPixel(offImage, x, y);
                if (s == kStencilWater) changedInWater += differs;
                else if (s != kStencilPlant) changedElsewhere += differs;
            }
        EXPECT_EQ(changedElsewhere, 0u) << "vegetation changed pixels that show neither plants nor water";
        EXPECT_GT(changedInWater, 0u) << "the plants' reflections do not show in the water";
    }
}

TEST_F(Vegetation, ReflectedPlantsInBothPipelines) {
    NamedPose pose = poseNamed("meadow");
    Renderer renderer(*shaders_, pose.scene);
    renderer.configure(kMediumWidth, kMediumHeight, layoutNamed("full"));
    auto atlas = attachPlantAtlas(*shaders_, renderer);
    // Deferred: the water pixels of the G-buffer hold the mirrored scene, plants among it.
    std::vector<uint8_t> stencil = stencilOf(renderer, pose.scene, PipelineKind::Deferred);
    std::vector<float> info = readTarget(renderer, Target::Info);
    size_t reflectedPlants = 0, misplaced = 0;
    for (int y = 0; y < kMediumHeight; ++y)
        for (int x = 0; x < kMediumWidth; ++x) {
            unsigned flags = infoFlags(texel(info, kMediumWidth, x, y));
            if ((flags & kSurfacePlant) && (flags & kSurfaceReflected)) {
                ++reflectedPlants;
                misplaced += stencil[size_t(y) * kMediumWidth + size_t(x)] != kStencilWater;
            }
        }
    EXPECT_GT(reflectedPlants, 20u) << "no reflected plants in the deferred G-buffer's water";
    EXPECT_EQ(misplaced, 0u) << "reflected plants outside the water";
    // Forward: the Reflection target changes when the plants go, inside the water only.
    std::vector<float> withPlants = (stencilOf(renderer, pose.scene, PipelineKind::Forward),
                                     readTarget(renderer, Target::Reflection));
    SceneSettings off = pose.scene;
    off.vegetation.enabled = false;
    std::vector<float> without = (stencilOf(renderer, off, PipelineKind::Forward), readTarget(renderer, Target::Reflection));
    size_t changed = 0;
    for (size_t i = 0; i < withPlants.size(); i += 4)
        changed += withPlants[i] != without[i] || withPlants[i + 1] != without[i + 1] || withPlants[i + 2] != without[i + 2];
    EXPECT_GT(changed, 20u) << "forward reflections do not show the plants";
}

TEST_F(Vegetation, WindMovesPlantsAndStillAirDoesNot) {
    NamedPose pose = poseNamed("meadow");
    pose.scene.hour = 10.0;  // the sky must not change with time
    pose.scene.water.reflections = false;
    Renderer renderer(*shaders_, pose.scene);
    renderer.configure(kMediumWidth, kMediumHeight, layoutNamed("standard"));
    auto atlas = attachPlantAtlas(*shaders_, renderer);
    auto plantMask = [&](float wind, double time) {
        SceneSettings scene = pose.scene;
        scene.timeSeconds = time;
        scene.vegetation.windStrength = wind;
        return stencilOf(renderer, scene, PipelineKind::Deferred);
    };
    auto differing = [](const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
        size_t n = 0;
        for (size_t i = 0; i < a.size(); ++i) n += (a[i] == kStencilPlant) != (b[i] == kStencilPlant);
        return n;
    };
    EXPECT_EQ(differing(plantMask(0.0f, 0.0), plantMask(0.0f, 1.5)), 0u) << "plants move in still air";
    size_t moved = differing(plantMask(1.0f, 0.0), plantMask(1.0f, 1.5));
    std::printf("[vegetation] wind 1, 1.5 s apart: %zu plant-mask pixels differ\n", moved);
    EXPECT_GT(moved, 20u) << "wind does not move the plants";
    // After days of animation the wind stays smooth: 1/30 s apart moves few pixels, not a jump.
    size_t late = differing(plantMask(1.0f, 1.0e6), plantMask(1.0f, 1.0e6 + 1.0 / 30.0));
    EXPECT_LT(late, moved) << "wind at t = 1e6 s jumps between frames";
}

TEST_F(Vegetation, CpuAtlasDrawsTheSameFrame) {
    if (!contextHasComputeShaders()) GTEST_SKIP() << "no compute shaders on this context: only the CPU path exists";
    NamedPose pose = poseNamed("meadow");
    Renderer renderer(*shaders_, pose.scene);
    renderer.configure(kMediumWidth, kMediumHeight, layoutNamed("standard"));
    PlantAtlas gpuAtlas(*shaders_, PlantInterpretation::Gpu), cpuAtlas(*shaders_, PlantInterpretation::Cpu);
    renderer.views().setPlantAtlas(&gpuAtlas);
    Image gpu = renderFinal(renderer, pose.scene, PipelineKind::Deferred);
    renderer.views().setPlantAtlas(&cpuAtlas);
    Image cpu = renderFinal(renderer, pose.scene, PipelineKind::Deferred);
    EXPECT_EQ(compareImages(gpu, cpu).maxAbs, 0) << "the CPU-interpreted atlas draws a different frame";
    EXPECT_GT(renderer.lastFrame().vegetation.stats().plantsDrawn, 0u);
}

// Fragment shader invocations of one frame, where the context counts them (GL 4.6 or
// ARB_pipeline_statistics_query); -1 otherwise.
long long fragmentInvocations(Renderer& renderer, const SceneSettings& scene) {
    if (epoxy_gl_version() < 46 && !epoxy_has_gl_extension("GL_ARB_pipeline_statistics_query")) return -1;
    GLuint query = 0;
    glGenQueries(1, &query);
    glBeginQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB, query);
    renderer.renderFrame(scene);
    glEndQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB);
    GLuint64 count = 0;
    glGetQueryObjectui64v(query, GL_QUERY_RESULT, &count);
    glDeleteQueries(1, &query);
    return (long long)count;
}

// Billboards trimmed to their cell's drawn bounds draw the plants they drew as whole cells: every
// texel the alpha test can keep lies inside its cell's box, the frames agree but for single edge
// pixels (atlas coordinates interpolated from other corners), and the plants
// cost fewer fragments.
TEST_F(Vegetation, TrimmedBillboardsDrawTheSamePlantsWithFewerFragments) {
    NamedPose pose = poseNamed("meadow");
    Renderer renderer(*shaders_, pose.scene);
    renderer.configure(kMediumWidth, kMediumHeight, layoutNamed("standard"));
    auto atlas = attachPlantAtlas(*shaders_, renderer);

    const std::vector<glm::vec4>& bounds = atlas->drawnBounds();
    ASSERT_EQ(bounds.size(), atlas->variantCount());
    const Image cells = atlas->read();  // top row first
    double boxArea = 0.0;
    for (size_t cell = 0; cell < bounds.size(); ++cell) {
        const glm::vec4 box = bounds[cell];
        ASSERT_LT(box.x, box.z) << "cell " << cell << " has no drawn bounds";
        boxArea += double(box.z - box.x) * double(box.w - box.y);
        int outside = 0;
        for (int y = 0; y < atlas->cellSize(); ++y)
            for (int x = 0; x < atlas->cellSize(); ++x) {
                const uint8_t* texel = &cells.rgba[(size_t(atlas->cellY(cell) + y) * size_t(cells.width) +
                                                    size_t(atlas->cellX(cell) + x)) * 4];
                if (texel[3] < uint8_t(OASIS_PLANT_ALPHA_THRESHOLD * 255.0)) continue;
                float u = (float(x) + 0.5f) / float(atlas->cellSize());
                float v = 1.0f - (float(y) + 0.5f) / float(atlas->cellSize());  // v up, as the box
                if (u < box.x || u > box.z || v < box.y || v > box.w) ++outside;
            }
        EXPECT_EQ(outside, 0) << "cell " << cell << ": drawn texels outside its box";
    }
    const double meanArea = boxArea / double(bounds.size());
    std::printf("[vegetation] drawn bounds: %.1f%% of a cell on average\n", 100.0 * meanArea);
    EXPECT_LT(meanArea, 0.8) << "the boxes hardly trim the cells";

    for (PipelineKind kind : {PipelineKind::Forward, PipelineKind::Deferred}) {
        renderer.setPipeline(kind);
        SceneSettings whole = pose.scene, none = pose.scene;
        whole.vegetation.trimmedBillboards = false;
        none.vegetation.enabled = false;
        long long trimmedCount = fragmentInvocations(renderer, pose.scene);
        renderer.renderFrame(pose.scene);
        renderer.views().render("final");
        Image trimmed = readDisplay(renderer);
        EXPECT_TRUE(hasContent(trimmed));
        long long wholeCount = fragmentInvocations(renderer, whole);
        renderer.renderFrame(whole);
        renderer.views().render("final");
        Image reference = readDisplay(renderer);
        long long noneCount = fragmentInvocations(renderer, none);

        ImageDifference difference = compareImages(reference, trimmed);
        long differing = 0;
        for (size_t i = 0; i < reference.rgba.size(); i += 4)
            if (std::memcmp(&reference.rgba[i], &trimmed.rgba[i], 3) != 0) ++differing;
        std::printf("[vegetation] %s: trimmed vs whole billboards PSNR %.2f dB, %ld of %d pixels differ\n",
                    pipelineName(kind), difference.psnrDb, differing, kMediumWidth * kMediumHeight);
        // Measured: 84-89 dB, 6-12 edge pixels at 320x180 (a trimmed corner's atlas coordinates
        // interpolate a little differently from the whole cell's; the mip level is the billboard's
        // own, the same at every corner).
        // A GPU interpolates the two quads' coordinates with its own precision, and an alpha test
        // at a cut edge flips whole pixels (H100: 29-55 pixels, 47.8 dB): 40 dB there.
        EXPECT_GE(difference.psnrDb, cpuRasteriser() ? 60.0 : 40.0) << pipelineName(kind);
        EXPECT_LE(differing, long(kMediumWidth * kMediumHeight / 200)) << pipelineName(kind) << ": more than 0.5% of pixels";
        if (trimmedCount < 0) {
            std::printf("[vegetation] no pipeline statistics query here: fragment counts not checked\n");
            continue;
        }
        double plantsTrimmed = double(trimmedCount - noneCount), plantsWhole = double(wholeCount - noneCount);
        std::printf("[vegetation] %s: plant fragments %.0f trimmed, %.0f whole (%.1f%%)\n", pipelineName(kind),
                    plantsTrimmed, plantsWhole, 100.0 * plantsTrimmed / plantsWhole);
        EXPECT_GT(plantsWhole, 0.0);
        EXPECT_LT(plantsTrimmed, 0.8 * plantsWhole) << pipelineName(kind);
    }
}

}  // namespace
}  // namespace oasis::gputest
