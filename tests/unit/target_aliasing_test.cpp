// The frame's targets as resources with lifetimes, without GL (render/target_aliasing.h,
// frame/target_lifetimes.h): which targets share a texture (lifetimes apart, formats the same),
// and the lifetimes the real frames' declarations give, forward's holding no G-buffer.
#include <gtest/gtest.h>

#include <algorithm>

#include "frame/pipeline.h"
#include "frame/target_lifetimes.h"

namespace oasis {
namespace {

unsigned sameFormat(Target) { return 1; }

TEST(TargetAliasing, TargetsWhoseLifetimesDoNotOverlapShareOneMemory) {
    TargetMemory memory = aliasTargets({{Target::Albedo, 0, 3}, {Target::Final, 4, 6}}, sameFormat);
    EXPECT_EQ(memory[size_t(Target::Final)], Target::Albedo);
    EXPECT_EQ(memory[size_t(Target::Albedo)], Target::Albedo);
}

TEST(TargetAliasing, OverlappingOrTouchingLifetimesKeepTheirOwn) {
    // A step that ends one lifetime and begins the other holds both at once.
    for (int finalFirst : {2, 3}) {
        TargetMemory memory = aliasTargets({{Target::Albedo, 0, 3}, {Target::Final, finalFirst, 6}}, sameFormat);
        EXPECT_EQ(memory[size_t(Target::Final)], Target::Final) << "final from step " << finalFirst;
    }
    TargetMemory beyond = aliasTargets({{Target::Albedo, 0, kBeyondFrame}, {Target::Final, 5, 6}}, sameFormat);
    EXPECT_EQ(beyond[size_t(Target::Final)], Target::Final) << "a target the frame leaves lends nothing";
}

TEST(TargetAliasing, DifferentFormatsNeverShare) {
    auto format = [](Target target) { return target == Target::Albedo ? 1u : 2u; };
    TargetMemory memory = aliasTargets({{Target::Albedo, 0, 1}, {Target::Final, 4, 6}}, format);
    EXPECT_EQ(memory[size_t(Target::Final)], Target::Final);
    auto notStored = [](Target target) { return target == Target::Final ? 0u : 1u; };
    EXPECT_EQ(aliasTargets({{Target::Albedo, 0, 1}, {Target::Final, 4, 6}}, notStored)[size_t(Target::Final)],
              Target::Final);
}

TEST(TargetAliasing, AMemoryIsLentToOneTargetAtATime) {
    // Normal and Info both begin after Albedo ends, but overlap each other: one of them gets it.
    TargetMemory memory = aliasTargets(
        {{Target::Albedo, 0, 1}, {Target::Normal, 2, 5}, {Target::Info, 3, 6}, {Target::Final, 7, 8}}, sameFormat);
    EXPECT_EQ(memory[size_t(Target::Normal)], Target::Albedo);
    EXPECT_EQ(memory[size_t(Target::Info)], Target::Info);
    EXPECT_EQ(memory[size_t(Target::Final)], Target::Albedo) << "free again after Normal's last step";
    EXPECT_EQ(lifetimeText({Target::Final, 7, kBeyondFrame}, memory), "final 7-end, memory of albedo");
}

bool hasLifetime(const std::vector<TargetLifetime>& lifetimes, Target target) {
    return std::any_of(lifetimes.begin(), lifetimes.end(), [&](const TargetLifetime& l) { return l.target == target; });
}

TEST(TargetLifetimes, TheForwardFrameUsesNoGBufferTheDeferredFrameDoes) {
    FrameSetup frame;
    frame.positionFromDepth = true;
    frame.reflectionsActive = true;
    const std::vector<Resource> sink{Target::Final};
    for (PipelineKind kind : {PipelineKind::Forward, PipelineKind::Deferred}) {
        Pipeline pipeline(kind);
        std::vector<TargetLifetime> lifetimes =
            targetLifetimes(pipeline.graph(frame, sink), frame, {Target::Final}, StepsOf::WholeFrame);
        const bool deferred = kind == PipelineKind::Deferred;
        for (Target gbuffer : {Target::Albedo, Target::Normal, Target::Info})
            EXPECT_EQ(hasLifetime(lifetimes, gbuffer), deferred) << pipelineName(kind) << " " << targetName(gbuffer);
        EXPECT_TRUE(hasLifetime(lifetimes, Target::DepthStencil));
        EXPECT_TRUE(hasLifetime(lifetimes, Target::Radiance));
        auto final = std::find_if(lifetimes.begin(), lifetimes.end(),
                                  [](const TargetLifetime& l) { return l.target == Target::Final; });
        ASSERT_NE(final, lifetimes.end());
        EXPECT_EQ(final->last, kBeyondFrame) << "the sink lives past the frame";
    }
}

TEST(TargetLifetimes, TheReducedReflectionsTargetsAreItsPassesAlone) {
    FrameSetup frame;
    frame.positionFromDepth = true;
    frame.reflectionsActive = true;
    frame.reflectionDivisor = 2;
    const std::vector<Resource> sink{Target::Final};
    for (PipelineKind kind : {PipelineKind::Forward, PipelineKind::Deferred}) {
        SCOPED_TRACE(pipelineName(kind));
        Pipeline pipeline(kind);  // the graph points at its passes
        FrameGraph graph = pipeline.graph(frame, sink);
        std::vector<TargetLifetime> reduced = targetLifetimes(graph, frame, {}, StepsOf::ReducedReflection);
        std::vector<TargetLifetime> rest = targetLifetimes(graph, frame, {}, StepsOf::FrameWithoutReducedReflection);
        EXPECT_TRUE(hasLifetime(reduced, Target::Reflection));
        EXPECT_FALSE(hasLifetime(reduced, Target::Final));
        EXPECT_FALSE(hasLifetime(reduced, Target::Radiance));
        EXPECT_EQ(hasLifetime(reduced, Target::Albedo), kind == PipelineKind::Deferred);
        EXPECT_TRUE(hasLifetime(rest, Target::Reflection)) << "the upsample's write and the composite's read";
        EXPECT_FALSE(hasLifetime(rest, Target::SceneDepth)) << "only the mirrored lighting reads the depth copy";
    }
}

}  // namespace
}  // namespace oasis
