// Covers src/check/check_diff.h: two reports written by check_report.cpp's checkReportJson read
// back and compared: a regression, a fix, a new skip, a skip no longer, numbers that moved (and one
// that moved too little), new and removed cases; the exit statuses of `oasis check --diff` (0, 1, 2)
// and its messages for files that are missing, not JSON or not a check report.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "check/check_diff.h"
#include "check/check_report.h"

namespace oasis {
namespace {

CaseResult makeCase(const std::string& name, Verdict verdict, double psnrDb = 45.0, int maxAbs = 2, long pixelsOver = 0) {
    CaseResult c;
    c.name = name;
    c.verdict = verdict;
    c.againstReference = {verdict != Verdict::Skip, psnrDb, maxAbs, pixelsOver, 0.0};  // a skip has no numbers
    c.reason = verdict == Verdict::Skip ? "the driver has no SSBOs" : "within the rule";
    return c;
}

CheckReport makeReport(const std::string& renderer, std::vector<CaseResult> cases) {
    CheckReport report;
    report.renderer = renderer;
    report.vendor = "Mesa";
    report.oasisVersion = "0.9";
    report.cases = std::move(cases);
    return report;
}

CheckRun runOf(const CheckReport& report, const std::string& path) {
    CheckRun run;
    std::string error;
    EXPECT_TRUE(parseCheckRun(checkReportJson(report), run, error)) << error;
    run.path = path;
    return run;
}

// A: the driver before; B: after. Each case of B stands for one section of the diff.
CheckReport before() {
    return makeReport("llvmpipe (LLVM 15.0.6, 256 bits)",
                      {makeCase("regressed", Verdict::Pass), makeCase("fixed", Verdict::Fail, 20.0, 90, 4000),
                       makeCase("newly-skipped", Verdict::Pass), makeCase("moved", Verdict::Pass, 45.0, 2, 0),
                       makeCase("moved-little", Verdict::Pass, 45.0, 2, 0), makeCase("unskipped", Verdict::Skip),
                       makeCase("still-skipped", Verdict::Skip), makeCase("removed", Verdict::Pass)});
}

CheckReport after() {
    CaseResult regressed = makeCase("regressed", Verdict::Fail, 28.25, 61, 1204);
    regressed.reason = "1204 pixels over the rule's level";
    regressed.firstDivergence = FirstDivergence{"LightVolumePass", "Radiance", 1204};
    return makeReport("NVIDIA GeForce RTX 4090/PCIe/SSE2",
                      {regressed, makeCase("fixed", Verdict::Pass), makeCase("newly-skipped", Verdict::Skip),
                       makeCase("moved", Verdict::Pass, 43.0, 3, 0), makeCase("moved-little", Verdict::Pass, 45.3, 2, 0),
                       makeCase("unskipped", Verdict::Fail, 30.0, 40, 300), makeCase("still-skipped", Verdict::Skip),
                       makeCase("added", Verdict::Pass)});
}

std::vector<std::string> names(const std::vector<CaseChange>& changes) {
    std::vector<std::string> out;
    for (const CaseChange& change : changes) out.push_back(change.name);
    return out;
}

TEST(CheckDiff, ReadsWhatTheReportWriterWrites) {
    CheckRun run = runOf(after(), "b.json");
    EXPECT_EQ(run.renderer, "NVIDIA GeForce RTX 4090/PCIe/SSE2");
    EXPECT_EQ(run.vendor, "Mesa");
    ASSERT_EQ(run.cases.size(), 8u);
    const CheckedCase& regressed = run.cases[0];
    EXPECT_EQ(regressed.verdict, "fail");
    EXPECT_TRUE(regressed.hasNumbers);
    EXPECT_NEAR(regressed.psnrDb, 28.25, 1e-9);
    EXPECT_EQ(regressed.maxAbs, 61);
    EXPECT_EQ(regressed.pixelsOver, 1204);
    EXPECT_EQ(regressed.firstDivergence, "LightVolumePass/Radiance, 1204 pixels");
    EXPECT_FALSE(run.cases[2].hasNumbers);  // a skip's numbers are null
    EXPECT_EQ(run.count("pass"), 4);
    EXPECT_EQ(run.count("fail"), 2);
    EXPECT_EQ(run.count("skip"), 2);
}

TEST(CheckDiff, SortsEveryChangeIntoItsSection) {
    CheckRun a = runOf(before(), "a.json"), b = runOf(after(), "b.json");
    CheckDiff diff = diffCheckRuns(a, b);
    using Names = std::vector<std::string>;
    EXPECT_EQ(names(diff.regressions), Names{"regressed"});
    EXPECT_EQ(names(diff.fixes), Names{"fixed"});
    EXPECT_EQ(names(diff.newSkips), Names{"newly-skipped"});
    EXPECT_EQ(names(diff.noLongerSkipped), Names{"unskipped"});
    EXPECT_EQ(names(diff.changedNumbers), Names{"moved"});  // 0.3 dB alone is not a change
    ASSERT_EQ(diff.newCases.size(), 1u);
    EXPECT_EQ(diff.newCases[0].name, "added");
    ASSERT_EQ(diff.removedCases.size(), 1u);
    EXPECT_EQ(diff.removedCases[0].name, "removed");
    EXPECT_EQ(diff.exitCode(), 1);
}

TEST(CheckDiff, PrintsDriversCountsAndSections) {
    CheckRun a = runOf(before(), "a.json"), b = runOf(after(), "b.json");
    std::string text = checkDiffText(a, b, diffCheckRuns(a, b));
    for (const char* expected : {
             "A: a.json\n   llvmpipe (LLVM 15.0.6, 256 bits) (Mesa), oasis 0.9\n   pass 5, fail 1, skip 2\n",
             "B: b.json\n   NVIDIA GeForce RTX 4090/PCIe/SSE2 (Mesa), oasis 0.9\n   pass 4, fail 2, skip 2\n",
             "regressions (1)\n  regressed: pass -> fail; PSNR 45.00 -> 28.25 dB, max abs 2 -> 61, pixels over 0 -> 1204; "
             "first diverges at LightVolumePass/Radiance, 1204 pixels; 1204 pixels over the rule's level\n",
             "fixes (1)\n  fixed: fail -> pass; PSNR 20.00 -> 45.00 dB, max abs 90 -> 2, pixels over 4000 -> 0",
             "new skips (1)\n  newly-skipped: pass -> skip; the driver has no SSBOs\n",
             "no longer skipped (1)\n  unskipped: skip -> fail; PSNR 30.00 dB, max abs 40, pixels over 300; within the rule\n",
             "changed numbers (1)\n  moved: PSNR 45.00 -> 43.00 dB, max abs 2 -> 3; within the rule\n",
             "new cases (1)\n  added: pass; PSNR 45.00 dB, max abs 2, pixels over 0; within the rule\n",
             "removed cases (1)\n  removed: pass;"}) {
        EXPECT_NE(text.find(expected), std::string::npos) << "missing: " << expected << "\nin:\n" << text;
    }
}

TEST(CheckDiff, NoRegressionIsExitZero) {
    CheckRun a = runOf(before(), "a.json");
    CheckDiff same = diffCheckRuns(a, a);
    EXPECT_EQ(same.exitCode(), 0);
    EXPECT_TRUE(same.fixes.empty() && same.changedNumbers.empty() && same.newCases.empty() && same.removedCases.empty());
    // A fix alone, and a failing case that fails worse, are not regressions.
    CheckReport worse = before();
    worse.cases[1].againstReference.maxAbs = 120;
    CheckDiff diff = diffCheckRuns(a, runOf(worse, "b.json"));
    EXPECT_EQ(names(diff.changedNumbers), std::vector<std::string>{"fixed"});
    EXPECT_EQ(diff.exitCode(), 0);
}

TEST(CheckDiff, RefusesWhatIsNotACheckReport) {
    CheckRun run;
    std::string error;
    EXPECT_FALSE(parseCheckRun("{\"cases\": [", run, error));
    EXPECT_NE(error.find("not valid JSON: at byte 11"), std::string::npos) << error;
    EXPECT_FALSE(parseCheckRun("{\"psnr_db\": 40}", run, error));
    EXPECT_NE(error.find("not an oasis check report"), std::string::npos) << error;
    EXPECT_FALSE(parseCheckRun("{\"schema\": \"oasis-check/1\"}", run, error));
    EXPECT_NE(error.find("no \"cases\" list"), std::string::npos) << error;
    EXPECT_FALSE(parseCheckRun("{\"schema\": \"oasis-check/1\", \"cases\": [{\"name\": \"a\", \"verdict\": \"maybe\"}]}", run, error));
    EXPECT_NE(error.find("case 1 (a) has verdict \"maybe\""), std::string::npos) << error;
    EXPECT_FALSE(parseCheckRun("{\"schema\": \"oasis-check/1\", \"cases\": [{\"verdict\": \"pass\"}]}", run, error));
    EXPECT_NE(error.find("case 1 \"name\" is missing"), std::string::npos) << error;
    EXPECT_FALSE(parseCheckRun("{\"schema\": \"oasis-check/1\", \"cases\": [{\"name\": \"a\", \"verdict\": \"pass\", "
                               "\"psnr_db\": \"40\"}]}", run, error));
    EXPECT_NE(error.find("\"psnr_db\" is neither a number nor null"), std::string::npos) << error;
    CheckReport twice = before();
    twice.cases.push_back(twice.cases[0]);
    EXPECT_FALSE(parseCheckRun(checkReportJson(twice), run, error));
    EXPECT_NE(error.find("case regressed appears twice"), std::string::npos) << error;
}

// Issue 42, defect 6: numbers out of their field's range, wrong types, a key twice, a NUL and no
// cases are exit 2 naming the key and why; strings reach the printed text escaped.
TEST(CheckDiff, RefusesOutOfRangeNumbersWrongTypesAndNoCases) {
    auto report = [](const std::string& fields) {
        return "{\"schema\": \"oasis-check/1\", \"cases\": [{\"name\": \"a\", \"verdict\": \"pass\"" + fields + "}]}";
    };
    const std::pair<const char*, const char*> bad[] = {
        {", \"max_abs\": 1e300", "\"max_abs\" is 1.0000000000000001e+300: out of its range (an integer in 0..255)"},
        {", \"max_abs\": -1", "\"max_abs\" is -1: out of its range"},
        {", \"max_abs\": 2.5", "\"max_abs\" is 2.5: out of its range (an integer"},
        {", \"pixels_over\": -3", "\"pixels_over\" is -3: out of its range"},
        {", \"pixels_over\": 0.5", "\"pixels_over\" is 0.5"},
        {", \"psnr_db\": -1", "\"psnr_db\" is -1: out of its range (a number in 0..100)"},
        {", \"psnr_db\": 1e300", "\"psnr_db\" is 1.0000000000000001e+300"},
        {", \"reason\": 5", "\"reason\" is not a string"},
        {", \"first_divergence\": {\"pixels\": -5}", "\"first_divergence\": \"pixels\" is -5"},
        {", \"first_divergence\": 3", "\"first_divergence\" is neither an object nor null"},
        {", \"verdict\": \"fail\"", "the key 'verdict' appears twice"},
        {", \"reason\": \"a\\u0000b\"", "a string holds a NUL"},
    };
    CheckRun run;
    std::string error;
    for (const auto& [fields, why] : bad) {
        EXPECT_FALSE(parseCheckRun(report(fields), run, error)) << fields;
        EXPECT_NE(error.find(why), std::string::npos) << fields << " -> " << error;
    }
    EXPECT_TRUE(parseCheckRun(report(", \"max_abs\": 255, \"pixels_over\": 0, \"psnr_db\": 100"), run, error)) << error;
    EXPECT_FALSE(parseCheckRun("{\"schema\": \"oasis-check/1\", \"cases\": []}", run, error));
    EXPECT_NE(error.find("\"cases\" is empty"), std::string::npos) << error;
    EXPECT_FALSE(parseCheckRun("{\"schema\": \"oasis-check/1\", \"cases\": [{\"name\": 3, \"verdict\": \"pass\"}]}", run, error));
    EXPECT_NE(error.find("\"name\" is not a string"), std::string::npos) << error;

    CheckReport a = before(), b = after();
    b.cases[0].name = "regressed";
    b.cases[0].reason = "fake\x1b[1A\x1b[2Kline\rover\x7f";
    b.renderer = "evil\x1b]0;title\x07";
    CheckRun runA = runOf(a, "a.json"), runB = runOf(b, "b\x1b[2J.json");
    std::string text = checkDiffText(runA, runB, diffCheckRuns(runA, runB));
    for (char raw : {'\x1b', '\r', '\x7f', '\x07'}) EXPECT_EQ(text.find(raw), std::string::npos) << text;
    EXPECT_NE(text.find("fake\\u001B[1A\\u001B[2Kline\\rover\\u007F"), std::string::npos) << text;
    EXPECT_NE(text.find("evil\\u001B]0;title\\u0007"), std::string::npos) << text;
}

std::string writeFile(const std::string& name, const std::string& text) {
    std::string path = ::testing::TempDir() + "check_diff_test_" + name;
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

struct Printed {
    int code;
    std::string out, err;
};

Printed runDiff(const std::string& a, const std::string& b) {
    ::testing::internal::CaptureStdout();
    ::testing::internal::CaptureStderr();
    Printed printed;
    printed.code = runCheckDiff(a, b);
    printed.out = ::testing::internal::GetCapturedStdout();
    printed.err = ::testing::internal::GetCapturedStderr();
    return printed;
}

TEST(CheckDiff, ExitStatusesOfTheCommand) {
    std::string a = writeFile("a.json", checkReportJson(before()));
    std::string b = writeFile("b.json", checkReportJson(after()));
    Printed regressed = runDiff(a, b);
    EXPECT_EQ(regressed.code, 1);
    EXPECT_NE(regressed.out.find("regressions (1)\n  regressed: pass -> fail"), std::string::npos) << regressed.out;
    EXPECT_EQ(regressed.err, "");
    CheckReport onlyFixed = before();
    onlyFixed.cases[1] = makeCase("fixed", Verdict::Pass);
    Printed fixed = runDiff(a, writeFile("fixed.json", checkReportJson(onlyFixed)));
    EXPECT_EQ(fixed.code, 0);
    EXPECT_NE(fixed.out.find("regressions (0)\nfixes (1)\n  fixed: fail -> pass"), std::string::npos) << fixed.out;

    std::string missing = ::testing::TempDir() + "check_diff_test_missing.json";
    Printed noFile = runDiff(a, missing);
    EXPECT_EQ(noFile.code, 2);
    EXPECT_EQ(noFile.out, "");
    EXPECT_NE(noFile.err.find("oasis: check --diff: cannot read " + missing + ": "), std::string::npos) << noFile.err;

    std::string broken = writeFile("broken.json", "{\"schema\": \"oasis-check/1\", \"cases\": [}");
    Printed notJson = runDiff(broken, b);
    EXPECT_EQ(notJson.code, 2);
    EXPECT_NE(notJson.err.find(broken + ": not valid JSON: at byte 38"), std::string::npos) << notJson.err;

    Printed directory = runDiff(a, ::testing::TempDir());
    EXPECT_EQ(directory.code, 2);
    EXPECT_NE(directory.err.find("it is a directory"), std::string::npos) << directory.err;
}

}  // namespace
}  // namespace oasis
