// `oasis check --diff` (check/check_diff.h): read two report.json files, match their cases by
// name, sort each changed case into its section, print the sections.
#include "check/check_diff.h"

#include "check/check_report.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <set>

#include "commands/json_value.h"
#include "io/file_input.h"
#include "render/image.h"
#include "io/printable_text.h"

namespace oasis {
namespace {

bool refuse(std::string& error, const std::string& why) {
    error = why;
    return false;
}

// The most pixels a case can count: a frame of the --size domain's largest side squared.
constexpr double kMaxCasePixels = 32768.0 * 32768.0;

// A member's string, escaped for the terminal (io/printable_text.h: every string --diff prints
// came from a file), or "" where it is absent, null or not a string (the driver's strings are
// informative: a report without them can still be compared).
std::string stringOf(const JsonValue* object, const char* key) {
    const JsonValue* member = object ? object->find(key) : nullptr;
    return member && member->isString() ? printableText(member->text) : "";
}

// A case's string member: absent or null gives "" where `optional`, any other type is an error.
bool caseString(const JsonValue& c, const char* key, bool optional, std::string& value, std::string& error) {
    const JsonValue* member = c.find(key);
    if (member && member->isString()) {
        value = printableText(member->text);
        return true;
    }
    if (optional && (!member || member->isNull())) return true;
    error = std::string("\"") + key + "\" is " + (member ? "not a string" : "missing");
    return false;
}

// A number-or-null member of a case within [lowest, highest] (an integer where `integer`): true
// with `present` false for null or absent; false (an error naming the key and why) for any other
// type or a number out of its range.
bool optionalNumber(const JsonValue& c, const char* key, double lowest, double highest, bool integer, double& value,
                    bool& present, std::string& error) {
    const JsonValue* member = c.find(key);
    present = member && member->isNumber();
    if (member && !member->isNumber() && !member->isNull()) {
        error = std::string("\"") + key + "\" is neither a number nor null";
        return false;
    }
    if (!present) return true;
    value = member->number;
    if (!(value >= lowest && value <= highest) || (integer && value != std::floor(value))) {
        char text[160];
        std::snprintf(text, sizeof text, "\"%s\" is %.17g: out of its range (%s in %.17g..%.17g)", key, value,
                      integer ? "an integer" : "a number", lowest, highest);
        error = text;
        return false;
    }
    return true;
}

// A case's first divergence, or "" where absent or null; `error` for a wrong type or range.
bool divergenceOf(const JsonValue& c, std::string& text, std::string& error) {
    const JsonValue* divergence = c.find("first_divergence");
    if (!divergence || divergence->isNull()) return true;
    if (!divergence->isObject()) return refuse(error, "\"first_divergence\" is neither an object nor null");
    std::string pass, target;
    double pixels = 0;
    bool hasPixels = false;
    if (!caseString(*divergence, "pass", true, pass, error) || !caseString(*divergence, "target", true, target, error) ||
        !optionalNumber(*divergence, "pixels", 0, kMaxCasePixels, true, pixels, hasPixels, error)) {
        error = "\"first_divergence\": " + error;
        return false;
    }
    text = pass + "/" + target + (hasPixels ? ", " + std::to_string(long(pixels)) + " pixels" : "");
    return true;
}

bool isUnexpected(const std::string& verdict) {
    for (Verdict v : allVerdicts())
        if (verdict == verdictName(v)) return unexpected(v);
    return false;
}

bool readCase(const JsonValue& c, CheckedCase& out, std::string& error) {
    if (!c.isObject()) return refuse(error, "is not an object");
    if (!caseString(c, "name", false, out.name, error)) return false;
    if (out.name.empty()) return refuse(error, "has an empty \"name\"");
    if (!caseString(c, "verdict", false, out.verdict, error) || !caseString(c, "reason", true, out.reason, error))
        return false;
    bool known = false;
    for (Verdict verdict : allVerdicts()) known = known || out.verdict == verdictName(verdict);
    if (!known) {
        error = "has verdict \"" + out.verdict + "\" (not pass, fail, skip, crash, timeout, flake, expected-fail or "
                "unexpected-pass)";
        return false;
    }
    double maxAbs = 0, pixelsOver = 0;
    bool hasPsnr = false, hasMaxAbs = false, hasPixelsOver = false;
    // PSNR of 8-bit images: 0 dB (every channel 255 apart) up to the cap for identical ones.
    if (!optionalNumber(c, "psnr_db", 0, kPsnrIdentical, false, out.psnrDb, hasPsnr, error) ||
        !optionalNumber(c, "max_abs", 0, 255, true, maxAbs, hasMaxAbs, error) ||
        !optionalNumber(c, "pixels_over", 0, kMaxCasePixels, true, pixelsOver, hasPixelsOver, error))
        return false;
    out.hasNumbers = hasPsnr && hasMaxAbs && hasPixelsOver;
    out.maxAbs = long(maxAbs);
    out.pixelsOver = long(pixelsOver);
    return divergenceOf(c, out.firstDivergence, error);
}

bool readCases(const JsonValue& cases, CheckRun& run, std::string& error) {
    std::set<std::string> names;
    for (size_t i = 0; i < cases.items.size(); ++i) {
        CheckedCase c;
        std::string why;
        if (!readCase(cases.items[i], c, why)) {
            error = "case " + std::to_string(i + 1) + (c.name.empty() ? "" : " (" + c.name + ")") + " " + why;
            return false;
        }
        if (!names.insert(c.name).second) return refuse(error, "case " + c.name + " appears twice");
        run.cases.push_back(c);
    }
    return true;
}

bool isCheckReport(const JsonValue& root) {
    const JsonValue* schema = root.find("schema");
    return schema && schema->isString() && schema->text.rfind("oasis-check/", 0) == 0;
}

std::string numbersText(const CheckedCase& c) {
    if (!c.hasNumbers) return "no numbers";
    char text[96];
    std::snprintf(text, sizeof(text), "PSNR %.2f dB, max abs %ld, pixels over %ld", c.psnrDb, c.maxAbs, c.pixelsOver);
    return text;
}

// "PSNR 45.10 -> 31.02 dB, max abs 3 -> 40, pixels over 0 -> 1204": the numbers that moved, old -> new.
std::string numberChanges(const CheckedCase& a, const CheckedCase& b) {
    std::string changes;
    auto add = [&](const std::string& part) { changes += (changes.empty() ? "" : ", ") + part; };
    char text[96];
    if (a.psnrDb != b.psnrDb) {
        std::snprintf(text, sizeof(text), "PSNR %.2f -> %.2f dB", a.psnrDb, b.psnrDb);
        add(text);
    }
    if (a.maxAbs != b.maxAbs) add("max abs " + std::to_string(a.maxAbs) + " -> " + std::to_string(b.maxAbs));
    if (a.pixelsOver != b.pixelsOver) add("pixels over " + std::to_string(a.pixelsOver) + " -> " + std::to_string(b.pixelsOver));
    return changes.empty() ? "the same numbers" : changes;
}

bool numbersMoved(const CheckedCase& a, const CheckedCase& b) {
    if (a.hasNumbers != b.hasNumbers) return true;
    if (!a.hasNumbers) return false;
    return std::fabs(a.psnrDb - b.psnrDb) > kPsnrChangeDb || a.maxAbs != b.maxAbs || a.pixelsOver != b.pixelsOver;
}

// One line per changed case: "  NAME: pass -> fail; NUMBERS; first diverges at ...; REASON", the
// numbers old -> new where both runs have them, else B's (a skip has none).
std::string changeLine(const CaseChange& change) {
    const CheckedCase &a = change.before, &b = change.after;
    std::vector<std::string> parts;
    if (a.verdict != b.verdict) parts.push_back(a.verdict + " -> " + b.verdict);
    if (a.hasNumbers && b.hasNumbers) parts.push_back(numberChanges(a, b));
    else if (b.hasNumbers) parts.push_back(numbersText(b));
    if (!b.firstDivergence.empty() && b.verdict == "fail") parts.push_back("first diverges at " + b.firstDivergence);
    if (!b.reason.empty()) parts.push_back(b.reason);
    std::string line = "  " + change.name + ":";
    for (size_t i = 0; i < parts.size(); ++i) line += (i ? "; " : " ") + parts[i];
    return line + "\n";
}

std::string caseLine(const CheckedCase& c) {
    std::string line = "  " + c.name + ": " + c.verdict;
    if (c.hasNumbers) line += "; " + numbersText(c);
    if (!c.reason.empty()) line += "; " + c.reason;
    return line + "\n";
}

std::string section(const std::string& title, const std::vector<CaseChange>& changes) {
    std::string text = title + " (" + std::to_string(changes.size()) + ")\n";
    for (const CaseChange& change : changes) text += changeLine(change);
    return text;
}

std::string section(const std::string& title, const std::vector<CheckedCase>& cases) {
    std::string text = title + " (" + std::to_string(cases.size()) + ")\n";
    for (const CheckedCase& c : cases) text += caseLine(c);
    return text;
}

std::string runHeader(const char* label, const CheckRun& run) {
    std::string driver = run.renderer.empty() ? "(no renderer named)" : run.renderer;
    std::string details;
    for (const std::string& part : {run.vendor, run.glVersion, run.api})
        if (!part.empty()) details += (details.empty() ? "" : "; ") + part;
    std::string oasis = run.oasisVersion + (run.oasisCommit.empty() ? "" : " " + run.oasisCommit);
    return std::string(label) + ": " + printableText(run.path) + "\n   " + driver + (details.empty() ? "" : " (" + details + ")") +
           (oasis.empty() ? "" : ", oasis " + oasis) + "\n   pass " + std::to_string(run.count("pass")) + ", fail " +
           std::to_string(run.count("fail")) + ", skip " + std::to_string(run.count("skip")) + "\n";
}

}  // namespace

int CheckRun::count(const std::string& verdict) const {
    int n = 0;
    for (const CheckedCase& c : cases) n += c.verdict == verdict;
    return n;
}

bool parseCheckRun(const std::string& json, CheckRun& run, std::string& error) {
    JsonValue root;
    std::string why;
    if (!parseJson(json, root, why)) return refuse(error, "not valid JSON: " + why);
    if (!isCheckReport(root)) return refuse(error, "not an oasis check report (no \"schema\": \"oasis-check/N\")");
    const JsonValue* cases = root.find("cases");
    if (!cases || !cases->isArray()) return refuse(error, "not an oasis check report (no \"cases\" list)");
    if (cases->items.empty()) return refuse(error, "\"cases\" is empty: a check report holds every case it ran");
    const JsonValue* driver = root.find("driver");
    const JsonValue* oasis = root.find("oasis");
    run.vendor = stringOf(driver, "vendor");
    run.renderer = stringOf(driver, "renderer");
    run.glVersion = stringOf(driver, "version");
    run.api = stringOf(driver, "api");
    run.oasisVersion = stringOf(oasis, "version");
    run.oasisCommit = stringOf(oasis, "commit");
    const JsonValue* summary = root.find("summary");
    const JsonValue* quick = summary ? summary->find("quick") : nullptr;
    run.quick = quick && quick->kind == JsonValue::Kind::Bool && quick->boolean;
    run.cases.clear();
    return readCases(*cases, run, error);
}

bool readCheckRun(const std::string& path, CheckRun& run, std::string& error) {
    std::string json;
    if (!readRegularFile(path, kCheckReportMaxBytes, json, error)) return false;
    run.path = path;
    if (parseCheckRun(json, run, error)) return true;
    error = printableText(path) + ": " + error;
    return false;
}

CheckDiff diffCheckRuns(const CheckRun& a, const CheckRun& b) {
    std::map<std::string, const CheckedCase*> inA, inB;
    for (const CheckedCase& c : a.cases) inA[c.name] = &c;
    for (const CheckedCase& c : b.cases) inB[c.name] = &c;
    CheckDiff diff;
    for (const CheckedCase& after : b.cases) {
        auto found = inA.find(after.name);
        if (found == inA.end()) {
            diff.newCases.push_back(after);
            continue;
        }
        const CheckedCase& before = *found->second;
        CaseChange change{after.name, before, after};
        bool wasSkipped = before.verdict == "skip", isSkipped = after.verdict == "skip";
        // A crash, a timeout or an unexpected pass is as unexpected as a failure (check_report.h).
        bool wasBad = isUnexpected(before.verdict), isBad = isUnexpected(after.verdict);
        if (!wasSkipped && !isSkipped && !wasBad && isBad) diff.regressions.push_back(change);
        else if (!wasSkipped && !isSkipped && wasBad && !isBad) diff.fixes.push_back(change);
        else if (!wasSkipped && isSkipped) diff.newSkips.push_back(change);
        else if (wasSkipped && !isSkipped) diff.noLongerSkipped.push_back(change);
        else if (!isSkipped && numbersMoved(before, after)) diff.changedNumbers.push_back(change);
    }
    for (const CheckedCase& before : a.cases)
        if (!inB.count(before.name)) diff.removedCases.push_back(before);
    return diff;
}

std::string checkDiffText(const CheckRun& a, const CheckRun& b, const CheckDiff& diff) {
    std::string text = runHeader("A", a) + runHeader("B", b);
    // A --quick run against a full one: the cases only one ran are the subset's, not news.
    if (a.quick != b.quick) {
        size_t both = b.cases.size() - diff.newCases.size();
        text += std::string(a.quick ? "A" : "B") + " is a --quick run and " + (a.quick ? "B" : "A") +
                " a full one: the " + std::to_string(both) + " cases both ran are compared; the " +
                std::to_string(diff.newCases.size() + diff.removedCases.size()) +
                " that only the full run has are not listed as new or removed\n";
    }
    text += section("regressions", diff.regressions) + section("fixes", diff.fixes) + section("new skips", diff.newSkips) +
            section("no longer skipped", diff.noLongerSkipped) + section("changed numbers", diff.changedNumbers);
    if (a.quick == b.quick) text += section("new cases", diff.newCases) + section("removed cases", diff.removedCases);
    return text;
}

int runCheckDiff(const std::string& pathA, const std::string& pathB) {
    CheckRun a, b;
    std::string error;
    if (!readCheckRun(pathA, a, error) || !readCheckRun(pathB, b, error)) {
        std::fprintf(stderr, "oasis: check --diff: %s\n", error.c_str());
        return 2;
    }
    CheckDiff diff = diffCheckRuns(a, b);
    std::fputs(checkDiffText(a, b, diff).c_str(), stdout);
    return diff.exitCode();
}

}  // namespace oasis
