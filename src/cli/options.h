// The command line: subcommands, the scene options every subcommand shares, and their parsing.
// Parsing is GL-free and reports the first bad argument in words (the caller exits 2).
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "debug/debug_view_pass.h"
#include "debug/view_controls.h"
#include "frame/pipeline.h"
#include "frame/view_fill.h"
#include "gl/capabilities.h"
#include "gl/driver_workarounds.h"
#include "render/frame_setup.h"
#include "render/gbuffer_layout.h"
#include "scene/camera.h"

namespace oasis {

// Shared by every subcommand: --size, --time, --hour, --camera, --gbuffer and the water's settings.
struct SceneOptions {
    int width = 1280, height = 720;
    double timeSeconds = 0.0;
    std::optional<double> hour;
    std::optional<CameraPose> camera;
    std::string gbuffer = kDefaultGBufferLayoutName;
    std::string depth = "standard";  // a depthConventions() name; reversed-z falls back without clip control
    WaterSettings water;
    VegetationSettings vegetation;
    FrameWorkSettings work;  // --tone-map, --depth-read
    ShadowSettings shadows;  // --shadows, --shadow-quality
    bool noCompute = false;  // interpret the plants on the CPU even where compute shaders exist
    int lights = 0;                          // point lights, 0..kMaxLights
    std::optional<LightsPath> lightsPath;    // forced light path; empty = from the context
    std::optional<LightMethod> lightMethod;  // forced deferred light method; empty = the default
    gl::ForcedFallbacks force;  // --force: capabilities switched off even where the driver has them
    gl::WorkaroundRequest workarounds;  // --workarounds, --workarounds-file ($OASIS_WORKAROUNDS): gl/driver_workarounds.h
    gl::Api api = gl::Api::Gl;  // --api: desktop OpenGL core or OpenGL ES 3.x (headless commands)
};

enum class Command { Default, Window, Render, Compare, Caps, Bench, Probe, Check };

// `oasis check`'s own options beyond the references and --diff (cli/check_options.cpp parses them;
// check/check.h says what each does).
struct CheckOptions {
    std::vector<std::string> caseGlobs;  // --case GLOB (repeatable): only the cases whose names match
    int shardIndex = 1, shardCount = 1;  // --shard I/N: the cases whose 1-based number is I modulo N
    int retries = 1;                     // --retries N: a failing case runs again up to N times
    double caseTimeoutSeconds = 60.0;    // --case-timeout S: a case's child still running is stopped
    int jobs = 0;                        // --jobs N: children at a time (0: this machine's cores, at most 4)
    std::string expectations;            // --expectations FILE (check/check_expectations.h)
    std::string junit;                   // --junit FILE
    std::string expectRenderer;          // --expect-renderer REGEX: refuse any other driver
    std::string baseline;                // --baseline DIR: this driver's own frames, judged identical
    // The child process a case renders in (check/check_child.cpp); never typed by a user.
    std::string child;                   // --child frame|passes|driver
    std::string childOut;                // --child-out PREFIX: PREFIX.json, .png, .bin
    std::string childWhere;              // --where FILE: the pixels a pass-by-pass search looks at
    bool childGpuPlants = false;         // --gpu-plants: the plants must be interpreted on the GPU
    std::vector<std::string> childArguments;  // after --: the case's `oasis render` arguments
};

struct Options {
    Command command = Command::Default;
    bool help = false;
    SceneOptions scene;
    PipelineKind pipeline = PipelineKind::Deferred;
    std::string view = "final";
    float viewExposure = 0.0f;  // render: the HDR views' exposure in stops
    ViewControls viewControls;  // render: --channel, --range, --overlay
    // render: the legend strip under a single view; unset, a buffer view has one and the final
    // frame none (a picture of the size asked for, usable as a --reference: issue 31, defect 4).
    std::optional<bool> legend;
    std::string out = "oasis.png";
    std::string outDir = "oasis-out";
    bool json = false;
    bool passTimes = false;  // compare / main job: per-pass medians too
    int timingFrames = 9;
    bool timingFramesGiven = false;  // --frames on the command line (bench has its own default)
    // --seed: the rounds' random order and the bootstrap's draws (unset: drawn at random, printed).
    std::optional<std::uint64_t> seed;
    // --until-ci: rounds added until the widest median interval's half-width is under this percent
    // of its median (0: not asked; capped at RoundPlan::kMaxRounds, commands/session.h).
    double untilCiPercent = 0.0;
    bool outDirGiven = false;        // --out-dir on the command line (bench writes to oasis-out/bench)
    bool quick = false;              // bench: the short smoke-test run
    std::optional<StencilViewPath> stencilView;
    WaterScene waterScene = WaterScene::Direct;  // render, probe, window: what views show under the water
    bool startPaused = false;  // window: the clock stands still from the first frame (Space runs it)
    std::string stopBefore;  // render: end the frame before this pass
    std::optional<std::pair<int, int>> probeAt;  // probe: the pixel, 0,0 top left
    bool graph = false;  // render: print the frame's passes with their reads and writes, no image
    bool probeShading = false;  // probe --shading: how the pixel was shaded, term by term
    bool probeHistory = false;  // probe --history: what each pass of the frame wrote there
    bool capture = false;  // render, compare, bench: RenderDoc captures of the rendered frames
    bool glDebug = false;  // every subcommand: synchronous debug output, stop at the first GL error
    // compare --driver / --reference (commands/driver_compare.h): the set-ups (cli/driver_setups.h),
    // the saved image, and the scene options as given, passed on to each child `oasis render`.
    std::vector<std::string> drivers;
    std::string reference;
    std::vector<std::string> sceneArguments;
    bool sizeGiven = false;  // --size on the command line (else a --reference's size is used)
    bool allowLarge = false;  // --allow-large: a --reference up to 32768 a side, not 4096 (io/png_text.h)
    // --driver-timeout: a child render still running after this many seconds is killed (exit 1).
    double driverTimeoutSeconds = 300.0;
    bool driverTimeoutGiven = false;
    bool pipelineGiven = false;
    // check (check/check.h): the reference frames' directory (empty: found beside the shaders),
    // --write-references DIR, and --diff A.json B.json.
    std::string checkReferences, writeReferences;
    std::vector<std::string> diffReports;
    bool checkTables = false;  // check --tables: print the dimensions and rules as Markdown
    CheckOptions check;
    std::vector<std::string> givenFlags;  // the options on the command line, in order (cli/option_rules.h)
    std::string commandLine;  // "oasis" and the arguments as given, shell-quoted (a PNG's provenance)
    bool comparesDrivers() const { return !drivers.empty() || !reference.empty(); }
};

struct ParseResult {
    bool ok = true;
    std::string error;  // set when !ok
    std::vector<std::string> notes;  // values the parser normalised (a wrapped angle), to say once on stderr
    Options options;
};

ParseResult parseCommandLine(const std::vector<std::string>& arguments);
std::string usage(Command command);
const char* commandName(Command command);

// Individual value parsers (exposed for tests).
// Each fails with a message naming the option and its domain (cli/input_domains.h) in `error`;
// parseCameraPose's `note` says when the yaw was wrapped (empty otherwise).
bool parseSize(const std::string& text, int& width, int& height, std::string* error = nullptr);
bool parseCameraPose(const std::string& text, CameraPose& pose, std::string* error = nullptr,
                     std::string* note = nullptr);

}  // namespace oasis
