// DepthCopyPass: in layouts that reconstruct position from depth (compact), copies the G-buffer's
// depth into the SceneDepth target (a full-screen draw) before the passes that read it. They draw into framebuffers
// with the depth-stencil target attached (stencil tests, the light volumes' depth test), so
// sampling that same texture would be a feedback loop: undefined in GL, and visibly wrong on
// zink at 1280x720. Mirrored, it copies the mirrored scene's depth for the reflection's lighting;
// after the frame the copy holds what the G-buffer holds (the mirrored scene inside the water).
#pragma once
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
        return frame.positionFromDepth && mirroredPassActive(frame, mirroring_);
    }

protected:
    void execute(PassContext& context) override;

private:
    Mirroring mirroring_;
};

}  // namespace oasis
