// Covers summariseRounds and roundOrder (src/commands/session.h), the statistics behind `oasis compare`'s times:
// each round's ratio to its own floor, so a machine that slows down between rounds moves the
// milliseconds but not the ratios, and one slow floor moves only its own round's.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <stdexcept>
#include <vector>

#include "commands/session.h"

namespace oasis {
namespace {

TEST(PipelineTimes, RatiosArePairedPerRoundSoDriftBetweenRoundsCancels) {
    // The machine runs at a different speed in every round (scale 1, 1.5, 2, 0.8, 1.2): each
    // round is forward 12, deferred 9 and the floor 1.5 at that speed.
    const std::vector<double> speed = {1.0, 1.5, 2.0, 0.8, 1.2};
    std::vector<double> forward, deferred, floor;
    for (double s : speed) {
        forward.push_back(12.0 * s);
        deferred.push_back(9.0 * s);
        floor.push_back(1.5 * s);
    }
    PipelineTimes t = summariseRounds(forward, deferred, floor);
    EXPECT_EQ(t.rounds, 5);
    EXPECT_DOUBLE_EQ(t.forwardRatio, 8.0);
    EXPECT_DOUBLE_EQ(t.deferredRatio, 6.0);
    EXPECT_DOUBLE_EQ(t.deferredRatioLowest, 6.0);
    EXPECT_DOUBLE_EQ(t.deferredRatioHighest, 6.0);
    // The milliseconds are the medians of the rounds (speed 1.2).
    EXPECT_DOUBLE_EQ(t.forwardMs, 14.4);
    EXPECT_DOUBLE_EQ(t.deferredMs, 10.8);
    EXPECT_DOUBLE_EQ(t.floorMs, 1.8);
}

TEST(PipelineTimes, OneSlowFloorMovesOnlyItsRoundAndTheExtremesShowIt) {
    std::vector<double> forward = {20, 20, 20, 20, 20}, deferred = {10, 10, 10, 10, 10}, floor = {2, 2, 5, 2, 2};
    PipelineTimes t = summariseRounds(forward, deferred, floor);
    EXPECT_DOUBLE_EQ(t.deferredRatio, 5.0);
    EXPECT_DOUBLE_EQ(t.forwardRatio, 10.0);
    EXPECT_DOUBLE_EQ(t.deferredRatioLowest, 2.0);
    EXPECT_DOUBLE_EQ(t.deferredRatioHighest, 5.0);
    EXPECT_DOUBLE_EQ(t.floorMs, 2.0);
}

TEST(PipelineTimes, EvenRoundCountsTakeTheMeanOfTheMiddleTwo) {
    PipelineTimes t = summariseRounds({10, 30}, {4, 12}, {1, 2});
    EXPECT_DOUBLE_EQ(t.forwardMs, 20.0);
    EXPECT_DOUBLE_EQ(t.deferredRatio, 5.0);  // rounds 4 and 6
    EXPECT_DOUBLE_EQ(t.forwardRatio, 12.5);  // rounds 10 and 15
}

TEST(PipelineTimes, MedianOfOddEvenAndNoValues) {
    EXPECT_DOUBLE_EQ(median({3, 1, 2}), 2.0);
    EXPECT_DOUBLE_EQ(median({4, 1, 3, 2}), 2.5);
    EXPECT_DOUBLE_EQ(median({}), 0.0);
}

TEST(PipelineTimes, MismatchedOrEmptyRoundsAreRefused) {
    EXPECT_THROW(summariseRounds({}, {}, {}), std::invalid_argument);
    EXPECT_THROW(summariseRounds({1, 2}, {1}, {1, 2}), std::invalid_argument);
}

// Issue 31, defect 5: the faster pipeline printed the larger ratio (medians of per-round ratios).
// The ratios printed are the medians' own, so they order as the milliseconds do and agree with
// them; rounds that spread over 10% of their median are flagged noisy.
TEST(PipelineTimes, PrintedRatiosAreTheMediansOwnAndNoiseIsFlagged) {
    std::vector<double> forward = {570, 560, 600}, deferred = {447, 300, 460}, floor = {25.45, 15, 30};
    PipelineTimes t = summariseRounds(forward, deferred, floor);
    EXPECT_DOUBLE_EQ(t.forwardOverFloor, t.forwardMs / t.floorMs);
    EXPECT_DOUBLE_EQ(t.deferredOverFloor, t.deferredMs / t.floorMs);
    EXPECT_LT(t.deferredMs, t.forwardMs);
    EXPECT_LT(t.deferredOverFloor, t.forwardOverFloor);  // the faster pipeline, the smaller ratio
    EXPECT_DOUBLE_EQ(t.deferredLowest, 300.0);
    EXPECT_DOUBLE_EQ(t.deferredHighest, 460.0);
    EXPECT_DOUBLE_EQ(t.floorLowest, 15.0);
    EXPECT_DOUBLE_EQ(t.floorHighest, 30.0);
    EXPECT_TRUE(t.noisy());
    PipelineTimes steady = summariseRounds({100, 101, 99}, {50, 51, 50}, {10, 10.5, 10});
    EXPECT_FALSE(steady.noisy());
    EXPECT_NEAR(steady.spread, 0.05, 1e-12);  // the floor's 0.5 over its median 10
}

}  // namespace
}  // namespace oasis

namespace oasis {
namespace {

// Issue 44: each round's order is a permutation drawn from the seed, the same for the same seed,
// and every stream comes first about a third of the time (so a drift cannot always land on one).
TEST(RoundOrder, SeededPermutationsThatShareTheFirstPlace) {
    std::mt19937_64 a(44), b(44);
    int first[3] = {0, 0, 0};
    for (int round = 0; round < 600; ++round) {
        std::vector<int> order = roundOrder(a, 3);
        ASSERT_EQ(order, roundOrder(b, 3));
        std::vector<int> sorted = order;
        std::sort(sorted.begin(), sorted.end());
        ASSERT_EQ(sorted, (std::vector<int>{0, 1, 2}));
        ++first[order[0]];
    }
    for (int stream = 0; stream < 3; ++stream) {
        EXPECT_GT(first[stream], 150) << stream;  // 200 expected; 150 is over 4 sigma below
        EXPECT_LT(first[stream], 250) << stream;
    }
    EXPECT_TRUE(roundOrder(a, 0).empty());
    EXPECT_EQ(roundOrder(a, 1), std::vector<int>{0});
}

}  // namespace
}  // namespace oasis
