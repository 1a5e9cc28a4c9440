// The frame's targets as the frame graph allocates them (issue 43 item 1): a forward frame holds no
// G-buffer; a frame holds the textures of the targets its running passes and its sink name, no more;
// a target whose lifetime follows another's of the same format takes its memory, and the picture
// stays the one drawn without aliasing, bit for bit. Numbers come from the allocation, not constants.
#include "check/oracle_inputs.h"
#include "frame/frame_readback.h"
#include "frame/target_lifetimes.h"
#include "gpu_test.h"

#include <set>

namespace oasis::gputest {
namespace {

class TargetMemory : public GpuTest {};

// The bytes the lifetimes name (each memory once, aliased targets in their owner's) plus Display:
// what the targets should hold after the frame.
double plannedBytes(const Renderer& renderer) {
    const FrameTargets& targets = renderer.targets();
    std::set<Target> memories;
    for (const TargetLifetime& lifetime : renderer.lastFrame().targetLifetimes)
        if (targets.layout().stores(lifetime.target)) memories.insert(targets.memory()[size_t(lifetime.target)]);
    double bytesPerPixel = 4.0;  // Display: the views have drawn it
    for (Target memory : memories) bytesPerPixel += targetFormat(targets.layout(), targets.depth(), memory).bytesPerPixel;
    return bytesPerPixel * targets.width() * targets.height();
}

// Every target the layout stores and Display: what FrameTargets allocated up front before issue 43.
double everyTargetBytes(const FrameTargets& targets) {
    double bytesPerPixel = 4.0;
    for (int t = 0; t < int(Target::Count); ++t)
        bytesPerPixel += targetFormat(targets.layout(), targets.depth(), Target(t)).bytesPerPixel;
    return bytesPerPixel * targets.width() * targets.height();
}

TEST_F(TargetMemory, TheForwardFrameHoldsNoGBufferAndEachFrameOnlyWhatItsGraphUses) {
    for (const std::string layout : {"full", "standard", "compact"}) {
        SCOPED_TRACE(layout);
        Renderer renderer(*shaders_, defaultPose().scene);
        renderer.configure(kSmallWidth, kSmallHeight, layoutNamed(layout));
        renderer.views().setSink({"final"});
        renderer.setPipeline(PipelineKind::Deferred);
        renderer.renderFrame(defaultPose().scene);  // a deferred frame first: its G-buffer must go back
        renderer.views().render("final");
        const FrameTargets& targets = renderer.targets();
        EXPECT_NE(targets.heldTexture(Target::Albedo), 0u);
        const double deferred = renderer.lastFrame().targetMemoryBytes();
        EXPECT_EQ(deferred, plannedBytes(renderer));

        renderer.setPipeline(PipelineKind::Forward);
        renderer.renderFrame(defaultPose().scene);
        renderer.views().render("final");
        for (Target gbuffer : {Target::Albedo, Target::Normal, Target::Position, Target::Info, Target::SceneDepth})
            EXPECT_EQ(targets.heldTexture(gbuffer), 0u) << targetName(gbuffer);
        const double forward = renderer.lastFrame().targetMemoryBytes();
        EXPECT_EQ(forward, plannedBytes(renderer));
        EXPECT_LT(forward, deferred);
        // The deferred frame seen through the final view uses every target these layouts store.
        EXPECT_LE(deferred, everyTargetBytes(targets));
        std::printf("[target memory] %s at %dx%d: forward %.0f, deferred %.0f, every target %.0f bytes\n",
                    layout.c_str(), targets.width(), targets.height(), forward, deferred, everyTargetBytes(targets));

        // A forward frame built for the albedo view: the views' fill after it makes the G-buffer.
        renderer.views().setSink({"albedo"});
        renderer.renderFrame(defaultPose().scene);
        renderer.views().render("albedo");
        EXPECT_NE(targets.heldTexture(Target::Albedo), 0u);
        renderer.views().setSink({});
    }
}

TEST_F(TargetMemory, FinalTakesTheAlbedosMemoryAfterItAndThePictureStays) {
    // The separate tone map writes Final after the mirrored lighting's last read of the G-buffer;
    // seen through the final view alone, nothing after the frame touches the G-buffer. As in
    // FrameSink: another hour first, then the frame for the final view, then the whole frame.
    SceneSettings scene = defaultPose().scene;
    scene.work.fuseToneMap = false;
    SceneSettings decoy = scene;
    decoy.hour = 17.5;
    Renderer renderer(*shaders_, scene);
    auto atlas = attachPlantAtlas(*shaders_, renderer);
    renderer.configure(kSmallWidth, kSmallHeight, layoutNamed("compact"));
    renderer.setPipeline(PipelineKind::Deferred);
    renderer.renderFrame(decoy);
    renderer.views().render(kOverviewName);

    renderer.views().setSink({"final"});
    renderer.renderFrame(scene);
    EXPECT_EQ(renderer.targets().memory()[size_t(Target::Final)], Target::Albedo);
    EXPECT_EQ(renderer.targets().heldTexture(Target::Final), renderer.targets().heldTexture(Target::Albedo));
    EXPECT_EQ(renderer.lastFrame().targetMemoryBytes(), plannedBytes(renderer));
    renderer.views().render("final");
    const Image aliased = readDisplay(renderer);
    // The albedo's values are gone: a read of it says so rather than return Final's texels.
    EXPECT_THROW(readTarget(renderer, Target::Albedo), std::logic_error);

    renderer.views().setSink({});
    renderer.renderFrame(scene);  // the whole frame's sink: everything lives past the frame, unaliased
    EXPECT_EQ(renderer.targets().memory()[size_t(Target::Final)], Target::Final);
    renderer.views().render("final");
    const Image unaliased = readDisplay(renderer);
    ASSERT_TRUE(hasContent(aliased));
    EXPECT_EQ(compareImages(unaliased, aliased).maxAbs, 0) << "the aliased frame's picture differs";
}

TEST_F(TargetMemory, WhatTheSinkNamesBesidesTheViewsLendsNoMemory) {
    // The check's shading oracle reads the G-buffer as the frame left it, after a frame built for
    // the final view: its reads in the sink keep the albedo's memory the albedo's, and the values
    // read are those of the whole frame's sink.
    SceneSettings scene = defaultPose().scene;
    scene.work.fuseToneMap = false;  // Final after the G-buffer's last read: it could take the albedo's memory
    Renderer renderer(*shaders_, scene);
    auto atlas = attachPlantAtlas(*shaders_, renderer);
    renderer.configure(kSmallWidth, kSmallHeight, layoutNamed("compact"));
    renderer.setPipeline(PipelineKind::Deferred);
    renderer.renderFrame(scene);
    const std::vector<float> whole = readTarget(renderer, Target::Albedo);

    renderer.views().setSink({"final"}, oracleReads(renderer.targets().layout()));
    renderer.renderFrame(scene);
    for (Target read : {Target::Albedo, Target::Normal, Target::Info, Target::DepthStencil, Target::Radiance})
        EXPECT_EQ(renderer.targets().holderAfterFrame(read), read) << targetName(read);
    EXPECT_NE(renderer.targets().memory()[size_t(Target::Final)], Target::Albedo);
    EXPECT_EQ(readTarget(renderer, Target::Albedo), whole);
    EXPECT_THROW(renderer.views().setSink({}, {Target::Albedo}), std::invalid_argument);
    renderer.views().setSink({});
}

}  // namespace
}  // namespace oasis::gputest
