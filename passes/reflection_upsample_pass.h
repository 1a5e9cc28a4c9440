// ReflectionUpsamplePass: with the reflection drawn at a reduced resolution (--reflection-resolution
// half|quarter), reads its smaller Reflection bilinearly into the frame's Reflection target at the
// frame's visible water (stencil-masked, clipped to the water's rectangle), where the water
// composite, the views and the probe read it as they do at full resolution. Inactive otherwise.
#pragma once
#include "passes/pass.h"

namespace oasis {

class ReflectionUpsamplePass : public Pass {
public:
    std::string name() const override { return "ReflectionUpsamplePass"; }
    std::vector<Target> reads() const override { return {Target::Reflection, Target::DepthStencil}; }
    std::vector<Target> writes() const override { return {Target::Reflection}; }
    bool active(const FrameSetup& frame) const override {
        return frame.reflectionsActive && frame.reflectionDivisor > 1;
    }

protected:
    void execute(PassContext& context) override;
};

}  // namespace oasis
