// The shading oracle's result as JSON and as a line for people (check/oracle_report.h).
#include "check/oracle_report.h"

#include <cstdio>

#include "io/json_text.h"

namespace oasis {
namespace {

std::string scientific(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3e", value);
    return text;
}

std::string textMember(const JsonValue& object, const char* key) {
    const JsonValue* value = object.find(key);
    return value && value->isString() ? value->text : std::string();
}

double numberMember(const JsonValue& object, const char* key) {
    const JsonValue* value = object.find(key);
    return value && value->isNumber() ? value->number : 0.0;
}

}  // namespace

std::string shadingOracleJson(const ShadingOracle& oracle) {
    if (!oracle.ran) return "null";
    std::string leftOut = "{";
    for (size_t i = 0; i < oracle.leftOut.size(); ++i)
        leftOut += (i ? ", " : "") + jsonString(oracle.leftOut[i].first) + ": " + std::to_string(oracle.leftOut[i].second);
    leftOut += "}";
    std::string json = "{\"pixels_checked\": " + std::to_string(oracle.pixelsChecked) +
                       ", \"pixels_sampled\": " + std::to_string(oracle.pixelsSampled) + ", \"left_out\": " + leftOut +
                       ", \"max_relative_error\": " + scientific(oracle.maxRelativeError) +
                       ", \"bound\": " + scientific(oracle.bound) + ", \"verdict\": " + jsonString(oracle.verdict);
    if (!oracle.differingTerm.empty()) json += ", \"differing_term\": " + jsonString(oracle.differingTerm);
    if (!oracle.detail.empty()) json += ", \"detail\": " + jsonString(oracle.detail);
    return json + ", \"inputs\": " + jsonString(oracle.inputs) + "}";
}

ShadingOracle shadingOracleFromJson(const JsonValue& object) {
    ShadingOracle oracle;
    if (!object.isObject()) return oracle;
    oracle.ran = true;
    oracle.pixelsChecked = int(numberMember(object, "pixels_checked"));
    oracle.pixelsSampled = int(numberMember(object, "pixels_sampled"));
    if (const JsonValue* leftOut = object.find("left_out"); leftOut && leftOut->isObject())
        for (const auto& [kind, count] : leftOut->members) oracle.leftOut.push_back({kind, int(count.number)});
    oracle.maxRelativeError = numberMember(object, "max_relative_error");
    oracle.bound = numberMember(object, "bound");
    oracle.verdict = textMember(object, "verdict");
    oracle.differingTerm = textMember(object, "differing_term");
    oracle.detail = textMember(object, "detail");
    oracle.inputs = textMember(object, "inputs");
    return oracle;
}

std::string shadingOracleLine(const ShadingOracle& oracle) {
    std::string line = oracle.verdict + ", " + std::to_string(oracle.pixelsChecked) + " of " +
                       std::to_string(oracle.pixelsSampled) + " sampled pixels checked, max " +
                       scientific(oracle.maxRelativeError) + " relative per half-float store (bound " +
                       scientific(oracle.bound) + ")";
    if (!oracle.differingTerm.empty()) line += "; differing term: " + oracle.differingTerm;
    if (!oracle.leftOut.empty()) {
        line += "; left out:";
        for (size_t i = 0; i < oracle.leftOut.size(); ++i)
            line += (i ? ", " : " ") + oracle.leftOut[i].first + " " + std::to_string(oracle.leftOut[i].second);
    }
    if (!oracle.detail.empty()) line += "; " + oracle.detail;
    return line;
}

}  // namespace oasis
