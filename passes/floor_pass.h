// FloorPass: the timing floor. A full-screen write of every G-buffer target plus a full-screen
// read of them into Final: the least any deferred frame of this size and layout can cost.
// Not part of a pipeline; commands run it to report times as ratios against it.
#pragma once
#include "passes/pass.h"

namespace oasis {

class FloorPass : public Pass {
public:
    std::string name() const override { return "FloorPass"; }
    // Writes a floor into the G-buffer (and its depth), then reads it back into Final.
    std::vector<Access> declaredAccesses(const FrameSetup& frame) const override {
        std::vector<Access> used;
        for (Target target : surfaceOutputTargets(frame, SurfaceOutput::GBuffer)) used.push_back({target, Use::Write});
        appendDepthStencil(used, {Use::DepthTest, Use::DepthWrite});
        for (const Access& sample : gbufferSamples(frame, DepthRead::FromTarget)) used.push_back(sample);
        used.push_back({Target::Final, Use::Write});
        return used;
    }

protected:
    void execute(PassContext& context) override;
};

}  // namespace oasis
