// The soak: 10,000 frames in one process with every knob turning (both pipelines alternating, the
// camera flying 35,000 units, the light count and path, the G-buffer layout, the depth convention,
// the size and the debug view changing), after which the resident memory (VmRSS) and the live GL
// objects must be where they were after the warm-up. Its own binary and ctest label (soak), so
// the GPU suite and its driver matrix do not run it again.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>

#include "gl_objects_probe.h"
#include "gpu_test.h"

namespace oasis::gputest {
namespace {

// Resident memory of this process in KiB (VmRSS in /proc/self/status), -1 if it cannot be read.
long residentKiB() {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
        if (line.rfind("VmRSS:", 0) == 0) return std::stol(line.substr(6));
    return -1;
}

int soakFrames() {
    const char* frames = std::getenv("OASIS_SOAK_FRAMES");  // a shorter run while working on the soak
    return frames ? std::max(1, std::atoi(frames)) : 10000;
}

// What frame `i` draws. Each knob turns at its own period so that the combinations keep changing.
struct FrameKnobs {
    PipelineKind pipeline;
    const GBufferLayout* layout;
    const DepthConvention* depth;
    int width, height;
    int lightCount;
    std::optional<LightsPath> lightsPath;
    std::string view;
    double timeSeconds;
};

FrameKnobs knobsFor(int i) {
    static const int lightCounts[] = {0, 8, 64, 300};
    static const std::optional<LightsPath> lightsPaths[] = {std::nullopt, LightsPath::Ubo, LightsPath::SsboCount};
    static const std::vector<std::string> views = [] {
        std::vector<std::string> names;
        for (const DebugView& view : debugViews()) names.push_back(view.name);
        names.push_back(kOverviewName);
        return names;
    }();
    const auto& layouts = gbufferLayouts();
    const auto& conventions = depthConventions();
    FrameKnobs knobs;
    knobs.pipeline = i % 2 ? PipelineKind::Forward : PipelineKind::Deferred;
    knobs.layout = &layouts[size_t(i / 20) % layouts.size()];
    knobs.depth = &conventions[size_t(i / 50) % conventions.size()];
    bool large = (i / 100) % 2;
    knobs.width = large ? 64 : 32;
    knobs.height = large ? 36 : 18;
    knobs.lightCount = lightCounts[(i / 10) % 4];
    knobs.lightsPath = lightsPaths[(i / 250) % 3];
    // Mostly the final image, every seventh frame the next debug view (overview included).
    knobs.view = i % 7 ? "final" : views[size_t(i / 7) % views.size()];
    knobs.timeSeconds = 0.5 * i;  // 7 units a second: 3.5 units a frame; the hour turns too
    return knobs;
}

void drawFrame(Renderer& renderer, SceneSettings& scene, const FrameKnobs& knobs) {
    renderer.setPipeline(knobs.pipeline);
    renderer.setDepthConvention(*knobs.depth);
    renderer.configure(knobs.width, knobs.height, *knobs.layout);
    scene.timeSeconds = knobs.timeSeconds;
    scene.lights.count = knobs.lightCount;
    scene.lights.path = knobs.lightsPath;
    renderer.renderFrame(scene);
    renderer.views().render(knobs.view);
}

// What is measured at a checkpoint, after one frame of a fixed configuration (so the counts do
// not depend on which layout or size the schedule happened to be at).
struct Checkpoint {
    int frame;
    long rssKiB;
    LiveCounts live;
    GlNameProbe probe;
    int plantsPlaced;
    double cameraX;
};

Checkpoint measure(Renderer& renderer, SceneSettings& scene, int frame) {
    FrameKnobs fixed = knobsFor(0);
    fixed.timeSeconds = knobsFor(frame).timeSeconds;
    drawFrame(renderer, scene, fixed);
    glFinish();
    return {frame, residentKiB(), liveCounts(), probeNames(), int(renderer.lastFrame().vegetation.stats().plantsPlaced),
            renderer.lastFrame().setup.view.pose.position.x};
}

class Soak : public GpuTest {};

TEST_F(Soak, TenThousandFramesHoldStill) {
    // The tolerance for resident memory after the warm-up, from measurement (docs/soak.md): on
    // llvmpipe the checkpoints after frame 1000 drift by at most +0.5 MiB over the run; 4 MiB
    // still fails a leak of about 470 bytes a frame (one 32x18 RGBA8 target a frame is 2.3 KiB).
    const long kRssToleranceKiB = 4 * 1024;
    const int frames = soakFrames();
    const int warmUp = std::min(1000, frames / 2);  // every knob has taken every value by then
    const int checkEvery = std::max(1, frames / 10);

    NamedPose pose = defaultPose();
    Renderer renderer(*shaders_, pose.scene);
    std::unique_ptr<PlantAtlas> atlas = attachPlantAtlas(*shaders_, renderer);
    SceneSettings scene = pose.scene;
    // Cheaper frames, so 10,000 fit in CI's time: a coarser terrain grid (the software rasteriser's
    // cost is its triangle count, not the pixels) and fewer, nearer plants (placement is CPU work
    // each time the camera enters new chunks). Every pass still runs.
    scene.grid.rings = 40;
    scene.grid.segments = 32;
    scene.vegetation.density = 0.25f;
    scene.vegetation.drawDistance = 200.0f;
    const long rssAtStart = residentKiB();
    ASSERT_GT(rssAtStart, 0) << "cannot read VmRSS from /proc/self/status";

    auto start = std::chrono::steady_clock::now();
    std::vector<Checkpoint> checkpoints;
    for (int i = 0; i < frames; ++i) {
        drawFrame(renderer, scene, knobsFor(i));
        if ((i + 1) >= warmUp && ((i + 1 - warmUp) % checkEvery == 0 || i + 1 == frames)) {
            checkpoints.push_back(measure(renderer, scene, i + 1));
            ASSERT_TRUE(gpuState().glErrors.empty()) << "GL error by frame " << i + 1 << ": " << gpuState().glErrors[0];
        }
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    std::printf("[soak] %d frames in %.1f s (%.2f ms a frame, checkpoints included); VmRSS at start %ld KiB\n",
                frames, seconds, 1000.0 * seconds / frames, rssAtStart);
    for (const Checkpoint& c : checkpoints) {
        std::cout << "[soak] frame " << c.frame << ": VmRSS " << c.rssKiB << " KiB (" << std::showpos
                  << c.rssKiB - checkpoints.front().rssKiB << std::noshowpos << "), live " << c.live << ", probe "
                  << c.probe << ", camera x " << int(c.cameraX) << ", plants placed " << c.plantsPlaced << "\n";
    }
    std::cout.flush();

    const Checkpoint& base = checkpoints.front();
    for (const Checkpoint& c : checkpoints) {
        EXPECT_EQ(c.live, base.live) << "wrapper live object counts at frame " << c.frame << " differ from frame "
                                     << base.frame << "'s";
        EXPECT_EQ(c.probe, base.probe) << "glIs* probe at frame " << c.frame << " differs from frame " << base.frame
                                       << "'s";
        EXPECT_LE(std::abs(c.rssKiB - base.rssKiB), kRssToleranceKiB)
            << "VmRSS at frame " << c.frame << " is " << c.rssKiB << " KiB, frame " << base.frame << "'s "
            << base.rssKiB << " KiB (tolerance " << kRssToleranceKiB << " KiB)";
    }
    // The knobs really turned: the camera flew (plants were placed along the way) and it still draws.
    EXPECT_GT(checkpoints.back().cameraX - base.cameraX, 3.0 * (frames - warmUp));
    EXPECT_TRUE(std::any_of(checkpoints.begin(), checkpoints.end(), [](const Checkpoint& c) { return c.plantsPlaced > 0; }));
    EXPECT_TRUE(hasContent(renderFinal(renderer, scene, PipelineKind::Deferred)));
}

}  // namespace
}  // namespace oasis::gputest
