// `oasis check`'s result as data: the driver, its capabilities, and every case with its verdict,
// numbers and first diverging pass. Written as oasis-check/report.json (check_report.cpp, schema
// in docs/check.md) and report.html (check_html.cpp), read back by `oasis check --diff`.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "check/shading_oracle.h"
#include "render/image.h"

namespace oasis {

// Where a failing case first differs from its reference path, pass by pass.
struct FirstDivergence {
    std::string pass;    // "LightVolumePass"
    std::string target;  // "Radiance"
    long pixels = 0;     // pixels of that target above the tolerance's level
};

// What the case's renderer saw: the context's versions and renderer, the API asked for.
struct CaseContext {
    std::string glVersion, glslVersion, renderer, api;  // api: "OpenGL" or "OpenGL ES"
};

// A case's verdict. Pass, Fail and Skip are judged from its frames; Crash and Timeout say how its
// child process ended; Flake, ExpectedFail and UnexpectedPass come from --retries and
// --expectations (deqp-runner's results). Only Fail, Crash, Timeout and UnexpectedPass make the
// check's exit status 1.
enum class Verdict { Pass, Fail, Skip, Crash, Timeout, Flake, ExpectedFail, UnexpectedPass };
const char* verdictName(Verdict verdict);  // "pass", ..., "expected-fail", "unexpected-pass"
bool unexpected(Verdict verdict);
const std::vector<Verdict>& allVerdicts();

// One frame judged against another by a rule (check/check_judge.h's Judgement), as the report keeps it.
struct FrameComparison {
    bool compared = false;
    double psnrDb = 0.0;
    int maxAbs = 0;
    long pixelsOver = 0;      // pixels whose largest channel difference exceeds the rule's level
    double meanSigned = 0.0;  // levels: the frame's mean of one minus the other (check_judge.h)
};

struct CaseResult {
    std::string name;                  // "deferred-compact-ubo-night", stable across drivers
    std::vector<std::string> options;  // the command-line arguments that reproduce it (`oasis render ...`)
    Verdict verdict = Verdict::Skip;
    std::string reason;  // why it failed or was skipped (whose limit), or what it was judged against
    // Against the reference frame (the repository's llvmpipe frame of the same options): the numbers
    // and the rule applied; against the driver's own main path: the same, where it was compared.
    std::string referenceRule, mainPathRule;
    FrameComparison againstReference;  // compared where a reference frame was found
    FrameComparison againstMainPath;
    // The main path against the reference frame (the third comparison: it decides the blame).
    FrameComparison mainPathAgainstReference;
    bool mainPathMatchesReference = false;
    // The case against the reference frame over its interior pixels (check/pixel_classes.h), where
    // its child split them (a shaded case): judged by cross-driver-interior where another driver
    // drew the reference, measured and reported on the reference's own driver too.
    bool interiorCompared = false;
    long interiorPixels = 0;
    int interiorMaxAbs = 0;
    long interiorPixelsOver = 0;
    int interiorLevel = 0;
    double interiorMeanSigned = 0.0;
    bool interiorPass = false;
    std::vector<uint8_t> pixelClasses;  // for the report's pictures (not in the JSON)
    std::optional<FirstDivergence> firstDivergence;
    ShadingOracle oracle;  // a shaded case's: its radiance against the CPU's shading of its inputs
    // The case's own time: its frame's child (rendered ahead by prefetch or now), its re-runs, its
    // pass-by-pass search and its judging; a main path rendered ahead for several cases is no one's.
    double seconds = 0.0;
    // Who is to blame when it did not pass: "this path", "the main path", "the driver against the
    // reference", or "" (passed, skipped).
    std::string blame;
    Verdict observed = Verdict::Skip;  // what the last run gave, before --expectations and re-runs
    std::string expectation;           // the --expectations line that matched it, or ""
    int runs = 0;                      // how often it ran (1 + the re-runs of --retries)
    CaseContext context;               // what its renderer saw
    std::string reproduce;             // the `oasis render` command line that draws its frame
    std::string childTail;             // a crash's or timeout's last lines of output
    std::string ended;                 // a crash's or timeout's end: "killed by signal 6 (Aborted) in PlantAtlas"
    // Kept for the HTML report (not in the JSON): the case's frame, its reference, its main path's
    // frame, and the error mask with the name of the frame it was computed against.
    Image result, reference, mainPathImage, errorMask;
    std::string maskAgainst;  // "the reference frame" or "the main path"
};

struct CapabilityRow {
    std::string feature;  // "ssbo-light-list"
    bool available = false;
    bool used = false;
    std::string reason;    // why used or not
    std::string limitedBy; // "" (used), "driver", "forced tier" or "not asked for" (gl::limitedBy)
};

struct CheckReport {
    std::string oasisVersion, oasisCommit;
    std::string vendor, renderer, glVersion, glslVersion, api;  // the driver's strings
    std::vector<CapabilityRow> caps;
    // The driver workarounds in effect for the cases (gl/driver_workarounds.h): the applied rows'
    // names with why, as the driver's report measured them.
    std::vector<std::pair<std::string, std::string>> workarounds;
    std::vector<CaseResult> cases;
    bool quick = false;
    double seconds = 0.0;
    std::string isolation;  // how the cases ran: "child processes", or the page itself
    std::vector<std::string> notes;  // what the run itself met (a driver report that crashed)
    std::string referenceDir, referenceHash;  // the reference set used, and its content's hash
    std::string baselineDir;  // --baseline: this driver's frames, judged identical
    // The profile proposed where cases crashed or failed (check/check_profile.h).
    bool profileNeeded = false, profileFound = false;
    std::vector<std::string> profileFallbacks;
    std::string profileWhy;
    int profileFramesTried = 0;
    std::string selection;    // --case / --shard as given, "" for every case of the set
    std::string expectations;  // the --expectations file, or ""
    int retries = 0;
    double caseTimeoutSeconds = 0.0;
    int count(Verdict verdict) const;
    int passed() const;
    int failed() const;  // Fail, Crash, Timeout and UnexpectedPass: the unexpected results
    int skipped() const;
};

// report.json's text (schema: docs/check.md).
std::string checkReportJson(const CheckReport& report);
// The JUnit XML of --junit: one testcase per case, a failure with its message and reproduce line.
std::string checkReportJunit(const CheckReport& report);

}  // namespace oasis
