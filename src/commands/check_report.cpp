// report.json of `oasis check` (commands/check_report.h; the schema is docs/check.md).
#include "commands/check_report.h"

#include <algorithm>
#include <cstdio>

#include "commands/bench_report.h"

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

std::string caseJson(const CaseResult& c) {
    std::string divergence = "null";
    if (c.firstDivergence)
        divergence = "{\"pass\": " + jsonString(c.firstDivergence->pass) + ", \"target\": " +
                     jsonString(c.firstDivergence->target) + ", \"pixels\": " + std::to_string(c.firstDivergence->pixels) + "}";
    bool judged = c.referenceCompared;
    std::string json = "{\"name\": " + jsonString(c.name) + ", \"options\": " + stringList(c.options) +
                       ", \"verdict\": " + jsonString(verdictName(c.verdict)) + ", \"reason\": " + jsonString(c.reason);
    json += ", \"psnr_db\": " + (judged ? number(c.psnrDb) : "null");
    json += ", \"max_abs\": " + (judged ? std::to_string(c.maxAbs) : "null");
    json += ", \"pixels_over\": " + (judged ? std::to_string(c.pixelsOver) : "null");
    json += ", \"reference_rule\": " + jsonString(c.referenceRule);
    json += ", \"main_path\": ";
    json += c.mainPathCompared ? "{\"rule\": " + jsonString(c.mainPathRule) + ", \"psnr_db\": " + number(c.mainPathPsnrDb) +
                                     ", \"max_abs\": " + std::to_string(c.mainPathMaxAbs) +
                                     ", \"pixels_over\": " + std::to_string(c.mainPathPixelsOver) + "}"
                               : std::string("null");
    json += ", \"first_divergence\": " + divergence + ", \"seconds\": " + number(c.seconds, "%.3f") + "}";
    return json;
}

std::string capabilityJson(const CapabilityRow& row) {
    return "{\"feature\": " + jsonString(row.feature) + ", \"available\": " + (row.available ? "true" : "false") +
           ", \"used\": " + (row.used ? "true" : "false") + ", \"reason\": " + jsonString(row.reason) +
           ", \"limited_by\": " + (row.limitedBy.empty() ? std::string("null") : jsonString(row.limitedBy)) + "}";
}

int count(const CheckReport& report, Verdict verdict) {
    return int(std::count_if(report.cases.begin(), report.cases.end(),
                             [&](const CaseResult& c) { return c.verdict == verdict; }));
}

}  // namespace

const char* verdictName(Verdict verdict) {
    switch (verdict) {
        case Verdict::Pass: return "pass";
        case Verdict::Fail: return "fail";
        case Verdict::Skip: return "skip";
    }
    return "skip";
}

int CheckReport::passed() const { return count(*this, Verdict::Pass); }
int CheckReport::failed() const { return count(*this, Verdict::Fail); }
int CheckReport::skipped() const { return count(*this, Verdict::Skip); }

std::string checkReportJson(const CheckReport& report) {
    std::string json = "{\"schema\": \"oasis-check/1\", \"summary\": {\"pass\": " + std::to_string(report.passed()) +
                       ", \"fail\": " + std::to_string(report.failed()) + ", \"skip\": " + std::to_string(report.skipped()) +
                       ", \"cases\": " + std::to_string(report.cases.size()) + ", \"quick\": " +
                       (report.quick ? "true" : "false") + ", \"seconds\": " + number(report.seconds, "%.1f") + "}";
    json += ", \"oasis\": {\"version\": " + jsonString(report.oasisVersion) + ", \"commit\": " + jsonString(report.oasisCommit) + "}";
    json += ", \"driver\": {\"vendor\": " + jsonString(report.vendor) + ", \"renderer\": " + jsonString(report.renderer) +
            ", \"version\": " + jsonString(report.glVersion) + ", \"glsl_version\": " + jsonString(report.glslVersion) +
            ", \"api\": " + jsonString(report.api) + "}";
    json += ", \"caps\": [";
    for (size_t i = 0; i < report.caps.size(); ++i) json += (i ? ", " : "") + capabilityJson(report.caps[i]);
    json += "], \"cases\": [";
    for (size_t i = 0; i < report.cases.size(); ++i) json += (i ? ",\n  " : "\n  ") + caseJson(report.cases[i]);
    return json + "]}\n";
}

}  // namespace oasis
