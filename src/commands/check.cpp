// `oasis check` (commands/check.h): the cases in turn, each judged, then the report written whole.
#include "commands/check.h"

#include <sys/stat.h>

#include <cerrno>
#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <stdexcept>

#include "commands/check_cases.h"
#include "commands/check_diff.h"
#include "commands/check_html.h"
#include "commands/check_judge.h"
#include "commands/check_render.h"
#include "commands/provenance.h"
#include "commands/check_report.h"
#include "commands/session.h"
#include "context/gl_context.h"
#include "render/file_output.h"
#include "render/shader_library.h"

namespace oasis {
namespace {

using Clock = std::chrono::steady_clock;
constexpr const char* kCheckSize = "256x144";

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

bool isDirectory(const std::string& path) {
    struct stat info;
    return stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode);
}

std::string parentOf(const std::string& path) {
    size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? "." : path.substr(0, slash);
}

// The arguments every render of this check adds: the frame size, and --api gles where the check
// runs on OpenGL ES (its native tier; a case's own tier may say so again).
std::vector<std::string> withCommon(std::vector<std::string> arguments, const Options& options) {
    arguments.insert(arguments.begin(), {"--size", kCheckSize});
    bool hasApi = false;
    for (const std::string& argument : arguments) hasApi = hasApi || argument == "--api";
    if (options.scene.api == gl::Api::Gles && !hasApi) arguments.insert(arguments.end(), {"--api", "gles"});
    return arguments;
}

// The rule a case is held to against its own main path: identical, except where a fallback's
// rounding was measured to differ.
const ImageRule& mainPathRule(const CheckCase& c) {
    bool rounded = c.value("tier").name == "gles30" || c.value("light-method").name == "tiled";
    return imageRule(rounded ? "same-driver-fallback" : "identical");
}

// Why a case cannot run here at all before anything is rendered, or "".
std::string caseRefused(const CheckCase& c, const Options& options) {
    if (options.scene.api == gl::Api::Gles && c.value("tier").name == "gl33")
        return "the gl33 tier is a desktop OpenGL context; this check runs on OpenGL ES (--api gles)";
    return {};
}

struct Checker {
    const Options& options;
    std::string referenceDir;
    std::map<std::vector<std::string>, CaseFrame> mainPaths;  // by arguments: shared between cases
    std::vector<std::string> notes;  // the running case's, after its verdict's reasons

    const CaseFrame& mainPath(const CheckCase& c) {
        std::vector<std::string> arguments = withCommon(c.mainPathArguments(), options);
        auto found = mainPaths.find(arguments);
        if (found == mainPaths.end()) found = mainPaths.emplace(arguments, renderCaseFrame(arguments, false)).first;
        return found->second;
    }

    CaseResult run(const CheckCase& c) {
        Clock::time_point start = Clock::now();
        CaseResult result;
        result.name = c.name();
        result.options = withCommon(c.arguments(), options);
        result.referenceRule = imageRule("cross-driver").name;
        if (std::string refused = caseRefused(c, options); !refused.empty()) {
            result.reason = "forced tier: " + refused;
            return result;
        }
        CaseFrame frame = renderCaseFrame(result.options, c.value("plants").name == "plants-gpu");
        if (!frame.rendered) {
            result.reason = frame.limitedBy + ": " + frame.skipReason;
            result.seconds = secondsSince(start);
            return result;
        }
        result.result = frame.image;
        std::vector<std::string> failures;
        notes.clear();
        judgeAgainstReference(c, result, failures);
        bool mainPathFailed = judgeAgainstMainPath(c, result, failures);
        result.verdict = failures.empty() ? Verdict::Pass : Verdict::Fail;
        if (failures.empty())
            failures.push_back(result.referenceCompared ? "matches the reference frame and the driver's main path"
                                                        : "matches the driver's main path");
        if (!frame.drawnWith.empty()) notes.push_back(frame.drawnWith);
        failures.insert(failures.end(), notes.begin(), notes.end());
        for (const std::string& text : failures) result.reason += (result.reason.empty() ? "" : "; ") + text;
        if (mainPathFailed) findDivergence(c, result);
        else if (result.verdict == Verdict::Fail)
            result.reason += " (the case matches the driver's main path by its rule: the difference from the "
                             "reference is this driver's, not this path's)";
        result.seconds = secondsSince(start);
        return result;
    }

    // Without a reference frame the case is judged against the main path alone, and says so.
    void judgeAgainstReference(const CheckCase& c, CaseResult& result, std::vector<std::string>& failures) {
        std::string path = referenceDir + "/" + c.name() + ".png", error;
        if (referenceDir.empty() || !readPng(path, result.reference, error)) {
            result.referenceRule = "none";
            notes.push_back("no reference frame (" + (referenceDir.empty() ? std::string("no reference directory") : error) +
                            "): judged against the driver's main path alone");
            return;
        }
        const ImageRule& rule = imageRule("cross-driver");
        if (result.reference.width != result.result.width || result.reference.height != result.result.height) {
            failures.push_back("the reference frame " + path + " is not " + kCheckSize);
            return;
        }
        Judgement j = judge(result.result, result.reference, rule);
        result.referenceCompared = true;
        result.psnrDb = j.psnrDb;
        result.maxAbs = j.maxAbs;
        result.pixelsOver = j.pixelsOver;
        if (!j.pass) {
            failures.push_back("against the reference frame: " + j.summary);
            result.errorMask = errorMask(result.result, result.reference, rule);
        }
    }

    // True when the case fails against its main path (then the pass-by-pass search runs).
    bool judgeAgainstMainPath(const CheckCase& c, CaseResult& result, std::vector<std::string>& failures) {
        const CaseFrame& main = mainPath(c);
        if (!main.rendered) {
            failures.push_back("the driver's main path did not render: " + main.skipReason);
            return false;
        }
        const ImageRule& rule = mainPathRule(c);
        Judgement j = judge(result.result, main.image, rule);
        result.mainPathCompared = true;
        result.mainPathRule = rule.name;
        result.mainPathPsnrDb = j.psnrDb;
        result.mainPathMaxAbs = j.maxAbs;
        result.mainPathPixelsOver = j.pixelsOver;
        if (j.pass) return false;
        failures.push_back("against the driver's main path: " + j.summary);
        if (result.errorMask.width == 0) {
            result.errorMask = errorMask(result.result, main.image, rule);
            if (result.reference.width == 0) result.reference = main.image;
        }
        return true;
    }

    // Where the case's path parts from the main path on this driver, pass by pass.
    void findDivergence(const CheckCase& c, CaseResult& result) {
        try {
            std::vector<PassSnapshot> main = renderPassByPass(withCommon(c.mainPathArguments(), options));
            std::vector<PassSnapshot> candidate = renderPassByPass(result.options);
            // The pixels whose final colours part, bottom row first as the views read them.
            const Image& mainImage = mainPath(c).image;
            std::vector<bool> where(size_t(mainImage.width) * size_t(mainImage.height));
            for (int y = 0; y < mainImage.height; ++y)
                for (int x = 0; x < mainImage.width; ++x) {
                    int d = 0;
                    for (int k = 0; k < 3; ++k)
                        d = std::max(d, std::abs(int(mainImage.pixel(x, y)[k]) - int(result.result.pixel(x, y)[k])));
                    where[size_t(mainImage.height - 1 - y) * size_t(mainImage.width) + size_t(x)] = d > mainPathRule(c).level;
                }
            Divergence found;
            if (firstDivergence(main, candidate, mainPathRule(c).level, where, found))
                result.firstDivergence = FirstDivergence{found.pass, found.target, found.pixels};
        } catch (const std::exception& error) {
            result.reason += " (pass by pass: " + std::string(error.what()) + ")";
        }
    }
};

void fillDriver(CheckReport& report, const Options& options) {
    Options native = options;
    HeadlessContext context(maxGlVersionFor(native.scene));
    RenderSession session(native, RenderSession::Shaders::CapabilitiesOnly);
    const gl::Capabilities& caps = session.caps;
    // The context's own strings: GL_VENDOR and GL_RENDERER natively; in a browser, whose GL_RENDERER
    // is masked ("WebKit WebGL"), WEBGL_debug_renderer_info's where it is offered (web_context.cpp).
    ContextInfo info = queryContextInfo();
    report.vendor = info.vendor.empty() ? caps.vendor : info.vendor;
    report.renderer = info.renderer.empty() ? caps.renderer : info.renderer;
    report.glVersion = caps.version;
    report.glslVersion = caps.glslVersion;
    report.api = caps.es ? "OpenGL ES" : "OpenGL";
    for (const gl::FeatureReport& feature : session.features())
        report.caps.push_back({feature.name, feature.available, feature.used, feature.reason, feature.limitedBy});
}

std::string formatSeconds(double seconds) {
    char text[32];
    std::snprintf(text, sizeof(text), "%d:%02d", int(seconds) / 60, int(seconds) % 60);
    return text;
}

// Makes the directories, then writes the files as one set (whole or not at all); false after
// saying what failed.
bool writeSet(const std::vector<std::string>& directories, const std::vector<OutputFile>& files) {
    for (const std::string& dir : directories)
        if (mkdir(dir.c_str(), 0755) != 0 && errno != EEXIST) {
            std::fprintf(stderr, "oasis: cannot create directory %s: %s\n", dir.c_str(), std::strerror(errno));
            return false;
        }
    std::vector<std::string> written;
    std::string error;
    if (writeFilesWhole(files, written, error)) return true;
    std::fprintf(stderr, "oasis: %s\n", error.c_str());
    for (const std::string& path : written)
        std::fprintf(stderr, "oasis: wrote %s before the failure (complete, kept)\n", path.c_str());
    return false;
}

int writeReferences(const Options& options, const std::vector<CheckCase>& cases) {
    std::vector<OutputFile> files;
    for (const CheckCase& c : cases) {
        std::vector<std::string> arguments = withCommon(c.arguments(), options);
        CaseFrame frame = renderCaseFrame(arguments, false);
        if (!frame.rendered) {
            std::fprintf(stderr, "oasis: check --write-references: %s cannot be rendered here: %s\n", c.name().c_str(),
                         frame.skipReason.c_str());
            return 1;
        }
        files.push_back({options.writeReferences + "/" + c.name() + ".png", {}});
        encodePng(frame.image, files.back().bytes, frame.provenance);
        std::fprintf(stderr, "oasis check: [%d/%zu] %s\n", c.index, cases.size(), c.name().c_str());
    }
    if (!writeSet({options.writeReferences}, files)) return 1;
    std::fprintf(stderr, "oasis check: wrote %zu reference frames to %s\n", files.size(), options.writeReferences.c_str());
    return 0;
}

// The report's files as one set (written whole or not at all): report.json, and for each failing
// case its frame, the frame it was judged against and the error mask.
int writeCheckReport(const Options& options, const CheckReport& report) {
    std::string directory = options.outDirGiven ? options.outDir : "oasis-check";
    std::vector<OutputFile> files = {{directory + "/report.json", checkReportJson(report)},
                                     {directory + "/report.html", checkReportHtml(report)}};
    for (const CaseResult& c : report.cases) {
        if (c.verdict != Verdict::Fail) continue;
        for (const auto& [suffix, image] : {std::pair{"result", &c.result}, {"reference", &c.reference}, {"mask", &c.errorMask}}) {
            if (image->width == 0) continue;
            files.push_back({directory + "/cases/" + c.name + "-" + suffix + ".png", {}});
            encodePng(*image, files.back().bytes);
        }
    }
    if (!writeSet({directory, directory + "/cases"}, files)) return 1;
    std::printf("oasis check: %d passed, %d failed, %d skipped of %zu cases in %s on %s\n", report.passed(),
                report.failed(), report.skipped(), report.cases.size(), formatSeconds(report.seconds).c_str(),
                report.renderer.c_str());
    std::fprintf(stderr, "  wrote %s/report.json, %s/report.html%s\n", directory.c_str(), directory.c_str(),
                report.failed() ? (" and the failing cases' images in " + directory + "/cases").c_str() : "");
    return report.failed() ? 1 : 0;
}

}  // namespace

// The tables docs/check.md shows (docs/update.sh check-tables regenerates them; a test compares):
// the dimensions with their values, and the image rules with the measurement behind each.
std::string checkTablesMarkdown() {
    std::string text = "| dimension | values (the first is the driver's own choice where the dimension is a path) |\n| --- | --- |\n";
    for (const CheckDimension& dimension : checkDimensions()) {
        text += "| " + dimension.name + (dimension.pathOnly ? " (path)" : "") + " | ";
        for (size_t v = 0; v < dimension.values.size(); ++v) {
            const CheckValue& value = dimension.values[v];
            std::string arguments;
            for (const std::string& argument : value.arguments) arguments += (arguments.empty() ? "" : " ") + argument;
            text += (v ? ", " : "") + value.name + (arguments.empty() ? "" : " (`" + arguments + "`)");
        }
        text += " |\n";
    }
    text += "\n| rule | a pixel differs above | PSNR at least | max abs at most | differing pixels at most | set by |\n"
            "| --- | --- | --- | --- | --- | --- |\n";
    for (const ImageRule& rule : imageRules()) {
        char line[1024];
        std::snprintf(line, sizeof(line), "| %s | %d levels | %.0f dB | %d | %.1f%% | %s |\n", rule.name.c_str(), rule.level,
                      rule.minPsnrDb, rule.maxAbs, rule.maxFractionOver * 100.0, rule.measuredBy.c_str());
        text += line;
    }
    PairCoverage coverage = pairCoverage(coveringCases());
    text += "\n" + std::to_string(coveringCases().size()) + " cases meet all " + std::to_string(coverage.pairs) +
            " required pairs; `--quick` runs " + std::to_string(quickCases(coveringCases()).size()) + " of them.\n";
    return text;
}

std::string findCheckReferences() {
    if (const char* set = std::getenv("OASIS_CHECK_REFERENCES"); set && *set) return set;
    // Beside the shaders in use (an install's share/oasis, or a copy made with its references),
    // then the install prefix's and the source tree's.
    std::string shaders = findShaderDirectory();
    for (const std::string& candidate : {parentOf(shaders) + "/check-references", std::string(OASIS_INSTALL_CHECK_REFERENCES),
                                         std::string(OASIS_SOURCE_CHECK_REFERENCES)})
        if (isDirectory(candidate)) return candidate;
    return {};
}

int runCheckCommand(const Options& options) {
    if (!options.diffReports.empty()) return runCheckDiff(options.diffReports[0], options.diffReports[1]);
    if (options.checkTables) {
        std::fputs(checkTablesMarkdown().c_str(), stdout);
        return 0;
    }
    Clock::time_point start = Clock::now();
    std::vector<CheckCase> all = coveringCases();
    std::vector<CheckCase> cases = options.quick ? quickCases(all) : all;
    PairCoverage coverage = pairCoverage(all);
    try {
        if (!options.writeReferences.empty()) return writeReferences(options, all);
        CheckReport report;
        report.quick = options.quick;
        report.oasisVersion = oasisRelease();
        report.oasisCommit = oasisCommit();
        fillDriver(report, options);
        Checker checker{options, options.checkReferences.empty() ? findCheckReferences() : options.checkReferences, {}, {}};
        std::printf("oasis check: %zu cases%s (the full set of %zu meets all %d compatible pairs of %zu dimensions' "
                    "values) on %s\n", cases.size(), options.quick ? " (--quick: every value once)" : "", all.size(),
                    coverage.pairs, checkDimensions().size(), report.renderer.c_str());
        if (checker.referenceDir.empty())
            std::printf("  reference frames: NONE FOUND (set OASIS_CHECK_REFERENCES or --references DIR): every case is "
                        "judged against this driver's main path alone\n");
        else
            std::printf("  reference frames: %s\n", checker.referenceDir.c_str());
        for (size_t i = 0; i < cases.size(); ++i) {
            double elapsed = secondsSince(start);
            std::fprintf(stderr, "oasis check: case %zu of %zu, %s (%s elapsed%s)\n", i + 1, cases.size(),
                         cases[i].name().c_str(), formatSeconds(elapsed).c_str(),
                         i ? (", about " + formatSeconds(elapsed / double(i) * double(cases.size() - i)) + " left").c_str() : "");
            report.cases.push_back(checker.run(cases[i]));
            const CaseResult& r = report.cases.back();
            std::printf("  %-4s %s%s%s\n", verdictName(r.verdict), r.name.c_str(), r.verdict == Verdict::Pass ? "" : ": ",
                        r.verdict == Verdict::Pass ? "" : r.reason.c_str());
        }
        report.seconds = secondsSince(start);
        return writeCheckReport(options, report);
    } catch (const std::exception& error) {
        std::fprintf(stderr, "oasis: check: %s\n", error.what());
        return 1;
    }
}

}  // namespace oasis
