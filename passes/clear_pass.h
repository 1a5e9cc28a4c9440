// ClearPass: resets what a pipeline reads before anything drew it: depth to the far plane and stencil
// 0 ("nothing drawn"), and in the G-buffer layouts that store position Info's sky flag.
#pragma once
#include "passes/pass.h"

namespace oasis {

class ClearPass : public Pass {
public:
    // What a frame stopped early (--stop-before) does with Radiance and Reflection: the frame's own
    // clear starts them from black; the views' fill of a stopped forward frame keeps the frame's.
    enum class StoppedFrameTargets { Cleared, Kept };
    explicit ClearPass(SurfaceOutput output, StoppedFrameTargets stopped = StoppedFrameTargets::Cleared)
        : output_(output), stopped_(stopped) {}
    std::string name() const override { return std::string("ClearPass.") + surfaceOutputName(output_); }
    std::vector<Access> declaredAccesses(const FrameSetup& frame) const override;
    std::string sceneStep() const override { return "clear"; }
    bool clearsWholeTargets(const FrameSetup&) const override { return true; }

protected:
    void execute(PassContext& context) override;

private:
    SurfaceOutput output_;
    StoppedFrameTargets stopped_;
    bool clearsStoppedFrameTargets(const FrameSetup& frame) const {
        return !frame.runsToEnd && stopped_ == StoppedFrameTargets::Cleared;
    }
};

}  // namespace oasis
