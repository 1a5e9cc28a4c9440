// Where `oasis check` renders: natively every case, main path, pass-by-pass search and the driver's
// own report in a child process of its own (check/check_child.cpp), so that a crash, a hang or a
// setting one case makes (the gl33 tier's version override) stays with that case; in the page, where
// there are no processes, in the page itself (a tab that dies is the verdict).
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "cli/options.h"
#include "check/check_render.h"
#include "check/check_report.h"

namespace oasis {

// How a child ended.
enum class RunEnd {
    Finished,  // it said what it did (rendered, skipped, or the error of a case that cannot render)
    Crashed,   // killed by a signal, or exited without a word
    TimedOut,  // still running at the limit: its process group was killed
};
struct RunOutcome {
    RunEnd end = RunEnd::Finished;
    std::string detail;  // Crashed: "killed by signal 6 (Aborted)"; TimedOut: "still running after 60 s"
    std::string tail;    // its last lines of output (control bytes escaped), for the report
    std::string error;   // Finished with an error that is not a limit (a shader that does not build)
    double seconds = 0.0;  // how long it ran, however it ended (the wall clock, from start to answer)
};

struct FrameRun {
    RunOutcome outcome;
    CaseFrame frame;  // rendered or skipped, when outcome.end == Finished and no error
};

struct PassesRun {
    RunOutcome outcome;
    std::vector<PassSnapshot> snapshots;  // the targets' values at the pixels of `where` only
};

struct DriverRun {
    RunOutcome outcome;
    CheckReport driver;  // vendor, renderer, versions, api and caps filled; nothing else
};

class CaseRunner {
public:
    virtual ~CaseRunner() = default;
    // The frame of `oasis render ARGUMENTS --legend off` (check/check_render.h).
    virtual FrameRun frame(const std::vector<std::string>& arguments, bool gpuPlants) = 0;
    // The frame pass by pass; `where` (bottom row first) says which pixels' values are kept.
    virtual PassesRun passes(const std::vector<std::string>& arguments, const std::vector<bool>& where, int width,
                             int height) = 0;
    // The driver's strings and capabilities, on the context `oasis caps ARGUMENTS` would make.
    virtual DriverRun driver(const std::vector<std::string>& arguments) = 0;
    // "child processes" or "the page itself": how the report says the cases ran.
    virtual std::string isolation() const = 0;
};

// A child process per call, each limited to `caseTimeoutSeconds` (the pass-by-pass search to
// kPassesTimeoutFactor times that); the scratch files go to a directory removed with the runner.
// Not in the web build.
constexpr double kPassesTimeoutFactor = 8.0;
std::unique_ptr<CaseRunner> makeChildRunner(double caseTimeoutSeconds);
// Everything in this process (the page's check).
std::unique_ptr<CaseRunner> makeInProcessRunner();

// The child's side: `oasis check --child frame|passes|driver --child-out PREFIX [--where FILE]
// [--gpu-plants] -- ARGUMENTS` renders and writes PREFIX.json (and .png or .bin). Exit 0 when it
// wrote its answer, 1 when even that failed, 2 for arguments it cannot read.
int runCheckChild(const Options& options);

}  // namespace oasis
