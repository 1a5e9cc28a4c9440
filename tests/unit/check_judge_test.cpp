// oasis check's image rules (check/check_judge.h): a frame passes or fails each rule by its own
// numbers, and the error mask marks exactly the pixels above the rule's level.
#include <gtest/gtest.h>

#include "check/check_case_judge.h"
#include "check/check_cases.h"
#include "check/check_judge.h"

namespace oasis {
namespace {

Image flat(int width, int height, uint8_t value) {
    Image image(width, height);
    for (size_t i = 0; i < image.rgba.size(); ++i) image.rgba[i] = (i % 4 == 3) ? 255 : value;
    return image;
}

TEST(CheckJudge, OneLevelAtOnePixelFailsIdenticalOnly) {
    Image reference = flat(64, 36, 100), result = reference;
    result.pixel(10, 5)[1] = 101;
    EXPECT_FALSE(judge(result, reference, imageRule("identical")).pass);
    Judgement fallback = judge(result, reference, imageRule("same-driver-fallback"));
    EXPECT_TRUE(fallback.pass);
    EXPECT_EQ(fallback.maxAbs, 1);
    EXPECT_EQ(fallback.pixelsOver, 0);  // a pixel differs only above the rule's level
    EXPECT_TRUE(judge(result, reference, imageRule("cross-driver")).pass);
}

TEST(CheckJudge, ThePixelCapDecidesForAnotherRasteriser) {
    const ImageRule& rule = imageRule("cross-driver");
    Image reference = flat(100, 100, 80), result = reference;
    int allowed = int(rule.maxFractionOver * 100 * 100);
    for (int i = 0; i < allowed; ++i) result.pixel(i % 100, i / 100)[0] = 80 + rule.level + 1;
    Judgement atCap = judge(result, reference, rule);
    EXPECT_EQ(atCap.pixelsOver, allowed);
    EXPECT_TRUE(atCap.pass) << atCap.summary;
    result.pixel(99, 99)[0] = 80 + rule.level + 1;
    EXPECT_FALSE(judge(result, reference, rule).pass);
}

TEST(CheckJudge, TheMaskMarksThePixelsOverTheLevel) {
    const ImageRule& rule = imageRule("same-driver-fallback");
    Image reference = flat(8, 4, 40), result = reference;
    result.pixel(3, 2)[2] = 40 + rule.level + 1;  // over
    result.pixel(5, 1)[0] = 40 + rule.level;      // not over
    Image mask = errorMask(result, reference, rule);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x) EXPECT_EQ(mask.pixel(x, y)[0] == 255, x == 3 && y == 2) << x << "," << y;
}

// The ES 3.0 tier draws the water and the shadow cascades by other geometry than its main path: a
// few shore pixels far apart pass (SwiftShader's 5 pixels at 211 levels), a frame 3% too bright does not.
TEST(CheckJudge, OtherGeometryPassesAtTheShoreNotAShiftedFrame) {
    const ImageRule& rule = imageRule("same-driver-geometry");
    Image reference = flat(256, 144, 150), result = reference;
    for (int i = 0; i < 5; ++i) result.pixel(40 + i, 60)[0] = 150 - 140;
    EXPECT_TRUE(judge(result, reference, rule).pass) << judge(result, reference, rule).summary;
    EXPECT_FALSE(judge(result, reference, imageRule("same-driver-fallback")).pass);
    Image brighter = reference;
    for (size_t i = 0; i < brighter.rgba.size(); ++i)
        if (i % 4 != 3) brighter.rgba[i] = uint8_t(150 * 103 / 100);
    EXPECT_FALSE(judge(brighter, reference, rule).pass) << judge(brighter, reference, rule).summary;
}

TEST(CheckJudge, EachCaseIsHeldToItsMainPathByWhatItsPathPromises) {
    int es30 = 0, tiled = 0, same = 0;
    for (const CheckCase& c : coveringCases()) {
        const std::string& rule = mainPathRule(c).name;
        if (c.value("tier").name == "gles30") {
            EXPECT_EQ(rule, "same-driver-geometry") << c.name();
            ++es30;
        } else if (c.value("light-method").name == "tiled") {
            EXPECT_EQ(rule, "same-driver-fallback") << c.name();
            ++tiled;
        } else {
            EXPECT_EQ(rule, "identical") << c.name();
            ++same;
        }
    }
    EXPECT_GT(es30, 0);
    EXPECT_GT(tiled, 0);
    EXPECT_GT(same, 0);
}

// The mean signed difference sees a shift that the per-pixel tests let through, and edge
// differences of both signs cancel in it.
TEST(CheckJudge, TheMeanSignedDifferenceIsTheShiftNotTheEdges) {
    Image reference = flat(64, 36, 100), shifted = reference, edges = reference;
    for (size_t i = 0; i < shifted.rgba.size(); ++i)
        if (i % 4 != 3) shifted.rgba[i] = 103;
    Judgement shift = judge(shifted, reference, imageRule("cross-driver"));
    EXPECT_TRUE(shift.pass);  // 3 levels everywhere passes the cross-driver rule's per-pixel tests
    EXPECT_DOUBLE_EQ(shift.meanSigned, 3.0);
    for (int x = 0; x < 64; ++x) {
        edges.pixel(x, 10)[0] = 200;  // one row brighter by 100 in red,
        edges.pixel(x, 20)[0] = 0;    // one darker by 100
    }
    Judgement edge = judge(edges, reference, imageRule("cross-driver"));
    EXPECT_EQ(edge.maxAbs, 100);
    EXPECT_DOUBLE_EQ(edge.meanSigned, 0.0);
    EXPECT_NE(shift.summary.find("mean +3.000 levels"), std::string::npos) << shift.summary;
    // The note on a shift beyond every measured driver's: the shift has it, the edges do not.
    EXPECT_NE(meanShiftNote(shift).find("+3.00 levels"), std::string::npos) << meanShiftNote(shift);
    EXPECT_NE(meanShiftNote(shift).find("too bright"), std::string::npos);
    EXPECT_EQ(meanShiftNote(edge), "");
}

TEST(CheckJudge, SizesMustAgree) {
    EXPECT_THROW(judge(flat(4, 4, 0), flat(4, 5, 0), imageRule("identical")), std::invalid_argument);
    EXPECT_THROW(imageRule("no-such-rule"), std::invalid_argument);
}

}  // namespace
}  // namespace oasis
