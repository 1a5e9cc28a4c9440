// `oasis bench` on a surfaceless EGL context: the reference renders, the floors, then every
// configuration's images (error) and timings, the Pareto frontiers and the outputs.
#include "bench/bench.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>

#include "bench/bench_depth.h"
#include "bench/bench_outputs.h"
#include "bench/bench_report.h"
#include "commands/session.h"
#include "context/gl_context.h"
#include "frame/frame_readback.h"
#include "frame/frame_traffic.h"
#include "frame/gpu_timer.h"
#include "gl/frame_capture.h"
#include "io/file_output.h"
#include "render/gbuffer_layout.h"
#include "render/image.h"
#include "io/printable_text.h"

namespace oasis {
namespace {

bool gCaptured = false;  // --capture: the first timed frame has been armed

std::string describeCapturedConfig(const BenchConfig& config) {
    return std::string(pipelineName(config.pipeline)) + " " + config.layout + " " + std::to_string(config.width) + "x" +
           std::to_string(config.height) + " " + config.variation(qualityKnobs()) + ", " +
           std::to_string(config.lights) + " lights, depth " + config.depth;
}

using Clock = std::chrono::steady_clock;

double elapsedMs(Clock::time_point since) {
    return std::chrono::duration<double, std::milli>(Clock::now() - since).count();
}

SceneSettings frameScene(const SceneSettings& base, const std::vector<QualityKnob>& knobs,
                         const std::vector<int>& levels, int lights, const BenchFrame& frame,
                         LightMethod method = LightMethod::Volumes) {
    SceneSettings scene = applyKnobs(base, knobs, levels);
    scene.lights.count = lights;
    scene.lights.method = method;
    scene.timeSeconds = frame.time;
    scene.camera = frame.pose;
    return scene;
}

Image renderFinalImage(Renderer& renderer, const SceneSettings& scene) {
    renderer.renderFrame(scene);
    renderer.views().render("final");
    return readDisplay(renderer);
}

double pooledPsnr(double meanSquaredError) {
    return meanSquaredError > 0.0 ? std::min(kPsnrIdentical, 10.0 * std::log10(255.0 * 255.0 / meanSquaredError))
                                  : kPsnrIdentical;
}

// A configuration's error over every fixed frame: against the references and, where given, against
// the reference layout's frames with the same knobs; also its memory. `images` gets its frames.
BenchResult measureError(Renderer& renderer, const SceneSettings& base, const BenchConfig& config,
                         const std::vector<BenchFrame>& frames, const std::vector<Image>& references,
                         const std::vector<Image>* sameKnobs, std::vector<Image>& images) {
    const std::vector<QualityKnob>& knobs = qualityKnobs();
    const GBufferLayout& layout = renderer.targets().layout();
    renderer.setPipeline(config.pipeline);
    BenchResult result;
    result.config = config;
    result.variation = config.variation(knobs);
    result.knobSettings = config.knobSettings(knobs);
    double squaredError = 0.0, ssimSum = 0.0, sameKnobsSquared = 0.0;
    images.clear();
    for (size_t f = 0; f < frames.size(); ++f) {
        Image image = renderFinalImage(renderer, frameScene(base, knobs, config.levels, config.lights, frames[f], config.lightMethod));
        ImageDifference difference = compareImages(image, references[f]);
        squaredError += difference.rmse * difference.rmse;
        result.maxAbs = std::max(result.maxAbs, difference.maxAbs);
        ssimSum += ssim(image, references[f]);
        if (sameKnobs) {
            ImageDifference own = compareImages(image, (*sameKnobs)[f]);
            sameKnobsSquared += own.rmse * own.rmse;
            result.sameKnobsMaxAbs = std::max(result.sameKnobsMaxAbs, own.maxAbs);
        }
        images.push_back(std::move(image));
    }
    // Error pooled over the frames (all the same size): PSNR and RMSE from the mean squared error.
    double mse = squaredError / double(frames.size());
    result.rmse = std::sqrt(mse);
    result.psnrDb = pooledPsnr(mse);
    result.sameKnobsPsnrDb = sameKnobs ? pooledPsnr(sameKnobsSquared / double(frames.size())) : kPsnrIdentical;
    result.ssim = ssimSum / double(frames.size());
    const DepthConvention& depth = renderer.targets().depth();
    int sharedBytes = layout.format(Target::Radiance).bytesPerPixel + layout.format(Target::Reflection).bytesPerPixel +
                      layout.format(Target::Final).bytesPerPixel;
    bool deferred = config.pipeline == PipelineKind::Deferred;
    result.gbufferBytesPerPixel = deferred ? gbufferBytesPerPixel(layout, depth) : 0;
    result.bytesPerPixel = sharedBytes + (deferred ? gbufferBytesPerPixel(layout, depth) : depth.depthStencil.bytesPerPixel);
    result.targetMiB = double(result.bytesPerPixel) * config.width * config.height / (1024.0 * 1024.0);
    return result;
}

// Times the configurations of one knob setting together: at each fixed frame, after two warm-up
// frames each, their timed frames interleave (each round one frame of each and the floor on
// `floorRenderer`, in an order drawn at random for the round from `random`), so load that changes
// during the run reaches all of them and their floor alike, and none is always first or last:
// each configuration's ratio is the median of its frames' own ratios to the floor of their round.
// Then each one's per-pass frames.
struct Timed {
    Renderer* renderer;
    BenchResult* result;
};
// The first frame's memory traffic, counted once: the counts do not vary from run to run.
void countTraffic(const std::vector<Timed>& group, Renderer& floorRenderer, const std::vector<SceneSettings>& scenes) {
    FrameTraffic floor = measureFloorTraffic(floorRenderer);
    for (size_t c = 0; c < group.size(); ++c) {
        group[c].renderer->setPipeline(group[c].result->config.pipeline);
        FrameTraffic traffic = measureFrameTraffic(*group[c].renderer, scenes[c]);
        if (!traffic.measured()) continue;
        group[c].result->trafficBytesPerPixel = traffic.bytesPerPixel();
        group[c].result->clearedBytesPerPixel = traffic.clearedBytesPerPixel();
        group[c].result->floorTrafficBytesPerPixel = floor.bytesPerPixel();
    }
}
void timeInterleaved(const std::vector<Timed>& group, Renderer& floorRenderer, const SceneSettings& base,
                     const std::vector<BenchFrame>& frames, const BenchPlan& plan, std::mt19937_64& random) {
    const std::vector<QualityKnob>& knobs = qualityKnobs();
    std::vector<std::vector<double>> samples(group.size()), floorRatios(group.size());
    std::vector<double> floorSamples;
    std::vector<std::vector<std::string>> passOrder(group.size());
    std::vector<std::map<std::string, std::vector<double>>> passSamples(group.size());
    for (const BenchFrame& frame : frames) {
        std::vector<SceneSettings> scenes;
        for (const Timed& t : group) {
            scenes.push_back(frameScene(base, knobs, t.result->config.levels, t.result->config.lights, frame,
                                    t.result->config.lightMethod));
            t.renderer->setPipeline(t.result->config.pipeline);
            for (int warm = 0; warm < 2; ++warm) t.renderer->renderFrame(scenes.back());
        }
        floorRenderer.renderFloor();
        glFinish();
        for (int i = 0; i < plan.timedFrames; ++i) {
            std::vector<double> roundMs(group.size() + 1);  // the configurations', then the floor's
            for (int slot : roundOrder(random, int(group.size()) + 1)) {
                size_t c = size_t(slot);
                if (c == group.size()) {
                    Clock::time_point start = Clock::now();
                    floorRenderer.renderFloor();
                    glFinish();
                    roundMs[c] = elapsedMs(start);
                    continue;
                }
                group[c].renderer->setPipeline(group[c].result->config.pipeline);
                if (plan.captureFirstTimedFrame && !gCaptured) {
                    gl::armCaptures(1);
                    gCaptured = true;
                    std::fprintf(stderr, "oasis bench: capturing the first timed frame: %s\n",
                                 describeCapturedConfig(group[c].result->config).c_str());
                }
                Clock::time_point start = Clock::now();
                group[c].renderer->renderFrame(scenes[c]);
                glFinish();
                roundMs[c] = elapsedMs(start);
            }
            floorSamples.push_back(roundMs.back());
            for (size_t c = 0; c < group.size(); ++c) {
                samples[c].push_back(roundMs[c]);
                floorRatios[c].push_back(roundMs[c] / roundMs.back());
            }
        }
        if (&frame == &frames.front()) countTraffic(group, floorRenderer, scenes);
        for (size_t c = 0; c < group.size(); ++c) {
            group[c].renderer->setPipeline(group[c].result->config.pipeline);
            std::vector<PassTimes> timed;
            if (plan.clock.gpuTimers) {
                PassTimerQueries queries(plan.passFrames + 1);
                for (int i = 0; i < plan.passFrames; ++i) queries.timeFrame(*group[c].renderer, scenes[c]);
                timed = queries.drain();
            } else {
                for (int i = 0; i < plan.passFrames; ++i) timed.push_back(renderFrameTimingPasses(*group[c].renderer, scenes[c]));
            }
            for (const PassTimes& frameTimes : timed)
                for (const auto& [name, ms] : frameTimes) {
                    if (!passSamples[c].count(name)) passOrder[c].push_back(name);
                    passSamples[c][name].push_back(ms);
                }
        }
    }
    for (size_t c = 0; c < group.size(); ++c) {
        BenchResult& result = *group[c].result;
        result.ms = describeSamples(samples[c]);
        result.msMedian = result.ms.median;
        result.floorMs = median(floorSamples);
        result.pairedFloorRatio = median(floorRatios[c]);
        result.msMin = *std::min_element(samples[c].begin(), samples[c].end());
        result.msMax = *std::max_element(samples[c].begin(), samples[c].end());
        for (const std::string& name : passOrder[c]) result.passesMs.emplace_back(name, median(passSamples[c][name]));
    }
}

// Each depth convention the context can draw, on a renderer of its own with the full layout.
std::vector<DepthPrecision> compareDepthPrecision(const RenderSession& session, int width, int height,
                                                  const std::vector<BenchFrame>& frames) {
    const std::vector<QualityKnob>& knobs = qualityKnobs();
    std::vector<SceneSettings> scenes;
    for (const BenchFrame& frame : frames) scenes.push_back(frameScene(session.scene, knobs, defaultLevels(knobs), defaultLightCount(), frame));
    Renderer renderer(*session.shaders, session.scene);
    renderer.views().setPlantAtlas(session.plantAtlas.get());
    RendererCapabilities clipControl = renderer.paths().capabilities;
    clipControl.clipControl.available = session.caps.clipControlAvailable(&clipControl.clipControl.reason);
    clipControl.workarounds = session.workarounds;  // the session's set, --workarounds applied
    renderer.setCapabilities(clipControl);
    std::vector<DepthPrecision> rows;
    for (const DepthConvention& depth : depthConventions()) {
        renderer.setDepthConvention(depth);
        if (renderer.paths().depthFellBack) {
            std::fprintf(stderr, "oasis bench: depth precision: %s not measured (%s)\n", depth.name.c_str(),
                         renderer.paths().depthReason.c_str());
            continue;
        }
        renderer.configure(width, height, *findGBufferLayout("full"));
        for (DepthPrecision& row : measureDepthPrecision(renderer, scenes, depthBands(session.scene))) rows.push_back(row);
    }
    return rows;
}

}  // namespace

BenchPlan benchPlan(const Options& options) {
    BenchPlan plan;
    if (options.quick) {
        plan.sizes = {{320, 180}};
        plan.frameTimes = {0.0};
        plan.timedFrames = 3;
        plan.passFrames = 1;
        plan.floorFrames = 3;
        plan.cheapestOnly = true;
        plan.lightCounts = quickLightCounts();
    } else {
        plan.lightCounts = benchLightCounts();
        plan.sizes = {{1280, 720}, {640, 360}};
        plan.frameTimes = {0.0, 30.0, 40.0};  // each with water, plants and hills in view
    }
    if (options.timingFramesGiven) plan.timedFrames = options.timingFrames;
    return plan;
}

int runBenchCommand(const Options& options) {
    try {
        // --api gles: the bench on an OpenGL ES context (desktop: the newest core context, as always).
        HeadlessContext context(options.scene.api == gl::Api::Gles ? maxGlVersionFor(options.scene) : MaxGlVersion{});
        gl::setFrameTerminators(true);  // each frame a frame for capture tools; set-up its own
        RenderSession session(options);
        gl::endFrame();
        Renderer& renderer = *session.renderer;
        std::string rendererName = queryContextInfo().renderer;
        BenchPlan plan = benchPlan(options);
        plan.workarounds = session.workarounds.appliedList();
        plan.captureFirstTimedFrame = options.capture;
        plan.clock = session.timingClock();
        plan.seed = roundSeed(options);
        std::mt19937_64 random(plan.seed);  // every group's rounds draw their orders from it in turn
        const std::vector<QualityKnob>& knobs = qualityKnobs();
        const GBufferLayout& reference = findGBufferLayout("full") ? *findGBufferLayout("full") : gbufferLayouts()[0];
        std::vector<std::string> layouts = {reference.name};  // first: the others are compared with it
        for (const GBufferLayout& layout : gbufferLayouts())
            if (layout.name != reference.name) layouts.push_back(layout.name);
        std::vector<BenchConfig> configs = benchConfigs(knobs, layouts, plan.sizes, plan.cheapestOnly, plan.lightCounts);
        // The fixed frames: poses on the default flight over the default terrain, so every
        // configuration (whatever its terrain octaves) looks from the same place.
        std::vector<BenchFrame> frames;
        for (double time : plan.frameTimes) frames.push_back({time, defaultCameraPath(TerrainShape{}, time)});
        // Reversed-z beside the default layout's deferred configurations, where the context can draw it.
        std::vector<std::string> extraDepths;
        std::string clipControlWhy;
        if (session.caps.clipControlAvailable(&clipControlWhy))
            for (const DepthConvention& depth : depthConventions())
                if (depth.name != standardDepthConvention().name) extraDepths.push_back(depth.name);
        if (extraDepths.empty())
            std::fprintf(stderr, "oasis bench: no reversed-z configurations (%s)\n", clipControlWhy.c_str());
        insertDepthConfigs(configs, defaultGBufferLayout().name, extraDepths);
        std::string outDir = options.outDirGiven ? options.outDir : "oasis-out/bench";
        std::error_code made;
        std::filesystem::create_directories(outDir, made);
        if (made) throw std::runtime_error("cannot create directory " + outDir + ": " + made.message());

        std::FILE* tableOut = options.json ? stderr : stdout;
        std::fprintf(tableOut,
                     "oasis bench: %zu configurations (%zu sizes x %zu light counts x %zu frames), %s\n  timing: %s; "
                     "each round's order random (seed %llu; --seed repeats it)\n  %s\n  driver workarounds: %s\n",
                     configs.size(), plan.sizes.size(), plan.lightCounts.size(), frames.size(),
                     queryContextInfo().summary().c_str(), timingNote(plan.clock).c_str(),
                     static_cast<unsigned long long>(plan.seed), describePlantAtlas(session).c_str(),
                     plan.workarounds.empty() ? "none" : plan.workarounds.c_str());
        // A renderer per layout and depth convention (the session's for the default layout with
        // standard depth), so that configurations timed in turn never reallocate targets; forward
        // uses the default layout's.
        // Their frames are looked at through the final view alone (the images, the times, the
        // traffic): targets nothing reads after their last pass lend their memory (FrameViews::setSink).
        renderer.views().setSink({"final"});
        std::map<std::pair<std::string, std::string>, Renderer*> renderers;  // (layout, depth)
        std::vector<std::unique_ptr<Renderer>> extraRenderers;
        auto addRenderer = [&](const std::string& layout, const std::string& depth) {
            extraRenderers.push_back(std::make_unique<Renderer>(*session.shaders, session.scene));
            extraRenderers.back()->views().setPlantAtlas(session.plantAtlas.get());
            extraRenderers.back()->views().setSink({"final"});
            extraRenderers.back()->views().setStencilPath(renderer.views().stencilPath());
            RendererCapabilities withClipControl = extraRenderers.back()->paths().capabilities;
            withClipControl.clipControl = {true, clipControlWhy};
            withClipControl.workarounds = session.workarounds;  // the session's set, --workarounds applied
            extraRenderers.back()->setCapabilities(withClipControl);
            extraRenderers.back()->setDepthConvention(*findDepthConvention(depth));
            renderers[{layout, depth}] = extraRenderers.back().get();
        };
        const std::string standardDepth = standardDepthConvention().name;
        for (const GBufferLayout& layout : gbufferLayouts()) {
            if (layout.name == defaultGBufferLayout().name)
                renderers[{layout.name, standardDepth}] = &renderer;
            else
                addRenderer(layout.name, standardDepth);
        }
        for (const std::string& depth : extraDepths) addRenderer(defaultGBufferLayout().name, depth);
        Clock::time_point runStart = Clock::now();
        std::vector<BenchResult> results;
        std::vector<Floor> floors;
        for (const auto& [width, height] : plan.sizes) {
            // The floors of every layout at this size, then per light count its references.
            double defaultFloor = 0.0;
            for (const GBufferLayout& layout : gbufferLayouts()) {
                renderer.configure(width, height, layout);
                double ms = medianFloorMs(renderer, plan.floorFrames);
                floors.push_back({width, height, layout.name, ms});
                if (layout.name == defaultGBufferLayout().name) defaultFloor = ms;
            }
            std::fprintf(stderr, "oasis bench: %dx%d floor %.2f ms (%s)\n", width, height, defaultFloor,
                         defaultGBufferLayout().name.c_str());
            for (int lights : plan.lightCounts) {
                // The reference for each frame at this size with these lights.
                renderer.configure(width, height, reference);
                renderer.setPipeline(PipelineKind::Deferred);
                std::vector<Image> references;
                for (const BenchFrame& frame : frames)
                    references.push_back(
                        renderFinalImage(renderer, frameScene(session.scene, knobs, highestLevels(knobs), lights, frame)));
                std::fprintf(stderr, "oasis bench: %dx%d reference with %d lights rendered\n", width, height, lights);
                for (auto& [key, layoutRenderer] : renderers)
                    layoutRenderer->configure(width, height, *findGBufferLayout(key.first));
                // One knob setting at a time (its configurations are consecutive): errors, then times.
                std::vector<BenchConfig> sized;
                for (const BenchConfig& config : configs)
                    if (config.width == width && config.height == height && config.lights == lights)
                        sized.push_back(config);
                for (size_t first = 0; first < sized.size();) {
                    std::string variation = sized[first].variation(knobs);
                    size_t end = first;
                    while (end < sized.size() && sized[end].variation(knobs) == variation) ++end;
                    std::vector<Image> referenceLayoutImages;  // deferred with the reference layout, these knobs
                    size_t groupStart = results.size();
                    std::vector<Renderer*> groupRenderers;
                    for (size_t i = first; i < end; ++i) {
                        const BenchConfig& config = sized[i];
                        Renderer& own = *renderers.at(
                            {config.layout == kNoLayout ? defaultGBufferLayout().name : config.layout, config.depth});
                        bool isReferenceLayout = config.pipeline == PipelineKind::Deferred &&
                                                 config.layout == reference.name && config.depth == standardDepth;
                        std::vector<Image> images;
                        BenchResult result = measureError(own, session.scene, config, frames, references,
                                                          referenceLayoutImages.empty() ? nullptr : &referenceLayoutImages,
                                                          images);
                        if (isReferenceLayout) referenceLayoutImages = std::move(images);
                        results.push_back(result);
                        groupRenderers.push_back(&own);
                    }
                    std::vector<Timed> group;
                    for (size_t i = groupStart; i < results.size(); ++i)
                        group.push_back({groupRenderers[i - groupStart], &results[i]});
                    timeInterleaved(group, renderer, session.scene, frames, plan, random);
                    for (size_t i = groupStart; i < results.size(); ++i) {
                        const BenchResult& result = results[i];
                        std::fprintf(stderr, "[%zu/%zu] %s %s %dx%d %s ... %.1f ms, %.2f dB (%.0f s)\n", i + 1,
                                     configs.size(), pipelineName(result.config.pipeline), layoutLabel(result.config).c_str(),
                                     width, height, result.variation.c_str(), result.msMedian, result.psnrDb,
                                     elapsedMs(runStart) / 1000.0);
                    }
                    first = end;
                }
            }
        }
        markParetoFrontiers(results);
        std::vector<DepthPrecision> depthPrecision =
            compareDepthPrecision(session, plan.sizes.front().first, plan.sizes.front().second, frames);

        std::string csv = benchCsvHeader() + "\n";
        for (const BenchResult& r : results) csv += benchCsvRow(r) + "\n";
        std::string json = benchJson(results, floors, frames, plan, options, rendererName, reference.name, depthPrecision);
        std::fputs(tableText(results).c_str(), tableOut);
        // The floors alone come first, timed before any configuration; the floor each row divides by
        // is the one timed in turn with its frames (bench.json's floor_ms), under the same load, and
        // can be several times these: both are printed, so neither reads as the other (issue 31, defect 5).
        for (const Floor& floor : floors)
            std::fprintf(tableOut, "floor %dx%d %s: %.2f ms (timed alone, before the configurations)\n", floor.width,
                         floor.height, floor.layout.c_str(), floor.ms);
        std::fputs(floorsInTurnText(results).c_str(), tableOut);
        std::fprintf(tableOut,
                     "ms: wall time around glFinish, %d timed frames per fixed frame (times:", plan.timedFrames);
        for (const BenchFrame& frame : frames) std::fprintf(tableOut, " %.0f s", frame.time);
        std::fprintf(tableOut, "); xfloor: ms med over the %s layout's floor timed in turn with the configuration's frames (bench.json's "
                               "floor_ms; its floor_ratio is the median of each frame's own ratio); error pooled over the frames against "
                               "deferred/%s with every knob at its highest and the same lights; own dB: PSNR against "
                               "deferred/%s with the same knobs and lights; pareto: per size and light count "
                               "(\"in pipeline\": only among its pipeline's configurations)\n",
                     defaultGBufferLayout().name.c_str(), reference.name.c_str(), reference.name.c_str());
        std::fprintf(tableOut, "ms med, 95%% interval, CV: the timed frames of every fixed frame together, the interval from "
                               "their order statistics (stats/timing_stats.h); pareto: a row is off its frontier only when "
                               "another's whole interval lies at or below its own, with no more error\n");
        auto fewest = std::min_element(results.begin(), results.end(), [](const BenchResult& a, const BenchResult& b) {
            return a.ms.confidence < b.ms.confidence;
        });
        if (fewest != results.end() && fewest->ms.confidence < kIntervalConfidence)
            std::fprintf(tableOut, "*: from %d timed frames the interval is their range, which holds the median with %.0f%% "
                                   "confidence only (95%% from %d frames: more --frames)\n",
                         fewest->ms.count, 100.0 * fewest->ms.confidence, kMinRoundsForInterval);
        // The bench's B/px and compare's "bytes/pixel" count different targets (issue 44, item 7).
        std::fprintf(tableOut, "B/px: every target the frame writes (the G-buffer with its depth-stencil for deferred, the "
                               "depth-stencil for forward, plus radiance, reflection and final: bench.json's "
                               "bytes_per_pixel); compare's \"bytes/pixel\" is the G-buffer with its depth alone "
                               "(gbuffer_bytes_per_pixel)\n");
        if (!results.empty() && results.front().floorTrafficBytesPerPixel >= 0.0)
            std::fprintf(tableOut, "moved/px: bytes written and read per pixel of the first frame, counted by the driver's "
                                   "queries (docs/traffic.md); the floor moves %.1f B/px\n",
                         results.front().floorTrafficBytesPerPixel);
        std::fprintf(tableOut, "depth precision at %s (deferred, full layout, default knobs; error of the position "
                               "reconstructed from depth against the stored float position, world units and relative "
                               "to distance):\n%s",
                     sizeName(plan.sizes.front().first, plan.sizes.front().second).c_str(),
                     depthPrecisionTable(depthPrecision).c_str());
        if (options.json) std::fputs(json.c_str(), stdout);
        // The measurements are printed above whatever happens here, so a long run is never lost.
        // The files are one set (io/file_output.h): on a failure none is renamed, and the
        // directory keeps an earlier run's four files together rather than a mix of two runs.
        std::vector<OutputFile> reports = {{outDir + "/bench.csv", csv}, {outDir + "/bench.json", json},
                                           {outDir + "/bench.svg", benchSvg(results, rendererName)},
                                           {outDir + "/depth_precision.csv", depthPrecisionCsv(depthPrecision)}};
        std::vector<std::string> written;
        std::string error;
        if (!writeFilesWhole(reports, written, error)) {
            std::fprintf(stderr, "oasis: %s\n", error.c_str());
            for (const std::string& path : written)
                std::fprintf(stderr, "oasis: wrote %s before the failure (complete, kept)\n", printableText(path).c_str());
            return 1;
        }
        std::fprintf(tableOut, "wrote %s/bench.csv, %s/bench.json, %s/bench.svg, %s/depth_precision.csv in %.0f s\n",
                     outDir.c_str(), outDir.c_str(), outDir.c_str(), outDir.c_str(), elapsedMs(runStart) / 1000.0);
        return 0;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "oasis: %s\n", error.what());
        return 1;
    }
}

}  // namespace oasis
