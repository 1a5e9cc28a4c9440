// `oasis check --expectations FILE`: what a CI farm already knows about a driver, one line a rule
// as ANGLE's test expectations write them:
//     CASE-GLOB [renderer /REGEX/] = fail|skip|flake|crash|timeout  # reason
// The first rule whose glob matches the case's name (and whose regex, if any, finds the driver's
// renderer string) applies: skip does not run the case; fail, crash and timeout turn that outcome
// into expected-fail and a pass into unexpected-pass; flake turns any failure into flake.
#pragma once
#include <optional>
#include <string>
#include <vector>

namespace oasis {

struct Expectation {
    std::string glob;           // fnmatch(3) pattern over case names
    std::string rendererRegex;  // ECMAScript regex searched in GL_RENDERER, "" = any driver
    std::string result;         // "fail", "skip", "flake", "crash" or "timeout"
    std::string reason;         // the text after '#', trimmed
    int line = 0;               // 1-based, for the report ("FILE:LINE")
};

// Parses the file's text. False with `error` = "line N: WHAT" for a line that is not a rule, a
// comment or blank (an unknown result, a regex that does not compile, text after the result).
bool parseExpectations(const std::string& text, std::vector<Expectation>& rules, std::string& error);

// The first rule for `caseName` on `renderer`, if any.
std::optional<Expectation> findExpectation(const std::vector<Expectation>& rules, const std::string& caseName,
                                           const std::string& renderer);

}  // namespace oasis
