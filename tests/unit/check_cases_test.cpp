// oasis check's covering set (check/check_cases.h): every compatible pair of values meets in
// some case, no case holds a forbidden pair, the set is the same every time (names shared by every
// driver's report), and --quick's subset meets every value.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "check/check_cases.h"

namespace oasis {
namespace {

TEST(CheckCases, EveryCompatiblePairMeetsAndNoForbiddenOne) {
    std::vector<CheckCase> cases = coveringCases();
    PairCoverage coverage = pairCoverage(cases);
    EXPECT_EQ(coverage.covered, coverage.pairs);
    EXPECT_GT(coverage.pairs, 300);
    const auto& dimensions = checkDimensions();
    for (const CheckCase& c : cases) {
        ASSERT_EQ(c.values.size(), dimensions.size());
        for (size_t d = 0; d < c.values.size(); ++d)
            for (size_t e = d + 1; e < c.values.size(); ++e)
                EXPECT_TRUE(compatibleValues(int(d), c.values[d], int(e), c.values[e])) << c.name();
    }
    // Far fewer than the whole cross product (6*2*3*2*4*4*3*2*2*3*4 = 331,776).
    EXPECT_LT(cases.size(), 60u);
    std::printf("check cases: %zu covering %d pairs\n", cases.size(), coverage.pairs);
}

TEST(CheckCases, TheSetIsDeterministicAndNamed) {
    std::vector<CheckCase> first = coveringCases(), second = coveringCases();
    ASSERT_EQ(first.size(), second.size());
    std::set<std::string> names;
    for (size_t i = 0; i < first.size(); ++i) {
        EXPECT_EQ(first[i].name(), second[i].name());
        names.insert(first[i].name());
    }
    EXPECT_EQ(names.size(), first.size());
}

TEST(CheckCases, QuickMeetsEveryValue) {
    std::vector<CheckCase> all = coveringCases(), quick = quickCases(all);
    const auto& dimensions = checkDimensions();
    for (size_t d = 0; d < dimensions.size(); ++d)
        for (size_t v = 0; v < dimensions[d].values.size(); ++v) {
            bool met = false;
            for (const CheckCase& c : quick) met = met || c.values[d] == int(v);
            EXPECT_TRUE(met) << dimensions[d].name << " " << dimensions[d].values[v].name;
        }
    EXPECT_LE(quick.size(), 10u);
    std::printf("quick cases: %zu\n", quick.size());
}

TEST(CheckCases, TheMainPathLeavesPathsToTheDriver) {
    for (const CheckCase& c : coveringCases()) {
        std::vector<std::string> main = c.mainPathArguments();
        for (const char* path : {"--lights-path", "--light-method", "--no-compute", "--force", "--api", "--stencil-view"})
            EXPECT_EQ(std::count(main.begin(), main.end(), path), 0) << c.name() << " " << path;
    }
}

}  // namespace
}  // namespace oasis
