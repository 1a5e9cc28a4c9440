// The check's CI-farm pieces without GL: the expectations file, the pass snapshots that cross from a
// child process, the driver's release in a version string, the JUnit file and the verdicts.
#include <gtest/gtest.h>

#include "check/check_expectations.h"
#include "check/check_references.h"
#include "check/check_report.h"
#include "check/check_snapshots.h"

namespace oasis {
namespace {

TEST(CheckExpectations, ReadsRulesCommentsAndRendererRegexes) {
    std::vector<Expectation> rules;
    std::string error;
    ASSERT_TRUE(parseExpectations("# known\n\n01-* renderer /llvmpipe/ = crash   # aborts\n*-ubo-*=fail\n  04-* = skip\n",
                                  rules, error))
        << error;
    ASSERT_EQ(rules.size(), 3u);
    EXPECT_EQ(rules[0].glob, "01-*");
    EXPECT_EQ(rules[0].rendererRegex, "llvmpipe");
    EXPECT_EQ(rules[0].result, "crash");
    EXPECT_EQ(rules[0].reason, "aborts");
    EXPECT_EQ(rules[0].line, 3);
    EXPECT_EQ(rules[1].result, "fail");
    EXPECT_EQ(rules[2].line, 5);
    // The first matching rule applies; a renderer regex that does not match leaves the rule out.
    EXPECT_EQ(findExpectation(rules, "01-day", "llvmpipe (LLVM 15.0.6, 256 bits)")->result, "crash");
    EXPECT_FALSE(findExpectation(rules, "01-day", "NVIDIA H200"));
    EXPECT_EQ(findExpectation(rules, "22-dusk-x-ubo-volumes", "any")->result, "fail");
    EXPECT_FALSE(findExpectation(rules, "37-far", "any"));
}

TEST(CheckExpectations, ABadLineIsRefusedNamingIt) {
    std::vector<Expectation> rules;
    std::string error;
    for (const auto& [text, why] : std::vector<std::pair<std::string, std::string>>{
             {"ok-* = fail\n01-* = broken\n", "line 2: the result 'broken'"},
             {"01-*\n", "line 1: expected 'CASE-GLOB"},
             {"= fail\n", "line 1: no case glob"},
             {"01-* llvmpipe = fail\n", "line 1: expected 'renderer /REGEX/'"},
             {"01-* renderer llvmpipe = fail\n", "between slashes"},
             {"01-* renderer /(/ = fail\n", "does not compile"},
             {std::string("01-* = fail\0x", 13), "a NUL byte"}}) {
        rules.clear();
        EXPECT_FALSE(parseExpectations(text, rules, error)) << text;
        EXPECT_NE(error.find(why), std::string::npos) << error;
    }
}

TEST(CheckSnapshots, RoundTripAndTruncationRefused) {
    std::vector<PassSnapshot> snapshots = {{"TerrainPass", {{"Albedo", {0.25f, 0.5f, 1.0f, 1.0f, 2.0f, 3.0f, 4.0f, 5.0f}}}},
                                           {"LightingPass", {{"Radiance", {1e-7f, -2.5f, 65504.0f, 0.0f}}, {"Final", {}}}}};
    std::string bytes = encodeSnapshots(snapshots), error;
    std::vector<PassSnapshot> back;
    ASSERT_TRUE(decodeSnapshots(bytes, back, error)) << error;
    ASSERT_EQ(back.size(), 2u);
    EXPECT_EQ(back[1].pass, "LightingPass");
    EXPECT_EQ(back[1].targets[0].second, snapshots[1].targets[0].second);
    EXPECT_EQ(back[0].targets[0].second, snapshots[0].targets[0].second);
    for (size_t cut : {size_t(0), size_t(5), bytes.size() / 2, bytes.size() - 1})
        EXPECT_FALSE(decodeSnapshots(bytes.substr(0, cut), back, error)) << cut;
    EXPECT_FALSE(decodeSnapshots(bytes + "x", back, error));
}

TEST(CheckSnapshots, KeepPixelsKeepsTheMaskedOnesInOrder) {
    std::vector<PassSnapshot> snapshots = {{"A", {{"T", {0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2}}}}};
    keepPixels(snapshots, {false, true, true});
    EXPECT_EQ(snapshots[0].targets[0].second, (std::vector<float>{1, 1, 1, 1, 2, 2, 2, 2}));
    keepPixels(snapshots, {});  // an empty mask keeps everything
    EXPECT_EQ(snapshots[0].targets[0].second.size(), 8u);
}

TEST(CheckReferences, TheDriverReleaseIsTheSameAcrossTiers) {
    EXPECT_EQ(driverRelease("4.5 (Core Profile) Mesa 22.3.6"), "Mesa 22.3.6");
    EXPECT_EQ(driverRelease("3.3 (Core Profile) Mesa 22.3.6"), "Mesa 22.3.6");
    EXPECT_EQ(driverRelease("OpenGL ES 3.2 Mesa 22.3.6"), "Mesa 22.3.6");
    EXPECT_EQ(driverRelease("4.6.0 NVIDIA 580.159.04"), "NVIDIA 580.159.04");
    EXPECT_NE(driverRelease("4.5 (Core Profile) Mesa 22.3.6"), driverRelease("4.5 (Core Profile) Mesa 23.0.1"));
}

TEST(CheckReport, OnlyFailCrashTimeoutAndUnexpectedPassAreUnexpected) {
    for (Verdict verdict : allVerdicts())
        EXPECT_EQ(unexpected(verdict), verdict == Verdict::Fail || verdict == Verdict::Crash ||
                                           verdict == Verdict::Timeout || verdict == Verdict::UnexpectedPass)
            << verdictName(verdict);
    CheckReport report;
    for (Verdict verdict : allVerdicts()) {
        CaseResult c;
        c.name = std::string("case-") + verdictName(verdict);
        c.verdict = verdict;
        c.reason = "because <&>";
        c.reproduce = "oasis render --size 256x144 --out x.png";
        report.cases.push_back(c);
    }
    EXPECT_EQ(report.failed(), 4);
    std::string json = checkReportJson(report);
    EXPECT_NE(json.find("\"unexpected\": 4"), std::string::npos);
    EXPECT_NE(json.find("\"expected_fail\": 1"), std::string::npos);
    std::string junit = checkReportJunit(report);
    EXPECT_NE(junit.find("tests=\"8\" failures=\"4\" skipped=\"1\""), std::string::npos) << junit;
    EXPECT_NE(junit.find("<failure type=\"crash\""), std::string::npos);
    EXPECT_NE(junit.find("reproduce: oasis render --size 256x144"), std::string::npos);
    EXPECT_NE(junit.find("because &lt;&amp;&gt;"), std::string::npos);
    EXPECT_EQ(junit.find("because <&>"), std::string::npos);
}

}  // namespace
}  // namespace oasis
