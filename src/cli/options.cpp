// Command-line parsing and help text.
#include "cli/options.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "debug/debug_views.h"
#include "render/depth_convention.h"
#include "render/gbuffer_layout.h"

namespace oasis {
namespace {

bool parseDouble(const std::string& text, double& value) {
    if (text.empty()) return false;
    char* end = nullptr;
    value = std::strtod(text.c_str(), &end);
    return end && *end == '\0' && std::isfinite(value);
}

bool parseInt(const std::string& text, int& value) {
    if (text.empty()) return false;
    char* end = nullptr;
    long parsed = std::strtol(text.c_str(), &end, 10);
    if (!end || *end != '\0' || parsed < -1000000000L || parsed > 1000000000L) return false;
    value = int(parsed);
    return true;
}

const char* kSceneOptionsHelp =
    "scene options (every subcommand):\n"
    "  --size WxH                frame size in pixels (default 1280x720)\n"
    "  --time SECONDS            animation time: camera flight and time of day (default 0 = 10:00)\n"
    "  --hour H                  override the hour of day, 0..24 (6 sunrise, 18 sunset)\n"
    "  --camera X,Y,Z,YAW,PITCH  fixed camera instead of the flight (degrees; yaw 0 = -Z, 90 = +X)\n"
    "  --reflections on|off      the mirrored scene in the water (default on; off reflects the sky alone)\n"
    "  --water-level Y           world height of the water plane (default 0)\n"
    "  --ripples S               ripple strength, 0 = a still mirror (default 1)\n"
    "  --absorption A            water absorption per unit depth, 0 = clear (default 0.09)\n"
    "  --vegetation on|off       the plant billboards (default on)\n"
    "  --vegetation-density D    plants per unit of ground, 0..4 times the default (default 1)\n"
    "  --wind S                  wind strength bending the plants, 0..3 (default 1)\n"
    "  --no-compute              interpret the plant atlas on the CPU, not in a compute shader\n"
    "  --lights N                point lights (lanterns, fireflies) around the lake, 0..4096 (default 0);\n"
    "                            they glow at night, e.g. --hour 21\n"
    "  --lights-path PATH        how shaders read the lights: ssbo, ssbo-count or ubo (default: ssbo\n"
    "                            where the context has SSBOs, else ubo)\n"
    "  --force LIST              switch capabilities off even where the driver has them, to reproduce\n"
    "                            another driver: no-ssbo,no-compute,no-stencil-texturing,no-dsa,\n"
    "                            no-clip-control,gl33 (gl33: an OpenGL 3.3 core context; no-clip-control:\n"
    "                            reversed-z depth falls back to standard); each fallback is reported once\n"
    "  --depth CONVENTION        depth buffer: standard (24-bit, near 0 far 1) or reversed-z (32-bit float,\n"
    "                            near 1 far 0; needs GL 4.5 or GL_ARB_clip_control) (default standard;\n"
    "                            `oasis bench` times and compares both itself)\n"
    "  --gbuffer LAYOUT          G-buffer layout: ";

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
    }
    return "";
}

bool parseSize(const std::string& text, int& width, int& height) {
    size_t x = text.find('x');
    if (x == std::string::npos) return false;
    return parseInt(text.substr(0, x), width) && parseInt(text.substr(x + 1), height) && width >= 1 &&
           height >= 1;
}

bool parseCameraPose(const std::string& text, CameraPose& pose) {
    if (!text.empty() && text.back() == ',') return false;  // getline would drop the empty last field
    std::vector<double> values;
    std::stringstream stream(text);
    std::string item;
    while (std::getline(stream, item, ',')) {
        double value = 0.0;
        if (!parseDouble(item, value)) return false;
        values.push_back(value);
    }
    if (values.size() != 5 || std::fabs(values[4]) > 90.0) return false;
    pose.position = glm::dvec3(values[0], values[1], values[2]);
    pose.yawDegrees = float(values[3]);
    pose.pitchDegrees = float(values[4]);
    return true;
}

std::string usage(Command command) {
    std::string scene = std::string(kSceneOptionsHelp) + gbufferLayoutNames() + " (default " + kDefaultGBufferLayoutName + ")\n";
    switch (command) {
        case Command::Render:
            return "usage: oasis render [scene options] [--pipeline forward|deferred] [--view NAME] [--out FILE.png]\n"
                   "  renders one frame and writes one debug view of it (default: deferred, final)\n"
                   "  --view NAME               " + debugViewNames() + "\n"
                   "  --view-exposure STOPS     the HDR views (radiance, reflection-raw): light times 2^STOPS,\n"
                   "                            -20..20 (default 0)\n"
                   "  --channel C               show the view's values, not its colours: rgb, r, g, b, a or\n"
                   "                            luminance (the channels each view fills: docs/command-line.md)\n"
                   "  --range LO,HI             values LO..HI to black..white (default: the frame's finite min..max)\n"
                   "  --overlay LIST            paint nan, inf, negative values in checkers (default nan,inf; none)\n"
                   "  --legend on|off           the legend strip under the image (default on)\n"
                   "  --stencil-view PATH       texturing | read-back (default: texturing where supported)\n"
                   "  --stop-before PASS        end the frame before the named pass, to see its inputs\n"
                   "                            (e.g. WaterCompositePass; a wrong name lists the passes);\n"
                   "                            Final is black then: view the targets the frame reached\n" + scene;
        case Command::Compare:
            return "usage: oasis compare [scene options] [--out-dir DIR] [--json] [--frames N] [--passes]\n"
                   "  renders the frame in both pipelines; prints PSNR, max abs and RMSE over 8-bit RGB and the\n"
                   "  median ms per frame of each (wall time around glFinish over N frames, default 9);\n"
                   "  writes forward.png, deferred.png and difference.png to DIR (default oasis-out);\n"
                   "  --passes adds each pass's median ms (glFinish after every pass)\n" + scene;
        case Command::Caps:
            return "usage: oasis caps [--json] [--force LIST]\n"
                   "  the context's GL version, vendor, renderer, GLSL version, the limits and extensions that\n"
                   "  matter to oasis, and for each feature oasis can use whether it is used here and why not\n" + scene;
        case Command::Bench:
            return "usage: oasis bench [--quick] [--out-dir DIR] [--json] [--frames N] [scene options]\n"
                   "  times every configuration of pipeline x G-buffer layout x quality knob (grid, octaves,\n"
                   "  vegetation, reflections; each knob alone at each level) x size over fixed frames of the\n"
                   "  camera path, also with a few point-light counts (the default knobs only; each count its\n"
                   "  own reference and frontiers), and its error against the reference (full layout, every\n"
                   "  knob at its highest, the same lights):\n"
                   "  median/min/max ms (wall time around glFinish), per-pass ms, ratio to the floor measured in\n"
                   "  the same run, PSNR, RMSE, max abs, SSIM, bytes per pixel, target memory, Pareto frontier.\n"
                   "  Prints a table; writes bench.csv, bench.json and bench.svg to DIR (default oasis-out/bench)\n"
                   "  --quick                   one frame at 320x180, each knob's cheapest level, the default and\n"
                   "                            the most lights, 3 timed frames\n"
                   "  --json                    print the JSON to stdout (the table goes to stderr)\n"
                   "  --frames N                timed frames per fixed frame (default 7, --quick 3)\n"
                   "  the bench sets --size, --time, --camera, --gbuffer, --lights and the knobs itself; other scene\n"
                   "  options (e.g. --hour, --ripples) set the scene every configuration starts from\n" + scene;
        case Command::Probe:
            return "usage: oasis probe --at X,Y [scene options] [--pipeline forward|deferred] [--json]\n"
                   "  renders the frame and prints, for pixel X,Y (0,0 the top-left pixel, as in the PNGs), every\n"
                   "  target's texel as stored (bytes, half floats or floats, per the G-buffer layout) and decoded\n"
                   "  on the GPU as the lighting pass reads it: albedo (linear, sRGB), normal, position (camera-\n"
                   "  relative, world, eye distance), info (specular power, intensity, flags), depth (stored, eye\n"
                   "  distance), stencil and its meaning, Radiance, Reflection, Final, the point lights reaching\n"
                   "  the surface, and on water pixels which scene the G-buffer holds there and why\n"
                   "  --at X,Y                  the pixel (required)\n"
                   "  --pipeline P              forward or deferred (default deferred)\n"
                   "  --json                    one JSON object instead of the text\n" + scene;
        case Command::Window:
            return "usage: oasis window [scene options]\n"
                   "  opens the interactive window (what `oasis` does when a display exists)\n" + scene;
        case Command::Default: break;
    }
    return "oasis - a forward/deferred renderer workbench\n"
           "usage: oasis [SUBCOMMAND] [options]\n"
           "  (none)     a window when a display exists; otherwise the headless main job: renders the\n"
           "             default frame in both pipelines and the debug overview to PNGs in --out-dir\n"
           "             (default oasis-out) and prints a summary\n"
           "  window     the interactive window\n"
           "  render     one frame, one debug view, to a PNG\n"
           "  compare    forward against deferred: image difference and time\n"
           "  caps       what this driver offers and which paths oasis takes on it (--json)\n"
           "  bench      time against error over pipelines, layouts, quality knobs and sizes\n"
           "  probe      every target's value at one pixel, stored and decoded (--at X,Y)\n"
           "  oasis SUBCOMMAND --help for its options\n" + scene +
           "  --out-dir DIR             where the main job writes (default oasis-out)\n";
}

ParseResult parseCommandLine(const std::vector<std::string>& arguments) {
    ParseResult result;
    Options& options = result.options;
    auto fail = [&](const std::string& message) {
        result.ok = false;
        result.error = message;
        return result;
    };
    size_t i = 0;
    if (i < arguments.size() && !arguments[i].empty() && arguments[i][0] != '-') {
        const std::string& name = arguments[i];
        if (name == "render") options.command = Command::Render;
        else if (name == "compare") options.command = Command::Compare;
        else if (name == "window") options.command = Command::Window;
        else if (name == "caps") options.command = Command::Caps;
        else if (name == "bench") options.command = Command::Bench;
        else if (name == "probe") options.command = Command::Probe;
        else return fail("unknown subcommand '" + name + "' (expected render, compare, bench, probe, caps or window)");
        ++i;
    }
    for (; i < arguments.size(); ++i) {
        const std::string& flag = arguments[i];
        static const std::vector<std::string> kValueOptions = {
            "--size", "--time", "--hour", "--camera", "--gbuffer", "--reflections", "--water-level", "--ripples",
            "--absorption", "--vegetation", "--vegetation-density", "--wind", "--pipeline", "--view", "--out",
            "--stencil-view", "--stop-before", "--out-dir", "--frames", "--lights", "--lights-path", "--force",
            "--depth", "--at", "--view-exposure", "--channel", "--range", "--overlay", "--legend"};
        bool takesValue = std::find(kValueOptions.begin(), kValueOptions.end(), flag) != kValueOptions.end();
        if (flag == "--help" || flag == "-h") { options.help = true; continue; }
        if (flag == "--json" && (options.command == Command::Caps || options.command == Command::Probe)) {
            options.json = true;
            continue;
        }
        bool compareOnly = flag == "--json" || flag == "--frames" || flag == "--out-dir" || flag == "--passes";
        if (compareOnly && (options.command == Command::Render || options.command == Command::Window ||
                            options.command == Command::Caps || options.command == Command::Probe))
            return fail("option " + flag + " belongs to `oasis compare`, `oasis bench` and the main job");
        if (flag == "--quick") {
            if (options.command != Command::Bench) return fail("option --quick belongs to `oasis bench`");
            options.quick = true;
            continue;
        }
        if (flag == "--depth" && options.command == Command::Bench)
            return fail("option --depth is set by `oasis bench` itself (it times and compares the depth conventions)");
        if (flag == "--passes" && options.command == Command::Bench)
            return fail("option --passes belongs to `oasis compare` (bench always times each pass)");
        static const std::vector<std::string> kSetByBench = {"--size", "--time", "--camera", "--gbuffer", "--reflections",
                                                             "--vegetation", "--vegetation-density", "--lights"};
        if (options.command == Command::Bench &&
            std::find(kSetByBench.begin(), kSetByBench.end(), flag) != kSetByBench.end())
            return fail("option " + flag + " is set by `oasis bench` itself (its sizes, frames, layouts and knobs)");
        if (flag == "--json") { options.json = true; continue; }
        if (flag == "--passes") { options.passTimes = true; continue; }
        if (flag == "--no-compute") { options.scene.noCompute = true; continue; }
        if (!takesValue)
            return fail("unknown option '" + flag + "' (see oasis " + commandName(options.command) + " --help)");
        if (i + 1 >= arguments.size()) return fail("option " + flag + " needs a value (see --help)");
        const std::string& value = arguments[++i];
        bool renderOnly = flag == "--pipeline" || flag == "--view" || flag == "--out" || flag == "--stencil-view" ||
                          flag == "--stop-before" || flag == "--view-exposure" || flag == "--channel" ||
                          flag == "--range" || flag == "--overlay" || flag == "--legend";
        if (flag == "--pipeline" && options.command == Command::Probe) renderOnly = false;
        if (renderOnly && options.command != Command::Render)
            return fail("option " + flag + " belongs to `oasis render`");
        if (flag == "--at" && options.command != Command::Probe) return fail("option --at belongs to `oasis probe`");
        if (flag == "--size") {
            if (!parseSize(value, options.scene.width, options.scene.height))
                return fail("--size expects WxH with positive integers, e.g. 1280x720, got '" + value + "'");
        } else if (flag == "--time") {
            if (!parseDouble(value, options.scene.timeSeconds))
                return fail("--time expects a number of seconds, got '" + value + "'");
        } else if (flag == "--hour") {
            double hour = 0.0;
            if (!parseDouble(value, hour) || hour < 0.0 || hour > 24.0)
                return fail("--hour expects a number from 0 to 24, got '" + value + "'");
            options.scene.hour = hour;
        } else if (flag == "--camera") {
            CameraPose pose;
            if (!parseCameraPose(value, pose))
                return fail("--camera expects X,Y,Z,YAW,PITCH (five numbers, |pitch| <= 90), got '" + value + "'");
            options.scene.camera = pose;
        } else if (flag == "--reflections") {
            if (value != "on" && value != "off")
                return fail("--reflections expects on or off, got '" + value + "'");
            options.scene.water.reflections = value == "on";
        } else if (flag == "--water-level" || flag == "--ripples" || flag == "--absorption") {
            double number = 0.0;
            bool nonNegative = flag != "--water-level";
            if (!parseDouble(value, number) || (nonNegative && number < 0.0) || std::fabs(number) > 1e6)
                return fail(flag + " expects a " + (nonNegative ? "non-negative " : "") + "number, got '" + value + "'");
            float& field = flag == "--water-level" ? options.scene.water.level
                           : flag == "--ripples"   ? options.scene.water.rippleStrength
                                                   : options.scene.water.absorption;
            field = float(number);
        } else if (flag == "--vegetation") {
            if (value != "on" && value != "off")
                return fail("--vegetation expects on or off, got '" + value + "'");
            options.scene.vegetation.enabled = value == "on";
        } else if (flag == "--vegetation-density" || flag == "--wind") {
            double number = 0.0;
            bool density = flag == "--vegetation-density";
            double highest = density ? VegetationSettings::kMaxDensity : VegetationSettings::kMaxWindStrength;
            if (!parseDouble(value, number) || number < 0.0 || number > highest)
                return fail(flag + " expects a number from 0 to " + std::to_string(int(highest)) + ", got '" + value + "'");
            (density ? options.scene.vegetation.density : options.scene.vegetation.windStrength) = float(number);
        } else if (flag == "--lights") {
            if (!parseInt(value, options.scene.lights) || options.scene.lights < 0 || options.scene.lights > kMaxLights)
                return fail("--lights expects an integer from 0 to " + std::to_string(kMaxLights) + ", got '" + value + "'");
        } else if (flag == "--lights-path") {
            LightsPath path;
            if (!parseLightsPath(value, path))
                return fail("--lights-path expects one of " + lightsPathNames() + ", got '" + value + "'");
            options.scene.lightsPath = path;
        } else if (flag == "--gbuffer") {
            if (!findGBufferLayout(value))
                return fail("--gbuffer: unknown layout '" + value + "' (one of: " + gbufferLayoutNames() + ")");
            options.scene.gbuffer = value;
        } else if (flag == "--depth") {
            if (!findDepthConvention(value))
                return fail("--depth: unknown convention '" + value + "' (one of: " + depthConventionNames() + ")");
            options.scene.depth = value;
        } else if (flag == "--pipeline") {
            if (!parsePipelineKind(value, options.pipeline))
                return fail("--pipeline expects forward or deferred, got '" + value + "'");
        } else if (flag == "--view") {
            if (!findDebugView(value) && value != kOverviewName)
                return fail("--view: unknown view '" + value + "' (one of: " + debugViewNames() + ")");
            options.view = value;
        } else if (flag == "--view-exposure") {
            double stops = 0.0;
            if (!parseDouble(value, stops) || stops < -20.0 || stops > 20.0)
                return fail("--view-exposure expects stops from -20 to 20, got '" + value + "'");
            options.viewExposure = float(stops);
        } else if (flag == "--channel") {
            ViewChannel channel;
            if (!parseViewChannel(value, channel))
                return fail("--channel expects one of " + viewChannelNames() + ", got '" + value + "'");
            options.viewControls.channel = channel;
        } else if (flag == "--range") {
            size_t comma = value.find(',');
            double low = 0.0, high = 0.0;
            if (comma == std::string::npos || !parseDouble(value.substr(0, comma), low) ||
                !parseDouble(value.substr(comma + 1), high) || !(low < high))
                return fail("--range expects LO,HI with finite LO < HI, got '" + value + "'");
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
        } else if (flag == "--force") {
            std::string error;
            if (!parseForcedFallbacks(value, options.scene.force, error)) return fail("--force: " + error);
        } else if (flag == "--at") {
            size_t comma = value.find(',');
            int x = -1, y = -1;
            if (comma == std::string::npos || !parseInt(value.substr(0, comma), x) ||
                !parseInt(value.substr(comma + 1), y) || x < 0 || y < 0)
                return fail("--at expects X,Y (two non-negative integers, 0,0 the top-left pixel), got '" + value + "'");
            options.probeAt = std::pair{x, y};
        } else if (flag == "--stop-before") {
            options.stopBefore = value;  // checked against the pipeline's passes when it runs
        } else if (flag == "--out") {
            options.out = value;
        } else if (flag == "--out-dir") {
            options.outDir = value;
            options.outDirGiven = true;
        } else if (flag == "--frames") {
            options.timingFramesGiven = true;
            if (!parseInt(value, options.timingFrames) || options.timingFrames < 1 || options.timingFrames > 1000)
                return fail("--frames expects an integer from 1 to 1000, got '" + value + "'");
        } else {
            return fail("unknown option '" + flag + "' (see oasis " + commandName(options.command) + " --help)");
        }
    }
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
    if (options.viewControls.range && options.view == kOverviewName)
        return fail("--range needs a single view, not --view overview");
    if (options.command == Command::Probe && !options.help) {
        if (!options.probeAt) return fail("`oasis probe` needs --at X,Y (the pixel to probe)");
        if (options.probeAt->first >= options.scene.width || options.probeAt->second >= options.scene.height)
            return fail("--at " + std::to_string(options.probeAt->first) + "," + std::to_string(options.probeAt->second) +
                        " is outside the " + std::to_string(options.scene.width) + "x" +
                        std::to_string(options.scene.height) + " frame (0,0 is the top-left pixel)");
    }
    return result;
}

}  // namespace oasis
