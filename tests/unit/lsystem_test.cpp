// L-system rewriting (exact symbol counts), the turtle program encoding, and agreement between the
// serial and the composition-based turtle interpreters.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

#include "scene/lsystem.h"
#include "scene/turtle.h"

namespace oasis {
namespace {

using Counts = std::map<char, uint64_t>;

// The rules as published, kept apart from the preset table so a typo there cannot hide.
struct PublishedRules {
    const char* preset;
    std::string axiom;
    std::map<char, std::string> rules;
    float angleDegrees;
};
const std::vector<PublishedRules>& publishedRules() {
    static const std::vector<PublishedRules> rules = {
        {"fractal-plant", "X", {{'X', "F+[[X]-X]-F[-FX]+X"}, {'F', "FF"}}, 25.0f},
        {"bush", "F", {{'F', "FF-[-F+F+F]+[+F-F-F]"}}, 22.5f},   // ABOP fig. 1.24c
        {"weed", "F", {{'F', "F[+F]F[-F]F"}}, 25.7f},            // ABOP fig. 1.24a
        {"grass", "F", {{'F', "F[+F]F[-F][F]"}}, 20.0f},         // ABOP fig. 1.24b
        {"sprig", "X", {{'X', "F[+X][-X]FX"}, {'F', "FF"}}, 25.7f},  // ABOP fig. 1.24e
    };
    return rules;
}

Counts countsOf(const std::string& s) {
    Counts counts;
    for (char c : s) ++counts[c];
    return counts;
}

// Symbol counts after n rewrites without building any string: each symbol's count multiplies
// through the counts of its replacement (a symbol without a rule maps to itself).
Counts predictCounts(const PublishedRules& system, int iterations) {
    Counts counts = countsOf(system.axiom);
    for (int i = 0; i < iterations; ++i) {
        Counts next;
        for (auto [symbol, count] : counts) {
            auto rule = system.rules.find(symbol);
            if (rule == system.rules.end()) {
                next[symbol] += count;
                continue;
            }
            for (auto [produced, times] : countsOf(rule->second)) next[produced] += count * times;
        }
        counts = next;
    }
    return counts;
}

void expectCountsMatch(const Counts& expected, const std::string& generation) {
    SymbolCounts actual = countSymbols(generation);
    uint64_t expectedTotal = 0;
    for (auto [symbol, count] : expected) {
        EXPECT_EQ(actual[static_cast<unsigned char>(symbol)], count) << "symbol " << symbol;
        expectedTotal += count;
    }
    EXPECT_EQ(generation.size(), expectedTotal);  // and no symbol outside `expected`
}

uint64_t pow64(uint64_t base, int exponent) {
    uint64_t result = 1;
    while (exponent-- > 0) result *= base;
    return result;
}

TEST(LSystem, FractalPlantLengthsMatchTheKnownSequence) {
    const PlantPreset* plant = findPlantPreset("fractal-plant");
    ASSERT_NE(plant, nullptr);
    const uint64_t known[] = {1, 18, 89, 379, 1551, 6263};
    for (int n = 0; n <= 5; ++n) EXPECT_EQ(rewrite(plant->system, n).size(), known[n]) << n;
}

// Closed forms for X -> F+[[X]-X]-F[-FX]+X, F -> FF (per X: 3 F, 4 X, 2 '+', 3 '-', 3 '[', 3 ']'):
//   X_n = 4^n                         (each X makes four X)
//   F_n = 2 F_{n-1} + 3 X_{n-1}  =>   F_n = 3 (4^n - 2^n) / 2
//   a constant c appearing k times per X: c_n = c_{n-1} + k 4^{n-1} = k (4^n - 1) / 3
// e.g. n = 1: 4 + 3 + 11 = 18, n = 5: 1024 + 1488 + 3751 = 6263.
TEST(LSystem, FractalPlantSymbolCountsFollowTheClosedForms) {
    const PlantPreset* plant = findPlantPreset("fractal-plant");
    ASSERT_NE(plant, nullptr);
    for (int n = 1; n <= 8; ++n) {
        uint64_t fourToN = pow64(4, n), twoToN = pow64(2, n), geometric = (fourToN - 1) / 3;
        Counts expected = {{'X', fourToN},       {'F', 3 * (fourToN - twoToN) / 2},
                           {'+', 2 * geometric}, {'-', 3 * geometric},
                           {'[', 3 * geometric}, {']', 3 * geometric}};
        SCOPED_TRACE("iteration " + std::to_string(n));
        expectCountsMatch(expected, rewrite(plant->system, n));
    }
    // The thesis quotes 60 074 lines after eight rewrites; these rules give 3 (4^8 - 2^8) / 2.
    EXPECT_EQ(countSymbol(rewrite(plant->system, 8), 'F'), 97920u);
}

TEST(LSystem, PresetTableHoldsThePublishedRules) {
    ASSERT_EQ(plantPresets().size(), publishedRules().size());
    for (const PublishedRules& published : publishedRules()) {
        const PlantPreset* preset = findPlantPreset(published.preset);
        ASSERT_NE(preset, nullptr) << published.preset;
        EXPECT_EQ(preset->system.axiom, published.axiom) << published.preset;
        EXPECT_EQ(preset->system.rules, published.rules) << published.preset;
        EXPECT_FLOAT_EQ(preset->system.angleDegrees, published.angleDegrees) << published.preset;
        EXPECT_GT(preset->system.iterations, 0);
        EXPECT_GT(preset->segmentLengthScale, 0.0f);
        EXPECT_LT(preset->segmentLengthScale, 1.0f);
    }
    EXPECT_EQ(findPlantPreset("no-such-plant"), nullptr);
}

TEST(LSystem, EveryPresetMatchesTheCountRecurrence) {
    for (const PublishedRules& published : publishedRules()) {
        const PlantPreset* preset = findPlantPreset(published.preset);
        ASSERT_NE(preset, nullptr);
        for (int n = 0; n <= 5; ++n) {
            SCOPED_TRACE(std::string(published.preset) + " iteration " + std::to_string(n));
            expectCountsMatch(predictCounts(published, n), rewrite(preset->system, n));
        }
    }
}

TEST(LSystem, KnownCountsOfTheOtherPresets) {
    // By hand from the rules: bush F -> FF-[-F+F+F]+[+F-F-F] has 8 F in 20 symbols, so 8^n F;
    // weed and grass have 5 F per F (5^n); sprig's X -> F[+X][-X]FX has 3 X (3^n X).
    auto generation = [](const char* name, int n) {
        return rewrite(findPlantPreset(name)->system, n);
    };
    EXPECT_EQ(generation("bush", 1).size(), 20u);
    EXPECT_EQ(countSymbol(generation("bush", 4), 'F'), 4096u);
    EXPECT_EQ(countSymbol(generation("weed", 5), 'F'), 3125u);
    EXPECT_EQ(countSymbol(generation("grass", 5), 'F'), 3125u);
    EXPECT_EQ(countSymbol(generation("sprig", 7), 'X'), 2187u);
}

TEST(LSystem, SymbolsWithoutRulesCopyThemselves) {
    LSystem system{"AB+", {{'A', "AB"}}, 90.0f, 2};
    EXPECT_EQ(rewrite(system, 0), "AB+");
    EXPECT_EQ(rewrite(system, 1), "ABB+");
    EXPECT_EQ(rewrite(system, 2), "ABBB+");
    EXPECT_EQ(alphabet(system), "+AB");
    EXPECT_EQ(alphabet(findPlantPreset("fractal-plant")->system), "+-FX[]");
}

TEST(LSystem, PredictedCountsEqualTheRewrittenStrings) {
    for (const PlantPreset& preset : plantPresets())
        for (int n = 0; n <= 6; ++n) {
            std::string generation = rewrite(preset.system, n);
            EXPECT_EQ(predictSymbolCounts(preset.system, n), countSymbols(generation)) << preset.name;
            EXPECT_EQ(predictLength(preset.system, n), generation.size()) << preset.name;
        }
}

TEST(LSystem, RunawayGrowthIsRefusedBeforeBuilding) {
    LSystem doubling{"F", {{'F', "FF"}}, 0.0f, 0};
    EXPECT_EQ(rewrite(doubling, 4, 16).size(), 16u);
    EXPECT_THROW(rewrite(doubling, 5, 16), std::length_error);
    EXPECT_THROW(rewrite(doubling, 40), std::length_error);
    EXPECT_EQ(predictLength(doubling, 63), uint64_t(1) << 63);
    EXPECT_EQ(predictLength(doubling, 200), UINT64_MAX);  // saturates, does not wrap
    EXPECT_THROW(rewrite(doubling, 200), std::length_error);
}

TEST(TurtleProgram, EncodingDropsNonTurtleSymbols) {
    TurtleProgram program = encodeTurtleProgram("FX+[-F]Y");
    const TurtleProgram expected = {uint32_t(TurtleOp::Forward), uint32_t(TurtleOp::TurnLeft),
                                    uint32_t(TurtleOp::Push), uint32_t(TurtleOp::TurnRight),
                                    uint32_t(TurtleOp::Forward), uint32_t(TurtleOp::Pop)};
    EXPECT_EQ(program, expected);
    EXPECT_EQ(countForwardSteps(program), 2u);
}

TEST(TurtleProgram, UnbalancedBracketsAreRejected) {
    EXPECT_THROW(encodeTurtleProgram("F]"), std::invalid_argument);
    EXPECT_THROW(encodeTurtleProgram("[F"), std::invalid_argument);
    EXPECT_THROW(encodeTurtleProgram("][F"), std::invalid_argument);
    EXPECT_NO_THROW(encodeTurtleProgram("[[F]][F]"));
}

void expectNear(glm::vec2 actual, glm::vec2 expected) {
    EXPECT_NEAR(actual.x, expected.x, 1e-6f);
    EXPECT_NEAR(actual.y, expected.y, 1e-6f);
}

// Heading 90 degrees is up (+y); + turns counter-clockwise.
TEST(Turtle, HandCheckedTwoStepProgram) {
    TurtleProgram program = encodeTurtleProgram("F+F");
    for (auto interpret : {interpretTurtle, interpretTurtleByComposition}) {
        std::vector<Segment2D> segments = interpret(program, 90.0f, 90.0f);
        ASSERT_EQ(segments.size(), 2u);
        expectNear(segments[0].start, {0, 0});
        expectNear(segments[0].end, {0, 1});
        expectNear(segments[1].start, {0, 1});
        expectNear(segments[1].end, {-1, 1});  // turned left from up: now facing -x
        EXPECT_FLOAT_EQ(segments[1].distanceFromRoot, 1.0f);
    }
}

TEST(Turtle, HandCheckedBranch) {
    // Up one, a branch to the left, then back at the fork turn right: (0,1) -> (1,1).
    TurtleProgram program = encodeTurtleProgram("F[+F]-F");
    for (auto interpret : {interpretTurtle, interpretTurtleByComposition}) {
        std::vector<Segment2D> segments = interpret(program, 90.0f, 90.0f);
        ASSERT_EQ(segments.size(), 3u);
        expectNear(segments[1].end, {-1, 1});
        EXPECT_EQ(segments[1].depth, 1u);
        EXPECT_FLOAT_EQ(segments[1].distanceFromRoot, 1.0f);
        expectNear(segments[2].start, {0, 1});
        expectNear(segments[2].end, {1, 1});
        EXPECT_EQ(segments[2].depth, 0u);
        EXPECT_FLOAT_EQ(segments[2].distanceFromRoot, 1.0f);
    }
}

TEST(Turtle, LinksPointPopsAtTheirPush) {
    TurtleLinks links = linkTurtleInstructions(encodeTurtleProgram("F[+F[F]]F"));
    //                   index:                                     0 1 2 3 4 5 6 7 8
    const std::vector<int32_t> predecessor = {-1, 0, 1, 2, 3, 4, 4, 1, 7};
    const std::vector<uint32_t> depth = {0, 1, 1, 1, 2, 2, 2, 1, 0};
    EXPECT_EQ(links.predecessor, predecessor);
    EXPECT_EQ(links.depth, depth);
}

// Largest coordinate difference over the plant's extent; 0 when the segments agree exactly.
double relativeDifference(const std::vector<Segment2D>& a, const std::vector<Segment2D>& b) {
    double extent = 1.0, worst = 0.0;
    for (const Segment2D& s : a)
        extent = std::max({extent, double(std::fabs(s.end.x)), double(std::fabs(s.end.y))});
    for (std::size_t i = 0; i < a.size(); ++i) {
        glm::vec2 ds = a[i].start - b[i].start, de = a[i].end - b[i].end;
        worst = std::max({worst, double(std::fabs(ds.x)), double(std::fabs(ds.y)),
                          double(std::fabs(de.x)), double(std::fabs(de.y))});
    }
    return worst / extent;
}

TEST(Turtle, SerialAndCompositionAgreeForEveryPreset) {
    for (const PlantPreset& preset : plantPresets()) {
        for (int n = 0; n <= 6; ++n) {
            SCOPED_TRACE(preset.name + " iteration " + std::to_string(n));
            std::string symbols = rewrite(preset.system, n);
            TurtleProgram program = encodeTurtleProgram(symbols);
            std::vector<Segment2D> serial = interpretTurtle(program, preset.system.angleDegrees);
            std::vector<Segment2D> composed =
                interpretTurtleByComposition(program, preset.system.angleDegrees);
            ASSERT_EQ(serial.size(), countSymbol(symbols, 'F'));
            ASSERT_EQ(composed.size(), serial.size());
            EXPECT_LE(relativeDifference(serial, composed), 1e-5);  // measured: under 3e-7
            for (std::size_t i = 0; i < serial.size(); ++i) {
                ASSERT_EQ(serial[i].depth, composed[i].depth) << i;
                ASSERT_EQ(serial[i].distanceFromRoot, composed[i].distanceFromRoot) << i;
            }
        }
    }
}

TEST(Turtle, PointerJumpingTakesLogarithmicRounds) {
    const LSystem& plant = findPlantPreset("fractal-plant")->system;
    TurtleProgram program = encodeTurtleProgram(rewrite(plant, 6));
    TurtleLinks links = linkTurtleInstructions(program);
    int rounds = 0;
    composeAlongPredecessors(localTurtleTransforms(program, 25.0f), links.predecessor, &rounds);
    EXPECT_GE(rounds, 1);
    EXPECT_LE(rounds, int(std::ceil(std::log2(double(program.size())))));
}

}  // namespace
}  // namespace oasis
