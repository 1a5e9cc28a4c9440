// Command-line parsing; numbers are read against cli/input_domains.h (the help text: cli/usage.cpp).
#include "cli/options.h"

#include <cstdlib>

#include <algorithm>
#include <cctype>

#include "cli/check_options.h"
#include "cli/driver_setups.h"
#include "cli/input_domains.h"
#include "cli/option_rules.h"
#include "cli/option_table.h"
#include "cli/scene_arguments.h"
#include "debug/debug_views.h"
#include "frame/encoding_error.h"
#include "render/depth_convention.h"
#include "io/file_output.h"
#include "render/gbuffer_layout.h"

namespace oasis {
namespace {

// A number of `name`'s domain (cli/input_domains.h), as the parser's error when it is not one.
bool readNumber(const std::string& name, const std::string& text, double& value, std::string& error) {
    return parseInDomain(text, inputDomain(name), value, error);
}

bool endsWith(const std::string& text, const std::string& suffix) {
    if (text.size() < suffix.size()) return false;
    for (size_t i = 0; i < suffix.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(text[text.size() - suffix.size() + i])) != suffix[i]) return false;
    return true;
}


}  // namespace

const char* commandName(Command command) {
    switch (command) {
        case Command::Default: return "";
        case Command::Window: return "window";
        case Command::Render: return "render";
        case Command::Compare: return "compare";
        case Command::Caps: return "caps";
        case Command::Bench: return "bench";
        case Command::Probe: return "probe";
        case Command::Check: return "check";
    }
    return "";
}

ParseResult parseCommandLine(const std::vector<std::string>& arguments) {
    ParseResult result;
    Options& options = result.options;
    auto fail = [&](const std::string& message) {
        result.ok = false;
        result.error = message;
        return result;
    };
    std::vector<std::string> command = {"oasis"};
    command.insert(command.end(), arguments.begin(), arguments.end());
    options.commandLine = shellCommandLine(command);
    size_t i = 0;
    if (i < arguments.size() && !arguments[i].empty() && arguments[i][0] != '-') {
        const std::string& name = arguments[i];
        if (name == "render") options.command = Command::Render;
        else if (name == "compare") options.command = Command::Compare;
        else if (name == "window") options.command = Command::Window;
        else if (name == "caps") options.command = Command::Caps;
        else if (name == "bench") options.command = Command::Bench;
        else if (name == "probe") options.command = Command::Probe;
        else if (name == "check") options.command = Command::Check;
        else return fail("unknown subcommand '" + name + "' (expected render, compare, bench, probe, caps, check or window)");
        ++i;
    }
    for (; i < arguments.size(); ++i) {
        const std::string& flag = arguments[i];
        options.givenFlags.push_back(flag);
        // The scene options' rows (cli/option_table.h), then the subcommands' own options.
        static const std::vector<std::string> kValueOptions = {
            "--pipeline", "--view", "--out", "--stencil-view", "--stop-before", "--out-dir", "--frames", "--seed", "--until-ci", "--at",
            "--view-exposure", "--water-scene", "--channel", "--range", "--overlay", "--legend", "--driver",
            "--reference", "--driver-timeout"};
        const OptionRow* row = findOption(flag);
        bool takesValue = (row && !row->bare) ||
                          std::find(kValueOptions.begin(), kValueOptions.end(), flag) != kValueOptions.end();
        if (flag == "--help" || flag == "-h") { options.help = true; continue; }
        if (options.command == Command::Check) {
            CheckOptionParse parsed = parseCheckOption(arguments, i, options);
            if (!parsed.ok) return fail(parsed.error);
            continue;
        }
        for (const char* checkOnly : {"--case", "--shard", "--jobs", "--case-timeout", "--retries", "--expectations",
                                      "--junit", "--expect-renderer", "--baseline", "--references", "--write-references"})
            if (flag == checkOnly) return fail("option " + flag + " belongs to `oasis check`");
        if (flag == "--shading" || flag == "--history") {
            if (options.command != Command::Probe) return fail("option " + flag + " belongs to `oasis probe`");
            (flag == "--shading" ? options.probeShading : options.probeHistory) = true;
            continue;
        }
        if (flag == "--json" && (options.command == Command::Caps || options.command == Command::Probe)) {
            options.json = true;
            continue;
        }
        bool compareOnly = flag == "--json" || flag == "--frames" || flag == "--out-dir" || flag == "--passes" ||
                           flag == "--seed" || flag == "--until-ci";
        if (compareOnly && (options.command == Command::Render || options.command == Command::Window ||
                            options.command == Command::Caps || options.command == Command::Probe))
            return fail("option " + flag + " belongs to `oasis compare`, `oasis bench` and the main job");
        if (flag == "--allow-large") {  // a --reference over 4096 a side (io/png_text.h)
            if (options.command != Command::Compare) return fail("option --allow-large belongs to `oasis compare --reference`");
            options.allowLarge = true;
            continue;
        }
        if (flag == "--quick") {
            if (options.command != Command::Bench) return fail("option --quick belongs to `oasis bench`");
            options.quick = true;
            continue;
        }
        if (flag == "--depth" && options.command == Command::Bench)
            return fail("option --depth is set by `oasis bench` itself (it times and compares the depth conventions)");
        if (flag == "--passes" && options.command == Command::Bench)
            return fail("option --passes belongs to `oasis compare` (bench always times each pass)");
        if (flag == "--until-ci" && options.command == Command::Bench)
            return fail("option --until-ci belongs to `oasis compare` and the main job (bench: --frames N)");
        static const std::vector<std::string> kSetByBench = {"--size", "--time", "--camera", "--gbuffer", "--reflections",
                                                             "--vegetation", "--vegetation-density", "--lights"};
        if (options.command == Command::Bench &&
            std::find(kSetByBench.begin(), kSetByBench.end(), flag) != kSetByBench.end())
            return fail("option " + flag + " is set by `oasis bench` itself (its sizes, frames, layouts and knobs)");
        if (flag == "--json") { options.json = true; continue; }
        if (flag == "--passes") { options.passTimes = true; continue; }
        if (row && row->bare) {  // scene switches: a child render gets them too
            std::string error;
            readOption(*row, "", options, result.notes, error);
            if (options.command == Command::Compare) options.sceneArguments.push_back(flag);
            continue;
        }
        if (flag == "--start-paused") {
            if (options.command != Command::Window && options.command != Command::Default)
                return fail("option --start-paused belongs to the window (`oasis window`)");
            options.startPaused = true;
            continue;
        }
        if (flag == "--graph") {
            if (options.command != Command::Render) return fail("option --graph belongs to `oasis render`");
            options.graph = true;
            continue;
        }
        if (flag == "--capture") {
            if (options.command != Command::Render && options.command != Command::Compare &&
                options.command != Command::Bench)
                return fail("option --capture belongs to `oasis render`, `oasis compare` and `oasis bench` (in the "
                            "window: F9 or the panel's capture button)");
            options.capture = true;
            continue;
        }
        if (!takesValue)
            return fail("unknown option '" + flag + "' (see oasis " + commandName(options.command) + " --help)");
        if (i + 1 >= arguments.size()) return fail("option " + flag + " needs a value (see --help)");
        const std::string& value = arguments[++i];
        bool renderOnly = flag == "--pipeline" || flag == "--view" || flag == "--out" || flag == "--stencil-view" ||
                          flag == "--stop-before" || flag == "--view-exposure" || flag == "--channel" ||
                          flag == "--range" || flag == "--overlay" || flag == "--legend";
        if (flag == "--pipeline" && (options.command == Command::Probe || options.command == Command::Compare))
            renderOnly = false;  // compare: only with --driver / --reference (checked after the loop)
        if (flag == "--stop-before" && options.command == Command::Probe) renderOnly = false;  // probe a stopped frame
        if ((flag == "--driver" || flag == "--reference" || flag == "--driver-timeout") &&
            options.command != Command::Compare)
            return fail("option " + flag + " belongs to `oasis compare`");
        // What a child `oasis render` of compare --driver needs to draw the same frame.
        static const std::vector<std::string> kNotForwarded = {"--driver", "--reference", "--driver-timeout", "--out-dir",
                                                               "--frames", "--seed", "--until-ci"};
        if (options.command == Command::Compare &&
            std::find(kNotForwarded.begin(), kNotForwarded.end(), flag) == kNotForwarded.end()) {
            options.sceneArguments.push_back(flag);
            options.sceneArguments.push_back(value);
        }
        if (renderOnly && options.command != Command::Render)
            return fail("option " + flag + " belongs to `oasis render`");
        if (flag == "--at" && options.command != Command::Probe) return fail("option --at belongs to `oasis probe`");
        if (flag == "--water-scene" && options.command != Command::Render && options.command != Command::Probe &&
            options.command != Command::Window && options.command != Command::Default)
            return fail("option --water-scene belongs to `oasis render`, `oasis probe` and the window");
        if (row) {
            std::string error;
            if (!readOption(*row, value, options, result.notes, error)) return fail(error);
        } else if (flag == "--driver") {
            if (!findDriverSetup(value))
                return fail("--driver: unknown set-up '" + value + "' (one of: " + driverSetupNames() + ")");
            if (options.drivers.size() == 2)
                return fail("--driver given three times: compare takes two set-ups, or one and --reference FILE.png");
            options.drivers.push_back(value);
        } else if (flag == "--driver-timeout") {
            std::string error;
            if (!readNumber(flag, value, options.driverTimeoutSeconds, error)) return fail(error);
            options.driverTimeoutGiven = true;
        } else if (flag == "--reference") {
            if (!endsWith(value, ".png")) return fail("--reference expects a PNG file (FILE.png), got '" + value + "'");
            if (!options.reference.empty()) return fail("--reference given twice");
            options.reference = value;
        } else if (flag == "--pipeline") {
            if (!parsePipelineKind(value, options.pipeline))
                return fail("--pipeline expects forward or deferred, got '" + value + "'");
            options.pipelineGiven = true;
        } else if (flag == "--view") {
            if (!findDebugView(value) && value != kOverviewName && !findEncodingErrorView(value))
                return fail("--view: unknown view '" + value + "' (one of: " + debugViewNames() + ", " +
                            encodingErrorViewNames() + ")");
            options.view = value;
        } else if (flag == "--view-exposure") {
            double stops = 0.0;
            std::string error;
            if (!readNumber(flag, value, stops, error)) return fail(error);
            options.viewExposure = float(stops);
        } else if (flag == "--channel") {
            ViewChannel channel;
            if (!parseViewChannel(value, channel))
                return fail("--channel expects one of " + viewChannelNames() + ", got '" + value + "'");
            options.viewControls.channel = channel;
        } else if (flag == "--range") {
            size_t comma = value.find(',');
            if (comma == std::string::npos) return fail("--range expects LO,HI (two numbers, LO < HI), got '" + value + "'");
            double low = 0.0, high = 0.0;
            std::string error;
            if (!readNumber("--range LO", value.substr(0, comma), low, error) ||
                !readNumber("--range HI", value.substr(comma + 1), high, error))
                return fail(error);
            if (!(low < high)) return fail("--range expects LO < HI, got '" + value + "'");
            options.viewControls.range = std::pair{low, high};
        } else if (flag == "--overlay") {
            if (!parseOverlay(value, options.viewControls.overlay))
                return fail("--overlay expects none or a list of nan, inf, negative, got '" + value + "'");
        } else if (flag == "--legend") {
            if (value != "on" && value != "off") return fail("--legend expects on or off, got '" + value + "'");
            options.legend = value == "on";
        } else if (flag == "--stencil-view") {
            if (value == "texturing") options.stencilView = StencilViewPath::Texturing;
            else if (value == "read-back") options.stencilView = StencilViewPath::ReadBack;
            else return fail("--stencil-view expects texturing or read-back, got '" + value + "'");
        } else if (flag == "--water-scene") {
            std::optional<WaterScene> scene = parseWaterScene(value);
            if (!scene) return fail("--water-scene expects " + std::string(kWaterSceneNames) + ", got '" + value + "'");
            options.waterScene = *scene;
        } else if (flag == "--at") {
            size_t comma = value.find(',');
            if (comma == std::string::npos)
                return fail("--at expects X,Y (pixels, 0,0 the top-left pixel), got '" + value + "'");
            int x = 0, y = 0;
            std::string error;
            if (!parseIntInDomain(value.substr(0, comma), inputDomain("--at X"), x, error) ||
                !parseIntInDomain(value.substr(comma + 1), inputDomain("--at Y"), y, error))
                return fail(error);
            options.probeAt = std::pair{x, y};
        } else if (flag == "--stop-before") {
            if (value.empty()) return fail("--stop-before expects a pass name (see oasis render --help)");
            options.stopBefore = value;  // checked against --pipeline's passes after the loop
        } else if (flag == "--out") {
            // oasis writes PNG alone: another extension would name PNG data as something else.
            // A stream (/dev/stdout, a pipe) carries no name to check.
            if (!endsWith(value, ".png") && !namesAStream(value))
                return fail("--out expects a file name ending in .png (oasis writes PNG only) or a stream such as "
                            "/dev/stdout, got '" + value + "'");
            options.out = value;
        } else if (flag == "--out-dir") {
            if (value.empty()) return fail("--out-dir expects a directory name, got ''");
            options.outDir = value;
            options.outDirGiven = true;
        } else if (flag == "--frames") {
            options.timingFramesGiven = true;
            std::string error;
            if (!parseIntInDomain(value, inputDomain(flag), options.timingFrames, error)) return fail(error);
        } else if (flag == "--seed") {
            int seed = 0;
            std::string error;
            if (!parseIntInDomain(value, inputDomain(flag), seed, error)) return fail(error);
            options.seed = std::uint64_t(seed);
        } else if (flag == "--until-ci") {
            std::string error;
            if (!parseInDomain(value, inputDomain(flag), options.untilCiPercent, error)) return fail(error);
        } else {
            return fail("unknown option '" + flag + "' (see oasis " + commandName(options.command) + " --help)");
        }
    }
    // A workarounds file from the environment where the command line names none: every command,
    // a compare's or check's children included (they inherit the variable), reads the same file.
    if (options.scene.workarounds.file.empty())
        if (const char* file = std::getenv(gl::kWorkaroundsEnvironment); file && *file) {
            std::string error;
            if (!gl::readWorkaroundsFile(file, options.scene.workarounds, error))
                return fail("$" + std::string(gl::kWorkaroundsEnvironment) + ": " + error);
        }
    if (options.scene.api == gl::Api::Gles) {
        if (options.scene.force.gl33) return fail("--force gl33 makes a desktop OpenGL 3.3 context: not with --api gles");
    } else if (options.scene.force.gles30) {
        return fail("--force gles30 limits an OpenGL ES context: add --api gles");
    }
    if (options.probeHistory && !options.stopBefore.empty())
        return fail("--history lists every pass of the whole frame: not with --stop-before (a stopped frame's "
                    "passes are the history's first ones)");
    if (options.graph) {
        // The pass list replaces the picture: an option that only shapes the picture would be idle.
        // --view is not idle: the frame is culled for the view asked for (its sink).
        for (const char* idle : {"--out", "--channel", "--range", "--overlay", "--legend", "--view-exposure",
                                 "--capture"})
            if (std::find(options.givenFlags.begin(), options.givenFlags.end(), idle) != options.givenFlags.end())
                return fail(std::string("--graph prints the frame's passes and writes no picture: ") + idle +
                            " would do nothing (drop one of them)");
    }
    if (!options.stopBefore.empty()) {
        // A usage error like any other bad value: the pass lists are GL-free, so check before a context.
        Pipeline pipeline(options.pipeline);
        if (!pipeline.hasPass(options.stopBefore))
            return fail("--stop-before: the " + std::string(pipelineName(options.pipeline)) + " pipeline has no pass '" +
                        options.stopBefore + "' (its passes: " + pipeline.passNames() + ")");
    }
    if (options.command == Command::Check && !options.help && !options.diffReports.empty()) {
        // --diff reads two reports and renders nothing: an option of the rendering check would be ignored.
        for (const char* unused : {"--quick", "--write-references", "--references", "--tables", "--case", "--shard",
                                   "--jobs", "--case-timeout", "--retries", "--expectations", "--junit",
                                   "--expect-renderer", "--baseline"})
            if (std::find(options.givenFlags.begin(), options.givenFlags.end(), unused) != options.givenFlags.end())
                return fail(std::string("option ") + unused + " does nothing with --diff (it compares two reports "
                            "and renders nothing): drop one of them");
    }
    if (options.command == Command::Compare && !options.help) {
        if (options.allowLarge && options.reference.empty())
            return fail("option --allow-large belongs to `oasis compare --reference` (it admits a larger reference)");
        if (options.drivers.size() == 2 && !options.reference.empty())
            return fail("compare takes two --driver set-ups, or one --driver and --reference FILE.png, not both");
        if (options.drivers.size() == 1 && options.reference.empty())
            return fail("--driver " + options.drivers[0] + " needs a second --driver or --reference FILE.png");
        if (options.pipelineGiven && !options.comparesDrivers())
            return fail("option --pipeline belongs to `oasis render` and to `oasis compare --driver/--reference` "
                        "(plain compare renders both pipelines)");
        if (options.driverTimeoutGiven && !options.comparesDrivers())
            return fail("option --driver-timeout belongs to `oasis compare --driver/--reference` (the pipeline "
                        "comparison runs no child)");
        if (options.comparesDrivers() && (options.passTimes || options.timingFramesGiven || options.capture ||
                                          options.seed || options.untilCiPercent > 0.0))
            return fail("--passes, --frames, --seed, --until-ci and --capture belong to the pipeline comparison, not "
                        "compare --driver/--reference (it times nothing)");
    }
    if (findEncodingErrorView(options.view) && options.viewControls.channel)
        return fail("--channel: the " + options.view + " view has one value a pixel (use --range)");
    if (options.viewControls.channel) {
        const DebugView* view = findDebugView(options.view);
        if (!view) return fail("--channel needs a single view, not --view " + options.view);
        if (!viewHasChannel(*view, *options.viewControls.channel)) {
            std::string names;
            for (const std::string& name : view->values) names += (names.empty() ? "" : ", ") + name;
            return fail("--channel " + std::string(viewChannelName(*options.viewControls.channel)) + ": the " +
                        view->name + " view has " + std::to_string(view->values.size()) + " value channel(s) (" +
                        names + ")");
        }
    }
    if (findEncodingErrorView(options.view) && options.scene.gbuffer == "full")
        return fail("--view " + options.view + " compares the G-buffer layout against full: add --gbuffer standard or "
                    "--gbuffer compact");
    if (options.viewControls.range && options.view == kOverviewName)
        return fail("--range needs a single view, not --view overview");
    if (options.command == Command::Probe && !options.help) {
        if (!options.probeAt) return fail("`oasis probe` needs --at X,Y (the pixel to probe)");
        if (options.probeAt->first >= options.scene.width || options.probeAt->second >= options.scene.height)
            return fail("--at " + std::to_string(options.probeAt->first) + "," + std::to_string(options.probeAt->second) +
                        " is outside the " + std::to_string(options.scene.width) + "x" +
                        std::to_string(options.scene.height) + " frame (0,0 is the top-left pixel)");
    }
    std::string idle;
    if (!options.help && !applyOptionRules(options, result.notes, idle)) return fail(idle);
    return result;
}

}  // namespace oasis
