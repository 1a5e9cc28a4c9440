// Command set-up shared by the headless commands and the window.
#include "commands/session.h"

#include <algorithm>
#include <chrono>
#include <map>
#include <cstdio>
#include <stdexcept>
#include <vector>

namespace oasis {

SceneSettings sceneSettingsFrom(const SceneOptions& options) {
    SceneSettings scene;
    scene.timeSeconds = options.timeSeconds;
    scene.hour = options.hour;
    scene.camera = options.camera;
    scene.water = options.water;
    scene.vegetation = options.vegetation;
    scene.lights.count = options.lights;
    scene.lights.path = options.lightsPath;
    return scene;
}

StencilViewPath chooseStencilViewPath(std::optional<StencilViewPath> forced, std::string& reason) {
    bool supported = epoxy_gl_version() >= 43 || epoxy_has_gl_extension("GL_ARB_stencil_texturing");
    if (forced) {
        if (*forced == StencilViewPath::Texturing && !supported) {
            reason = "stencil texturing was asked for but this context lacks GL 4.3 / ARB_stencil_texturing: read-back";
            return StencilViewPath::ReadBack;
        }
        reason = std::string("forced on the command line: ") + stencilViewPathName(*forced);
        return *forced;
    }
    reason = supported ? "stencil texturing (GL 4.3 or ARB_stencil_texturing present)"
                       : "read-back (no GL 4.3 / ARB_stencil_texturing)";
    return supported ? StencilViewPath::Texturing : StencilViewPath::ReadBack;
}

RenderSession::RenderSession(const Options& options) : scene(sceneSettingsFrom(options.scene)) {
    std::string searched;
    std::string directory = findShaderDirectory(&searched);
    if (directory.empty())
        throw std::runtime_error("cannot find oasis's shaders (looked in: " + searched +
                                 "); set OASIS_SHADER_DIR to the shaders/ directory");
    shaders = std::make_unique<ShaderLibrary>(directory, glslDialectForCurrentContext());
    renderer = std::make_unique<Renderer>(*shaders, scene);
    renderer->configure(options.scene.width, options.scene.height, *findGBufferLayout(options.scene.gbuffer));
    renderer->setStencilViewPath(chooseStencilViewPath(options.stencilView, stencilPathReason));
    PlantInterpretation plantPath = choosePlantInterpretation(options.scene.noCompute, plantPathReason);
    try {
        plantAtlas = std::make_unique<PlantAtlas>(*shaders, plantPath);
    } catch (const std::runtime_error& error) {
        // A driver that offers compute but cannot build this shader (e.g. GL 3.3 with only the ARB
        // extensions) still gets its plants: from the CPU, saying why.
        if (plantPath != PlantInterpretation::Gpu) throw;
        plantPathReason = std::string("cpu (the compute path failed: ") + error.what() + ")";
        plantAtlas = std::make_unique<PlantAtlas>(*shaders, PlantInterpretation::Cpu);
    }
    renderer->setPlantAtlas(plantAtlas.get());
}

std::string describePlantAtlas(const RenderSession& session) {
    const PlantAtlas& atlas = *session.plantAtlas;
    char timing[96];
    std::snprintf(timing, sizeof(timing), ", atlas %dx%d in %.1f ms (segments %.1f ms)", atlas.width(),
                  atlas.height(), atlas.totalMs(), atlas.interpretMs());
    return "plants: " + session.plantPathReason + timing;
}

std::string describeVegetation(const Renderer& renderer) {
    const VegetationStats& stats = renderer.vegetationStats();
    if (!renderer.lastFrame().vegetationEnabled) return "vegetation: off";
    char text[256];
    std::snprintf(text, sizeof(text),
                  "vegetation: %zu plants placed in %zu chunks around the camera; drawn %zu (%zu chunks in view, "
                  "thinned with distance) and %zu in the reflection (%zu chunks)",
                  stats.plantsPlaced, stats.chunksInRange, stats.plantsDrawn, stats.chunksVisible,
                  stats.plantsDrawnMirrored, stats.chunksMirrored);
    return text;
}

std::string describeLights(const Renderer& renderer) {
    std::string text = "lights: " + std::to_string(renderer.lightsDrawn()) + ", path " + renderer.lightsPathReason();
    if (renderer.lightsDropped() > 0)
        text += "; WARNING: " + std::to_string(renderer.lightsDropped()) + " lights dropped (the ubo path holds " +
                std::to_string(renderer.uboLights().maxLights()) + ")";
    return text;
}

namespace {
template <typename Work>
double medianMs(int frames, Work work) {
    using Clock = std::chrono::steady_clock;
    for (int warm = 0; warm < 2; ++warm) work();
    glFinish();
    std::vector<double> samples;
    for (int i = 0; i < frames; ++i) {
        auto start = Clock::now();
        work();
        glFinish();
        samples.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
    }
    std::sort(samples.begin(), samples.end());
    size_t n = samples.size();
    return n % 2 ? samples[n / 2] : 0.5 * (samples[n / 2 - 1] + samples[n / 2]);
}
}  // namespace

double medianFrameMs(Renderer& renderer, const SceneSettings& scene, int frames) {
    return medianMs(frames, [&] { renderer.renderFrame(scene); });
}

std::vector<std::pair<std::string, double>> medianPassMs(Renderer& renderer, const SceneSettings& scene,
                                                         int frames) {
    renderer.renderFrame(scene);  // warm-up
    std::vector<std::string> order;
    std::map<std::string, std::vector<double>> samples;
    for (int i = 0; i < frames; ++i)
        for (const auto& [name, ms] : renderer.renderFrameTimingPasses(scene)) {
            if (!samples.count(name)) order.push_back(name);
            samples[name].push_back(ms);
        }
    std::vector<std::pair<std::string, double>> medians;
    for (const std::string& name : order) {
        std::vector<double>& v = samples[name];
        std::sort(v.begin(), v.end());
        size_t n = v.size();
        medians.emplace_back(name, n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]));
    }
    return medians;
}

double medianFloorMs(Renderer& renderer, int frames) {
    return medianMs(frames, [&] { renderer.renderFloor(); });
}

}  // namespace oasis
