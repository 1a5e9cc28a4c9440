// DepthCopyPass: in layouts that reconstruct position from depth (compact), copies the G-buffer's
// depth into the SceneDepth target (a full-screen draw) for the passes that read depth while they
// test against the depth-stencil target: the light volumes (depth and stencil tests, stencil
// written) and the reflection's lighting (the stencil keeps it inside the water; sampling the
// attached texture there was visibly wrong on zink at 1280x720). Every other reader (the direct
// lighting, tested read-only where the context allows it, tiling, views, probe) samples the target
// itself (DepthRead::FromTarget), so the direct copy runs only in frames with light volumes. Mirrored,
// it copies the mirrored scene's depth inside the water's rectangle, the only pixels read there.
#pragma once
#include "passes/pass.h"

namespace oasis {

class DepthCopyPass : public Pass {
public:
    explicit DepthCopyPass(Mirroring mirroring = Mirroring::Direct) : mirroring_(mirroring) {}
    std::string name() const override {
        return mirroring_ == Mirroring::Mirrored ? "DepthCopyPass.mirrored" : "DepthCopyPass";
    }
    std::vector<Access> declaredAccesses(const FrameSetup&) const override {
        return {{Target::DepthStencil, Use::Sample}, {Target::SceneDepth, Use::Replace},
                {Target::SceneDepth, Use::DepthWrite}};
    }
    bool reflectionWork() const override { return mirroring_ == Mirroring::Mirrored; }
    // Only a layout that rebuilds position from depth has the copy; the frame graph culls it where
    // no later pass samples the copy.
    bool active(const FrameSetup& frame) const override {
        return frame.positionFromDepth && mirroredPassActive(frame, mirroring_);
    }

protected:
    void execute(PassContext& context) override;

private:
    Mirroring mirroring_;
};

}  // namespace oasis
