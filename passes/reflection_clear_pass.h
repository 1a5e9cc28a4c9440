// ReflectionClearPass: with reflections active, resets depth inside the water to the far plane
// (and, for the G-buffers that store position, the "nothing drawn" values) so the mirrored scene is
// depth-tested against itself only. It clears nothing outside the water: Reflection is read only at
// water pixels, where the mirrored passes write every pixel.
#pragma once
#include "passes/pass.h"

namespace oasis {

class ReflectionClearPass : public Pass {
public:
    // Where it runs: in the frame, whose reflection drawn at a reduced resolution has targets of its
    // own, cleared and marked here (their Reflection among them); or in the views' fill of the
    // mirrored scene (frame/view_fill.h), always drawn into the frame's targets.
    enum class RunsIn { Frame, ViewFill };
    explicit ReflectionClearPass(SurfaceOutput output, RunsIn runsIn = RunsIn::Frame)
        : output_(output), runsIn_(runsIn) {}
    std::string name() const override { return std::string("ReflectionClearPass.") + surfaceOutputName(output_); }
    std::vector<Access> declaredAccesses(const FrameSetup& frame) const override;
    bool active(const FrameSetup& frame) const override;
    // Only the reduced reflection's own targets are cleared whole (markReducedWater); the frame's
    // are reset inside the water alone, by a stencil-masked draw.
    bool drawsInReflectionTargets() const override { return runsIn_ == RunsIn::Frame; }
    bool clearsWholeTargets(const FrameSetup& frame) const override {
        return runsIn_ == RunsIn::Frame && frame.reflectionDivisor > 1;
    }
protected:
    void execute(PassContext& context) override;

private:
    SurfaceOutput output_;
    RunsIn runsIn_;
};

}  // namespace oasis
