// One check case from its frames to its verdict (check/check_case_judge.h).
#include "check/check_case_judge.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <set>
#include <thread>

#include "check/check_html.h"

namespace oasis {
namespace {

using Clock = std::chrono::steady_clock;

bool isFailure(Verdict verdict) {
    return verdict == Verdict::Fail || verdict == Verdict::Crash || verdict == Verdict::Timeout;
}

// Why a case cannot run here at all before anything is rendered, or "".
std::string caseRefused(const CheckCase& c, const Options& options) {
    if (options.scene.api == gl::Api::Gles && c.value("tier").name == "gl33")
        return "the gl33 tier is a desktop OpenGL context; this check runs on OpenGL ES (--api gles)";
    return {};
}

std::string joined(const std::vector<std::string>& parts) {
    std::string text;
    for (const std::string& part : parts) text += (text.empty() ? "" : "; ") + part;
    return text;
}

// A child that did not finish, as the case's reason says it.
std::string endedHow(const RunOutcome& outcome) {
    return outcome.end == RunEnd::Crashed ? "crashed: " + outcome.detail : "timed out: " + outcome.detail;
}

FrameComparison comparisonOf(const Judgement& j) { return {true, j.psnrDb, j.maxAbs, j.pixelsOver, j.meanSigned}; }

// The pixels whose largest channel difference exceeds `level`, bottom row first as the views read.
std::vector<bool> differingPixels(const Image& a, const Image& b, int level) {
    std::vector<bool> where(size_t(a.width) * size_t(a.height));
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            int d = 0;
            for (int k = 0; k < 3; ++k) d = std::max(d, std::abs(int(a.pixel(x, y)[k]) - int(b.pixel(x, y)[k])));
            where[size_t(a.height - 1 - y) * size_t(a.width) + size_t(x)] = d > level;
        }
    return where;
}

}  // namespace

std::vector<std::string> checkCaseArguments(const CheckCase& c, const Options& options, bool mainPath) {
    std::vector<std::string> arguments = mainPath ? c.mainPathArguments() : c.arguments();
    arguments.insert(arguments.begin(), {"--size", kCheckSize});
    bool hasApi = std::find(arguments.begin(), arguments.end(), "--api") != arguments.end();
    if (options.scene.api == gl::Api::Gles && !hasApi) arguments.insert(arguments.end(), {"--api", "gles"});
    return arguments;
}

const ImageRule& mainPathRule(const CheckCase& c) {
    if (c.value("tier").name == "gles30") return imageRule("same-driver-geometry");
    if (c.value("light-method").name == "tiled") return imageRule("same-driver-fallback");
    return imageRule("identical");
}

bool CaseJudge::useBaseline(const std::string& dir, std::string& error) {
    if (!readBaselineManifest(dir, baseline_, error)) return false;
    baselineDir_ = dir;
    return true;
}

std::string CaseJudge::baselineNote() const {
    if (baselineDir_.empty()) return {};
    return "; this driver's baseline " + baselineDir_ + " (recorded on " + baseline_.renderer + ", " + baseline_.glVersion +
           ", oasis " + baseline_.oasisCommit + ")";
}

const FrameRun& CaseJudge::mainPath(const CheckCase& c, bool again) {
    std::vector<std::string> arguments = checkCaseArguments(c, options_, true);
    auto found = mainPaths_.find(arguments);
    if (found != mainPaths_.end() && again && found->second.outcome.end != RunEnd::Finished) {
        mainPaths_.erase(found);  // a re-run of a case whose main path crashed runs that again too
        found = mainPaths_.end();
    }
    if (found == mainPaths_.end()) found = mainPaths_.emplace(arguments, runner_.frame(arguments, false)).first;
    return found->second;
}

CaseResult CaseJudge::run(const CheckCase& c, CaseFrame* keptFrame) {
    Clock::time_point start = Clock::now();
    prefetchedSeconds_ = 0.0;
    CaseResult result;
    result.name = c.name();
    result.options = checkCaseArguments(c, options_);
    std::vector<std::string> reproduce = result.options;
    reproduce.insert(reproduce.end(), {"--legend", "off", "--out", result.name + ".png"});
    result.reproduce = renderCommandLine(reproduce);
    result.referenceRule = imageRule("cross-driver").name;
    std::optional<Expectation> expectation = findExpectation(expectations_, result.name, renderer_);
    if (expectation) result.expectation = options_.check.expectations + ":" + std::to_string(expectation->line) + ": " +
                                          expectation->result + (expectation->reason.empty() ? "" : "  # " + expectation->reason);
    std::string refused = caseRefused(c, options_);
    if (!refused.empty() || (expectation && expectation->result == "skip")) {
        result.reason = refused.empty() ? "expected skip (" + result.expectation + ")" : "forced tier: " + refused;
        result.verdict = result.observed = Verdict::Skip;
        return result;
    }
    Verdict first = attempt(c, result, keptFrame);  // a re-run's verdict replaces it; its name stays in the reason
    result.runs = 1;
    std::string firstReason = result.reason;
    bool expectedFailure = expectation && expectation->result != "flake";
    while (isFailure(result.observed) && !expectedFailure && result.runs <= options_.check.retries) {
        CaseResult again;
        again.name = result.name;
        again.options = result.options;
        again.reproduce = result.reproduce;
        again.referenceRule = result.referenceRule;
        again.expectation = result.expectation;
        again.runs = result.runs + 1;
        attempt(c, again, keptFrame);
        result = std::move(again);
        if (result.observed == Verdict::Pass) {
            result.verdict = Verdict::Flake;
            result.reason = std::string(verdictName(first)) + " on its first run, passed on run " + std::to_string(result.runs) +
                            " (first run: " + firstReason + ")";
        }
    }
    if (result.verdict != Verdict::Flake) result.verdict = result.observed;
    if (expectation) applyExpectation(result, expectation->result);
    result.seconds = std::chrono::duration<double>(Clock::now() - start).count() + prefetchedSeconds_;
    return result;
}

void CaseJudge::applyExpectation(CaseResult& result, const std::string& expected) const {
    bool failed = isFailure(result.observed);
    if (expected == "flake") {
        if (failed) result.verdict = Verdict::Flake;
        return;
    }
    if (result.observed == Verdict::Pass) {
        result.verdict = Verdict::UnexpectedPass;
        result.reason += " (expected " + expected + ": " + result.expectation + ")";
        return;
    }
    if (verdictName(result.observed) == expected) {
        result.verdict = Verdict::ExpectedFail;
        result.reason = "as expected (" + result.expectation + "): " + result.reason;
    }
}

void CaseJudge::prefetch(const std::vector<CheckCase>& cases, int jobs) {
    struct Request {
        std::vector<std::string> arguments;
        bool gpuPlants = false, mainPath = false;
        FrameRun run;
    };
    std::vector<Request> requests;
    std::set<std::vector<std::string>> seen;
    for (const CheckCase& c : cases) {
        if (!caseRefused(c, options_).empty()) continue;
        std::vector<std::string> arguments = checkCaseArguments(c, options_), main = checkCaseArguments(c, options_, true);
        if (seen.insert(arguments).second) requests.push_back({arguments, c.value("plants").name == "plants-gpu", false, {}});
        if (seen.insert(main).second && !mainPaths_.count(main)) requests.push_back({main, false, true, {}});
    }
    std::atomic<size_t> next{0};
    auto work = [&] {
        for (size_t k = next++; k < requests.size(); k = next++)
            requests[k].run = runner_.frame(requests[k].arguments, requests[k].gpuPlants);
    };
#ifdef __EMSCRIPTEN__
    (void)jobs;  // the page has one thread: the check runs there in turn
    work();
#else
    std::vector<std::thread> threads;
    for (int t = 1; t < jobs; ++t) threads.emplace_back(work);
    work();
    for (std::thread& thread : threads) thread.join();
#endif
    for (Request& request : requests)
        (request.mainPath ? mainPaths_ : prefetched_)[request.arguments] = std::move(request.run);
}

Verdict CaseJudge::attempt(const CheckCase& c, CaseResult& result, CaseFrame* keptFrame) {
    bool gpuPlants = c.value("plants").name == "plants-gpu";
    FrameRun run;
    if (auto ready = prefetched_.find(result.options); ready != prefetched_.end() && result.runs == 0) {
        run = std::move(ready->second);
        prefetched_.erase(ready);
        prefetchedSeconds_ += run.outcome.seconds;
    } else {
        run = runner_.frame(result.options, gpuPlants);
    }
    result.context = run.frame.context;
    if (run.outcome.end != RunEnd::Finished) {
        result.observed = run.outcome.end == RunEnd::Crashed ? Verdict::Crash : Verdict::Timeout;
        result.reason = "the case's process " + endedHow(run.outcome);
        result.childTail = run.outcome.tail;
        result.ended = run.outcome.detail;
        result.blame = "this path";
        return result.observed;
    }
    if (!run.outcome.error.empty()) {
        result.observed = Verdict::Fail;
        result.reason = "the case did not render: " + run.outcome.error;
        result.blame = "this path";
        return result.observed;
    }
    if (!run.frame.rendered) {
        result.observed = Verdict::Skip;
        result.reason = run.frame.limitedBy + ": " + run.frame.skipReason;
        return result.observed;
    }
    if (keptFrame) *keptFrame = run.frame;
    result.result = run.frame.image;
    std::vector<std::string> failures, notes;
    if (!run.frame.drawnWith.empty()) notes.push_back(run.frame.drawnWith);

    // 1. The case against the reference frame: identical where this very driver drew the reference.
    ReferenceFrame reference = readReferenceFrame(referenceDir_, result.name);
    // A frame drawn with another G-buffer layout than asked for (drawnWith) is not the reference's
    // maths, even on its driver: cross-driver then.
    bool sameDriver = reference.readable && !reference.renderer.empty() && reference.renderer == result.context.renderer &&
                      reference.driverRelease == driverRelease(result.context.glVersion) && run.frame.drawnWith.empty();
    const ImageRule& referenceRule = imageRule(sameDriver ? "identical" : "cross-driver");
    result.referenceRule = referenceRule.name;
    bool caseMatchesReference = false;
    if (!reference.readable) {
        failures.push_back("reference unreadable: " + reference.error);
        result.blame = "the reference set";
    } else if (reference.image.width != result.result.width || reference.image.height != result.result.height) {
        failures.push_back("reference unreadable: it is " + std::to_string(reference.image.width) + "x" +
                           std::to_string(reference.image.height) + ", the case " + kCheckSize);
        result.blame = "the reference set";
        reference.readable = false;
    } else {
        result.reference = reference.image;
        Judgement j = judge(result.result, reference.image, referenceRule);
        result.againstReference = comparisonOf(j);
        caseMatchesReference = j.pass;
        if (!sameDriver)
            if (std::string shift = meanShiftNote(j); !shift.empty()) notes.push_back(shift);
        if (!j.pass) {
            failures.push_back("against the reference frame: " + j.summary);
            result.errorMask = errorMask(result.result, reference.image, referenceRule);
            result.maskAgainst = "the reference frame";
        }
        // 1b. Its interiors, where its child split the pixels by the frame's geometry: the rule
        // binds another driver only (this one is held identical); the numbers are kept for both.
        if (run.frame.pixelClasses.size() == size_t(result.result.width) * size_t(result.result.height)) {
            const ImageRule& interiorRule = imageRule("cross-driver-interior");
            InteriorJudgement i = judgeInterior(result.result, reference.image, run.frame.pixelClasses, interiorRule);
            result.interiorCompared = true;
            result.interiorPixels = i.pixels;
            result.interiorMaxAbs = i.maxAbs;
            result.interiorPixelsOver = i.pixelsOver;
            result.interiorLevel = interiorRule.level;
            result.interiorMeanSigned = i.meanSigned;
            result.interiorPass = i.pass;
            result.pixelClasses = run.frame.pixelClasses;
            if (!sameDriver && !i.pass) {
                caseMatchesReference = false;
                failures.push_back("against the reference frame's interiors: " + i.summary);
                if (result.errorMask.width == 0) {
                    result.errorMask = interiorErrorMask(result.result, reference.image, run.frame.pixelClasses);
                    result.maskAgainst = "the reference frame (interior pixels)";
                }
            }
        }
    }

    // 2. The main path against the reference, 3. the case against its main path.
    const FrameRun& main = mainPath(c, result.runs > 0);
    bool mainRendered = main.outcome.end == RunEnd::Finished && main.outcome.error.empty() && main.frame.rendered;
    bool caseMatchesMain = false, mainMatchesReference = false;
    if (!mainRendered) {
        std::string how = main.outcome.end != RunEnd::Finished ? endedHow(main.outcome)
                          : !main.outcome.error.empty()        ? "did not render: " + main.outcome.error
                                                               : "did not render: " + main.frame.skipReason;
        failures.push_back("the driver's main path " + how);
        if (result.childTail.empty()) result.childTail = main.outcome.tail;
    } else {
        result.mainPathImage = main.frame.image;
        const ImageRule& rule = mainPathRule(c);
        Judgement j = judge(result.result, main.frame.image, rule);
        result.againstMainPath = comparisonOf(j);
        result.mainPathRule = rule.name;
        caseMatchesMain = j.pass;
        if (!j.pass) failures.push_back("against the driver's main path: " + j.summary);
        if (reference.readable) {
            Judgement m = judge(main.frame.image, reference.image, sameDriver ? rule : imageRule("cross-driver"));
            result.mainPathAgainstReference = comparisonOf(m);
            // Another driver's main path is held to the reference's interiors as the case is: a
            // shift both draw is the main path's (or the driver's), not this path's.
            bool interiorsHold = true;
            if (!sameDriver && main.frame.pixelClasses.size() == size_t(main.frame.image.width) * size_t(main.frame.image.height))
                interiorsHold = judgeInterior(main.frame.image, reference.image, main.frame.pixelClasses,
                                              imageRule("cross-driver-interior")).pass;
            result.mainPathMatchesReference = mainMatchesReference = m.pass && interiorsHold;
        }
        if (!j.pass && result.errorMask.width == 0) {
            result.errorMask = errorMask(result.result, main.frame.image, rule);
            result.maskAgainst = "the main path";
        }
    }

    // 4. This driver's own baseline, where one is given: identical, or a regression.
    bool matchesBaseline = true;
    if (!baselineDir_.empty()) {
        ReferenceFrame own = readReferenceFrame(baselineDir_, result.name);
        if (!own.readable) {
            failures.push_back("baseline frame unreadable: " + own.error);
            matchesBaseline = false;
        } else if (own.image.width != result.result.width || own.image.height != result.result.height) {
            failures.push_back("baseline frame unreadable: it is not " + std::string(kCheckSize));
            matchesBaseline = false;
        } else {
            Judgement b = judge(result.result, own.image, imageRule("identical"));
            matchesBaseline = b.pass;
            if (!b.pass) failures.push_back("against this driver's baseline " + baselineDir_ + ": " + b.summary);
        }
    }

    // 5. The shading oracle: the driver's radiance against the CPU's shading of the inputs it read.
    result.oracle = run.frame.oracle;
    const bool oracleFailed = result.oracle.ran && result.oracle.verdict == "fail";
    const bool onlyTheOracle = oracleFailed && failures.empty();
    if (oracleFailed)
        failures.push_back("shading oracle: " + result.oracle.differingTerm + " differs (" + result.oracle.detail + ")");

    // The verdict and whom it blames.
    bool referenceOk = reference.readable && caseMatchesReference;
    if (referenceOk && !mainRendered) {
        // This path draws the reference where the main path does not draw at all.
        std::string mainFailure = "the driver's main path ";
        failures.erase(std::remove_if(failures.begin(), failures.end(),
                                      [&](const std::string& f) { return f.rfind(mainFailure, 0) == 0; }),
                       failures.end());
        notes.push_back("the main path is off: it " + (main.outcome.end != RunEnd::Finished ? endedHow(main.outcome)
                                                       : "did not render") + "; this path matches the reference frame");
    }
    if (referenceOk && mainRendered && !mainMatchesReference && result.mainPathAgainstReference.compared) {
        // This path matches the reference where the main path does not: the main path is off.
        failures.erase(std::remove_if(failures.begin(), failures.end(),
                                      [](const std::string& f) { return f.rfind("against the driver's main path", 0) == 0; }),
                       failures.end());
        notes.push_back("the main path is off: it differs from the reference frame (" +
                        std::to_string(result.mainPathAgainstReference.maxAbs) + " max abs) where this path matches it");
    }
    if (failures.empty()) {
        result.observed = Verdict::Pass;
        result.blame.clear();
        failures.push_back(result.againstReference.compared ? "matches the reference frame" +
                                                          std::string(sameDriver ? " (drawn by this driver: identical)" : "") +
                                                          " and the driver's main path"
                                                    : "matches the driver's main path");
    } else {
        result.observed = Verdict::Fail;
        if (!result.blame.empty()) {
            // already named: the reference set
        } else if (!mainRendered) {
            result.blame = "the main path";
        } else if (!referenceOk && !mainMatchesReference && caseMatchesMain) {
            result.blame = "the main path";  // settled across cases: settleBlame
        } else if (!matchesBaseline && referenceOk && caseMatchesMain) {
            result.blame = "the driver against its baseline";
        } else {
            result.blame = "this path";
        }
        if (!caseMatchesMain && mainRendered && caseMatchesReference == mainMatchesReference && !referenceOk)
            notes.push_back("the main path differs from the reference too");
    }
    failures.insert(failures.end(), notes.begin(), notes.end());
    result.reason = joined(failures);
    // Also where a loose rule (the ES 3.0 tier's same-driver-geometry) let the case match its main
    // path and this path is blamed: the search still finds where the two part above the rule's level.
    // Not where the oracle alone failed: its frame matches its main path, and it names the term.
    if (result.observed == Verdict::Fail && mainRendered && !onlyTheOracle && (!caseMatchesMain || result.blame == "this path"))
        findDivergence(c, result);
    return result.observed;
}

void CaseJudge::findDivergence(const CheckCase& c, CaseResult& result) {
    const Image& main = result.mainPathImage;
    std::vector<bool> where = differingPixels(main, result.result, mainPathRule(c).level);
    PassesRun reference = runner_.passes(checkCaseArguments(c, options_, true), where, main.width, main.height);
    PassesRun candidate = runner_.passes(result.options, where, main.width, main.height);
    for (const PassesRun* run : {&reference, &candidate}) {
        if (run->outcome.end != RunEnd::Finished) {
            result.reason += " (pass by pass: the search's process " + endedHow(run->outcome) + ")";
            return;
        }
        if (!run->outcome.error.empty()) {
            result.reason += " (pass by pass: " + run->outcome.error + ")";
            return;
        }
    }
    Divergence found;
    if (firstDivergence(reference.snapshots, candidate.snapshots, mainPathRule(c).level, {}, found))
        result.firstDivergence = FirstDivergence{found.pass, found.target, found.pixels};
}

bool CaseJudge::frameHolds(const CheckCase& c, const std::vector<std::string>& arguments, std::string& why) {
    FrameRun run = runner_.frame(arguments, false);
    if (run.outcome.end != RunEnd::Finished) {
        why = endedHow(run.outcome);
        return false;
    }
    if (!run.outcome.error.empty()) {
        why = "did not render: " + run.outcome.error;
        return false;
    }
    if (!run.frame.rendered) {
        why = "skipped (" + run.frame.skipReason + ")";
        return true;  // the profile takes the path away: nothing left to go wrong there
    }
    ReferenceFrame reference = readReferenceFrame(referenceDir_, c.name());
    if (!reference.readable || reference.image.width != run.frame.image.width ||
        reference.image.height != run.frame.image.height) {
        why = "rendered (no reference to judge it by)";
        return true;
    }
    Judgement j = judge(run.frame.image, reference.image, imageRule("cross-driver"));
    why = j.pass ? "matches the reference" : "against the reference: " + j.summary;
    return j.pass;
}

void CaseJudge::settleBlame(std::vector<CaseResult>& cases) const {
    bool someFallbackMatches = std::any_of(cases.begin(), cases.end(), [](const CaseResult& c) {
        return c.observed == Verdict::Pass && !c.mainPathMatchesReference;
    });
    for (CaseResult& c : cases)
        if (c.blame == "the main path" && c.againstMainPath.compared && !someFallbackMatches)
            c.blame = "the driver against the reference";
}

}  // namespace oasis
