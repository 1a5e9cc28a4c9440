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
            targetLifetimes(pipeline.graph(frame, sink), frame, {Target::Final});
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

const TargetLifetime* lifetimeOf(const std::vector<TargetLifetime>& lifetimes, Target target, int divisor) {
    for (const TargetLifetime& lifetime : lifetimes)
        if (lifetime.target == target && lifetime.divisor == divisor) return &lifetime;
    return nullptr;
}

// The reduced reflection's targets are the frame's targets at its scale, touched by its passes
// alone; its Reflection lives until the upsample that reads it (declared: its memory is lent to no
// target of that size before then), and the frame's own Reflection from the upsample's write on.
TEST(TargetLifetimes, TheReducedReflectionsTargetsLiveFromItsPassesToTheUpsample) {
    FrameSetup frame;
    frame.positionFromDepth = true;
    frame.reflectionsActive = true;
    const std::vector<Resource> sink{Target::Final};
    for (int divisor : {2, 4})
        for (PipelineKind kind : {PipelineKind::Forward, PipelineKind::Deferred}) {
            SCOPED_TRACE(std::string(pipelineName(kind)) + " at 1/" + std::to_string(divisor));
            frame.reflectionDivisor = divisor;
            Pipeline pipeline(kind);  // the graph points at its passes
            FrameGraph graph = pipeline.graph(frame, sink);
            std::vector<TargetLifetime> lifetimes = targetLifetimes(graph, frame, {Target::Final});
            int upsample = -1, lastMirrored = -1;
            for (size_t k = 0; k < graph.steps.size(); ++k) {
                if (!graph.steps[k].runs) continue;
                if (graph.steps[k].pass->name() == "ReflectionUpsamplePass") upsample = int(k);
                if (graph.steps[k].pass->drawsInReflectionTargets()) lastMirrored = int(k);
            }
            ASSERT_GT(upsample, lastMirrored);
            const TargetLifetime* reduced = lifetimeOf(lifetimes, Target::Reflection, divisor);
            ASSERT_NE(reduced, nullptr);
            EXPECT_EQ(reduced->last, upsample) << "the upsample's read of the reduced Reflection is declared";
            EXPECT_EQ(lifetimeOf(lifetimes, Target::Final, divisor), nullptr);
            EXPECT_EQ(lifetimeOf(lifetimes, Target::Radiance, divisor), nullptr);
            EXPECT_EQ(lifetimeOf(lifetimes, Target::Albedo, divisor) != nullptr, kind == PipelineKind::Deferred);
            for (const TargetLifetime& lifetime : lifetimes)
                if (lifetime.divisor == divisor) EXPECT_LE(lifetime.last, upsample) << targetName(lifetime.target);
            const TargetLifetime* frameReflection = lifetimeOf(lifetimes, Target::Reflection, 1);
            ASSERT_NE(frameReflection, nullptr);
            EXPECT_EQ(frameReflection->first, upsample) << "the frame's Reflection is the upsample's write";
            EXPECT_EQ(lifetimeOf(lifetimes, Target::SceneDepth, 1), nullptr) << "only the mirrored lighting reads the copy";
            // No target of the reduced size takes the reduced Reflection's memory before the upsample.
            std::vector<TargetLifetime> ofScale;
            for (const TargetLifetime& lifetime : lifetimes)
                if (lifetime.divisor == divisor) ofScale.push_back(lifetime);
            const TargetMemory memory = aliasTargets(ofScale, [](Target) { return 1u; });  // every format alike
            for (const TargetLifetime& lifetime : ofScale)
                if (lifetime.target != Target::Reflection && memory[size_t(lifetime.target)] == Target::Reflection)
                    EXPECT_GT(lifetime.first, upsample) << targetName(lifetime.target);
        }
}

}  // namespace
}  // namespace oasis
