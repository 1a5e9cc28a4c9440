// One window frame: the chosen configuration drawn single or as the live comparison, the view
// controls and probes applied; a configuration whose programs do not build is undone.
#include "window/window_state.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "frame/overview_overlay.h"
#include "frame/view_mask.h"
#include "debug/error_image.h"
#include "frame/encoding_error.h"
#include "frame/frame_readback.h"
#include "frame/gpu_timer.h"

namespace oasis {
namespace window {

namespace {

// After a view is drawn: its values through the view controls (and the overlay where any value
// needs it) into Display, and the probes of the pixels hovered and pinned.
// An encoding-error view as the window's frame: the layout's deferred frame against full's (two
// more frames), on the depth ramp from 0 to the largest error, as `oasis render` draws it.
void showEncodingError(Renderer& renderer, const SceneSettings& scene, const EncodingErrorView& view,
                       WindowState& state) {
    if (renderer.targets().layout().name == "full") {
        state.errorViewSummary = view.name + " compares a layout against full: choose standard or compact (G)";
        renderer.views().render("final");
        return;
    }
    EncodingError error = measureEncodingError(renderer, scene, renderer.targets().layout());
    const std::vector<float>& values = error.*(view.values);
    ErrorSummary summary = summarizeError(values);
    char line[256];
    std::snprintf(line, sizeof(line), "%s against full: median %.4g, 99%% %.4g, max %.4g over %ld surface pixels",
                  error.layout.c_str(), summary.median, summary.p99, summary.max, summary.count);
    state.errorViewSummary = line;
    showImage(renderer, encodingErrorPicture(values, error.width, error.height, 0.0, summary.max > 0.0 ? summary.max : 1.0));
}

void inspectFrame(Renderer& renderer, const Configuration& config, Inspector& inspector, const WindowComparison& off) {
    inspector.statistics.reset();
    const DebugView* view = findDebugView(config.view);
    ViewControls controls = inspector.controls();
    // The values pass and its full-frame float read-back cost a frame's worth of bandwidth: only
    // while someone looks at the counts or asks for the values.
    if (view && (inspector.sectionOpen || controls.showValues())) {
        std::vector<float> values = renderer.views().readValues(view->name);
        ViewChannel channel = controls.channel.value_or(defaultChannel(*view));
        // As `oasis render` counts them: the sky's undrawn texels are not values (frame/view_mask.h).
        const DrawnPixels drawn = drawnPixels(renderer, *view);
        ValueStatistics statistics = valueStatistics(values, channel, &drawn);
        const FrameTargets& targets = renderer.targets();
        if (controls.showValues()) {
            showImage(renderer, mapViewValues(values, targets.width(), targets.height(), channel,
                                             rangeInUse(controls, statistics), controls.overlay, &drawn));
        } else if (((controls.overlay & kOverlayNan) && statistics.nan) ||
                   ((controls.overlay & kOverlayInfinity) && (statistics.positiveInfinity || statistics.negativeInfinity)) ||
                   ((controls.overlay & kOverlayNegative) && statistics.negative)) {
            Image image = readDisplay(renderer);
            paintOverlay(image, values, channel, controls.overlay, &drawn);
            showImage(renderer, image);
        }
        inspector.statistics = statistics;
    }
    // The overview's tiles get their overlays too, while the inspector section is open (13 reads).
    inspector.overviewCounts.clear();
    if (config.view == kOverviewName && inspector.sectionOpen && controls.overlay) {
        Image image = readDisplay(renderer);
        inspector.overviewCounts = overlayOverviewTiles(image, renderer, controls.overlay);
        showImage(renderer, image);
    }
    probeShownPixels(inspector, {{&renderer, ""}}, off, renderer.targets().width(), renderer.targets().height());
}

// One frame of `config` into the window's framebuffer (not yet swapped). Throws ShaderBuildError
// when a program it needs does not build; the scene must already hold the config's settings.
// What the comparison's medians were measured for: the configuration, the size and the scene's
// settings (the clock and the camera's flight are not changes: they move every frame).
std::string comparisonKey(const Configuration& config, const SceneSettings& scene, int width, int height,
                          const WindowComparison& c) {
    char key[512];
    std::snprintf(key, sizeof(key), "%s|%dx%d|%d %zu %d|%g %d %g %g|%d %g %g|%g", config.describe().c_str(), width,
                  height, int(c.mode), c.layoutB, int(c.passTimes), scene.water.level, int(scene.water.reflections),
                  scene.water.rippleStrength, scene.water.absorption, int(scene.vegetation.enabled),
                  scene.vegetation.density, scene.vegetation.windStrength, scene.hour ? *scene.hour : -1.0);
    return key;
}

// Both sides of the live comparison, each on its own renderer (no reallocation between them),
// timed, then shown split or as their difference; each probe reads the side shown at its pixel.
void drawComparison(RenderSession& session, const Configuration& config, const SceneSettings& scene, int width,
                    int height, WindowState& state) {
    WindowComparison& c = state.comparison;
    if (!state.sideB) state.sideB = session.makeRenderer();
    c.chooseSides(config.pipeline, config.layoutIndex);
    c.noteSettings(comparisonKey(config, scene, width, height, c));
    Renderer* renderers[2] = {session.renderer.get(), state.sideB.get()};
    const CompareSide* sides[2] = {&c.a, &c.b};
    RollingMedian* medians[2] = {&c.msA, &c.msB};
    std::vector<std::pair<std::string, double>>* passes[2] = {&c.passesA, &c.passesB};
    PassTimerQueries* queries[2] = {&c.queriesA, &c.queriesB};
    if (c.passTimes && !c.clock) c.clock = session.timingClock();  // once: a few frames of each clock
    Image images[2];
    state.frameMs = 0.0;
    for (int s : roundOrder(c.order, 2)) {
        Renderer& renderer = *renderers[s];
        renderer.setPipeline(sides[s]->pipeline);
        renderer.setDepthConvention(depthConventions()[config.depthIndex]);
        renderer.configure(width, height, gbufferLayouts()[sides[s]->layoutIndex]);
        // A layout the context cannot draw falls back (paths().gbuffer): the side is named by what it draws.
        if (sides[s]->pipeline == PipelineKind::Deferred && renderer.paths().gbufferFellBack)
            (s == 0 ? c.a : c.b).label = "deferred, " + renderer.targets().layout().name + " for " +
                                         renderer.paths().gbufferRequested;
        renderer.views().setExposure(state.inspector.exposureStops);
        renderer.views().setWaterScene(config.waterScene);
        glFinish();
        auto start = std::chrono::steady_clock::now();
        if (c.passTimes && c.clock->gpuTimers) {
            // Queries read a few frames later, never waited for: the table lags by those frames.
            queries[s]->timeFrame(renderer, scene);
            glFinish();
            *passes[s] = queries[s]->latest();
        } else if (c.passTimes) {
            *passes[s] = renderFrameTimingPasses(renderer, scene);
        } else {
            renderer.renderFrame(scene);
            glFinish();
        }
        double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        medians[s]->add(ms);
        state.frameMs += ms;
        // The comparison shows the table's views; an encoding-error view is a comparison of its own.
        renderer.views().render(findEncodingErrorView(config.view) ? std::string("final") : config.view);
        images[s] = readDisplay(renderer);
    }
    state.smoothedMs = state.smoothedMs == 0.0 ? state.frameMs : 0.9 * state.smoothedMs + 0.1 * state.frameMs;
    c.difference = compareImages(images[0], images[1]);
    // The probes read the side that drew each pixel shown; I's frames come after the images were read.
    std::vector<DrawnSide> drawn = {{renderers[0], "A: " + c.a.label}, {renderers[1], "B: " + c.b.label}};
    probeInDepthWhenAsked(state.inspector, scene, drawn, c, width, height);
    Renderer& shown = *renderers[0];
    showImage(shown, showsDifference(c.mode) ? differenceHeatmap(images[0], images[1])
                                            : splitImage(images[0], images[1], int(std::lround(c.divider * float(width)))));
    Inspector& inspector = state.inspector;
    inspector.statistics.reset();
    probeShownPixels(inspector, drawn, c, width, height);
    shown.present(width, height);
}

void drawConfiguration(RenderSession& session, const Configuration& config, const SceneSettings& scene, int width,
                       int height, WindowState& state) {
    if (state.comparison.mode != CompareMode::Off) {
        drawComparison(session, config, scene, width, height, state);
        return;
    }
    Renderer& renderer = *session.renderer;
    renderer.setPipeline(config.pipeline);
    renderer.setDepthConvention(depthConventions()[config.depthIndex]);
    renderer.configure(width, height, gbufferLayouts()[config.layoutIndex]);
    probeInDepthWhenAsked(state.inspector, scene, {{&renderer, ""}}, state.comparison, width, height);
    auto start = std::chrono::steady_clock::now();
    renderer.renderFrame(scene);
    glFinish();
    state.frameMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    state.smoothedMs = state.smoothedMs == 0.0 ? state.frameMs : 0.9 * state.smoothedMs + 0.1 * state.frameMs;
    renderer.views().setExposure(state.inspector.exposureStops);
    renderer.views().setWaterScene(config.waterScene);
    if (const EncodingErrorView* errorView = findEncodingErrorView(config.view))
        showEncodingError(renderer, scene, *errorView, state);
    else
        renderer.views().render(config.view);
    inspectFrame(renderer, config, state.inspector, state.comparison);
    renderer.present(width, height);
}

}  // namespace

// Draws the chosen configuration; when a program it needs does not build, says why, goes back to
// the last configuration that drew and draws that. False when nothing could be drawn. On the
// first frame there is nothing to go back to: the error ends the window (exit 1).
bool drawChosen(RenderSession& session, SceneSettings& scene, WindowState& state, int width, int height) {
    const Configuration wanted = currentConfiguration(state, scene);
    try {
        drawConfiguration(session, wanted, scene, width, height, state);
        state.lastDrawn = wanted;
        return true;
    } catch (const ShaderBuildError& error) {
        if (!state.lastDrawn) throw;
        if (wanted == *state.lastDrawn) {  // the scene itself changed (e.g. the camera rose out of the water)
            report(state, "cannot draw " + wanted.describe() + ": " + error.what(), true);
            return false;
        }
        report(state, "cannot switch to " + wanted.describe() + "; drawing " + state.lastDrawn->describe() +
                          " instead: " + error.what(), true);
        ++state.counts.switchesUndone;
        restoreConfiguration(*state.lastDrawn, state, scene);
    }
    try {
        drawConfiguration(session, *state.lastDrawn, scene, width, height, state);
        return true;
    } catch (const ShaderBuildError& error) {
        report(state, "cannot draw " + state.lastDrawn->describe() + ": " + error.what(), true);
        return false;
    }
}

}  // namespace window
}  // namespace oasis
