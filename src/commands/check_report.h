// `oasis check`'s result as data: the driver, its capabilities, and every case with its verdict,
// numbers and first diverging pass. Written as oasis-check/report.json (check_report.cpp, schema
// in docs/check.md) and report.html (check_html.cpp), read back by `oasis check --diff`.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "render/image.h"

namespace oasis {

// Where a failing case first differs from its reference path, pass by pass.
struct FirstDivergence {
    std::string pass;    // "LightVolumePass"
    std::string target;  // "Radiance"
    long pixels = 0;     // pixels of that target above the tolerance's level
};

enum class Verdict { Pass, Fail, Skip };
const char* verdictName(Verdict verdict);  // "pass", "fail", "skip"

struct CaseResult {
    std::string name;                  // "deferred-compact-ubo-night", stable across drivers
    std::vector<std::string> options;  // the command-line arguments that reproduce it (`oasis render ...`)
    Verdict verdict = Verdict::Skip;
    std::string reason;  // why it failed or was skipped (whose limit), or what it was judged against
    // Against the reference frame (the repository's llvmpipe frame of the same options): the numbers
    // and the rule applied; against the driver's own main path: the same, where it was compared.
    std::string referenceRule, mainPathRule;
    bool referenceCompared = false;  // a reference frame was found and compared
    double psnrDb = 0.0;  // against the reference frame
    int maxAbs = 0;
    long pixelsOver = 0;  // pixels whose largest channel difference exceeds the rule's level
    double mainPathPsnrDb = 0.0;
    int mainPathMaxAbs = 0;
    long mainPathPixelsOver = 0;
    bool mainPathCompared = false;
    std::optional<FirstDivergence> firstDivergence;
    double seconds = 0.0;
    // Kept for the HTML report (not in the JSON): the case's frame, its reference and the error mask.
    Image result, reference, errorMask;
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
    std::vector<CaseResult> cases;
    bool quick = false;
    double seconds = 0.0;
    int passed() const;
    int failed() const;
    int skipped() const;
};

// report.json's text (schema: docs/check.md).
std::string checkReportJson(const CheckReport& report);

}  // namespace oasis
