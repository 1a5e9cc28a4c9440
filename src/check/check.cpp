// `oasis check` (check/check.h): the options checked and the outputs proven writable before
// anything renders, the driver's report, the cases in turn (each in a process of its own: a
// crash or a hang ends its case, not the check), then the blame settled across cases and the
// report written whole.
#include "check/check.h"

#include <fcntl.h>
#include <fnmatch.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "check/check_case_judge.h"
#include "check/check_cases.h"
#include "check/check_diff.h"
#include "check/check_expectations.h"
#include "check/check_html.h"
#include "check/check_profile.h"
#include "check/check_references.h"
#include "check/check_report.h"
#include "check/check_runner.h"
#include "check/pixel_classes.h"
#include "commands/provenance.h"
#include "io/file_input.h"
#include "io/file_output.h"
#include "render/shader_library.h"

namespace oasis {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

bool isDirectory(const std::string& path) {
    struct stat info;
    return stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode);
}

std::string parentOf(const std::string& path) {
    size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
}

std::string formatSeconds(double seconds) {
    char text[32];
    std::snprintf(text, sizeof(text), "%d:%02d", int(seconds) / 60, int(seconds) % 60);
    return text;
}

// A directory the check will write into, made (with its parents) and proven writable now, before
// a case renders, so that a bad --out-dir costs milliseconds and not the whole run. Remembers
// what it made, to remove it again if the check ends without writing there.
class OutputDirectory {
public:
    ~OutputDirectory() { removeMade(); }
    bool prepare(const std::string& path, std::string& error) {
        path_ = path;
        std::vector<std::string> missing;
        for (std::string at = path; !at.empty() && at != "/" && at != "." && !isDirectory(at); at = parentOf(at))
            missing.push_back(at);
        for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
            if (mkdir(it->c_str(), 0755) != 0 && errno != EEXIST) {
                error = "cannot write " + path + ": " + std::strerror(errno);
                removeMade();
                return false;
            }
            made_.push_back(*it);
        }
        std::string probe = path + "/.oasis-write-probe-" + std::to_string(getpid());
        int fd = open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0644);
        bool written = fd >= 0 && write(fd, "x", 1) == 1;
        int writeErrno = errno;
        if (fd >= 0) close(fd);
        unlink(probe.c_str());
        if (!written) {
            error = "cannot write " + path + ": " + std::strerror(writeErrno);
            removeMade();
            return false;
        }
        return true;
    }
    // The directories it made that are still empty go again, deepest first (rmdir leaves any
    // that holds a file): a check that ends early leaves nothing empty behind.
    void removeMade() {
        for (auto it = made_.rbegin(); it != made_.rend(); ++it) rmdir(it->c_str());
        made_.clear();
    }

private:
    std::string path_;
    std::vector<std::string> made_;  // outermost first
};

// The cases --case and --shard select, in the set's order; `selection` says what was asked.
std::vector<CheckCase> selectCases(const std::vector<CheckCase>& cases, const CheckOptions& check, std::string& selection) {
    std::vector<CheckCase> chosen;
    for (const CheckCase& c : cases) {
        bool matches = check.caseGlobs.empty();
        for (const std::string& glob : check.caseGlobs) matches = matches || fnmatch(glob.c_str(), c.name().c_str(), 0) == 0;
        if (matches) chosen.push_back(c);
    }
    for (const std::string& glob : check.caseGlobs) selection += (selection.empty() ? "--case " : " --case ") + glob;
    if (check.shardCount > 1) {
        std::vector<CheckCase> shard;
        for (size_t k = 0; k < chosen.size(); ++k)
            if (int(k % size_t(check.shardCount)) == check.shardIndex - 1) shard.push_back(chosen[k]);
        chosen = shard;
        selection += (selection.empty() ? "" : " ") + std::string("--shard ") + std::to_string(check.shardIndex) + "/" +
                     std::to_string(check.shardCount);
    }
    return chosen;
}


// The report's files as one set (written whole or not at all): report.json, report.html, the
// JUnit file if asked for, and for each case that did not pass its frames and error mask.
int writeCheckReport(const Options& options, const std::string& directory, const CheckReport& report,
                     const std::string& profileFile) {
    std::vector<OutputFile> files = {{directory + "/report.json", checkReportJson(report)},
                                     {directory + "/report.html", checkReportHtml(report)}};
    if (!options.check.junit.empty()) files.push_back({options.check.junit, checkReportJunit(report)});
    if (!profileFile.empty()) files.push_back({directory + "/workarounds", profileFile});
    for (const CaseResult& c : report.cases) {
        if (c.verdict == Verdict::Pass || c.verdict == Verdict::Skip) continue;
        for (const auto& [suffix, image] : {std::pair{"result", &c.result}, {"reference", &c.reference},
                                            {"main-path", &c.mainPathImage}, {"mask", &c.errorMask}}) {
            if (image->width == 0) continue;
            files.push_back({directory + "/cases/" + c.name + "-" + suffix + ".png", {}});
            encodePng(*image, files.back().bytes);
        }
        // Which pixels its interior rule held (green) and which it left to the edges' rules.
        if (!c.pixelClasses.empty()) {
            files.push_back({directory + "/cases/" + c.name + "-classes.png", {}});
            encodePng(pixelClassImage(c.pixelClasses, c.result.width, c.result.height), files.back().bytes);
        }
    }
    bool withCases = files.size() > 2u + (options.check.junit.empty() ? 0u : 1u) + (profileFile.empty() ? 0u : 1u);
    if (withCases && mkdir((directory + "/cases").c_str(), 0755) != 0 && errno != EEXIST) {
        std::fprintf(stderr, "oasis: cannot write %s/cases: %s\n", directory.c_str(), std::strerror(errno));
        return 1;
    }
    std::vector<std::string> written;
    std::string error;
    if (!writeFilesWhole(files, written, error)) {
        std::fprintf(stderr, "oasis: %s\n", error.c_str());
        for (const std::string& path : written)
            std::fprintf(stderr, "oasis: wrote %s before the failure (complete, kept)\n", path.c_str());
        return 1;
    }
    std::string counts;
    for (Verdict verdict : allVerdicts()) {
        int n = report.count(verdict);
        if (n || verdict == Verdict::Pass || verdict == Verdict::Fail || verdict == Verdict::Skip)
            counts += (counts.empty() ? "" : ", ") + std::to_string(n) + " " +
                      (verdict == Verdict::Pass ? "passed" : verdict == Verdict::Fail ? "failed"
                                                           : verdict == Verdict::Skip ? "skipped" : verdictName(verdict));
    }
    std::printf("oasis check: %s of %zu cases in %s on %s\n", counts.c_str(), report.cases.size(),
                formatSeconds(report.seconds).c_str(), report.renderer.c_str());
    std::fprintf(stderr, "  wrote %s/report.json, %s/report.html%s%s\n", directory.c_str(), directory.c_str(),
                 options.check.junit.empty() ? "" : (", " + options.check.junit).c_str(),
                 withCases ? (" and the images of the cases that did not pass in " + directory + "/cases").c_str() : "");
    return report.failed() ? 1 : 0;
}

// The baseline's frames and manifest, written when --baseline names a directory without one.
int recordBaseline(const std::string& dir, const CheckReport& report, const std::vector<CaseFrame>& frames) {
    std::vector<OutputFile> files;
    BaselineManifest manifest{report.renderer, report.glVersion, report.oasisCommit, {}};
    for (size_t i = 0; i < report.cases.size(); ++i) {
        if (!frames[i].rendered) continue;
        manifest.cases.push_back(report.cases[i].name);
        files.push_back({dir + "/" + report.cases[i].name + ".png", {}});
        encodePng(frames[i].image, files.back().bytes, frames[i].provenance);
    }
    files.push_back({dir + "/baseline.json", baselineManifestJson(manifest)});
    std::vector<std::string> written;
    std::string error;
    if (!writeFilesWhole(files, written, error)) {
        std::fprintf(stderr, "oasis: %s\n", error.c_str());
        return 1;
    }
    std::fprintf(stderr, "oasis check: recorded this driver's baseline (%zu frames) in %s\n", manifest.cases.size(),
                 dir.c_str());
    return 0;
}

int writeReferences(const Options& options, CaseRunner& runner, const std::vector<CheckCase>& cases) {
    std::vector<OutputFile> files;
    for (const CheckCase& c : cases) {
        FrameRun run = runner.frame(checkCaseArguments(c, options), false);
        if (run.outcome.end != RunEnd::Finished || !run.outcome.error.empty() || !run.frame.rendered) {
            std::fprintf(stderr, "oasis: check --write-references: %s cannot be rendered here: %s\n", c.name().c_str(),
                         !run.outcome.detail.empty() ? run.outcome.detail.c_str()
                         : !run.outcome.error.empty() ? run.outcome.error.c_str() : run.frame.skipReason.c_str());
            return 1;
        }
        files.push_back({options.writeReferences + "/" + c.name() + ".png", {}});
        encodePng(run.frame.image, files.back().bytes, run.frame.provenance);
        std::fprintf(stderr, "oasis check: [%d/%zu] %s\n", c.index, cases.size(), c.name().c_str());
    }
    std::vector<std::string> written;
    std::string error;
    if (!writeFilesWhole(files, written, error)) {
        std::fprintf(stderr, "oasis: %s\n", error.c_str());
        return 1;
    }
    std::fprintf(stderr, "oasis check: wrote %zu reference frames to %s\n", files.size(), options.writeReferences.c_str());
    return 0;
}

std::unique_ptr<CaseRunner> makeRunner(const Options& options) {
#ifdef __EMSCRIPTEN__
    (void)options;
    return makeInProcessRunner();
#else
    return makeChildRunner(options.check.caseTimeoutSeconds);
#endif
}

// The case's line on stdout: the verdict, the name, and for anything but a pass what decided it.
void printCaseLine(const CaseResult& r) {
    std::string detail;
    if (r.verdict != Verdict::Pass) {
        if (!r.blame.empty()) detail += "blame: " + r.blame + "; ";
        if (r.firstDivergence)
            detail += "first diverges at " + r.firstDivergence->pass + " / " + r.firstDivergence->target + "; ";
        detail += r.reason;
    }
    std::printf("  %-15s %s%s%s\n", verdictName(r.verdict), r.name.c_str(), detail.empty() ? "" : ": ", detail.c_str());
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
    text += "\n| rule | a pixel differs above | PSNR at least | max abs at most | differing pixels at most | mean signed within "
            "| set by |\n| --- | --- | --- | --- | --- | --- | --- |\n";
    for (const ImageRule& rule : imageRules()) {
        char line[2048], mean[32] = "-";
        if (rule.maxMeanSigned < 255.0) std::snprintf(mean, sizeof(mean), "+-%.2f levels", rule.maxMeanSigned);
        std::snprintf(line, sizeof(line), "| %s%s | %d levels | %.0f dB | %d | %.1f%%%s | %s | %s |\n", rule.name.c_str(),
                      rule.interiorOnly ? " (interior pixels)" : "", rule.level, rule.minPsnrDb, rule.maxAbs,
                      rule.maxFractionOver * 100.0, rule.interiorOnly ? " of them" : "", mean, rule.measuredBy.c_str());
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
#ifndef __EMSCRIPTEN__
    if (!options.check.child.empty()) return runCheckChild(options);
#endif
    if (!options.diffReports.empty()) return runCheckDiff(options.diffReports[0], options.diffReports[1]);
    if (options.checkTables) {
        std::fputs(checkTablesMarkdown().c_str(), stdout);
        return 0;
    }
    Clock::time_point start = Clock::now();
    const CheckOptions& check = options.check;
    std::vector<CheckCase> all = coveringCases();
    try {
        std::unique_ptr<CaseRunner> runner = makeRunner(options);
        if (!options.writeReferences.empty()) {
            OutputDirectory out;
            std::string error;
            if (!out.prepare(options.writeReferences, error)) return std::fprintf(stderr, "oasis: %s\n", error.c_str()), 1;
            return writeReferences(options, *runner, all);
        }
        // Everything a run reads and writes is settled before the first case renders.
        CheckReport report;
        std::string selection;
        std::vector<CheckCase> cases = selectCases(options.quick ? quickCases(all) : all, check, selection);
        if (cases.empty()) {
            std::fprintf(stderr, "oasis: check: no case matches %s (oasis check --tables lists the dimensions; the "
                         "report of a full check names every case)\n", selection.c_str());
            return 2;
        }
        std::vector<Expectation> expectations;
        if (!check.expectations.empty()) {
            std::string text, error;
            // A regular file of at most 1 MiB (io/file_input.h): a FIFO or a device is refused, not read forever.
            if (!readRegularFile(check.expectations, size_t(1) << 20, text, error))
                return std::fprintf(stderr, "oasis: check: --expectations: %s\n", error.c_str()), 2;
            if (!parseExpectations(text, expectations, error))
                return std::fprintf(stderr, "oasis: check: --expectations %s: %s\n", check.expectations.c_str(), error.c_str()), 2;
        }
        std::string referenceDir = options.checkReferences.empty() ? findCheckReferences() : options.checkReferences;
        ReferenceSet references;
        std::string error;
        if (referenceDir.empty()) {
            std::fprintf(stderr, "oasis: check: no reference frames found (set --references DIR or "
                         "$OASIS_CHECK_REFERENCES; the source tree's are tests/check-references)\n");
            return 2;
        }
        if (!openReferenceSet(referenceDir, references, error)) return std::fprintf(stderr, "oasis: check: %s\n", error.c_str()), 2;
        CaseJudge judge(options, references.dir, *runner, expectations);
        bool recordingBaseline = false;
        if (!check.baseline.empty()) {
            if (baselineExists(check.baseline)) {
                if (!judge.useBaseline(check.baseline, error)) return std::fprintf(stderr, "oasis: check: %s\n", error.c_str()), 2;
            } else {
                recordingBaseline = true;
            }
        }
        std::string directory = options.outDirGiven ? options.outDir
                                : options.scene.api == gl::Api::Gles ? "oasis-check-gles" : "oasis-check";
        OutputDirectory out, baselineOut;
        if (!out.prepare(directory, error) || (!check.junit.empty() && !OutputDirectory().prepare(parentOf(check.junit), error)) ||
            (recordingBaseline && !baselineOut.prepare(check.baseline, error)))
            return std::fprintf(stderr, "oasis: %s (checked before the first case)\n", error.c_str()), 1;

        // The driver, from a child of its own too: a driver that crashes there still gets a report
        // (its capabilities measured again without compute, which the report's plant atlas uses).
        std::vector<std::string> driverArguments;
        if (options.scene.api == gl::Api::Gles) driverArguments = {"--api", "gles"};
        DriverRun driver = runner->driver(driverArguments);
        std::vector<std::string> runNotes;
        if (driver.outcome.end != RunEnd::Finished || !driver.outcome.error.empty()) {
            std::string how = driver.outcome.detail.empty() ? driver.outcome.error : driver.outcome.detail;
            driverArguments.push_back("--no-compute");
            DriverRun again = runner->driver(driverArguments);
            bool recovered = again.outcome.end == RunEnd::Finished && again.outcome.error.empty();
            runNotes.push_back("the driver's report " + how + (recovered ? "; it is from a re-run with --no-compute" : "") +
                               (driver.outcome.tail.empty() ? "" : "; its last output: " + driver.outcome.tail));
            if (recovered) driver = std::move(again);
        }
        report = driver.driver;
        report.notes = runNotes;
        if (driver.outcome.end != RunEnd::Finished || !driver.outcome.error.empty())
            report.renderer = "(unknown: the driver's report " +
                              (driver.outcome.detail.empty() ? driver.outcome.error : driver.outcome.detail) + ")";
        if (!check.expectRenderer.empty()) {
            std::regex expected;
            try {
                expected = std::regex(check.expectRenderer);
            } catch (const std::regex_error& regexError) {
                return std::fprintf(stderr, "oasis: check: --expect-renderer /%s/ does not compile: %s\n",
                                    check.expectRenderer.c_str(), regexError.what()), 2;
            }
            if (!std::regex_search(report.renderer, expected)) {
                return std::fprintf(stderr, "oasis: check: refused: this driver is '%s', not one --expect-renderer /%s/ "
                                    "finds\n", report.renderer.c_str(), check.expectRenderer.c_str()), 2;
            }
        }
        judge.setRenderer(report.renderer);
        report.quick = options.quick;
        report.oasisVersion = oasisRelease();
        report.oasisCommit = oasisCommit();
        report.isolation = runner->isolation();
        report.referenceDir = references.dir;
        report.referenceHash = references.hash;
        report.baselineDir = check.baseline;
        report.selection = selection;
        report.expectations = check.expectations;
        report.retries = check.retries;
        report.caseTimeoutSeconds = check.caseTimeoutSeconds;
        PairCoverage coverage = pairCoverage(all);
        std::printf("oasis check: %zu cases%s%s (the full set of %zu meets all %d compatible pairs of %zu dimensions' "
                    "values) on %s\n", cases.size(), options.quick ? " (--quick: every value once)" : "",
                    selection.empty() ? "" : (" (" + selection + ")").c_str(), all.size(), coverage.pairs,
                    checkDimensions().size(), report.renderer.c_str());
        std::printf("  reference frames: %s (%d frames, %s)%s\n", references.dir.c_str(), references.frames,
                    references.hash.c_str(), judge.baselineNote().c_str());
        for (const std::string& note : report.notes) std::printf("  note: %s\n", note.c_str());
        int jobs = check.jobs ? check.jobs : std::clamp(int(std::thread::hardware_concurrency()), 1, 4);
#ifdef __EMSCRIPTEN__
        jobs = 1;
#endif
        if (jobs > 1) {
            std::fprintf(stderr, "oasis check: rendering the %zu cases and their main paths, %d processes at a time\n",
                         cases.size(), jobs);
            judge.prefetch(cases, jobs);
        }
        std::vector<CaseFrame> frames;
        std::string profileFile;
        for (size_t i = 0; i < cases.size(); ++i) {
            double elapsed = secondsSince(start);
            std::fprintf(stderr, "oasis check: case %zu of %zu, %s (%s elapsed%s)\n", i + 1, cases.size(),
                         cases[i].name().c_str(), formatSeconds(elapsed).c_str(),
                         i ? (", about " + formatSeconds(elapsed / double(i) * double(cases.size() - i)) + " left").c_str() : "");
            CaseFrame frame;
            report.cases.push_back(judge.run(cases[i], recordingBaseline ? &frame : nullptr));
            if (recordingBaseline) frames.push_back(std::move(frame));
        }
        // The verdict lines once the blame is settled across the cases (the progress is stderr's).
        judge.settleBlame(report.cases);
        for (const CaseResult& result : report.cases) printCaseLine(result);
        // What works on this driver: the fallbacks under which nothing that broke breaks.
        if (report.failed()) {
            std::fprintf(stderr, "oasis check: looking for the fallbacks under which no case crashes or fails\n");
            ProposedProfile profile = proposeProfile(judge, options, cases, report.cases);
            report.profileNeeded = profile.needed;
            report.profileFound = profile.found;
            report.profileFallbacks = profile.fallbacks;
            report.profileWhy = profile.why;
            report.profileFramesTried = profile.framesTried;
            if (profile.found) {
                profileFile = profileFileText(profile, report.renderer, report.glVersion);
                std::string list;
                for (const std::string& name : profile.fallbacks) list += (list.empty() ? "" : ",") + name;
                std::printf("  proposed: --force %s mends every crash and failure (%d frames tried; written to "
                            "%s/workarounds)\n", list.c_str(), profile.framesTried, directory.c_str());
            } else if (profile.needed) {
                std::printf("  proposed: nothing: %s\n", profile.why.c_str());
            }
        }
        report.seconds = secondsSince(start);
        if (recordingBaseline && recordBaseline(check.baseline, report, frames) != 0) return 1;
        return writeCheckReport(options, directory, report, profileFile);
    } catch (const std::exception& error) {
        std::fprintf(stderr, "oasis: check: %s\n", error.what());
        return 1;
    }
}

}  // namespace oasis
