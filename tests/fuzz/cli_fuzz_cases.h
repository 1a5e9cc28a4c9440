// The CLI fuzzer's cases (cli_fuzz.cpp runs them): what the argument lists are drawn from (edge
// numbers, odd texts, output names, one row per option the parser knows, checked against
// `oasis --help` at start: a new flag is added here; the --force names, the subcommands), the
// random generator and the deterministic sweep.
#pragma once
#include <algorithm>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace {

using Args = std::vector<std::string>;

// ---- What the generator draws from -------------------------------------------------------------

// Numbers at and past every edge a parser or a renderer can trip on: float and double range ends,
// subnormals, signed zero, NaN and infinity spellings, integers past 32 and 64 bits, the camera
// coordinates whose chunk index reaches INT_MAX, and texts strtod half-accepts.
const std::vector<std::string> kExtremeNumbers = {
    "6.9e10", "68719476110", "-68719476110", "1e308", "-1e308", "1e300", "-1e300", "1.7976931348623157e308",
    "1e309", "-0", "-0.0", "0", "4.9e-324", "-4.9e-324", "2.2250738585072014e-308", "1e-310", "nan", "NaN",
    "-nan", "nan(0x1)", "inf", "-inf", "Infinity", "9223372036854775807", "9223372036854775808",
    "-9223372036854775809", "18446744073709551616", "2147483647", "2147483648", "-2147483648",
    "-2147483649", "4294967296", "1e9", "-1e9", "1e12", "1e8", "3.4028235e38", "3.5e38", "-3.5e38", "1e-45",
    "0x10", "0x1p3", "1e", "1.5.5", "", " ", " 1", "+1", "1 ", "\t2", "1\n", "١", "１", "½", "\xff\xfe",
    "1e1000", "1,2", "-", "+", ".", "e5", "00000000000000000000000001", "1_000", "0b101", "١٢٣"};

// The sweep's share of them: one of each kind (the sweep renders every one that is accepted, and a
// render costs about a second here), in every numeric slot.
const std::vector<std::string> kSweepNumbers = {
    "6.9e10", "68719476110", "1e308", "-1e308", "1e300", "-0", "4.9e-324", "nan", "inf", "9223372036854775808",
    "2147483648", "1e9", "3.5e38", "", " 1", "+1", "١", "1e1000"};

// Texts that are not numbers or names: empty, spaces, signs, unicode, control bytes, long.
const std::vector<std::string> kOddTexts = {
    "", " ", "-", "--", "---", "--=", "-h", "--help", "x", "on", "off", "ON", "Off ", " on", "final\n",
    "ünïcödé", "日本語", "\xc3\x28", "\x01\x02", "$(id)", "%s%n", std::string(300, 'a'), "none", "null"};

// Output names, all inside the case's directory (never an absolute path that exists: a writer
// that renames into place must not be pointed at /dev or /).
const std::vector<std::string> kOutNames = {
    "a.png", "b.PNG", "x.jpg", "noext", "missing-dir/a.png", "ünï.png", " lead.png", "-dash.png", ".",
    "", "../up.png", "/nonexistent-oasis-fuzz/x.png", "dir.png/", "a.png.png", "existing-dir"};
const std::vector<std::string> kOutDirs = {
    "out", "o u t", "ünï", "", ".", "a/b/c", "/nonexistent-oasis-fuzz/dir", "existing-file", "existing-dir"};

enum class Value { None, Size, Number, Integer, Camera, Choice, ForceList, PassName, OutFile, OutDir, Pixel, Range };

// One row per option the parser knows (src/cli/options.cpp): how its value is drawn and its domain
// (inside it the generator mostly stays; the extremes come on top).
struct Flag {
    const char* name;
    Value value;
    double low = 0, high = 0;           // Number / Integer
    std::vector<std::string> choices;   // Choice (views and layouts come from --help too)
};
const std::vector<Flag>& flags() {
    static const std::vector<Flag> table = {
        {"--size", Value::Size},
        {"--time", Value::Number, 0, 3600},
        {"--hour", Value::Number, 0, 24},
        {"--camera", Value::Camera},
        {"--reflections", Value::Choice, 0, 0, {"on", "off"}},
        {"--water-level", Value::Number, -20, 40},
        {"--ripples", Value::Number, 0, 4},
        {"--absorption", Value::Number, 0, 2},
        {"--vegetation", Value::Choice, 0, 0, {"on", "off"}},
        {"--billboards", Value::Choice, 0, 0, {"trimmed", "whole"}},
        {"--reflection-bounds", Value::Choice, 0, 0, {"on", "off"}},
        {"--reflection-resolution", Value::Choice, 0, 0, {"full", "half", "quarter"}},
        {"--tone-map", Value::Choice, 0, 0, {"fused", "separate"}},
        {"--depth-read", Value::Choice, 0, 0, {"in-place", "copy"}},
        {"--reflection-plant-cull", Value::Choice, 0, 0, {"auto", "on", "off"}},
        {"--shadows", Value::Choice, 0, 0, {"on", "off"}},
        {"--shadow-quality", Value::Choice, 0, 0, {"low", "medium", "high"}},
        {"--vegetation-density", Value::Number, 0, 4},
        {"--wind", Value::Number, 0, 3},
        {"--no-compute", Value::None},
        {"--lights", Value::Integer, 0, 4096},
        {"--lights-path", Value::Choice, 0, 0, {"ssbo", "ssbo-count", "ubo"}},
        {"--light-method", Value::Choice, 0, 0, {"volumes", "tiled"}},
        {"--force", Value::ForceList},
        {"--api", Value::Choice, 0, 0, {"gl", "gles"}},
        {"--workarounds", Value::Choice, 0, 0, {"default", "none", "all", "flush-before-compute-read", "array-write-by-loop", "depth-clamp-off"}},
        {"--workarounds-file", Value::Choice, 0, 0, {"/dev/null", "no-such-workarounds-file"}},  // empty, or exit 2
        {"--depth", Value::Choice, 0, 0, {"standard", "reversed-z"}},
        {"--gbuffer", Value::Choice},
        {"--pipeline", Value::Choice, 0, 0, {"forward", "deferred"}},
        {"--view", Value::Choice},
        {"--stencil-view", Value::Choice, 0, 0, {"texturing", "read-back"}},
        {"--stop-before", Value::PassName},
        {"--out", Value::OutFile},
        {"--out-dir", Value::OutDir},
        {"--json", Value::None},
        {"--frames", Value::Integer, 1, 3},  // more frames only cost time: the extremes test the domain
        {"--seed", Value::Integer, 0, 999999},
        // A tight target costs rounds (up to 200: over the 20 s case limit at 32x18 on a loaded
        // machine): kept loose here; the sweep reads its extremes without timing (below).
        {"--until-ci", Value::Number, 45, 50},
        {"--passes", Value::None},
        {"--graph", Value::None},  // render: the frame's passes on stdout, no image
        {"--shading", Value::None},  // probe: the lighting's terms
        {"--history", Value::None},  // probe: every pass at the pixel (a frame per pass that left it: kept small)
        {"--at", Value::Pixel},
        {"--view-exposure", Value::Number, -20, 20},
        {"--channel", Value::Choice, 0, 0, {"rgb", "r", "g", "b", "a", "luminance"}},
        {"--range", Value::Range, -10, 10},
        {"--overlay", Value::Choice, 0, 0, {"nan", "inf", "negative", "nan,inf", "nan,inf,negative", "none"}},
        {"--legend", Value::Choice, 0, 0, {"on", "off"}},
        {"--water-scene", Value::Choice, 0, 0, {"direct", "mirrored"}},
        {"--start-paused", Value::None},  // the window's: refused (exit 2) by the headless commands
        // compare's set-ups: the fast llvmpipe ones (zink and softpipe cost seconds a case).
        {"--driver", Value::Choice, 0, 0, {"llvmpipe", "no-ssbo", "gl33", "no-dsa"}},
        {"--reference", Value::OutFile},  // mostly missing files: the parse and read errors
        {"--allow-large", Value::None},  // compare --reference's: refused (exit 2) without --reference
        // Low limits kill the children mid-render (exit 1): the kill path, fuzzed.
        {"--driver-timeout", Value::Number, 0.1, 20},
        {"--quick", Value::None},
        // check's own (refused by the fuzzed subcommands, which do not include check: it runs minutes)
        {"--case-timeout", Value::Number, 0.1, 20},
        {"--jobs", Value::Integer, 1, 4},
        {"--retries", Value::Integer, 0, 3},
        {"--shard", Value::Choice, 0, 0, {"1/2", "2/2", "0/1", "3/2", "1/1000"}},
        {"--capture", Value::None},   // exit 1 here: no RenderDoc (tests/capture checks the capture)
        {"--gl-debug", Value::None},
        {"--help", Value::None},
        {"-h", Value::None},
    };
    return table;
}
const std::vector<std::string> kForceNames = {"no-ssbo", "no-compute", "no-stencil-texturing", "no-dsa",
                                              "no-clip-control", "gl33", "gles30", "no-depth-clamp",
                                              "no-read-only-depth"};
// "" is the main job (no subcommand). bench runs minutes, so its cases always end in an option
// bench refuses (--size): they fuzz its parsing, cli.bench_quick_smoke runs it.
const std::vector<std::string> kSubcommands = {"render", "render", "render", "compare", "", "caps", "window",
                                               "bench", "probe"};

// ---- Generation ---------------------------------------------------------------------------------

struct Generator {
    std::mt19937_64 rng;
    const std::map<std::string, std::vector<std::string>>& choices;  // per flag, from --help
    const std::vector<std::string>& passes;

    explicit Generator(uint64_t seed, const std::map<std::string, std::vector<std::string>>& c,
                       const std::vector<std::string>& p)
        : rng(seed), choices(c), passes(p) {}

    bool chance(double p) { return std::uniform_real_distribution<double>(0, 1)(rng) < p; }
    int integer(int low, int high) { return std::uniform_int_distribution<int>(low, high)(rng); }
    template <typename T> const T& pick(const std::vector<T>& items) { return items[integer(0, int(items.size()) - 1)]; }

    std::string number(double low, double high) {
        double x = std::uniform_real_distribution<double>(low, high)(rng);
        char text[64];
        switch (integer(0, 3)) {
            case 0: std::snprintf(text, sizeof text, "%g", x); break;
            case 1: std::snprintf(text, sizeof text, "%.17g", x); break;
            case 2: std::snprintf(text, sizeof text, "%.0f", x); break;
            default: std::snprintf(text, sizeof text, "%.3e", x); break;
        }
        return text;
    }
    std::string edgeOf(double low, double high) {
        double edges[] = {low, high, std::nextafter(low, -1e300), std::nextafter(high, 1e300), low - 1, high + 1};
        char text[64];
        std::snprintf(text, sizeof text, "%.17g", edges[integer(0, 5)]);
        return text;
    }
    std::string extreme() { return chance(0.85) ? pick(kExtremeNumbers) : pick(kOddTexts); }

    std::string size() {
        if (chance(0.8)) return std::to_string(integer(16, 64)) + "x" + std::to_string(integer(9, 36));
        static const std::vector<std::string> odd = {
            "1x1", "2x1", "1x36", "64x1", "0x0", "0x10", "-1x5", "64x", "x36", "64X36", " 64x36", "+32x+18",
            "64x36x2", "64.5x36", "1000000000x1", "1x1000000000", "20000x8", "16385x1", "2147483648x1",
            "64x-0", "６４x36", "64 x 36", "0x1p5x8", "1e2x9", "x", ""};
        return pick(odd);
    }
    std::string camera() {
        std::vector<std::string> fields = {number(0, 1000), number(1, 80), number(0, 1000), number(-360, 360),
                                           number(-89, 89)};
        for (auto& field : fields)
            if (chance(0.1)) field = extreme();
        if (chance(0.1)) fields.push_back(number(0, 10));
        if (chance(0.1)) fields.pop_back();
        std::string text;
        for (size_t i = 0; i < fields.size(); ++i) text += (i ? "," : "") + fields[i];
        if (chance(0.05)) text += ",";
        return text;
    }
    std::string forceList() {
        std::string text;
        int count = integer(1, 3);
        for (int i = 0; i < count; ++i) text += (i ? "," : "") + (chance(0.9) ? pick(kForceNames) : extreme());
        return text;
    }
    std::string valueFor(const Flag& flag) {
        switch (flag.value) {
            case Value::None: return {};
            case Value::Size: return size();
            case Value::Number:
                return chance(0.7) ? number(flag.low, flag.high) : chance(0.4) ? edgeOf(flag.low, flag.high) : extreme();
            case Value::Integer:
                return chance(0.7) ? std::to_string(integer(int(flag.low), int(flag.high)))
                                   : chance(0.4) ? edgeOf(flag.low, flag.high) : extreme();
            case Value::Camera: return camera();
            case Value::Choice: {
                auto found = choices.find(flag.name);
                const auto& names = found != choices.end() ? found->second : flag.choices;
                if (names.empty() || chance(0.15)) return chance(0.5) ? pick(kOddTexts) : mangle(names.empty() ? "x" : pick(names));
                return pick(names);
            }
            case Value::ForceList: return forceList();
            case Value::PassName: return passes.empty() || chance(0.3) ? pick(kOddTexts) : pick(passes);
            case Value::OutFile: return pick(kOutNames);
            case Value::OutDir: return pick(kOutDirs);
            case Value::Pixel:  // mostly inside the small frames the cases render
                return chance(0.8) ? std::to_string(integer(0, 40)) + "," + std::to_string(integer(0, 20))
                                   : (chance(0.5) ? extreme() : pick(kOddTexts)) + "," + std::to_string(integer(0, 9));
            case Value::Range:
                if (chance(0.7)) {
                    double low = std::stod(number(flag.low, flag.high));
                    return number(flag.low, low) + "," + number(low, flag.high);
                }
                return (chance(0.5) ? extreme() : number(flag.low, flag.high)) + "," + (chance(0.5) ? extreme() : pick(kOddTexts));
        }
        return {};
    }
    // A small change to a text: a character dropped, doubled, upper-cased, a space or sign or
    // multi-byte character put in front or inside.
    std::string mangle(std::string text) {
        static const std::vector<std::string> inserts = {" ", "+", "-", "0", "é", "\t", ",", "x", "e", "."};
        size_t at = text.empty() ? 0 : size_t(integer(0, int(text.size())));
        switch (integer(0, 3)) {
            case 0: if (!text.empty()) text.erase(std::min(at, text.size() - 1), 1); break;
            case 1: text.insert(at, pick(inserts)); break;
            case 2: if (!text.empty()) text[std::min(at, text.size() - 1)] ^= 0x20; break;
            default: text = pick(inserts) + text; break;
        }
        return text;
    }

    // A plausible list (flags with fitting values), then 0-3 mutations on the token list.
    Args arguments(const std::string& subcommand) {
        Args args;
        if (!subcommand.empty()) args.push_back(subcommand);
        int count = integer(0, 5);
        for (int i = 0; i < count; ++i) {
            const Flag& flag = pick(flags());
            if ((flag.name == std::string("--help") || flag.name == std::string("-h")) && chance(0.8)) continue;
            args.push_back(flag.name);
            if (flag.value != Value::None) args.push_back(valueFor(flag));
        }
        int mutations = chance(0.6) ? 0 : integer(1, 3);
        for (int m = 0; m < mutations; ++m) mutate(args);
        // The history renders up to a frame per pass: at the default 1280x720 that outlasts a
        // case's time limit on llvmpipe, so such a case gets a small frame (its parse is fuzzed anyway).
        if (std::find(args.begin(), args.end(), "--history") != args.end() &&
            std::find(args.begin(), args.end(), "--size") == args.end())
            args.insert(args.end(), {"--size", "48x27"});
        return args;
    }
    void mutate(Args& args) {
        size_t n = args.size();
        size_t at = n ? size_t(integer(0, int(n) - 1)) : 0;
        switch (integer(0, 6)) {
            case 0: if (n) args.erase(args.begin() + long(at)); break;                      // drop a token
            case 1: if (n) args.insert(args.begin() + long(at), args[at]); break;           // repeat one
            case 2: if (n > 1) std::swap(args[at], args[size_t(integer(0, int(n) - 1))]); break;
            case 3: if (n) args[at] = mangle(args[at]); break;
            case 4: args.insert(args.begin() + long(n ? at : 0), extreme()); break;
            case 5: args.insert(args.begin() + long(n ? at : 0), pick(flags()).name); break;  // a flag, no value
            default: args.push_back(chance(0.5) ? pick(kOddTexts) : pick(kSubcommands)); break;
        }
    }
};

// Every extreme number in every numeric slot, alone on an otherwise good command line: the
// deterministic part, run in full before the random cases.
std::vector<Args> sweepCases() {
    std::vector<Args> cases;
    for (const Flag& flag : flags()) {
        if (flag.value != Value::Number && flag.value != Value::Integer) continue;
        const std::string name = flag.name;
        std::string sub = name == "--frames" || name == "--seed" || name == "--until-ci" || name == "--driver-timeout"
                              ? "compare"
                              : "render";
        for (const std::string& value : kSweepNumbers) {
            Args args = {sub, flag.name, value, "--size", "32x18"};
            if (sub == "compare") args.insert(args.end(), {"--out-dir", "out"});
            // A missing reference ends a good parse before any child starts: the sweep reads the number only.
            // --until-ci's good values are then refused as the driver comparison's (it times nothing).
            if (name == "--driver-timeout" || name == "--until-ci") args.insert(args.end(), {"--reference", "missing.png"});
            cases.push_back(args);
        }
    }
    // The camera's five fields one at a time, the others at a pose that sees land, water and plants.
    const std::vector<std::string> pose = {"420", "6", "160", "40", "-4"};
    for (size_t field = 0; field < pose.size(); ++field)
        for (const std::string& value : kSweepNumbers) {
            std::vector<std::string> fields = pose;
            fields[field] = value;
            std::string camera;
            for (size_t i = 0; i < fields.size(); ++i) camera += (i ? "," : "") + fields[i];
            cases.push_back({"render", "--camera", camera, "--size", "32x18"});
        }
    for (const std::string& value : kSweepNumbers) {
        cases.push_back({"render", "--size", value + "x18"});
        cases.push_back({"render", "--size", "32x" + value});
    }
    // The graph's text in every sweep, not only where the random cases happen to reach one.
    for (const char* view : {"final", "albedo", "stencil"})
        for (const char* pipeline : {"deferred", "forward"})
            cases.push_back({"render", "--graph", "--view", view, "--pipeline", pipeline, "--size", "32x18"});
    return cases;
}

}  // namespace
