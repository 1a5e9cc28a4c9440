// render / compare / main job on a surfaceless EGL context.
#include "commands/headless_commands.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <tuple>

#include "io/json_text.h"
#include "commands/compare_json.h"
#include "commands/comparison.h"
#include "frame/overview_overlay.h"
#include "commands/probe_report.h"
#include "commands/provenance.h"
#include "commands/session.h"
#include "commands/timing_report.h"
#include "commands/traffic_report.h"
#include "frame/view_mask.h"
#include "context/gl_context.h"
#include "debug/error_image.h"
#include "debug/view_legend.h"
#include "frame/encoding_error.h"
#include "frame/frame_graph.h"
#include "frame/frame_readback.h"
#include "frame/pixel_probe.h"
#include "frame/target_lifetimes.h"
#include "gl/frame_capture.h"
#include "io/file_output.h"
#include "io/printable_text.h"

namespace oasis {
namespace {

bool ensureDirectory(const std::string& path, std::string& error) {
    if (mkdir(path.c_str(), 0755) == 0 || errno == EEXIST) return true;
    error = "cannot create directory " + path + ": " + std::strerror(errno);
    return false;
}

Image renderFinal(Renderer& renderer, const SceneSettings& scene, PipelineKind kind) {
    renderer.setPipeline(kind);
    renderer.renderFrame(scene);
    renderer.views().render("final");
    return readDisplay(renderer);
}

// With `capture`, RenderDoc captures the forward and the deferred frame whose images are written.
Comparison compareFrame(RenderSession& session, const RoundPlan& plan, bool passTimes, bool capture = false) {
    Renderer& renderer = *session.renderer;
    Comparison result;
    // Its frames are looked at through the final view (the images, the times, the traffic; a
    // capture keeps the whole frame); the last, left for what follows (the main job's overview), is whole.
    renderer.views().setSink(capture ? std::vector<std::string>{} : std::vector<std::string>{"final"});
    for (PipelineKind kind : {PipelineKind::Forward, PipelineKind::Deferred}) {  // shader builds: frames of their own
        renderer.setPipeline(kind);
        renderer.renderFrame(session.scene, FrameRequest::buildingPrograms("final"));
    }
    if (capture) gl::armCaptures(2);
    result.forward = renderFinal(renderer, session.scene, PipelineKind::Forward);
    // The frame's passes; the final view's pass after them draws no traffic compare counts.
    result.forwardGraph = frameGraphJson(withoutViewSteps(renderer.lastFrame().graph()));
    result.forwardTargetBytes = renderer.lastFrame().targetMemoryBytes();
    result.deferred = renderFinal(renderer, session.scene, PipelineKind::Deferred);
    result.deferredGraph = frameGraphJson(withoutViewSteps(renderer.lastFrame().graph()));
    result.deferredTargetBytes = renderer.lastFrame().targetMemoryBytes();
    result.difference = compareImages(result.forward, result.deferred);
    result.differing = countDifferingPixels(result.forward, result.deferred);
    result.times = timePipelinesInTurn(renderer, session.scene, plan);
    if (passTimes) {
        result.clock = session.timingClock();
        std::mt19937_64 random(plan.seed + 3);  // the rounds' order as the frames', its own draws
        std::vector<std::vector<PassTimes>> frames;
        std::vector<PassTimes> passes = medianPassMsInTurn(renderer, session.scene, result.times.rounds, result.clock,
                                                           {PipelineKind::Forward, PipelineKind::Deferred}, &random,
                                                           &frames);
        result.forwardPasses = passes[0];
        result.deferredPasses = passes[1];
        result.forwardPassStats = passSampleStats(frames[0]);
        result.deferredPassStats = passSampleStats(frames[1]);
        renderer.setPipeline(PipelineKind::Forward);
        result.forwardTraffic = measureFrameTraffic(renderer, session.scene);
        renderer.setPipeline(PipelineKind::Deferred);
        result.deferredTraffic = measureFrameTraffic(renderer, session.scene);
        result.floorTraffic = measureFloorTraffic(renderer);
    }
    renderer.views().setSink({});
    renderer.renderFrame(session.scene);  // leave the frame, not the floor, in the targets
    return result;
}

// One PNG of a set: its file name, its image and where the image comes from (commands/provenance.h).
struct ImageFile {
    std::string file;
    const Image* image;
    Provenance provenance;
};

// Writes the images as one set (io/file_output.h): all of them or, on a failure, none, so the
// directory never mixes this run's images with an earlier run's. On failure the message names the
// file; a path is reported written only once it is complete under its name.
bool writeImages(const std::string& directory, const std::vector<ImageFile>& images, std::vector<std::string>& written) {
    std::string error;
    if (!ensureDirectory(directory, error)) { std::fprintf(stderr, "oasis: %s\n", error.c_str()); return false; }
    std::vector<OutputFile> files;
    for (const ImageFile& image : images) {
        files.push_back({directory + "/" + image.file, {}});
        if (!encodePng(*image.image, files.back().bytes, provenanceTexts(image.provenance))) {
            std::fprintf(stderr, "oasis: cannot write %s: PNG encoding failed\n", printableText(files.back().path).c_str());
            return false;
        }
    }
    if (writeFilesWhole(files, written, error)) return true;
    std::fprintf(stderr, "oasis: %s\n", error.c_str());
    for (const std::string& path : written)
        std::fprintf(stderr, "oasis: wrote %s before the failure (complete, kept)\n", printableText(path).c_str());
    return false;
}

// compare's set: each pipeline's final frame and the difference of the two with its legend.
std::vector<ImageFile> comparisonFiles(const Options& options, const Comparison& c, const Image& heat) {
    int height = c.forward.height;
    return {{"forward.png", &c.forward, pictureProvenance(options, "final", "forward", height, height)},
            {"deferred.png", &c.deferred, pictureProvenance(options, "final", "deferred", height, height)},
            {"difference.png", &heat, pictureProvenance(options, "difference", "forward and deferred", heat.height, height)}};
}

void printSummary(const Options& options, const RenderSession& session, const Comparison& c) {
    const FrameTargets& targets = session.renderer->targets();
    const FrameSetup& frame = session.renderer->lastFrame().setup;
    std::printf("oasis: %dx%d, G-buffer '%s' (%d bytes/pixel: G-buffer and depth-stencil; bench's B/px adds the other targets), depth %s, time %.2f s (%.2f h), on %s\n",
                targets.width(), targets.height(), targets.layout().name.c_str(),
                gbufferBytesPerPixel(targets.layout(), targets.depth()),
                session.renderer->paths().depthReason.c_str(), options.scene.timeSeconds, frame.hour,
                queryContextInfo().summary().c_str());
    std::printf("  forward vs deferred: PSNR %.2f dB%s, max abs %d, RMSE %.4f (8-bit RGB)\n", c.difference.psnrDb,
                c.difference.psnrDb >= kPsnrIdentical ? " (identical)" : "", c.difference.maxAbs, c.difference.rmse);
    std::printf("  %s\n", c.differing.describe().c_str());
    std::printf("%s", timesText(c.times, session.renderer->parts().geometry.terrainTriangles()).c_str());
    std::printf("  %s\n", describePlantAtlas(session).c_str());
    std::printf("  %s\n", describeVegetation(*session.renderer).c_str());
    std::printf("  %s\n", describeLights(*session.renderer).c_str());
    std::printf("  %s\n", describeReflectionBounds(*session.renderer, session.scene).c_str());
    for (const auto& [pipeline, passes, traffic] :
         {std::tuple{"forward", &c.forwardPassStats, &c.forwardTraffic}, {"deferred", &c.deferredPassStats, &c.deferredTraffic}}) {
        if (passes->empty()) continue;
        int frames = passes->front().second.count;
        std::string interval = frames >= kMinRoundsForInterval ? "its 95% interval" : "the frames' range (no 95% interval under " +
                               std::to_string(kMinRoundsForInterval) + ")";
        std::printf("  %s per pass (median ms and %s over %d frames, %s)%s:\n", pipeline, interval.c_str(), frames,
                    c.clock.gpuTimers ? "GPU timer queries" : "wall time, glFinish after each",
                    traffic->measured() ? trafficColumnsHeader().c_str() : "");
        for (const auto& [name, stats] : *passes)
            std::printf("    %-30s %7.2f %-17s%s\n", name.c_str(), stats.median, intervalText(stats.low, stats.high).c_str(),
                        trafficColumns(*traffic, name).c_str());
    }
    if (!c.forwardPasses.empty()) std::printf("  pass clock: %s\n", c.clock.describe().c_str());
    std::printf("%s", trafficSummary(c.forwardTraffic, c.deferredTraffic, c.floorTraffic).c_str());
}

RoundPlan roundPlan(const Options& options) {
    RoundPlan plan;
    plan.rounds = options.timingFrames;
    plan.seed = roundSeed(options);
    plan.untilCiPercent = options.untilCiPercent;
    return plan;
}

// Runs `body` with a headless context and a session, turning failures into messages and exit 1.
// Frames for capture tools: the set-up (plant atlas) is a frame of its own, each renderFrame
// starts one, the command's end closes the last (gl/frame_capture.h).
template <typename Body>
int withHeadlessSession(const Options& options, Body body) {
    try {
        HeadlessContext context(maxGlVersionFor(options.scene));
        gl::setFrameTerminators(true);
        RenderSession session(options);
        gl::endFrame();
        int code = body(session);
        gl::endFrame();
        return code;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "oasis: %s\n", error.what());
        return 1;
    }
}

}  // namespace

// difference.png: the heat map of `a` against `b` with its scale bar and numbers (forward against
// deferred here; two driver set-ups, or a frame and a saved reference, in commands/driver_compare).
Image differenceImage(const Image& a, const std::string& aName, const Image& b, const std::string& bName) {
    constexpr int kFullScale = 16;
    ImageDifference difference = compareImages(a, b);
    Legend legend;
    legend.title = "difference: per pixel the largest channel difference |" + aName + " - " + bName +
                   "| in 8-bit levels";
    legend.scale = LegendScale::DifferenceHeat;
    legend.low = 0.0;
    legend.high = kFullScale;
    char numbers[160];
    std::snprintf(numbers, sizeof(numbers), "whole frame: PSNR %.2f dB%s, max abs %d, RMSE %.4f (8-bit RGB)",
                  difference.psnrDb, difference.maxAbs == 0 ? " (identical)" : "", difference.maxAbs,
                  difference.rmse);
    // "identical" only at max abs 0: the 100 dB cap is also reached by a 1-level difference in a
    // few pixels (zink against llvmpipe).
    legend.notes.push_back(numbers);
    legend.notes.push_back(countDifferingPixels(a, b).describe());  // the heat map shows where, this how many
    LegendRenderer legends;
    Image heat = differenceHeatmap(a, b, kFullScale);
    return stackImages(heat, legends.draw(legend, heat.width));
}

// An encoding-error view: the layout's frame against full's, on the depth view's ramp from 0 (or
// --range) to the largest error; pixels with no common surface dark grey; its legend and summary.
Image encodingErrorImage(const Options& options, RenderSession& session, const EncodingErrorView& view,
                         std::FILE* report) {
    Renderer& renderer = *session.renderer;
    EncodingError error = measureEncodingError(renderer, session.scene, renderer.targets().layout());
    const std::vector<float>& values = error.*(view.values);
    ErrorSummary summary = summarizeError(values);
    auto [low, high] = options.viewControls.range.value_or(std::pair{0.0, summary.max > 0.0 ? summary.max : 1.0});
    Image image = encodingErrorPicture(values, error.width, error.height, low, high);
    char line[256];
    std::snprintf(line, sizeof(line), "%s, %s against full: median %.4g, 99%% %.4g, max %.4g over %ld surface pixels",
                  view.name.c_str(), error.layout.c_str(), summary.median, summary.p99, summary.max, summary.count);
    std::fprintf(report, "oasis: %s\n", line);
    if (!options.legend.value_or(true)) return image;  // an error view is a buffer view: a legend by default
    Legend legend;
    legend.title = view.name + " (deferred, " + error.layout + " against full): " + view.legend;
    legend.scale = LegendScale::LinearRamp;
    legend.low = low;
    legend.high = high;
    legend.notes = {line, "dark grey: no common surface (sky, or the two frames' flags differ)",
                    "under the water: " + renderer.views().scene().description};
    LegendRenderer legends;
    return stackImages(image, legends.draw(legend, image.width));
}

// The image `render` writes: the view (or its values through the controls), the overlay, and
// under a single view its legend; `report` gets the value counts.
Image renderedViewImage(const Options& options, Renderer& renderer, std::FILE* report) {
    renderer.views().setExposure(options.viewExposure);
    renderer.views().render(options.view);
    Image image = readDisplay(renderer);
    const DebugView* view = findDebugView(options.view);
    const ViewControls& controls = options.viewControls;
    if (!view) {  // the overview: every tile labelled, each with its own overlay and counts
        for (const std::string& line : overlayOverviewTiles(image, renderer, controls.overlay))
            std::fprintf(report, "oasis: %s\n", line.c_str());
        std::fprintf(report, "oasis: overview overlay: %s\n", overlayNames(controls.overlay).c_str());
        std::fprintf(report, "oasis: overview: under the water its G-buffer, depth and light tiles show %s\n",
                     renderer.views().scene().description.c_str());
        return image;
    }
    std::vector<float> values = renderer.views().readValues(options.view);
    ViewChannel channel = controls.channel.value_or(defaultChannel(*view));
    const DrawnPixels drawn = drawnPixels(renderer, *view);  // the sky left out (issue 31, defect 1)
    ValueStatistics statistics = valueStatistics(values, channel, &drawn);
    if (controls.showValues())
        image = mapViewValues(values, image.width, image.height, channel, rangeInUse(controls, statistics),
                              controls.overlay, &drawn);
    else
        paintOverlay(image, values, channel, controls.overlay, &drawn);
    std::fprintf(report, "oasis: view %s values (%s): %ld, NaN %ld, +Inf %ld, -Inf %ld, negative %ld; finite min %.6g, max %.6g; "
                 "not drawn %ld px (left out)\n",
                 view->name.c_str(), describeChannel(*view, channel).c_str(), statistics.values, statistics.nan,
                 statistics.positiveInfinity, statistics.negativeInfinity, statistics.negative, statistics.min,
                 statistics.max, statistics.undrawn);
    // The final frame is a picture: the size asked for, no strip unless --legend on.
    if (!options.legend.value_or(view->name != "final")) return image;
    gl::endFrame();  // the frame ends with its view read back; the legend strip is a frame of its own
    const FrameData& frame = renderer.lastFrame().setup.data;
    LegendRenderer legends;
    Legend legend = viewLegend(*view, controls, statistics, frame.depthRange.x, frame.depthRange.y,
                               frame.terrainGridCounts.w, waterNote(*view, renderer.views().scene().description));
    std::string undrawn = undrawnNote(*view, statistics.undrawn, controls.showValues());
    if (!undrawn.empty()) legend.notes.push_back(undrawn);
    return stackImages(image, legends.draw(legend, image.width));
}

Image renderRequestedImage(const Options& options, RenderSession& session, std::FILE* report,
                           const std::vector<Resource>& readAfter) {
    Renderer& renderer = *session.renderer;
    renderer.setPipeline(options.pipeline);
    const EncodingErrorView* errorView = findEncodingErrorView(options.view);
    // The frame is built for what is written (its sink): the view, and the info view whose
    // SKY flags mask the sky out of its values. A capture keeps the whole frame to inspect;
    // the encoding-error views and a stopped frame read more and keep it too.
    if (!errorView && !options.capture) {
        std::vector<std::string> sink = {options.view};
        if (const DebugView* view = findDebugView(options.view); view && masksUndrawn(*view)) sink.push_back("info");
        renderer.views().setSink(sink, readAfter);
    }
    // Shader builds in a frame of their own; the frame after it (captured with --capture) only draws.
    if (options.stopBefore.empty()) renderer.renderFrame(session.scene, FrameRequest::buildingPrograms(errorView ? "" : options.view));
    if (options.capture) gl::armCaptures(1);
    renderer.renderFrame(session.scene, options.stopBefore);
    if (options.graph) return Image();
    return errorView ? encodingErrorImage(options, session, *errorView, report) : renderedViewImage(options, renderer, report);
}

int runRenderCommand(const Options& options) {
    return withHeadlessSession(options, [&](RenderSession& session) {
        Renderer& renderer = *session.renderer;
        const EncodingErrorView* errorView = findEncodingErrorView(options.view);
        // Logs go to stderr always: stdout carries only what was asked for (a PNG with --out
        // /dev/stdout), never a log line (issue 31, defect 8).
        std::FILE* report = stderr;
        Image image = renderRequestedImage(options, session, report);
        if (options.graph) {
            // The header names the pipeline: one frame is printed, the other is --pipeline's other value.
            std::printf("# the %s pipeline's frame, %dx%d, built for view %s (--pipeline %s prints the other)\n",
                        pipelineName(options.pipeline), renderer.targets().width(), renderer.targets().height(),
                        options.view.c_str(),
                        options.pipeline == PipelineKind::Forward ? "deferred" : "forward");
            std::printf("%s", frameGraphText(renderer.lastFrame().graph()).c_str());
            const LastFrame frame = renderer.lastFrame();
            std::printf("%s", targetLifetimesText(frame.graph(), frame.targetLifetimes, renderer.targets(), 1).c_str());
            if (const int divisor = frame.setup.reflectionDivisor; divisor > 1 && frame.setup.reflectionsActive) {
                // Drawn reduced: the reflection's own targets, the same targets' resources at a scale.
                std::printf("# the reflection's own targets, at 1/%d of the frame:\n", divisor);
                std::printf("%s",
                            targetLifetimesText(frame.graph(), frame.targetLifetimes, renderer.targets(), divisor).c_str());
            }
            std::printf("%s", heldTargetMemoryText(renderer.targets()).c_str());
            return 0;
        }
        std::string error;
        Provenance provenance = pictureProvenance(options, options.view,
                                                  errorView ? "deferred" : pipelineName(options.pipeline),
                                                  image.height, renderer.targets().height());
        if (!writePng(options.out, image, error, provenanceTexts(provenance))) {
            std::fprintf(stderr, "oasis: %s\n", error.c_str());
            return 1;
        }
        std::fprintf(report, "oasis: wrote %s (%s pipeline, view %s, %dx%d)\n", printableText(options.out).c_str(),
                     pipelineName(options.pipeline), options.view.c_str(), renderer.targets().width(),
                     renderer.targets().height());
        // compare --driver reads this line to tell whether the set-up got the driver it asked for.
        ContextInfo context = queryContextInfo();
        std::fprintf(report, "oasis: renderer: %s; GL %s\n", context.renderer.c_str(), context.version.c_str());
        // compare --driver records this line in its report: the driver workarounds that drew the frame.
        const std::string applied = session.workarounds.appliedList();
        std::fprintf(report, "oasis: workarounds: %s\n", applied.empty() ? "none" : applied.c_str());
        std::fprintf(report, "oasis: %s\n", describePlantAtlas(session).c_str());
        std::fprintf(report, "oasis: %s\n", describeVegetation(renderer).c_str());
        std::fprintf(report, "oasis: %s\n", describeLights(renderer).c_str());
        std::fprintf(report, "oasis: %s\n", describeReflectionBounds(renderer, session.scene).c_str());
        std::fprintf(report, "oasis: gbuffer %s\n", renderer.paths().gbufferReason.c_str());
        return 0;
    });
}

int runCompareCommand(const Options& options) {
    return withHeadlessSession(options, [&](RenderSession& session) {
        Comparison c = compareFrame(session, roundPlan(options), options.passTimes, options.capture);
        Image heat = differenceImage(c.forward, "forward", c.deferred, "deferred");
        std::vector<std::string> written;
        if (!writeImages(options.outDir, comparisonFiles(options, c, heat), written)) return 1;
        if (options.json) {
            printCompareJson(options, session, c);
        } else {
            printSummary(options, session, c);
            for (const std::string& path : written) std::fprintf(stderr, "  wrote %s\n", printableText(path).c_str());  // a log line
        }
        return 0;
    });
}

int runMainJob(const Options& options) {
    return withHeadlessSession(options, [&](RenderSession& session) {
        // stdout carries the summary (or with --json the JSON alone, compare's keys); log lines go to stderr.
        std::FILE* report = stderr;
        std::fprintf(report, "oasis: no display, running the headless main job (stencil view: %s)\n",
                     session.stencilPathReason.c_str());
        Comparison c = compareFrame(session, roundPlan(options), options.passTimes);
        session.renderer->views().render(kOverviewName);
        Image overview = readDisplay(*session.renderer);
        Image heat = differenceImage(c.forward, "forward", c.deferred, "deferred");
        std::vector<ImageFile> files = comparisonFiles(options, c, heat);
        files.push_back({"overview.png", &overview,
                         pictureProvenance(options, kOverviewName, pipelineName(session.renderer->pipeline()),
                                           overview.height, overview.height)});
        std::vector<std::string> written;
        if (!writeImages(options.outDir, files, written)) return 1;
        if (options.json) printCompareJson(options, session, c);
        else printSummary(options, session, c);
        for (const std::string& path : written) std::fprintf(report, "  wrote %s\n", printableText(path).c_str());
        return 0;
    });
}

int runProbeCommand(const Options& options) {
    return withHeadlessSession(options, [&](RenderSession& session) {
        Renderer& renderer = *session.renderer;
        // The layout's encoding error at the pixel first (two deferred frames), then the frame asked for.
        std::optional<EncodingError> error;
        if (renderer.targets().layout().name != "full")
            error = measureEncodingError(renderer, session.scene, renderer.targets().layout());
        renderer.setPipeline(options.pipeline);
        ProbeReport probed = probeInDepth(renderer, session.scene, options.probeAt->first, options.probeAt->second,
                                          {options.probeShading, options.probeHistory, options.stopBefore});
        if (error) addEncodingError(probed.probe, *error);
        std::string report = options.json ? reportJson(probed) : reportText(probed);
        std::fputs((report + (options.json ? "\n" : "")).c_str(), stdout);
        return 0;
    });
}

}  // namespace oasis
