// The check's child processes (check/check_runner.h): the parent's side runs
// `oasis check --child KIND --child-out PREFIX ... -- ARGUMENTS` under a time limit and reads back
// PREFIX.json (and .png, .bin); the child's side renders and writes them. A child that dies or
// hangs ends its own case only.
#include "check/check_runner.h"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "io/json_text.h"
#include "commands/child_process.h"
#include "check/check_snapshots.h"
#include "commands/json_value.h"
#include "check/oracle_report.h"
#include "check/pixel_classes.h"
#include "gl/objects.h"
#include "io/file_output.h"
#include "io/interruption.h"

extern char** environ;

namespace oasis {
namespace {

// ---- the child's side ------------------------------------------------------------------------

// A child that dies says where: the debug group it was in (the pass, or PlantAtlas), as the last
// line the parent keeps. Not async-signal-safe in general; the process is ending either way, and
// this line is what the tester needs most. SIGTERM is the parent's stop at the time limit.
void sayWhereAndDie(int signalNumber) {
    std::string line = "oasis check child: " + std::string(signalNumber == SIGTERM ? "stopped" : "died") + " in " +
                       gl::debugGroupPath() + " (signal " + std::to_string(signalNumber) + ")\n";
    ssize_t ignored = write(STDERR_FILENO, line.data(), line.size());
    (void)ignored;
    signal(signalNumber, SIG_DFL);
    raise(signalNumber);
}

void reportWhereOnDeath() {
    for (int signalNumber : {SIGABRT, SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGTERM}) signal(signalNumber, sayWhereAndDie);
}

std::string contextJson(const CaseContext& context) {
    return "{\"gl_version\": " + jsonString(context.glVersion) + ", \"glsl_version\": " + jsonString(context.glslVersion) +
           ", \"renderer\": " + jsonString(context.renderer) + ", \"api\": " + jsonString(context.api) + "}";
}

bool writeText(const std::string& path, const std::string& text) {
    std::string error;
    return writeFileWhole(path, text, error);
}

int childFrame(const Options& options) {
    const CheckOptions& check = options.check;
    std::string json;
    try {
        CaseFrame frame = renderCaseFrame(check.childArguments, check.childGpuPlants, false);
        if (frame.rendered) {
            std::string error;
            if (!writePng(check.childOut + ".png", frame.image, error, frame.provenance)) throw std::runtime_error(error);
            if (!frame.pixelClasses.empty() &&
                !writePng(check.childOut + "-classes.png", pixelClassImage(frame.pixelClasses, frame.image.width,
                                                                           frame.image.height), error))
                throw std::runtime_error(error);
        }
        json = "{\"rendered\": " + std::string(frame.rendered ? "true" : "false") +
               ", \"skip_reason\": " + jsonString(frame.skipReason) + ", \"limited_by\": " + jsonString(frame.limitedBy) +
               ", \"drawn_with\": " + jsonString(frame.drawnWith) + ", \"pixel_classes\": " +
               (frame.pixelClasses.empty() ? "false" : "true") + ", \"context\": " + contextJson(frame.context) +
               ", \"oracle\": " + shadingOracleJson(frame.oracle) + ", \"error\": \"\"}";
    } catch (const std::exception& error) {
        json = "{\"rendered\": false, \"error\": " + jsonString(error.what()) + "}";
    }
    return writeText(check.childOut + ".json", json) ? 0 : 1;
}

int childPasses(const Options& options) {
    const CheckOptions& check = options.check;
    std::string json;
    try {
        std::vector<bool> where;
        int width = 0, height = 0;
        std::string error;
        if (!readPixelMask(check.childWhere, where, width, height, error)) throw std::runtime_error(error);
        std::vector<PassSnapshot> snapshots = renderPassByPass(check.childArguments, false);
        keepPixels(snapshots, where);
        if (!writeFileWhole(check.childOut + ".bin", encodeSnapshots(snapshots), error)) throw std::runtime_error(error);
        json = "{\"error\": \"\"}";
    } catch (const std::exception& error) {
        json = "{\"error\": " + jsonString(error.what()) + "}";
    }
    return writeText(check.childOut + ".json", json) ? 0 : 1;
}

int childDriver(const Options& options) {
    std::string json;
    try {
        CheckReport driver = driverReport(options.check.childArguments);
        json = "{\"vendor\": " + jsonString(driver.vendor) + ", \"renderer\": " + jsonString(driver.renderer) +
               ", \"version\": " + jsonString(driver.glVersion) + ", \"glsl_version\": " + jsonString(driver.glslVersion) +
               ", \"api\": " + jsonString(driver.api) + ", \"caps\": [";
        for (size_t i = 0; i < driver.caps.size(); ++i) {
            const CapabilityRow& row = driver.caps[i];
            json += std::string(i ? ", " : "") + "{\"feature\": " + jsonString(row.feature) + ", \"available\": " +
                    (row.available ? "true" : "false") + ", \"used\": " + (row.used ? "true" : "false") +
                    ", \"reason\": " + jsonString(row.reason) + ", \"limited_by\": " + jsonString(row.limitedBy) + "}";
        }
        json += "], \"workarounds\": [";
        for (size_t i = 0; i < driver.workarounds.size(); ++i)
            json += std::string(i ? ", " : "") + "{\"name\": " + jsonString(driver.workarounds[i].first) +
                    ", \"why\": " + jsonString(driver.workarounds[i].second) + "}";
        json += "], \"error\": \"\"}";
    } catch (const std::exception& error) {
        json = "{\"error\": " + jsonString(error.what()) + "}";
    }
    return writeText(options.check.childOut + ".json", json) ? 0 : 1;
}

// ---- the parent's side -----------------------------------------------------------------------

// The last `count` lines of a child's output, each control byte but the line ends shown as \xNN.
std::string lastLines(const std::string& output, int count) {
    size_t begin = output.size();
    for (int lines = 0; begin > 0 && lines <= count;) {
        --begin;
        if (output[begin] == '\n' && begin + 1 < output.size()) ++lines;
        if (lines > count) ++begin;
    }
    std::string tail;
    for (size_t i = begin; i < output.size(); ++i) {
        unsigned char c = static_cast<unsigned char>(output[i]);
        if ((c < 0x20 && c != '\n' && c != '\t') || c == 0x7f) {
            char escaped[8];
            std::snprintf(escaped, sizeof(escaped), "\\x%02x", c);
            tail += escaped;
        } else {
            tail += char(c);
        }
    }
    while (!tail.empty() && tail.back() == '\n') tail.pop_back();
    return tail;
}

// The debug group a dying child named (sayWhereAndDie), as " in PASS", or "".
std::string whereItDied(const std::string& output) {
    for (const char* said : {"oasis check child: died in ", "oasis check child: stopped in "}) {
        size_t at = output.rfind(said);
        if (at == std::string::npos) continue;
        size_t begin = at + std::strlen(said), end = output.find(" (signal", begin);
        return " in " + lastLines(output.substr(begin, end == std::string::npos ? std::string::npos : end - begin), 0);
    }
    return {};
}

std::string stringMember(const JsonValue& object, const char* key) {
    const JsonValue* value = object.find(key);
    return value && value->isString() ? value->text : std::string();
}

bool boolMember(const JsonValue& object, const char* key) {
    const JsonValue* value = object.find(key);
    return value && value->kind == JsonValue::Kind::Bool && value->boolean;
}

class ChildRunner : public CaseRunner {
public:
    explicit ChildRunner(double caseTimeoutSeconds) : timeout_(caseTimeoutSeconds) {
        const char* tmp = std::getenv("TMPDIR");
        std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/oasis-check-XXXXXX";
        std::vector<char> name(pattern.begin(), pattern.end());
        name.push_back('\0');
        if (!mkdtemp(name.data())) throw std::runtime_error("cannot make a scratch directory " + pattern + ": " + std::strerror(errno));
        scratch_ = name.data();
        removal_ = RemovedOnInterrupt(scratch_, RemovedOnInterrupt::Kind::DirectoryTree);
    }
    ~ChildRunner() override {
        removeDirectoryTree(scratch_);
        removal_.release();
    }

    FrameRun frame(const std::vector<std::string>& arguments, bool gpuPlants) override {
        FrameRun run;
        std::string prefix = nextPrefix();
        std::vector<std::string> extra;
        if (gpuPlants) extra.push_back("--gpu-plants");
        JsonValue answer;
        run.outcome = runKind("frame", prefix, extra, arguments, timeout_, answer);
        if (run.outcome.end != RunEnd::Finished || !run.outcome.error.empty()) return run;
        CaseFrame& frame = run.frame;
        frame.rendered = boolMember(answer, "rendered");
        frame.skipReason = stringMember(answer, "skip_reason");
        frame.limitedBy = stringMember(answer, "limited_by");
        frame.drawnWith = stringMember(answer, "drawn_with");
        if (const JsonValue* oracle = answer.find("oracle")) frame.oracle = shadingOracleFromJson(*oracle);
        if (const JsonValue* context = answer.find("context"); context && context->isObject())
            frame.context = {stringMember(*context, "gl_version"), stringMember(*context, "glsl_version"),
                             stringMember(*context, "renderer"), stringMember(*context, "api")};
        if (frame.rendered) {
            std::string error;
            PngTexts texts;
            if (!readPng(prefix + ".png", frame.image, error, &texts)) {
                run.outcome.error = "the child's frame cannot be read back: " + error;
                frame.rendered = false;
            } else {
                frame.provenance = texts.texts;
            }
            Image classes;
            if (frame.rendered && boolMember(answer, "pixel_classes")) {
                if (!readPng(prefix + "-classes.png", classes, error, nullptr) || classes.width != frame.image.width ||
                    classes.height != frame.image.height) {
                    run.outcome.error = "the child's edges and interiors cannot be read back: " + error;
                    frame.rendered = false;
                } else {
                    frame.pixelClasses = pixelClassesOf(classes);
                }
            }
        }
        return run;
    }

    PassesRun passes(const std::vector<std::string>& arguments, const std::vector<bool>& where, int width,
                     int height) override {
        PassesRun run;
        std::string prefix = nextPrefix(), error;
        if (!writePixelMask(prefix + ".where", where, width, height, error)) {
            run.outcome.error = error;
            return run;
        }
        JsonValue answer;
        run.outcome = runKind("passes", prefix, {"--where", prefix + ".where"}, arguments,
                              timeout_ * kPassesTimeoutFactor, answer);
        if (run.outcome.end != RunEnd::Finished || !run.outcome.error.empty()) return run;
        std::ifstream file(prefix + ".bin", std::ios::binary);
        std::stringstream bytes;
        bytes << file.rdbuf();
        if (!decodeSnapshots(bytes.str(), run.snapshots, error)) run.outcome.error = "the child's pass snapshots: " + error;
        return run;
    }

    DriverRun driver(const std::vector<std::string>& arguments) override {
        DriverRun run;
        JsonValue answer;
        run.outcome = runKind("driver", nextPrefix(), {}, arguments, timeout_, answer);
        if (run.outcome.end != RunEnd::Finished || !run.outcome.error.empty()) return run;
        CheckReport& driver = run.driver;
        driver.vendor = stringMember(answer, "vendor");
        driver.renderer = stringMember(answer, "renderer");
        driver.glVersion = stringMember(answer, "version");
        driver.glslVersion = stringMember(answer, "glsl_version");
        driver.api = stringMember(answer, "api");
        if (const JsonValue* caps = answer.find("caps"); caps && caps->isArray())
            for (const JsonValue& row : caps->items)
                driver.caps.push_back({stringMember(row, "feature"), boolMember(row, "available"), boolMember(row, "used"),
                                       stringMember(row, "reason"), stringMember(row, "limited_by")});
        if (const JsonValue* workarounds = answer.find("workarounds"); workarounds && workarounds->isArray())
            for (const JsonValue& row : workarounds->items)
                driver.workarounds.push_back({stringMember(row, "name"), stringMember(row, "why")});
        return run;
    }

    std::string isolation() const override { return "child processes"; }

private:
    std::string nextPrefix() { return scratch_ + "/" + std::to_string(++serial_); }  // any thread

    // Runs one child and reads its answer (PREFIX.json) into `answer`.
    RunOutcome runKind(const std::string& kind, const std::string& prefix, const std::vector<std::string>& extra,
                       const std::vector<std::string>& arguments, double limit, JsonValue& answer) {
        std::vector<std::string> command = {"oasis", "check", "--child", kind, "--child-out", prefix};
        command.insert(command.end(), extra.begin(), extra.end());
        command.push_back("--");
        command.insert(command.end(), arguments.begin(), arguments.end());
        std::vector<std::string> environment;
        for (char** entry = environ; *entry; ++entry) environment.push_back(*entry);
        RunOutcome outcome;
        ChildResult child;
        const auto start = std::chrono::steady_clock::now();
        try {
            child = runChild(command, environment, limit);
        } catch (const std::exception& error) {
            outcome.end = RunEnd::Crashed;
            outcome.detail = error.what();
            return outcome;
        }
        outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        outcome.tail = lastLines(child.output, 12);
        char text[160];
        if (child.timedOut) {
            std::snprintf(text, sizeof(text), "still running after %g s (--case-timeout): its process group was killed",
                          limit);
            outcome.end = RunEnd::TimedOut;
            outcome.detail = text + whereItDied(child.output);
            return outcome;
        }
        if (WIFSIGNALED(child.status)) {
            std::snprintf(text, sizeof(text), "killed by signal %d (%s)", WTERMSIG(child.status), strsignal(WTERMSIG(child.status)));
            outcome.end = RunEnd::Crashed;
            outcome.detail = text + whereItDied(child.output);
            return outcome;
        }
        std::ifstream file(prefix + ".json", std::ios::binary);
        std::stringstream bytes;
        bytes << file.rdbuf();
        std::string error;
        if (!file || !parseJson(bytes.str(), answer, error) || !answer.isObject()) {
            int code = WIFEXITED(child.status) ? WEXITSTATUS(child.status) : -1;
            std::snprintf(text, sizeof(text), "exited with %d without its answer", code);
            outcome.end = RunEnd::Crashed;
            outcome.detail = text;
            return outcome;
        }
        outcome.error = stringMember(answer, "error");
        return outcome;
    }

    double timeout_;
    std::string scratch_;
    RemovedOnInterrupt removal_;
    std::atomic<int> serial_{0};
};

}  // namespace

std::unique_ptr<CaseRunner> makeChildRunner(double caseTimeoutSeconds) {
    return std::make_unique<ChildRunner>(caseTimeoutSeconds);
}

int runCheckChild(const Options& options) {
    if (options.check.childOut.empty()) {
        std::fprintf(stderr, "oasis: check --child needs --child-out PREFIX\n");
        return 2;
    }
    reportWhereOnDeath();
    if (options.check.child == "frame") return childFrame(options);
    if (options.check.child == "passes") return childPasses(options);
    return childDriver(options);
}

}  // namespace oasis
