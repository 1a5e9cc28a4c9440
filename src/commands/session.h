// What every command does before and around rendering: find the shaders, turn options into
// scene settings, pick capability-dependent paths (and say why), and time frames.
#pragma once
#include <cstdint>
#include <memory>
#include <random>
#include <optional>
#include <string>
#include <utility>

#include "context/gl_context.h"

#include "cli/options.h"
#include "frame/gpu_timer.h"
#include "frame/renderer.h"
#include "gl/capabilities.h"
#include "stats/timing_stats.h"

namespace oasis {

SceneSettings sceneSettingsFrom(const SceneOptions& options);

// Stencil texturing where the capabilities allow it (GL 4.3 or ARB_stencil_texturing, not switched
// off by --force no-stencil-texturing); `reason` says why the path was chosen.
StencilViewPath chooseStencilViewPath(const gl::Capabilities& caps, std::optional<StencilViewPath> forced,
                                      std::string& reason);

// The context a command should make for these options: at most 3.3 with --force gl33.
MaxGlVersion maxGlVersionFor(const SceneOptions& options);

// What the context offers a renderer (frame/render_paths.h), measured once with --force applied.
// `workarounds`: the driver workarounds in effect (gl/driver_workarounds.h), the session's.
RendererCapabilities rendererCapabilities(const gl::Capabilities& caps, const SceneSettings& scene,
                                          const gl::WorkaroundSet& workarounds);

// Everything a command renders with, on the current context. Throws std::runtime_error with a
// readable message when the shaders cannot be found (or OASIS_SHADER_DIR is bad) or the targets
// cannot be allocated.
struct RenderSession {
    gl::Capabilities caps;  // measured once from the context, with --force applied
    // The driver workarounds in effect: the table's for this GL_RENDERER / GL_VERSION, the
    // --workarounds-file's ($OASIS_WORKAROUNDS) rules and --workarounds applied, each with why.
    gl::WorkaroundSet workarounds;
    RendererCapabilities rendererCaps;  // from caps: what every renderer of the session is given
    std::unique_ptr<ShaderLibrary> shaders;
    std::unique_ptr<Renderer> renderer;
    SceneSettings scene;
    std::string stencilPathReason;
    std::unique_ptr<PlantAtlas> plantAtlas;  // built at start-up; the renderer's atlas view shows it
    std::string plantPathReason;            // which interpretation path and why, e.g. "gpu (...)"

    PlantInterpretation plantPath = PlantInterpretation::Cpu;  // the path chosen (the atlas may have fallen back)
    std::optional<TimingClock> measuredClock;  // timingClock()'s, once measured

    // Required: no shader directory is an error. CapabilitiesOnly (`oasis caps`): without one the
    // session still measures and reports everything; only the plant atlas, the one thing it would
    // compile, is not built, and its report says so.
    enum class Shaders { Required, CapabilitiesOnly };
    explicit RenderSession(const Options& options, Shaders need = Shaders::Required);

    // Another renderer over the same shaders, capabilities, depth convention, stencil path and plant
    // atlas as `renderer` (the window's comparison draws its second side with it, so neither side
    // reallocates its targets every frame).
    std::unique_ptr<Renderer> makeRenderer() const;

    // Whether per-pass times come from GPU timer queries here: measured once, on first use, with
    // the renderer's active pipeline at its size (frame/gpu_timer.h).
    const TimingClock& timingClock();

    // Every feature oasis can use: used here or not, and why (what `oasis caps` prints).
    std::vector<gl::FeatureReport> features() const;
    // The fallbacks this session took, one line each ("stencil view: read-back (...)"); the
    // constructor prints each once to stderr, the window shows them in its panel.
    std::vector<std::string> fallbacks() const;
};

// "plants: gpu (compute shaders and SSBOs present), atlas 1280x512 in 12.3 ms" for the commands' output.
std::string describePlantAtlas(const RenderSession& session);

// "vegetation: 24312 plants placed in ...; drawn 5321 ..." for the last frame, or "vegetation: off".
std::string describeVegetation(const Renderer& renderer);
// "lights: 64, path ssbo (GL 4.3 / ...)" for the last frame, with a warning when lights were dropped.
std::string describeLights(const Renderer& renderer);
// "reflection passes: bounded to the visible water (...)" or why they cover the whole screen.
std::string describeReflectionBounds(const Renderer& renderer, const SceneSettings& scene);

// Median wall-clock milliseconds of `frames` floors, each ended by glFinish, after two warm-ups
// (the bench's floors alone). Whole frames are always timed this way (the floor too), so the
// ratios to the floor compare like with like on every driver.
double medianFloorMs(Renderer& renderer, int frames);

// Both pipelines and the floor timed in rounds: after kWarmupFrames of each (discarded), each round
// renders a forward frame, a deferred frame and the floor in an order drawn at random for that
// round (seeded), each by wall time around glFinish. What the machine does meanwhile falls on all
// three of a round alike, and a slow drift cannot land on whichever is always timed first (issue
// 44; back-to-back blocks put deferred at 9.9x to 12.0x its floor in six runs here).
struct PipelineTimes {
    static constexpr int kWarmupFrames = 2;  // of each, before the rounds
    int rounds = 0;
    int warmup = 0;             // frames of each discarded before the rounds
    std::uint64_t seed = 0;     // of the rounds' order and the ratios' bootstrap
    double forwardMs = 0.0, deferredMs = 0.0, floorMs = 0.0;  // medians over the rounds
    // Each stream's median with its 95% interval, CV and outliers (stats/timing_stats.h).
    SampleStats forward, deferred, floor;
    // Ratios of the medians with bootstrap intervals over the paired rounds; the verdicts come from
    // the intervals alone.
    RatioStats deferredOverForward, forwardOverFloorInterval, deferredOverFloorInterval;
    // Medians of each round's own ratio to its floor, and the lowest and highest round's: the JSON's
    // forward_floor_ratio and deferred_floor_ratio (kept for scripts; the same quantity as
    // forwardOverFloor by another route, see docs/command-line.md).
    double forwardRatio = 0.0, deferredRatio = 0.0;
    double deferredRatioLowest = 0.0, deferredRatioHighest = 0.0;
    // What the summary prints beside the medians, so the numbers read side by side agree: each
    // pipeline's median ms over the median floor ms (issue 31, defect 5: a median of per-round
    // ratios made the faster pipeline's ratio the larger), and each stream's lowest and highest round.
    double forwardOverFloor = 0.0, deferredOverFloor = 0.0;
    double forwardLowest = 0.0, forwardHighest = 0.0, deferredLowest = 0.0, deferredHighest = 0.0;
    double floorLowest = 0.0, floorHighest = 0.0;
    // The largest (highest - lowest) / median of the three streams (the JSON's rounds_spread and
    // noisy, kept for scripts; the intervals replace it in the text).
    double spread = 0.0;
    static constexpr double kNoiseSpread = 0.10;
    bool noisy() const { return spread > kNoiseSpread; }
    // The widest of the three medians' intervals as half its width over its median (what
    // --until-ci compares with its target), and which stream it is.
    double widestRelativeHalfWidth() const;
    const char* widestStream() const;
    // --until-ci: the target (0: not asked) and whether the rounds reached it before the cap.
    double untilCiPercent = 0.0;
    bool untilCiReached = false;
};
// How many rounds, in what order, and how precise: --frames, --seed and --until-ci.
struct RoundPlan {
    int rounds = 9;
    std::uint64_t seed = 0;
    double untilCiPercent = 0.0;  // 0: exactly `rounds`; else more rounds until the widest interval is narrower
    static constexpr int kMaxRounds = 200;  // --until-ci's cap (about 70 s a 1280x720 run on llvmpipe)
};
// Leaves the renderer on the pipeline it was on.
PipelineTimes timePipelinesInTurn(Renderer& renderer, const SceneSettings& scene, const RoundPlan& plan);
// The seed a run uses: --seed's, or one drawn at random (printed, so the run can be repeated).
std::uint64_t roundSeed(const Options& options);
// The order of one round's `count` streams (compare: 0 forward, 1 deferred, 2 floor), drawn from
// `random` by Fisher-Yates with modulo draws, so a seed gives the same orders with every library.
std::vector<int> roundOrder(std::mt19937_64& random, int count);
// The medians, intervals and each round's ratios from the rounds' milliseconds (index i of each is
// round i; the three the same length, at least one round); `seed` seeds the ratios' bootstrap.
PipelineTimes summariseRounds(const std::vector<double>& forwardMs, const std::vector<double>& deferredMs,
                              const std::vector<double>& floorMs, std::uint64_t seed = 0);
// Median milliseconds of each pass of each of `pipelines` over `frames` frames of each, their
// frames in turn (one of each per round, so drift reaches all alike), in pass order: by GPU timer
// queries where `clock` trusts them (no glFinish between passes), else wall time with a glFinish
// after each pass (frame/gpu_timer.h). One list per pipeline, in their order; leaves the
// renderer on the pipeline it was on.
// With `random`, each round's order of the pipelines is drawn from it; with `frameTimes`, each
// pipeline's per-frame pass times are kept there too (for the passes' intervals).
std::vector<PassTimes> medianPassMsInTurn(Renderer& renderer, const SceneSettings& scene, int frames,
                                          const TimingClock& clock, const std::vector<PipelineKind>& pipelines,
                                          std::mt19937_64* random = nullptr,
                                          std::vector<std::vector<PassTimes>>* frameTimes = nullptr);
// The same for the active pipeline alone.
PassTimes medianPassMs(Renderer& renderer, const SceneSettings& scene, int frames, const TimingClock& clock);

}  // namespace oasis
