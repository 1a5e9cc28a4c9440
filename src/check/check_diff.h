// `oasis check --diff A.json B.json`: two runs of `oasis check` (two drivers, or one driver before
// and after a change) compared case by case, the way piglit's summaries compare runs: what
// regressed, what was fixed, what is newly skipped, whose numbers moved, which cases came or went.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace oasis {

// One case as --diff reads it back from report.json.
struct CheckedCase {
    std::string name, verdict, reason;  // verdict: "pass", "fail" or "skip"
    bool hasNumbers = false;            // psnr_db, max_abs and pixels_over all numbers (not null)
    double psnrDb = 0.0;
    long maxAbs = 0, pixelsOver = 0;
    std::string firstDivergence;  // "LightVolumePass/Radiance, 1204 pixels", or "" where null
};

// What --diff reads of one report.json.
struct CheckRun {
    std::string path;
    std::string vendor, renderer, glVersion, api;  // the driver's strings
    std::string oasisVersion, oasisCommit;
    std::vector<CheckedCase> cases;  // in the file's order
    bool quick = false;               // summary.quick: a --quick run's subset
    int count(const std::string& verdict) const;
};

// report.json's size limit: a full check's report is tens of kilobytes.
constexpr size_t kCheckReportMaxBytes = size_t(64) << 20;

// Reads report.json's text into `run`. False with `error` saying what is wrong: not JSON (with the
// byte), not an oasis check report (no "schema": "oasis-check/N", no "cases" list), a case without
// a name or with an unknown verdict, numbers that are neither numbers nor null, a name twice.
bool parseCheckRun(const std::string& json, CheckRun& run, std::string& error);
// The same from the file `path` (read with io/file_input.h's checks, at most
// kCheckReportMaxBytes); `error` names the file.
bool readCheckRun(const std::string& path, CheckRun& run, std::string& error);

// One case whose outcome or numbers changed from A to B.
struct CaseChange {
    std::string name;
    CheckedCase before, after;
};

// A PSNR that moves by more than this is a change worth a line (max abs and pixels over: any change).
constexpr double kPsnrChangeDb = 0.5;

struct CheckDiff {
    std::vector<CaseChange> regressions;      // pass in A, fail in B
    std::vector<CaseChange> fixes;            // fail in A, pass in B
    std::vector<CaseChange> newSkips;         // pass or fail in A, skip in B
    std::vector<CaseChange> noLongerSkipped;  // skip in A, pass or fail in B
    std::vector<CaseChange> changedNumbers;   // the same verdict (pass or fail), the numbers moved
    std::vector<CheckedCase> newCases;        // in B only
    std::vector<CheckedCase> removedCases;    // in A only
    // 1 when a case regressed, else 0 (--diff's exit status).
    int exitCode() const { return regressions.empty() ? 0 : 1; }
};

// A's cases matched with B's by name; sections in B's order (removed cases in A's).
CheckDiff diffCheckRuns(const CheckRun& a, const CheckRun& b);

// The text --diff prints: both drivers and their counts, then each section with its cases.
std::string checkDiffText(const CheckRun& a, const CheckRun& b, const CheckDiff& diff);

// `oasis check --diff A B` whole: prints the diff on stdout and returns 1 if a case regressed, 0 if
// none did; 2 with "oasis: check --diff: ..." on stderr if either file cannot be read or is not a
// check report.
int runCheckDiff(const std::string& pathA, const std::string& pathB);

}  // namespace oasis
