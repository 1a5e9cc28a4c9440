// The per-pass timer queries (frame/gpu_timer.h) on the driver under test: one query per pass
// that ran, named and ordered as the wall-clock timing names them, finite; a ring of one frame
// reads or drops every frame; the start-up check gives a clock and says why.
#include "gpu_test.h"

#include "frame/gpu_timer.h"

namespace oasis::gputest {
namespace {

std::vector<std::string> names(const PassTimes& times) {
    std::vector<std::string> list;
    for (const auto& [name, ms] : times) list.push_back(name);
    return list;
}

class GpuTimerTest : public GpuTest, public ::testing::WithParamInterface<PipelineKind> {};

TEST_P(GpuTimerTest, OneQueryPerPassThatRanInPassOrder) {
    const SceneSettings scene = sceneAtHeight(435.0, 4.0, 140.0, 30.0f, -3.0f);
    Renderer renderer(*shaders_, scene);
    auto atlas = attachPlantAtlas(*shaders_, renderer);
    renderer.configure(96, 54, layoutNamed("compact"));
    renderer.setPipeline(GetParam());
    const PassTimes wall = renderFrameTimingPasses(renderer, scene);
    PassTimerQueries queries(4);
    for (int i = 0; i < 3; ++i) queries.timeFrame(renderer, scene);
    const std::vector<PassTimes> frames = queries.drain();
    ASSERT_EQ(frames.size(), 3u);
    EXPECT_EQ(queries.framesDropped(), 0);
    for (const PassTimes& frame : frames) {
        EXPECT_EQ(names(frame), names(wall));
        for (const auto& [name, ms] : frame) {
            EXPECT_TRUE(std::isfinite(ms) && ms >= 0.0) << name << " read " << ms << " ms";
            EXPECT_LT(ms, 60000.0) << name;
        }
    }
    EXPECT_EQ(names(queries.latest()), names(wall));
}

TEST_P(GpuTimerTest, ARingOfOneFrameDropsWhatIsStillPending) {
    const SceneSettings scene = sceneAtHeight(435.0, 4.0, 140.0, 30.0f, -3.0f);
    Renderer renderer(*shaders_, scene);
    renderer.configure(64, 36, layoutNamed("full"));
    renderer.setPipeline(GetParam());
    PassTimerQueries queries(1);
    for (int i = 0; i < 4; ++i) queries.timeFrame(renderer, scene);
    // Every frame is either read (by the next frame's look, or the drain) or given up on.
    std::vector<PassTimes> read = queries.drain();
    EXPECT_EQ(int(read.size()) + queries.framesDropped(), 4);
    EXPECT_GE(read.size(), 1u);  // the last one, waited for
}

TEST_P(GpuTimerTest, TheStartUpCheckChoosesAClockAndSaysWhy) {
    const SceneSettings scene = sceneAtHeight(435.0, 4.0, 140.0, 30.0f, -3.0f);
    Renderer renderer(*shaders_, scene);
    renderer.configure(96, 54, layoutNamed("compact"));
    renderer.setPipeline(GetParam());
    TimingClock clock = measureTimingClock(renderer, scene, 3);
    ASSERT_FALSE(clock.reason.empty());
    if (clock.reason.find("no GL_TIME_ELAPSED") != std::string::npos) {
        EXPECT_FALSE(clock.gpuTimers);
    } else {
        // Both rules of judgeTimerQueries: the sum apart within the limit, and no pass whose query reads
        // more than its glFinish-bracketed wall time allows (said in the reason when one does).
        bool passOver = clock.reason.find("query reads more than its pass took") != std::string::npos;
        EXPECT_EQ(clock.gpuTimers, clock.disagreement <= kTimerDisagreement && !passOver) << clock.reason;
        EXPECT_NE(clock.reason.find("per pass"), std::string::npos) << clock.reason;
    }
    std::printf("[ timing ] %s on %s: %s\n", pipelineName(GetParam()), gpuState().info.renderer.c_str(),
                clock.describe().c_str());
}

INSTANTIATE_TEST_SUITE_P(Pipelines, GpuTimerTest, ::testing::Values(PipelineKind::Forward, PipelineKind::Deferred),
                         [](const auto& info) { return std::string(pipelineName(info.param)); });

}  // namespace
}  // namespace oasis::gputest
