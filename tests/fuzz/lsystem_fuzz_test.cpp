// Fuzzes the L-system code in process: oasis has no rule text parser (the plant rules are the
// preset table in src/scene/lsystem.cpp, out of the command line's reach), so random axioms and
// rules, any byte included, go straight into rewriting, the turtle encoding and both turtle
// interpreters. Asserts what must hold for every input: predicted counts equal the built string,
// runaway growth is refused before building, unbalanced brackets are refused (balanced ones never),
// and the serial and composition interpreters agree. A fixed seed, printed; bounded in count.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>
#include <string>

#include "scene/lsystem.h"
#include "scene/turtle.h"

namespace oasis {
namespace {

constexpr uint64_t kSeed = 12;
constexpr int kCases = 10000;
constexpr uint64_t kMaxSymbols = 20000;  // small enough for both interpreters to stay fast

std::string randomSymbols(std::mt19937_64& rng, int maxLength) {
    // Mostly turtle symbols and growth markers (so rules compose into real plants), and now and
    // then any byte at all, NUL and bytes above 127 included.
    static const std::string kUsual = "FF+-[]XY";
    std::uniform_int_distribution<int> length(0, maxLength), usual(0, int(kUsual.size()) - 1), byte(0, 255);
    std::string symbols(size_t(length(rng)), ' ');
    for (char& symbol : symbols) symbol = rng() % 8 ? kUsual[size_t(usual(rng))] : char(byte(rng));
    return symbols;
}

LSystem randomSystem(std::mt19937_64& rng) {
    LSystem system;
    system.axiom = randomSymbols(rng, 6);
    int rules = int(rng() % 4);
    for (int i = 0; i < rules; ++i) {
        std::string symbol = randomSymbols(rng, 1);
        system.rules[symbol.empty() ? 'F' : symbol[0]] = randomSymbols(rng, 12);
    }
    system.angleDegrees = std::uniform_real_distribution<float>(-180.0f, 180.0f)(rng);
    return system;
}

bool bracketsBalance(const std::string& symbols) {
    long depth = 0;
    for (char symbol : symbols) {
        if (symbol == '[') ++depth;
        if (symbol == ']' && --depth < 0) return false;
    }
    return depth == 0;
}

// Largest end-point difference between the two interpretations over the plant's extent.
double relativeDifference(const std::vector<Segment2D>& a, const std::vector<Segment2D>& b) {
    double extent = 1.0, worst = 0.0;
    for (size_t i = 0; i < a.size(); ++i) {
        extent = std::max({extent, double(std::fabs(a[i].end.x)), double(std::fabs(a[i].end.y))});
        worst = std::max({worst, double(std::fabs(a[i].end.x - b[i].end.x)), double(std::fabs(a[i].end.y - b[i].end.y)),
                          double(std::fabs(a[i].start.x - b[i].start.x)), double(std::fabs(a[i].start.y - b[i].start.y))});
    }
    return worst / extent;
}

TEST(LSystemFuzz, RandomRulesKeepEveryInvariant) {
    std::mt19937_64 rng(kSeed);
    int built = 0, refusedGrowth = 0, refusedBrackets = 0;
    for (int c = 0; c < kCases; ++c) {
        LSystem system = randomSystem(rng);
        int iterations = int(rng() % 9);
        SCOPED_TRACE("seed " + std::to_string(kSeed) + " case " + std::to_string(c) + " iterations " +
                     std::to_string(iterations));
        uint64_t predicted = predictLength(system, iterations);
        if (predicted > kMaxSymbols) {
            EXPECT_THROW(rewrite(system, iterations, kMaxSymbols), std::length_error);
            ++refusedGrowth;
            continue;
        }
        std::string symbols = rewrite(system, iterations, kMaxSymbols);
        ASSERT_EQ(symbols.size(), predicted);
        ASSERT_EQ(countSymbols(symbols), predictSymbolCounts(system, iterations));
        if (!bracketsBalance(symbols)) {
            EXPECT_THROW(encodeTurtleProgram(symbols), std::invalid_argument);
            ++refusedBrackets;
            continue;
        }
        TurtleProgram program = encodeTurtleProgram(symbols);
        ASSERT_EQ(program.size(), size_t(std::count_if(symbols.begin(), symbols.end(), [](char s) {
                      return s == 'F' || s == '+' || s == '-' || s == '[' || s == ']';
                  })));
        std::vector<Segment2D> serial = interpretTurtle(program, system.angleDegrees);
        std::vector<Segment2D> composed = interpretTurtleByComposition(program, system.angleDegrees);
        ASSERT_EQ(serial.size(), countSymbol(symbols, 'F'));
        ASSERT_EQ(composed.size(), serial.size());
        for (size_t i = 0; i < serial.size(); ++i) {
            ASSERT_TRUE(std::isfinite(serial[i].end.x) && std::isfinite(serial[i].end.y)) << i;
            ASSERT_EQ(serial[i].depth, composed[i].depth) << i;
            ASSERT_EQ(serial[i].distanceFromRoot, composed[i].distanceFromRoot) << i;
        }
        // The float serial loop drifts most on long chains (~7e-5 on the weed preset).
        EXPECT_LE(relativeDifference(serial, composed), 1e-3);
        ++built;
    }
    std::printf("lsystem fuzz: seed %llu, %d cases: %d interpreted, %d refused as too long, %d with unbalanced brackets\n",
                (unsigned long long)kSeed, kCases, built, refusedGrowth, refusedBrackets);
    // The generator must reach every branch, or the test proves less than it says.
    EXPECT_GT(built, kCases / 10);
    EXPECT_GT(refusedGrowth, 0);
    EXPECT_GT(refusedBrackets, 0);
}

}  // namespace
}  // namespace oasis
