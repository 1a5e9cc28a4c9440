// Fuzzes oasis's command line end to end: random and mutated argument lists run against the real
// binary for a bounded time. Per case: no signal and no hang (a per-case limit kills the child);
// exit 0 only with every image the case writes complete and, where it is a picture, not one flat
// colour; exit 1 or 2 only with a stderr line starting "oasis: "; no sanitizer report.
// Prints the seed, the case count and the time; a failing case is printed as a command to paste.
//
// usage: oasis_cli_fuzz OASIS WORK_DIR [--seconds S] [--seed N] [--case-limit S] [--jobs J]
//                       [--known FILE]
// The flag table (cli_fuzz_cases.h) is checked against `oasis [SUBCOMMAND] --help` at start, so a new flag
// that the fuzzer does not know fails the run until it is added here.
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <stb_image.h>

#include "cli_fuzz_cases.h"

namespace {

namespace fs = std::filesystem;
using Args = std::vector<std::string>;
using Clock = std::chrono::steady_clock;

// ---- Running one case ---------------------------------------------------------------------------

std::string shellQuote(const std::string& text) {
    if (!text.empty() && text.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-_.,/+=:") == std::string::npos)
        return text;
    std::string quoted = "'";
    for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
}
std::string commandLine(const std::string& oasis, const Args& args) {
    std::string line = shellQuote(oasis);
    for (const auto& arg : args) line += " " + shellQuote(arg);
    return line;
}

std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

struct Running {
    int index = 0;
    Args args;
    fs::path dir;
    pid_t pid = -1;
    Clock::time_point start;
};

// The child runs in its own process group (so a hang is killed with Mesa's threads), in the case's
// directory (default outputs land there), with no display (no subcommand = the headless main job).
pid_t launch(const std::string& oasis, const Running& run) {
    pid_t pid = fork();
    if (pid != 0) return pid;
    setpgid(0, 0);
    if (chdir(run.dir.c_str()) != 0) _exit(125);
    int out = open("stdout.txt", O_WRONLY | O_CREAT | O_TRUNC, 0644);
    int err = open("stderr.txt", O_WRONLY | O_CREAT | O_TRUNC, 0644);
    int none = open("/dev/null", O_RDONLY);
    if (out < 0 || err < 0 || none < 0) _exit(125);
    dup2(none, 0), dup2(out, 1), dup2(err, 2);
    unsetenv("DISPLAY");
    unsetenv("WAYLAND_DISPLAY");
    std::vector<char*> argv = {const_cast<char*>(oasis.c_str())};
    for (const auto& arg : run.args) argv.push_back(const_cast<char*>(arg.c_str()));
    argv.push_back(nullptr);
    execv(oasis.c_str(), argv.data());
    _exit(126);
}

// The value of the last occurrence of a flag the parser would have read (later ones win).
std::string lastValue(const Args& args, const std::string& flag, const std::string& fallback) {
    std::string value = fallback;
    for (size_t i = 0; i + 1 < args.size(); ++i)
        if (args[i] == flag) value = args[i + 1];
    return value;
}
bool has(const Args& args, const std::string& token) { return std::find(args.begin(), args.end(), token) != args.end(); }

// An image written by oasis: a regular file that decodes completely, of the frame's size; a picture
// (not a debug view that may be empty) must have more than one colour, when it has room for any.
std::string checkImage(const fs::path& path, int width, int height, bool picture, bool legend = false) {
    std::error_code ignored;
    if (!fs::is_regular_file(path, ignored)) return path.string() + " is not a written file";
    int w = 0, h = 0, channels = 0;
    unsigned char* pixels = stbi_load(path.c_str(), &w, &h, &channels, 4);
    if (!pixels) return path.string() + " does not decode as an image: " + stbi_failure_reason();
    std::string problem;
    // A legend strip sits under a single view and the difference image from 160 pixels wide.
    if (w != width || (legend && width >= 160 ? h <= height : h != height))
        problem = path.string() + " is " + std::to_string(w) + "x" + std::to_string(h) + ", expected " +
                  std::to_string(width) + "x" + std::to_string(height);
    if (problem.empty() && picture && width >= 8 && height >= 8) {
        const uint32_t* rgba = reinterpret_cast<const uint32_t*>(pixels);
        if (std::all_of(rgba, rgba + size_t(w) * size_t(h), [&](uint32_t p) { return p == rgba[0]; }))
            problem = path.string() + " is one flat colour";
    }
    stbi_image_free(pixels);
    return problem;
}

// `render --graph`: a first line naming the pipeline ("# the deferred pipeline's frame, ..."), then
// one line a pass, from the first pass of every frame, each `NAME  READS -> WRITES` or `NAME  culled: WHY`,
// then, for a frame built for a view, a line "# after the frame, ..." and the views' passes in the same
// form, then the resources' blocks ("# buffers: ...", "# targets: ..."), every line of them a "# " line.
std::string checkGraphText(const std::string& text) {
    static const std::regex kPassLine("[A-Z][A-Za-z]*Pass(\\.[a-z-]+)* +(.* -> .+|culled: .+|cut: .+)");
    static const std::regex kHeader("# the (forward|deferred) pipeline's frame, [0-9]+x[0-9]+, built for view .+\n");
    std::smatch header;
    if (!std::regex_search(text, header, kHeader, std::regex_constants::match_continuous))
        return "render --graph printed no header naming its pipeline";
    if (text.compare(size_t(header.length()), 19, "TerrainHeightsPass ") != 0) return "render --graph printed no pass list";
    std::istringstream lines(text.substr(size_t(header.length())));
    bool resources = false;  // past the passes: the buffers' and targets' blocks
    for (std::string line; std::getline(lines, line);) {
        if (!resources && line.rfind("# after the frame, ", 0) == 0) continue;  // the views' passes follow
        resources = resources || line.rfind("# ", 0) == 0;
        if (resources && line.rfind("# ", 0) != 0)
            return "render --graph printed a line after its resources' blocks: '" + line + "'";
        if (!resources && !std::regex_match(line, kPassLine))
            return "render --graph printed a line that is not a pass: '" + line + "'";
    }
    if (!resources) return "render --graph printed no resources (buffers, targets)";
    return {};
}

const std::regex kSanitizerReport("runtime error:|ERROR: AddressSanitizer|ERROR: LeakSanitizer|SUMMARY: (Address|Undefined|Leak)");
const std::regex kNonFinite("(^|[^a-zA-Z_])(-?nan|-?inf)([^a-zA-Z_]|$)", std::regex::icase);

// What a successful exit must have produced, by subcommand.
std::string checkSuccess(const Running& run, const std::string& stdoutText) {
    const Args& args = run.args;
    std::string sub = !args.empty() && !args[0].empty() && args[0][0] != '-' ? args[0] : "";
    if (has(args, "--help") || has(args, "-h"))
        return stdoutText.rfind("usage: oasis", 0) == 0 || stdoutText.rfind("oasis - ", 0) == 0 ? "" : "help without a usage text";
    int width = 1280, height = 720;
    std::string size = lastValue(args, "--size", "1280x720");
    if (std::sscanf(size.c_str(), "%dx%d", &width, &height) != 2) return "exit 0 with --size '" + size + "'";
    if (sub == "render" && has(args, "--graph")) return checkGraphText(stdoutText);
    if (sub == "render") {
        std::string view = lastValue(args, "--view", "final");
        // A channel or a range may rightly map the whole frame to one grey (alpha is 1 everywhere).
        bool picture = (view == "final" || view == "overview") && !has(args, "--stop-before") &&
                       !has(args, "--channel") && !has(args, "--range");
        // A buffer view carries its legend strip under the frame unless --legend off; the final
        // frame only with --legend on.
        bool legend = view != "overview" && lastValue(args, "--legend", view == "final" ? "off" : "on") != "off";
        return checkImage(run.dir / lastValue(args, "--out", "oasis.png"), width, height, picture, legend);
    }
    if (sub == "probe") {
        bool json = has(args, "--json");
        if (json ? stdoutText.rfind("{\"x\": ", 0) != 0 : stdoutText.rfind("pixel ", 0) != 0) return "probe printed no probe";
        if (json && std::regex_search(stdoutText, kNonFinite)) return "a non-finite number in the probe's JSON";
        return {};
    }
    if (sub == "compare" || sub.empty()) {
        if (std::regex_search(stdoutText, kNonFinite)) return "a non-finite number in the output";
        fs::path dir = run.dir / lastValue(args, "--out-dir", "oasis-out");
        std::vector<std::pair<std::string, bool>> files = {{"forward.png", true}, {"deferred.png", true}, {"difference.png", false}};
        if (sub.empty()) files.push_back({"overview.png", true});
        for (const auto& [file, picture] : files)
            if (std::string problem = checkImage(dir / file, width, height, picture, file == "difference.png"); !problem.empty())
                return problem;
        return {};
    }
    if (sub == "caps") return stdoutText.empty() ? "caps printed nothing" : "";
    return "exit 0 from `oasis " + sub + "` (no display here; bench cases end in an option it refuses)";
}

struct Outcome {
    std::string failure;  // empty: the case passed
    int exitCode = -1;
};

Outcome judge(const Running& run, int status, bool timedOut, double limit) {
    Outcome outcome;
    std::string out = readFile(run.dir / "stdout.txt"), err = readFile(run.dir / "stderr.txt");
    if (timedOut) { outcome.failure = "hang: killed after " + std::to_string(int(limit)) + " s"; return outcome; }
    if (WIFSIGNALED(status)) { outcome.failure = std::string("crash: signal ") + strsignal(WTERMSIG(status)); return outcome; }
    outcome.exitCode = WEXITSTATUS(status);
    if (std::regex_search(err, kSanitizerReport)) outcome.failure = "sanitizer report";
    else if (outcome.exitCode == 0) outcome.failure = checkSuccess(run, out);
    else if (outcome.exitCode == 1 || outcome.exitCode == 2) {
        if (err.rfind("oasis: ", 0) != 0 && err.find("\noasis: ") == std::string::npos)
            outcome.failure = "exit " + std::to_string(outcome.exitCode) + " without a line 'oasis: ...' on stderr";
    } else outcome.failure = "exit code " + std::to_string(outcome.exitCode) + " (expected 0, 1 or 2)";
    return outcome;
}

// ---- Set-up from the binary's own help ------------------------------------------------------------

std::string capture(const std::string& oasis, const Args& args, const fs::path& dir) {
    Running run{0, args, dir};
    fs::create_directories(dir);
    pid_t pid = launch(oasis, run);
    int status = 0;
    waitpid(pid, &status, 0);
    return readFile(dir / "stdout.txt") + readFile(dir / "stderr.txt");
}

std::vector<std::string> splitNames(const std::string& text) {
    std::vector<std::string> names;
    std::regex name("[a-z][a-z0-9-]*");
    for (std::sregex_iterator it(text.begin(), text.end(), name), end; it != end; ++it) names.push_back(it->str());
    return names;
}

struct Known {
    std::vector<std::pair<std::regex, std::string>> patterns;  // regex over the command line, why
    bool matches(const std::string& line, std::string& why) const {
        for (const auto& [pattern, reason] : patterns)
            if (std::regex_search(line, pattern)) { why = reason; return true; }
        return false;
    }
};
Known readKnown(const std::string& path) {
    Known known;
    if (path.empty()) return known;
    std::ifstream in(path);
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#') continue;
        size_t tab = line.find("\t#");
        known.patterns.push_back({std::regex(line.substr(0, tab)), tab == std::string::npos ? "" : line.substr(tab + 2)});
    }
    return known;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: %s OASIS WORK_DIR [--seconds S] [--seed N] [--case-limit S] [--jobs J] [--known FILE]\n", argv[0]);
        return 2;
    }
    std::string oasis = fs::absolute(argv[1]).string();
    fs::path work = fs::absolute(argv[2]);
    double seconds = 90, caseLimit = 20;
    uint64_t seed = 12;
    int jobs = 2;
    std::string knownFile;
    Args replay;  // after --: one argument list, judged and reported (to reproduce a failure)
    bool replaying = false;
    for (int i = 3; i < argc; i += 2) {
        if (argv[i] == std::string("--")) {
            replay.assign(argv + i + 1, argv + argc);
            replaying = true;
            break;
        }
        if (i + 1 >= argc) { std::fprintf(stderr, "cli fuzz: %s needs a value\n", argv[i]); return 2; }
        std::string flag = argv[i], value = argv[i + 1];
        if (flag == "--seconds") seconds = std::atof(value.c_str());
        else if (flag == "--seed") seed = std::strtoull(value.c_str(), nullptr, 10);
        else if (flag == "--case-limit") caseLimit = std::atof(value.c_str());
        else if (flag == "--jobs") jobs = std::max(1, std::atoi(value.c_str()));
        else if (flag == "--known") knownFile = value;
        else { std::fprintf(stderr, "cli fuzz: unknown option %s\n", flag.c_str()); return 2; }
    }
    fs::remove_all(work);
    fs::create_directories(work);
    Known known = readKnown(knownFile);

    // Every flag --help lists must be in the table; views and layouts are taken from it.
    std::map<std::string, std::vector<std::string>> choices;
    std::set<std::string> helpFlags;
    for (std::string sub : {"", "render", "compare", "caps", "bench", "window", "probe"}) {
        Args args = sub.empty() ? Args{"--help"} : Args{sub, "--help"};
        std::string help = capture(oasis, args, work / "help");
        std::regex flag("--[a-z][a-z-]*");
        for (std::sregex_iterator it(help.begin(), help.end(), flag), end; it != end; ++it) helpFlags.insert(it->str());
        std::smatch match;
        if (std::regex_search(help, match, std::regex("--view NAME +([^\n]*)"))) choices["--view"] = splitNames(match[1]);
        if (std::regex_search(help, match, std::regex("--gbuffer LAYOUT +G-buffer layout: ([a-z, -]*)"))) choices["--gbuffer"] = splitNames(match[1]);
    }
    helpFlags.erase("--help");
    for (const std::string& flag : helpFlags)
        if (std::none_of(flags().begin(), flags().end(), [&](const Flag& f) { return f.name == flag; })) {
            std::fprintf(stderr, "cli fuzz: `oasis --help` lists %s, which the fuzzer's flag table does not know: add it to tests/fuzz/cli_fuzz_cases.h\n", flag.c_str());
            return 1;
        }
    if (choices["--view"].empty() || choices["--gbuffer"].empty()) {
        std::fprintf(stderr, "cli fuzz: could not read the view and layout names from `oasis render --help`\n");
        return 1;
    }
    if (!has(choices["--view"], "overview")) choices["--view"].push_back("overview");
    // The pass names, from the refusal of a wrong one ("... one of: A, B, ...").
    std::vector<std::string> passes;
    std::string refusal = capture(oasis, {"render", "--size", "16x9", "--stop-before", "NoSuchPass", "--out", "x.png"}, work / "passes");
    std::regex passName("[A-Z][A-Za-z]*Pass(\\.[a-z]+)*");
    for (std::sregex_iterator it(refusal.begin(), refusal.end(), passName), end; it != end; ++it)
        if (it->str() != "NoSuchPass") passes.push_back(it->str());
    std::vector<Args> sweep = replaying ? std::vector<Args>{replay} : sweepCases();
    if (replaying) seconds = 0;
    std::printf("cli fuzz: seed %llu, %.0f s, %d jobs, per-case limit %.0f s, %zu flags, %zu views, %zu layouts, %zu passes, %zu known-failure patterns, %zu sweep cases\n",
                (unsigned long long)seed, seconds, jobs, caseLimit, helpFlags.size(), choices["--view"].size(),
                choices["--gbuffer"].size(), passes.size(), known.patterns.size(), sweep.size());
    std::fflush(stdout);

    auto begin = Clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - begin).count(); };
    std::vector<Running> running;
    std::map<int, int> exitCodes;
    int started = 0, finished = 0, swept = 0, failures = 0, skipped = 0;
    while (true) {
        while (int(running.size()) < jobs && (started < int(sweep.size()) || elapsed() < seconds)) {
            int index = started++;
            Args args;
            if (index < int(sweep.size())) {
                args = sweep[size_t(index)];
            } else {
                // Each case from its own seed: the list does not depend on scheduling or timing.
                Generator generator(seed * 1000003ull + uint64_t(index), choices, passes);
                std::string sub = generator.pick(kSubcommands);
                args = generator.arguments(sub);
                // Keep every render small and short: a size and one timed frame unless the list has them.
                if (!has(args, "--size") || sub == "bench") { args.push_back("--size"); args.push_back(generator.size()); }
                if ((sub == "compare" || sub.empty()) && !has(args, "--frames")) { args.push_back("--frames"); args.push_back("1"); }
            }
            std::string why;
            if (known.matches(commandLine("oasis", args), why)) { ++skipped; continue; }
            Running run{index, args, work / ("case-" + std::to_string(index))};
            fs::create_directories(run.dir / "existing-dir");
            std::ofstream(run.dir / "existing-file") << "x";
            run.start = Clock::now();
            run.pid = launch(oasis, run);
            running.push_back(run);
        }
        if (running.empty()) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
        for (size_t i = 0; i < running.size();) {
            Running& run = running[i];
            int status = 0;
            bool timedOut = false;
            pid_t done = waitpid(run.pid, &status, WNOHANG);
            if (done == 0) {
                if (std::chrono::duration<double>(Clock::now() - run.start).count() < caseLimit) { ++i; continue; }
                kill(-run.pid, SIGKILL);
                waitpid(run.pid, &status, 0);
                timedOut = true;
            }
            Outcome outcome = judge(run, status, timedOut, caseLimit);
            ++finished;
            swept += run.index < int(sweep.size());
            ++exitCodes[outcome.exitCode];
            if (outcome.failure.empty()) {
                fs::remove_all(run.dir);
            } else {
                ++failures;
                std::string err = readFile(run.dir / "stderr.txt");
                if (err.size() > 3000) err = "..." + err.substr(err.size() - 3000);
                std::printf("FAIL case %d: %s\n  (cd %s && %s)\n  stderr:\n%s\n", run.index, outcome.failure.c_str(),
                            shellQuote(run.dir.string()).c_str(), commandLine(oasis, run.args).c_str(), err.c_str());
                std::fflush(stdout);
            }
            running.erase(running.begin() + long(i));
        }
    }
    std::string codes;
    for (const auto& [code, count] : exitCodes) codes += (codes.empty() ? "" : ", ") + (code < 0 ? std::string("killed") : "exit " + std::to_string(code)) + ": " + std::to_string(count);
    std::printf("cli fuzz: %d cases (%d swept, %d random) in %.1f s (%s), %d skipped as known failures, %d failed (seed %llu)\n",
                finished, swept, finished - swept, elapsed(),
                codes.c_str(), skipped, failures, (unsigned long long)seed);
    return failures ? 1 : 0;
}
