// DepthCopyPass: in layouts that reconstruct position from depth (compact), copies the G-buffer's
// depth into the SceneDepth target (a full-screen draw) for the passes that read depth while they
// test against the depth-stencil target: the light volumes (depth and stencil tests, stencil
// written) and the reflection's lighting (the stencil keeps it inside the water; sampling the
// attached texture there was visibly wrong on zink at 1280x720). Every other reader (the direct
// lighting, tested read-only where the context allows it, tiling, views, probe) samples the target
// itself (DepthRead::FromTarget), so the direct copy runs only in frames with light volumes. Mirrored,
// it copies the mirrored scene's depth inside the water's rectangle, the only pixels read there.
#pragma once
#include "passes/light_volume_pass.h"
#include "passes/pass.h"

namespace oasis {

class DepthCopyPass : public Pass {
public:
    explicit DepthCopyPass(Mirroring mirroring = Mirroring::Direct) : mirroring_(mirroring) {}
    std::string name() const override {
        return mirroring_ == Mirroring::Mirrored ? "DepthCopyPass.mirrored" : "DepthCopyPass";
    }
    std::vector<Target> reads() const override { return {Target::DepthStencil}; }
    std::vector<Target> writes() const override { return {Target::SceneDepth}; }
    bool reflectionWork() const override { return mirroring_ == Mirroring::Mirrored; }
    bool active(const FrameSetup& frame) const override {
        if (!frame.positionFromDepth || !mirroredPassActive(frame, mirroring_)) return false;
        return mirroring_ == Mirroring::Mirrored || !frame.depthReadInPlace ||
               LightVolumePass::volumesActive(frame, mirroring_);
    }

protected:
    void execute(PassContext& context) override;

private:
    Mirroring mirroring_;
};

}  // namespace oasis
