// The README's lights table (not part of the suite: DISABLED_, run by docs/measure_lights.sh):
// ms per frame of each pipeline at 1280x720, the default frame at 21:00, for 0..4096 of the
// scene's lights, wall time around glFinish. Medians of OASIS_LIGHT_FRAMES frames (default 5)
// after a warm-up frame; a forward frame slower than 5 s is timed once (a single sample).
// OASIS_LIGHT_FORWARD_MAX=N times forward only up to N lights (deferred alone above; "-").
#include <chrono>
#include <cstdlib>

#include "commands/session.h"
#include "gpu_test.h"

namespace oasis::gputest {
namespace {

double timeFrames(Renderer& renderer, const SceneSettings& scene, int frames, int* used) {
    using Clock = std::chrono::steady_clock;
    std::vector<double> samples;
    for (int i = 0; i < frames; ++i) {
        glFinish();
        auto start = Clock::now();
        renderer.renderFrame(scene);
        glFinish();
        samples.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
        if (samples.back() > 5000.0) break;
    }
    std::sort(samples.begin(), samples.end());
    *used = int(samples.size());
    size_t n = samples.size();
    return n % 2 ? samples[n / 2] : 0.5 * (samples[n / 2 - 1] + samples[n / 2]);
}

TEST_F(GpuTest, DISABLED_LightsTable) {
    const char* framesText = std::getenv("OASIS_LIGHT_FRAMES");
    const int frames = framesText ? std::max(1, std::atoi(framesText)) : 5;
    const char* forwardMaxText = std::getenv("OASIS_LIGHT_FORWARD_MAX");
    const int forwardMax = forwardMaxText ? std::atoi(forwardMaxText) : kMaxLights;
    SceneSettings scene;
    scene.hour = 21.0;
    Renderer renderer(*shaders_, scene);
    renderer.configure(1280, 720, layoutNamed("standard"));
    // LightingPass is one full-screen shade of the G-buffer: the least a light costs when each one
    // is shaded over the whole screen (the seed's deferred mode also cleared the stencil per light).
    std::printf("| lights | forward ms | deferred ms | deferred LightVolumePass ms (direct + mirrored) | LightingPass ms |\n");
    std::printf("| --- | --- | --- | --- | --- |\n");
    for (int count : {0, 1, 4, 16, 64, 256, 1024, 4096}) {
        scene.lights.count = count;
        double ms[2] = {0.0, 0.0};
        int used[2] = {0, 0};
        for (PipelineKind kind : {PipelineKind::Forward, PipelineKind::Deferred}) {
            if (kind == PipelineKind::Forward && count > forwardMax) continue;
            renderer.setPipeline(kind);
            SceneSettings warm = scene;
            warm.lights.count = std::min(count, 1);  // builds the programs without a full slow frame
            renderer.renderFrame(warm);
            ms[int(kind == PipelineKind::Deferred)] = timeFrames(renderer, scene, frames, &used[kind == PipelineKind::Deferred]);
        }
        renderer.setPipeline(PipelineKind::Deferred);
        double volumes = 0.0, fullScreen = 0.0;
        for (const auto& [name, passMs] : medianPassMs(renderer, scene, std::max(1, frames / 2), TimingClock{})) {
            if (name.rfind("LightVolumePass", 0) == 0) volumes += passMs;
            if (name == "LightingPass") fullScreen = passMs;
        }
        char forwardText[48] = "-";
        if (used[0] > 0) std::snprintf(forwardText, sizeof(forwardText), "%.1f%s", ms[0], used[0] < frames ? " (1 frame)" : "");
        std::printf("| %d | %s | %.1f | %.1f | %.1f |\n", count, forwardText, ms[1], volumes, fullScreen);
        std::fflush(stdout);
    }
    std::printf("\nrenderer: %s; %d lights drawn at most; path %s\n", queryContextInfo().renderer.c_str(),
                renderer.paths().lightsDrawn, renderer.paths().lights.reason.c_str());
}

}  // namespace
}  // namespace oasis::gputest
