// Command set-up shared by the headless commands and the window.
#include "commands/session.h"

#include <algorithm>
#include <chrono>
#include <deque>
#include <functional>
#include <map>
#include <set>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "cli/input_domains.h"
#include "cli/option_table.h"

namespace oasis {

SceneSettings sceneSettingsFrom(const SceneOptions& options) {
    SceneSettings scene;
    applySceneOptions(options, scene);  // the fields the option rows reach (cli/option_table.h)
    return scene;
}

RendererCapabilities rendererCapabilities(const gl::Capabilities& caps, const SceneSettings& scene,
                                          const gl::WorkaroundSet& workarounds) {
    RendererCapabilities c;
    c.workarounds = workarounds;
    c.ssbo.available = caps.ssboAvailable(&c.ssbo.reason);
    c.compute.available = caps.computeAvailable(&c.compute.reason);
    c.clipControl.available = caps.clipControlAvailable(&c.clipControl.reason);
    c.readOnlyDepth.available = caps.readOnlyDepthAvailable(&c.readOnlyDepth.reason);
    c.depthStencilRead.available = caps.depthStencilReadAvailable(&c.depthStencilRead.reason);
    c.norm16Targets.available = caps.norm16TargetsAvailable(&c.norm16Targets.reason);
    c.forcedLightsPath = scene.lights.path;
    c.forcedLightMethod = scene.lights.method;
    return c;
}

StencilViewPath chooseStencilViewPath(const gl::Capabilities& caps, std::optional<StencilViewPath> forced,
                                      std::string& reason) {
    std::string why;
    bool supported = caps.stencilTexturingAvailable(&why);
    if (forced) {
        if (*forced == StencilViewPath::Texturing && !supported) {
            reason = "read-back (stencil texturing was asked for but " + why + ")";
            return StencilViewPath::ReadBack;
        }
        reason = std::string(stencilViewPathName(*forced)) + " (--stencil-view)";
        return *forced;
    }
    reason = supported ? "stencil-texturing (" + why + ")" : "read-back (" + why + ")";
    return supported ? StencilViewPath::Texturing : StencilViewPath::ReadBack;
}

namespace {
// "oasis: workaround: NAME (WHY)" on stderr for each applied workaround, once a process: a check
// or a bench makes many sessions on one driver, and the set is the same in each.
void reportWorkaroundsOnce(const gl::WorkaroundSet& set) {
    static std::set<std::string> printed;
    for (const gl::WorkaroundState& state : set.rows) {
        std::string line = "oasis: workaround: " + state.name + " (" + state.why + ")";
        if (state.applied && printed.insert(line).second) std::fprintf(stderr, "%s\n", line.c_str());
    }
}
// A report row: `can` says whether the driver has the feature and whether --force leaves it.
gl::FeatureReport reportOf(std::string name, bool used, std::string reason, const gl::Availability& can) {
    return {std::move(name), used, std::move(reason), can.driver, gl::limitedBy(used, can)};
}

// Clip control serves --depth reversed-z only: without it a standard frame loses nothing, so it is
// a fallback only where reversed-z was asked for or clip control was switched off by --force.
gl::FeatureReport clipControlFeature(const gl::Capabilities& caps, const Renderer& renderer) {
    gl::Availability can = caps.availability(&gl::Capabilities::clipControlAvailable);
    const std::string& why = can.reason;
    if (renderer.paths().depth->needsClipControl())
        return reportOf("clip-control", true, "depth " + renderer.paths().depthReason, can);
    if (renderer.paths().depthFellBack)
        return reportOf("clip-control", false, "fallback: depth " + renderer.paths().depthReason, can);
    if (caps.forced.noClipControl)
        return reportOf("clip-control", false, "fallback: " + why + " (--depth reversed-z would draw standard depth)", can);
    // `why` names a forced tier itself where one hides what the driver has.
    return reportOf("clip-control", false,
                    "not used: depth " + renderer.paths().depthReason +
                        (can.tier ? "; " + why + " for --depth reversed-z" : can.driver ? "; " + why : "; the driver has " + why),
                    can);
}

// 16-bit unorm targets serve the compact layout's RG16 normal: without them the renderer draws the
// standard layout, a fallback only where a layout that needs them was asked for.
gl::FeatureReport norm16TargetsFeature(const gl::Capabilities& caps, const Renderer& renderer) {
    gl::Availability can = caps.availability(&gl::Capabilities::norm16TargetsAvailable);
    const RenderPaths& paths = renderer.paths();
    if (paths.gbufferFellBack) return reportOf("norm16-targets", false, "fallback: gbuffer " + paths.gbufferReason, can);
    if (paths.gbuffer && paths.gbuffer->needsNorm16Targets())
        return reportOf("norm16-targets", true, "gbuffer " + paths.gbufferReason, can);
    return reportOf("norm16-targets", false,
                    "not used: gbuffer " + (paths.gbuffer ? paths.gbuffer->name : std::string("none")) +
                        " has no 16-bit unorm target; " +
                        (can.tier ? can.reason : "--gbuffer compact would draw standard: " + can.reason),
                    can);
}
}  // namespace

MaxGlVersion maxGlVersionFor(const SceneOptions& options) {
    if (options.api == gl::Api::Gles) return MaxGlVersion{3, 2, true};
    return options.force.gl33 ? MaxGlVersion{3, 3} : MaxGlVersion{};
}

const TimingClock& RenderSession::timingClock() {
    if (!measuredClock) measuredClock = measureTimingClock(*renderer, scene);
    return *measuredClock;
}

std::unique_ptr<Renderer> RenderSession::makeRenderer() const {
    auto second = std::make_unique<Renderer>(*shaders, scene);
    RendererCapabilities same = rendererCaps;
    same.readOnlyDepth = renderer->paths().capabilities.readOnlyDepth;  // as the first took it
    same.forcedLightsPath = scene.lights.path;  // the scene's now: the window's panel may have changed it
    same.forcedLightMethod = scene.lights.method;
    second->setCapabilities(same);
    second->setDepthConvention(*renderer->paths().depth);
    // The layout the first was asked for: a second falls back (and says why) as the first did.
    const GBufferLayout* requested = findGBufferLayout(renderer->paths().gbufferRequested);
    second->configure(renderer->targets().width(), renderer->targets().height(),
                      requested ? *requested : renderer->targets().layout());
    second->views().setStencilPath(renderer->views().stencilPath());
    second->views().setWaterScene(renderer->views().waterScene());
    second->views().setPlantAtlas(plantAtlas.get());
    return second;
}

// --force, and the forced fallbacks a workarounds file or --workarounds names (a profile `oasis
// check` proposed): resolved against the context's own strings before the capabilities are
// measured with them.
static gl::ForcedFallbacks forcedFallbacksOf(const Options& options) {
    gl::ForcedFallbacks forced = options.scene.force;
    ContextInfo context = queryContextInfo();
    for (const auto& [name, row] : gl::resolveWorkarounds(options.scene.workarounds, context.renderer, context.version)
                                       .forcedFallbacks())
        forced.forceByWorkaround(name, row);
    return forced;
}

RenderSession::RenderSession(const Options& options, Shaders need)
    : caps(gl::measureCapabilities(forcedFallbacksOf(options))),
      workarounds(gl::resolveWorkarounds(options.scene.workarounds, caps.renderer, caps.version)),
      scene(sceneSettingsFrom(options.scene)) {
    reportWorkaroundsOnce(workarounds);
    std::string searched;
    std::string directory = findShaderDirectory(&searched);
    if (directory.empty() && need == Shaders::Required)
        throw std::runtime_error("cannot find oasis's shaders (looked in: " + searched +
                                 "); set OASIS_SHADER_DIR to the shaders/ directory");
    GlslDialect dialect = caps.es ? glslDialectForEs(caps) : glslDialectForCurrentContext();
    if (caps.forced.gl33) dialect.versionLine = "#version 330 core";
    const std::string noDepthClamp = "OASIS_NO_DEPTH_CLAMP 1";  // the ES dialect may have it already
    if (!caps.depthClampAvailable() && std::find(dialect.defines.begin(), dialect.defines.end(), noDepthClamp) == dialect.defines.end())
        dialect.defines.push_back(noDepthClamp);
    shaders = std::make_unique<ShaderLibrary>(directory, dialect);
    renderer = std::make_unique<Renderer>(*shaders, scene);
    rendererCaps = rendererCapabilities(caps, scene, workarounds);
    renderer->setCapabilities(rendererCaps);
    renderer->setDepthConvention(*findDepthConvention(options.scene.depth));
    renderer->configure(options.scene.width, options.scene.height, *findGBufferLayout(options.scene.gbuffer));
    renderer->views().setStencilPath(chooseStencilViewPath(caps, options.stencilView, stencilPathReason));
    renderer->views().setWaterScene(options.waterScene);
    plantPath = choosePlantInterpretation(caps, options.scene.noCompute, plantPathReason);
    if (directory.empty()) {
        plantPathReason += "; not built: no shader directory (looked in: " + searched + ")";
        for (const std::string& line : fallbacks()) std::fprintf(stderr, "oasis: fallback: %s\n", line.c_str());
        return;
    }
    try {
        plantAtlas = std::make_unique<PlantAtlas>(*shaders, plantPath);
    } catch (const std::runtime_error& error) {
        // A driver that offers compute but cannot build this shader (e.g. GL 3.3 with only the ARB
        // extensions) still gets its plants: from the CPU, saying why.
        if (plantPath != PlantInterpretation::Gpu) throw;
        plantPathReason = std::string("cpu (the compute path failed: ") + error.what() + ")";
        plantAtlas = std::make_unique<PlantAtlas>(*shaders, PlantInterpretation::Cpu);
    }
    renderer->views().setPlantAtlas(plantAtlas.get());
    for (const std::string& line : fallbacks()) std::fprintf(stderr, "oasis: fallback: %s\n", line.c_str());
}

std::vector<gl::FeatureReport> RenderSession::features() const {
    using gl::Capabilities;
    std::vector<gl::FeatureReport> list;
    // The light list: the renderer's path choice (from the capabilities above and --lights-path).
    bool ssbo = renderer->paths().lights.path != LightsPath::Ubo;
    list.push_back(reportOf("ssbo-light-list", ssbo,
                            ssbo ? "SSBO light list, path " + renderer->paths().lights.reason
                                 : "fallback: UBO light list, path " + renderer->paths().lights.reason,
                            caps.availability(&Capabilities::ssboAvailable)));
    // The deferred light method (--light-method): tiled where asked for and compute exists.
    bool tiled = renderer->paths().lightMethod.method == LightMethod::Tiled;
    bool tiledRefused = !tiled && scene.lights.method == LightMethod::Tiled;
    gl::Availability compute = caps.availability(&Capabilities::computeAvailable);
    // Not asked for, it still says why --light-method tiled would fall back where it would.
    list.push_back(reportOf("tiled-light-culling", tiled,
                            tiled ? "deferred lights by " + renderer->paths().lightMethod.reason
                                  : (tiledRefused ? "fallback: deferred lights by " : "not used: deferred lights by ") +
                                        renderer->paths().lightMethod.reason +
                                        (tiledRefused || compute.tier ? "" : "; tiled needs compute: " + compute.reason),
                            compute));
    bool gpuPlants = plantAtlas ? plantAtlas->path() == PlantInterpretation::Gpu : plantPath == PlantInterpretation::Gpu;
    // The GPU path chosen but its build failed (the constructor fell back): the driver's limit too.
    gl::Availability plants = compute;
    if (!gpuPlants && plantPath == PlantInterpretation::Gpu) plants.driver = false;
    list.push_back(reportOf("compute-plant-interpretation", gpuPlants,
                            gpuPlants ? plantPathReason : "fallback: " + plantPathReason, plants));
    bool texturing = renderer->views().stencilPath() == StencilViewPath::Texturing;
    list.push_back(reportOf("stencil-texturing", texturing,
                            texturing ? "stencil view by " + stencilPathReason : "fallback: stencil view by " + stencilPathReason,
                            caps.availability(&Capabilities::stencilTexturingAvailable)));
    gl::Availability floats = caps.availability(&Capabilities::floatRenderTargetsAvailable);
    list.push_back(reportOf("float-render-targets", floats.tier,
                            floats.tier ? "Radiance, Reflection and the G-buffer: " + floats.reason
                                        : "required and missing: " + floats.reason,
                            floats));
    // Never used, --force no-dsa or not: what limits it is oasis's choice unless the driver lacks it.
    gl::FeatureReport dsa = reportOf("direct-state-access", false,
                                     "not used: oasis edits GL objects through glBind* on every context, so no path depends "
                                     "on it (driver: " + (caps.driverHasDsa() ? std::string("has it") : "lacks it") +
                                         (caps.forced.noDsa ? "; --force no-dsa accepted, nothing changes)" : ")"),
                                     caps.availability(&Capabilities::dsaAvailable));
    if (dsa.available) dsa.limitedBy = gl::kLimitedByNotAskedFor;
    list.push_back(dsa);
    list.push_back(clipControlFeature(caps, *renderer));
    list.push_back(norm16TargetsFeature(caps, *renderer));
    const GBufferLayout& layout = renderer->targets().layout();
    // Sampling the depth-stencil target is core on every context oasis makes: the layout decides.
    list.push_back(reportOf("depth-read-in-place", layout.positionFromDepth(),
                            layout.positionFromDepth()
                                ? "the " + layout.name + " layout rebuilds position from depth: the direct lighting, tiling, "
                                  "views and probe sample the depth-stencil target itself (the lighting tests against it "
                                  "read-only where read-only-depth says so); DepthCopyPass copies it only for passes that "
                                  "write stencil or may not read what they test (light volumes, the reflection's lighting)"
                                : "not used: the " + layout.name + " layout stores position, no pass reads depth",
                            gl::Availability{true, true, {}}));
    bool readOnlyDepth = renderer->paths().capabilities.readOnlyDepth.available;
    list.push_back(reportOf("read-only-depth", readOnlyDepth,
                            readOnlyDepth ? "the deferred lighting shades only the surfaces (a far-plane triangle depth-tested "
                                            "against the depth-stencil target it samples, writes off; SkyPass draws the sky): " +
                                                renderer->paths().capabilities.readOnlyDepth.reason
                                          : renderer->paths().capabilities.readOnlyDepth.reason,
                            caps.availability(&Capabilities::readOnlyDepthAvailable)));
    gl::Availability depthStencilRead = caps.availability(&Capabilities::depthStencilReadAvailable);
    list.push_back(reportOf("depth-stencil-read", depthStencilRead.tier, depthStencilRead.reason, depthStencilRead));
    gl::Availability clipDistances = caps.availability(&Capabilities::clipDistancesAvailable);
    list.push_back(reportOf("clip-distances", clipDistances.tier,
                            clipDistances.tier ? "the reflection clipped at the water plane by " + clipDistances.reason
                                               : clipDistances.reason,
                            clipDistances));
    gl::Availability depthClamp = caps.availability(&Capabilities::depthClampAvailable);
    list.push_back(reportOf("depth-clamp", depthClamp.tier,
                            depthClamp.tier ? "shadow casters nearer the sun than a cascade kept by " + depthClamp.reason
                                            : depthClamp.reason,
                            depthClamp));
    gl::Availability debug = caps.availability(&Capabilities::debugOutputAvailable);
    list.push_back(reportOf("debug-output", debug.tier,
                            debug.tier ? "GL errors to stderr and a debug group per pass: " + debug.reason
                                       : "fallback: no debug messages or groups (" + debug.reason + ")",
                            debug));
    return list;
}

std::vector<std::string> RenderSession::fallbacks() const {
    std::vector<std::string> lines;
    for (const gl::FeatureReport& feature : features())
        if (!feature.used && feature.reason.compare(0, 9, "not used:") != 0) {
            const std::string prefix = "fallback: ";
            bool prefixed = feature.reason.compare(0, prefix.size(), prefix) == 0;
            lines.push_back(feature.name + ": " + feature.reason.substr(prefixed ? prefix.size() : 0));
        }
    if (caps.forced.noDsa) lines.push_back("direct-state-access: --force no-dsa accepted; oasis never uses DSA");
    if (caps.forced.gl33) lines.push_back("context: OpenGL " + std::to_string(caps.major) + "." +
                                          std::to_string(caps.minor) + " core (--force gl33)");
    if (caps.forced.gles30) lines.push_back("context: OpenGL ES 3.0 feature set (--force gles30; GLSL 300 es)");
    return lines;
}

std::string describePlantAtlas(const RenderSession& session) {
    const PlantAtlas& atlas = *session.plantAtlas;
    char timing[96];
    std::snprintf(timing, sizeof(timing), ", atlas %dx%d in %.1f ms (segments %.1f ms)", atlas.width(),
                  atlas.height(), atlas.totalMs(), atlas.interpretMs());
    return "plants: " + session.plantPathReason + timing;
}

std::string describeVegetation(const Renderer& renderer) {
    const VegetationStats& stats = renderer.lastFrame().vegetation.stats();
    if (!renderer.lastFrame().setup.vegetationEnabled) return "vegetation: off";
    char text[256];
    std::snprintf(text, sizeof(text),
                  "vegetation: %zu plants placed in %zu chunks around the camera; drawn %zu (%zu chunks in view, "
                  "thinned with distance) and %zu in the reflection (%zu chunks",
                  stats.plantsPlaced, stats.chunksInRange, stats.plantsDrawn, stats.chunksVisible,
                  stats.plantsDrawnMirrored, stats.chunksMirrored);
    std::string described = text;
    if (renderer.lastFrame().setup.mirroredPlantsCulled)
        described += "; culled on the CPU, their image on dry land: " + std::to_string(stats.chunksMirroredOnLand) +
                     " more chunks and " + std::to_string(stats.plantsMirroredOnLand) + " plants in these";
    return described + ")";
}

std::string describeReflectionBounds(const Renderer& renderer, const SceneSettings& scene) {
    std::string resolution;
    if (const int divisor = renderer.lastFrame().setup.reflectionDivisor;
        divisor > 1 && renderer.lastFrame().setup.reflectionsActive)
        resolution = "; drawn at " + std::string(reflectionResolutionName(divisor)) + " resolution (" +
                     std::to_string(renderer.targets().width(divisor)) + "x" +
                     std::to_string(renderer.targets().height(divisor)) +
                     "), upsampled bilinearly at the water";
    if (renderer.paths().waterBoundsAvailable && !scene.water.reflectionBounds)
        return "reflection passes: whole screen, stencil-masked (--reflection-bounds off)" + resolution;
    return "reflection passes: " + renderer.paths().waterBoundsReason + resolution;
}

std::string describeLights(const Renderer& renderer) {
    std::string text = "lights: " + std::to_string(renderer.paths().lightsDrawn) + ", path " + renderer.paths().lights.reason +
                       ", method " + renderer.paths().lightMethod.reason;
    if (renderer.paths().lightsDropped > 0)
        text += "; WARNING: " + std::to_string(renderer.paths().lightsDropped) + " lights dropped (the ubo path holds " +
                std::to_string(renderer.paths().uboLights.maxLights()) + ")";
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
    return median(samples);
}
}  // namespace

std::vector<PassTimes> medianPassMsInTurn(Renderer& renderer, const SceneSettings& scene, int frames,
                                          const TimingClock& clock, const std::vector<PipelineKind>& pipelines,
                                          std::mt19937_64* random, std::vector<std::vector<PassTimes>>* frameTimes) {
    const PipelineKind active = renderer.pipeline();
    for (PipelineKind kind : pipelines) {  // a warm-up each
        renderer.setPipeline(kind);
        renderer.renderFrame(scene);
    }
    const size_t count = pipelines.size();
    std::vector<std::vector<PassTimes>> timed(count);
    auto order = [&] {
        if (random) return roundOrder(*random, int(count));
        std::vector<int> fixed;
        for (size_t k = 0; k < count; ++k) fixed.push_back(int(k));
        return fixed;
    };
    if (clock.gpuTimers) {
        // Room for every frame of each: none dropped, read at the end.
        std::deque<PassTimerQueries> queries;  // not movable: a deque builds each in place
        for (size_t k = 0; k < count; ++k) queries.emplace_back(frames + 1);
        for (int i = 0; i < frames; ++i)
            for (int k : order()) {
                renderer.setPipeline(pipelines[size_t(k)]);
                queries[size_t(k)].timeFrame(renderer, scene);
            }
        for (size_t k = 0; k < count; ++k) timed[k] = queries[k].drain();
    } else {
        for (int i = 0; i < frames; ++i)
            for (int k : order()) {
                renderer.setPipeline(pipelines[size_t(k)]);
                timed[size_t(k)].push_back(renderFrameTimingPasses(renderer, scene));
            }
    }
    renderer.setPipeline(active);
    if (frameTimes) *frameTimes = timed;
    std::vector<PassTimes> medians;
    for (const std::vector<PassTimes>& frameTimes : timed) medians.push_back(medianPassTimes(frameTimes));
    return medians;
}

PassTimes medianPassMs(Renderer& renderer, const SceneSettings& scene, int frames, const TimingClock& clock) {
    return medianPassMsInTurn(renderer, scene, frames, clock, {renderer.pipeline()}).front();
}

double medianFloorMs(Renderer& renderer, int frames) {
    return medianMs(frames, [&] { renderer.renderFloor(); });
}

std::uint64_t roundSeed(const Options& options) {
    if (options.seed) return *options.seed;
    return std::random_device{}() % (std::uint64_t(inputDomain("--seed").high) + 1);  // one --seed accepts
}

std::vector<int> roundOrder(std::mt19937_64& random, int count) {
    std::vector<int> order(size_t(std::max(count, 0)));
    for (int i = 0; i < count; ++i) order[size_t(i)] = i;
    for (int i = count - 1; i > 0; --i) std::swap(order[size_t(i)], order[size_t(random() % std::uint64_t(i + 1))]);
    return order;
}

PipelineTimes timePipelinesInTurn(Renderer& renderer, const SceneSettings& scene, const RoundPlan& plan) {
    using Clock = std::chrono::steady_clock;
    const PipelineKind active = renderer.pipeline();
    auto frameOf = [&](PipelineKind kind) {
        return [&renderer, &scene, kind] {
            renderer.setPipeline(kind);
            renderer.renderFrame(scene);
        };
    };
    const std::function<void()> work[3] = {frameOf(PipelineKind::Forward), frameOf(PipelineKind::Deferred),
                                            [&renderer] { renderer.renderFloor(); }};
    for (const auto& each : work)
        for (int warm = 0; warm < PipelineTimes::kWarmupFrames; ++warm) each();
    glFinish();
    std::mt19937_64 random(plan.seed);
    std::vector<double> ms[3];
    auto runRounds = [&](int count) {
        for (int round = 0; round < count; ++round)
            for (int i : roundOrder(random, 3)) {
                auto start = Clock::now();
                work[i]();
                glFinish();
                ms[i].push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
            }
    };
    runRounds(plan.rounds);
    PipelineTimes times = summariseRounds(ms[0], ms[1], ms[2], plan.seed);
    // --until-ci: double the rounds (all kept) until the widest interval is narrow enough or the cap.
    while (plan.untilCiPercent > 0.0 && 100.0 * times.widestRelativeHalfWidth() >= plan.untilCiPercent &&
           times.rounds < RoundPlan::kMaxRounds) {
        runRounds(std::min(times.rounds, RoundPlan::kMaxRounds - times.rounds));
        times = summariseRounds(ms[0], ms[1], ms[2], plan.seed);
    }
    times.untilCiPercent = plan.untilCiPercent;
    times.untilCiReached = plan.untilCiPercent > 0.0 && 100.0 * times.widestRelativeHalfWidth() < plan.untilCiPercent;
    times.warmup = PipelineTimes::kWarmupFrames;
    renderer.setPipeline(active);
    return times;
}

double PipelineTimes::widestRelativeHalfWidth() const {
    return std::max({forward.relativeHalfWidth(), deferred.relativeHalfWidth(), floor.relativeHalfWidth()});
}

const char* PipelineTimes::widestStream() const {
    double widest = widestRelativeHalfWidth();
    return forward.relativeHalfWidth() == widest ? "forward" : deferred.relativeHalfWidth() == widest ? "deferred" : "floor";
}

PipelineTimes summariseRounds(const std::vector<double>& forwardMs, const std::vector<double>& deferredMs,
                              const std::vector<double>& floorMs, std::uint64_t seed) {
    if (forwardMs.empty() || forwardMs.size() != deferredMs.size() || forwardMs.size() != floorMs.size())
        throw std::invalid_argument("summariseRounds: the three need one sample per round, at least one round");
    std::vector<double> forwardRatios, deferredRatios;
    for (size_t round = 0; round < floorMs.size(); ++round) {
        forwardRatios.push_back(forwardMs[round] / floorMs[round]);
        deferredRatios.push_back(deferredMs[round] / floorMs[round]);
    }
    PipelineTimes times;
    times.rounds = int(floorMs.size());
    times.seed = seed;
    times.forward = describeSamples(forwardMs);
    times.deferred = describeSamples(deferredMs);
    times.floor = describeSamples(floorMs);
    // Each ratio's bootstrap its own stream of the seed, so the three are not the same draws.
    times.deferredOverForward = pairedMedianRatio(deferredMs, forwardMs, seed);
    times.forwardOverFloorInterval = pairedMedianRatio(forwardMs, floorMs, seed + 1);
    times.deferredOverFloorInterval = pairedMedianRatio(deferredMs, floorMs, seed + 2);
    times.forwardMs = median(forwardMs);
    times.deferredMs = median(deferredMs);
    times.floorMs = median(floorMs);
    times.forwardRatio = median(forwardRatios);
    times.deferredRatio = median(deferredRatios);
    times.deferredRatioLowest = *std::min_element(deferredRatios.begin(), deferredRatios.end());
    times.deferredRatioHighest = *std::max_element(deferredRatios.begin(), deferredRatios.end());
    times.forwardOverFloor = times.forwardMs / times.floorMs;
    times.deferredOverFloor = times.deferredMs / times.floorMs;
    auto [forwardLow, forwardHigh] = std::minmax_element(forwardMs.begin(), forwardMs.end());
    auto [deferredLow, deferredHigh] = std::minmax_element(deferredMs.begin(), deferredMs.end());
    auto [floorLow, floorHigh] = std::minmax_element(floorMs.begin(), floorMs.end());
    times.forwardLowest = *forwardLow, times.forwardHighest = *forwardHigh;
    times.deferredLowest = *deferredLow, times.deferredHighest = *deferredHigh;
    times.floorLowest = *floorLow, times.floorHighest = *floorHigh;
    times.spread = std::max({(*forwardHigh - *forwardLow) / times.forwardMs, (*deferredHigh - *deferredLow) / times.deferredMs,
                             (*floorHigh - *floorLow) / times.floorMs});
    return times;
}

}  // namespace oasis
