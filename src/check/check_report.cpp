// report.json of `oasis check` (check/check_report.h; the schema is docs/check.md).
#include "check/check_report.h"

#include <algorithm>
#include <cstdio>

#include "io/json_text.h"
#include "check/oracle_report.h"

namespace oasis {
namespace {

std::string number(double value, const char* format = "%.4f") {
    char text[64];
    std::snprintf(text, sizeof(text), format, value);
    return text;
}

std::string stringList(const std::vector<std::string>& items) {
    std::string json = "[";
    for (size_t i = 0; i < items.size(); ++i) json += (i ? ", " : "") + jsonString(items[i]);
    return json + "]";
}

// "psnr_db", "max_abs", "pixels_over", "mean_signed": null each where nothing was compared.
std::string comparisonMembers(const FrameComparison& c) {
    return "\"psnr_db\": " + (c.compared ? number(c.psnrDb) : "null") + ", \"max_abs\": " +
           (c.compared ? std::to_string(c.maxAbs) : "null") + ", \"pixels_over\": " +
           (c.compared ? std::to_string(c.pixelsOver) : "null") + ", \"mean_signed\": " +
           (c.compared ? number(c.meanSigned, "%.4f") : "null");
}

std::string caseJson(const CaseResult& c) {
    std::string divergence = "null";
    if (c.firstDivergence)
        divergence = "{\"pass\": " + jsonString(c.firstDivergence->pass) + ", \"target\": " +
                     jsonString(c.firstDivergence->target) + ", \"pixels\": " + std::to_string(c.firstDivergence->pixels) + "}";
    std::string json = "{\"name\": " + jsonString(c.name) + ", \"options\": " + stringList(c.options) +
                       ", \"verdict\": " + jsonString(verdictName(c.verdict)) + ", \"reason\": " + jsonString(c.reason);
    json += ", " + comparisonMembers(c.againstReference);
    json += ", \"reference_rule\": " + jsonString(c.referenceRule);
    json += ", \"main_path\": ";
    json += c.againstMainPath.compared
                ? "{\"rule\": " + jsonString(c.mainPathRule) + ", " + comparisonMembers(c.againstMainPath) + "}"
                : std::string("null");
    json += ", \"main_path_against_reference\": ";
    json += c.mainPathAgainstReference.compared ? "{" + comparisonMembers(c.mainPathAgainstReference) + ", \"pass\": " +
                                                      (c.mainPathMatchesReference ? "true" : "false") + "}"
                                                : std::string("null");
    json += ", \"interior\": ";
    json += c.interiorCompared ? "{\"pixels\": " + std::to_string(c.interiorPixels) + ", \"max_abs\": " +
                                     std::to_string(c.interiorMaxAbs) + ", \"over\": " + std::to_string(c.interiorPixelsOver) +
                                     ", \"level\": " + std::to_string(c.interiorLevel) + ", \"mean_signed\": " +
                                     number(c.interiorMeanSigned, "%.4f") + ", \"pass\": " +
                                     (c.interiorPass ? "true" : "false") + "}"
                               : std::string("null");
    json += ", \"blame\": " + (c.blame.empty() ? std::string("null") : jsonString(c.blame));
    json += ", \"observed\": " + jsonString(verdictName(c.observed)) + ", \"expectation\": " +
            (c.expectation.empty() ? std::string("null") : jsonString(c.expectation)) + ", \"runs\": " + std::to_string(c.runs);
    json += ", \"context\": {\"gl_version\": " + jsonString(c.context.glVersion) + ", \"glsl_version\": " +
            jsonString(c.context.glslVersion) + ", \"renderer\": " + jsonString(c.context.renderer) + ", \"api\": " +
            jsonString(c.context.api) + "}";
    json += ", \"reproduce\": " + jsonString(c.reproduce);
    json += ", \"child_output\": " + (c.childTail.empty() ? std::string("null") : jsonString(c.childTail));
    json += ", \"oracle\": " + shadingOracleJson(c.oracle);
    json += ", \"first_divergence\": " + divergence + ", \"seconds\": " + number(c.seconds, "%.3f") + "}";
    return json;
}

std::string capabilityJson(const CapabilityRow& row) {
    return "{\"feature\": " + jsonString(row.feature) + ", \"available\": " + (row.available ? "true" : "false") +
           ", \"used\": " + (row.used ? "true" : "false") + ", \"reason\": " + jsonString(row.reason) +
           ", \"limited_by\": " + (row.limitedBy.empty() ? std::string("null") : jsonString(row.limitedBy)) + "}";
}

// The summary's key of a verdict ("expected-fail" -> "expected_fail").
std::string summaryKey(Verdict verdict) {
    std::string key = verdictName(verdict);
    for (char& c : key)
        if (c == '-') c = '_';
    return key;
}

std::string xmlEscape(const std::string& text) {
    std::string out;
    for (unsigned char c : text) {
        if (c == '&') out += "&amp;";
        else if (c == '<') out += "&lt;";
        else if (c == '>') out += "&gt;";
        else if (c == '"') out += "&quot;";
        else if (c < 0x20 && c != '\n' && c != '\t') out += "?";  // XML 1.0 has no other control characters
        else out += char(c);
    }
    return out;
}

}  // namespace

const char* verdictName(Verdict verdict) {
    switch (verdict) {
        case Verdict::Pass: return "pass";
        case Verdict::Fail: return "fail";
        case Verdict::Skip: return "skip";
        case Verdict::Crash: return "crash";
        case Verdict::Timeout: return "timeout";
        case Verdict::Flake: return "flake";
        case Verdict::ExpectedFail: return "expected-fail";
        case Verdict::UnexpectedPass: return "unexpected-pass";
    }
    return "skip";
}

bool unexpected(Verdict verdict) {
    return verdict == Verdict::Fail || verdict == Verdict::Crash || verdict == Verdict::Timeout ||
           verdict == Verdict::UnexpectedPass;
}

const std::vector<Verdict>& allVerdicts() {
    static const std::vector<Verdict> verdicts = {Verdict::Pass,  Verdict::Fail,         Verdict::Skip,
                                                  Verdict::Crash, Verdict::Timeout,      Verdict::Flake,
                                                  Verdict::ExpectedFail, Verdict::UnexpectedPass};
    return verdicts;
}

int CheckReport::count(Verdict verdict) const {
    return int(std::count_if(cases.begin(), cases.end(), [&](const CaseResult& c) { return c.verdict == verdict; }));
}
int CheckReport::passed() const { return count(Verdict::Pass); }
int CheckReport::failed() const {
    return int(std::count_if(cases.begin(), cases.end(), [](const CaseResult& c) { return unexpected(c.verdict); }));
}
int CheckReport::skipped() const { return count(Verdict::Skip); }

std::string checkReportJunit(const CheckReport& report) {
    std::string xml = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites>\n<testsuite name=\"oasis-check\" tests=\"" +
                      std::to_string(report.cases.size()) + "\" failures=\"" + std::to_string(report.failed()) +
                      "\" skipped=\"" + std::to_string(report.skipped()) + "\" time=\"" + number(report.seconds, "%.3f") +
                      "\">\n  <properties><property name=\"renderer\" value=\"" + xmlEscape(report.renderer) +
                      "\"/><property name=\"gl_version\" value=\"" + xmlEscape(report.glVersion) + "\"/></properties>\n";
    for (const CaseResult& c : report.cases) {
        xml += "  <testcase classname=\"oasis.check\" name=\"" + xmlEscape(c.name) + "\" time=\"" +
               number(c.seconds, "%.3f") + "\">";
        std::string message = std::string(verdictName(c.verdict)) + (c.blame.empty() ? "" : " (blame: " + c.blame + ")") +
                              ": " + c.reason;
        if (unexpected(c.verdict))
            xml += "\n    <failure type=\"" + std::string(verdictName(c.verdict)) + "\" message=\"" + xmlEscape(message) +
                   "\">" + xmlEscape(message + "\nreproduce: " + c.reproduce +
                                      (c.childTail.empty() ? "" : "\nlast output:\n" + c.childTail)) + "</failure>\n  ";
        else if (c.verdict == Verdict::Skip)
            xml += "<skipped message=\"" + xmlEscape(c.reason) + "\"/>";
        else if (c.verdict != Verdict::Pass)
            xml += "<system-out>" + xmlEscape(message) + "</system-out>";
        xml += "</testcase>\n";
    }
    return xml + "</testsuite>\n</testsuites>\n";
}

std::string checkReportJson(const CheckReport& report) {
    std::string json = "{\"schema\": \"oasis-check/1\", \"summary\": {";
    for (Verdict verdict : allVerdicts()) json += "\"" + summaryKey(verdict) + "\": " + std::to_string(report.count(verdict)) + ", ";
    json += "\"unexpected\": " + std::to_string(report.failed()) + ", \"cases\": " + std::to_string(report.cases.size()) +
            ", \"quick\": " + (report.quick ? "true" : "false") + ", \"seconds\": " + number(report.seconds, "%.1f") + "}";
    json += ", \"run\": {\"isolation\": " + jsonString(report.isolation) + ", \"selection\": " + jsonString(report.selection) +
            ", \"retries\": " + std::to_string(report.retries) + ", \"case_timeout_s\": " +
            number(report.caseTimeoutSeconds, "%.1f") + ", \"expectations\": " +
            (report.expectations.empty() ? std::string("null") : jsonString(report.expectations)) +
            ", \"notes\": " + stringList(report.notes) + "}";
    json += ", \"proposed_workarounds\": ";
    json += report.profileNeeded ? "{\"found\": " + std::string(report.profileFound ? "true" : "false") +
                                       ", \"fallbacks\": " + stringList(report.profileFallbacks) +
                                       ", \"file\": " + (report.profileFound ? jsonString("workarounds") : std::string("null")) +
                                       ", \"frames_tried\": " + std::to_string(report.profileFramesTried) +
                                       ", \"why\": " + jsonString(report.profileWhy) + "}"
                                 : std::string("null");
    json += ", \"references\": {\"dir\": " + jsonString(report.referenceDir) + ", \"hash\": " +
            jsonString(report.referenceHash) + ", \"baseline\": " +
            (report.baselineDir.empty() ? std::string("null") : jsonString(report.baselineDir)) + "}";
    json += ", \"oasis\": {\"version\": " + jsonString(report.oasisVersion) + ", \"commit\": " + jsonString(report.oasisCommit) + "}";
    json += ", \"driver\": {\"vendor\": " + jsonString(report.vendor) + ", \"renderer\": " + jsonString(report.renderer) +
            ", \"version\": " + jsonString(report.glVersion) + ", \"glsl_version\": " + jsonString(report.glslVersion) +
            ", \"api\": " + jsonString(report.api) + ", \"workarounds\": [";
    for (size_t i = 0; i < report.workarounds.size(); ++i)
        json += std::string(i ? ", " : "") + "{\"name\": " + jsonString(report.workarounds[i].first) + ", \"applied\": true, \"why\": " +
                jsonString(report.workarounds[i].second) + "}";
    json += "]}";
    json += ", \"caps\": [";
    for (size_t i = 0; i < report.caps.size(); ++i) json += (i ? ", " : "") + capabilityJson(report.caps[i]);
    json += "], \"cases\": [";
    for (size_t i = 0; i < report.cases.size(); ++i) json += (i ? ",\n  " : "\n  ") + caseJson(report.cases[i]);
    return json + "]}\n";
}

}  // namespace oasis
