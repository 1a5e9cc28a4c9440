// The frame's targets as the frame graph allocates them (issue 43 item 1): a forward frame holds no
// G-buffer; a frame holds the textures of the targets its running passes and its sink name, no more;
// a target whose lifetime follows another's of the same format takes its memory, and the picture
// stays the one drawn without aliasing, bit for bit. Numbers come from the allocation, not constants.
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

}  // namespace
}  // namespace oasis::gputest
