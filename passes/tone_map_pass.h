// ToneMapPass: Radiance (linear HDR) to Final (8-bit display colour); the last pass of both pipelines
// when it runs: only where the tone map cannot be fused into the passes that write each pixel's
// colour last (FrameSetup::toneMapFused: --stop-before, the deferred light volumes).
#pragma once
#include "passes/pass.h"

namespace oasis {

class ToneMapPass : public Pass {
public:
    std::string name() const override { return "ToneMapPass"; }
    std::vector<Access> declaredAccesses(const FrameSetup&) const override {
        return {{Target::Radiance, Use::Sample}, {Target::Final, Use::Write}};
    }
    bool active(const FrameSetup& frame) const override { return !frame.toneMapFused; }

protected:
    void execute(PassContext& context) override;
};

}  // namespace oasis
