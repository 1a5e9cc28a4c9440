// One check case from its frames to its verdict: rendered through a CaseRunner, judged three ways
// (the case against the reference frame, its main path against the reference, the case against
// its main path), and against this driver's baseline where one is given; a failure re-run
// (--retries), then read through --expectations; and the blame: "this path", "the main path" or
// "the driver against the reference" (settled across cases once all have run).
#pragma once
#include <map>
#include <string>
#include <vector>

#include "cli/options.h"
#include "check/check_cases.h"
#include "check/check_expectations.h"
#include "check/check_judge.h"
#include "check/check_references.h"
#include "check/check_runner.h"

namespace oasis {

// The frame size every case renders at.
constexpr const char* kCheckSize = "256x144";

// The `oasis render` arguments of a case (or of its main path) as the check renders it: the
// frame size first, and --api gles where the check runs on OpenGL ES.
std::vector<std::string> checkCaseArguments(const CheckCase& c, const Options& options, bool mainPath = false);

// The rule a case is held to against its own main path on the same driver: identical, except where
// a fallback's rounding was measured to differ (tiled lights) or its geometry (the ES 3.0 tier).
const ImageRule& mainPathRule(const CheckCase& c);

class CaseJudge {
public:
    CaseJudge(const Options& options, std::string referenceDir, CaseRunner& runner, std::vector<Expectation> expectations)
        : options_(options), referenceDir_(std::move(referenceDir)), runner_(runner), expectations_(std::move(expectations)) {}

    // Judges every case against DIR's frames too (identical), from now on.
    bool useBaseline(const std::string& dir, std::string& error);
    std::string baselineNote() const;  // "; baseline DIR recorded by ... " or ""
    void setRenderer(const std::string& renderer) { renderer_ = renderer; }

    // Renders every case's frame and every main path among `cases` ahead, `jobs` children at a
    // time (each still a process of its own); run() then judges from what is ready.
    void prefetch(const std::vector<CheckCase>& cases, int jobs);

    // Runs and judges one case. `keptFrame`, if given, gets its frame (a baseline being recorded).
    CaseResult run(const CheckCase& c, CaseFrame* keptFrame);

    // Whether the frame of ARGUMENTS renders (or is skipped as a path not taken) without a crash,
    // a timeout or an error, and matches the case's reference frame by the cross-driver rule:
    // what a proposed profile must give (check/check_profile.h). `why` says what it gave.
    bool frameHolds(const CheckCase& c, const std::vector<std::string>& arguments, std::string& why);

    // "the main path" is the blame only where some fallback matched the reference while its main
    // path did not: a driver whose every path misses the reference is "the driver against the
    // reference".
    void settleBlame(std::vector<CaseResult>& cases) const;

private:
    Verdict attempt(const CheckCase& c, CaseResult& result, CaseFrame* keptFrame);
    const FrameRun& mainPath(const CheckCase& c, bool again);
    void findDivergence(const CheckCase& c, CaseResult& result);
    void applyExpectation(CaseResult& result, const std::string& expected) const;

    const Options& options_;
    std::string referenceDir_;
    CaseRunner& runner_;
    std::vector<Expectation> expectations_;
    std::string renderer_;
    std::string baselineDir_;
    BaselineManifest baseline_;
    std::map<std::vector<std::string>, FrameRun> mainPaths_;  // by arguments: shared between cases
    std::map<std::vector<std::string>, FrameRun> prefetched_;  // cases' first frames, by arguments
    // The seconds of the prefetched children the case being judged took its frames from: they ran
    // before run() began, and are the case's own time.
    double prefetchedSeconds_ = 0.0;
};

}  // namespace oasis
