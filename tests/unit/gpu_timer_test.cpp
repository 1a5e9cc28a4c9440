// The timer-query trust decision (frame/gpu_timer.h): agreement per pass, not per frame.
#include <gtest/gtest.h>

#include "frame/gpu_timer.h"

namespace oasis {
namespace {

PassTimes passes(std::initializer_list<double> ms) {
    static const char* names[] = {"ClearPass.gbuffer", "TerrainPass.gbuffer", "LightingPass", "ToneMapPass"};
    PassTimes times;
    size_t i = 0;
    for (double m : ms) times.emplace_back(names[i++], m);
    return times;
}

TEST(TimerTrust, QueriesThatAgreeWithWallTimePerPassAreTrusted) {
    // glFinish after each pass adds a little to every wall time: zink's 7 % apart.
    TimingClock clock = judgeTimerQueries(passes({0.9, 8.0, 14.5, 3.8}), passes({1.0, 8.6, 15.2, 4.1}));
    EXPECT_TRUE(clock.gpuTimers) << clock.reason;
    EXPECT_NEAR(clock.disagreement, (0.1 + 0.6 + 0.7 + 0.3) / 28.9, 1e-12);
    EXPECT_EQ(clock.name(), "gpu-timer-query");
    EXPECT_NE(clock.reason.find("timer queries trusted"), std::string::npos);
}

TEST(TimerTrust, AFrameThatAgreesWhileItsPassesDoNotIsNotTrusted) {
    // llvmpipe: the frame's sum is right (52.7 against 57.3 ms) but the deferred rasterisation is
    // counted in whichever query is open: the clear reads 15 ms, the lighting 2.
    TimingClock clock = judgeTimerQueries(passes({15.1, 2.7, 2.1, 32.8}), passes({1.26, 9.5, 18.6, 27.9}));
    EXPECT_FALSE(clock.gpuTimers) << clock.reason;
    EXPECT_GT(clock.disagreement, kTimerDisagreement);
    EXPECT_EQ(clock.name(), "wall-glfinish");
    // The reason names the pass most apart and both of its readings.
    EXPECT_NE(clock.reason.find("LightingPass, 2.1 ms against 18.6 ms"), std::string::npos) << clock.reason;
}

TEST(TimerTrust, AQueryLongerThanItsBracketedPassIsNotTrusted) {
    // llvmpipe without the G-buffer's colour clear: 30.5 ms by queries, 31.9 ms by wall, 29 % apart
    // at best 24 %; a pass reads 18.2 ms where a glFinish around it took 14 ms.
    TimingClock clock = judgeTimerQueries(passes({18.2, 7.0, 0.4, 5.9}), passes({14.0, 7.0, 2.8, 5.9}));
    EXPECT_LE(clock.disagreement, kTimerDisagreement);
    EXPECT_FALSE(clock.gpuTimers) << clock.reason;
    EXPECT_NE(clock.reason.find("ClearPass.gbuffer's query reads more than its pass took with a glFinish around it "
                                "(18.2 ms against 14 ms)"), std::string::npos) << clock.reason;
    // Within 25 % plus 0.5 ms over its wall time a query is noise between the two sets of frames.
    EXPECT_TRUE(judgeTimerQueries(passes({2.9, 8.0}), passes({2.0, 8.2})).gpuTimers);
    EXPECT_FALSE(judgeTimerQueries(passes({3.1, 8.0}), passes({2.0, 8.2})).gpuTimers);
}

TEST(TimerTrust, TheLimitIsInclusiveAndDifferentPassListsAreNeverTrusted) {
    EXPECT_TRUE(judgeTimerQueries(passes({7.5, 0.0}), passes({10.0, 0.0})).gpuTimers);   // 25 % exactly
    EXPECT_FALSE(judgeTimerQueries(passes({7.4, 0.0}), passes({10.0, 0.0})).gpuTimers);  // 26 %
    PassTimes renamed = passes({1.0, 2.0});
    renamed[1].first = "SkyPass.forward";
    EXPECT_FALSE(judgeTimerQueries(renamed, passes({1.0, 2.0})).gpuTimers);
    EXPECT_FALSE(judgeTimerQueries(passes({1.0}), passes({1.0, 2.0})).gpuTimers);
    EXPECT_FALSE(judgeTimerQueries({}, {}).gpuTimers);
}

TEST(TimerTrust, MediansArePerPassInFirstSeenOrder) {
    PassTimes a = passes({1.0, 5.0}), b = passes({3.0, 4.0}), c = passes({2.0, 9.0});
    PassTimes medians = medianPassTimes({a, b, c});
    ASSERT_EQ(medians.size(), 2u);
    EXPECT_EQ(medians[0], (std::pair<std::string, double>{"ClearPass.gbuffer", 2.0}));
    EXPECT_EQ(medians[1], (std::pair<std::string, double>{"TerrainPass.gbuffer", 5.0}));
}

}  // namespace
}  // namespace oasis
