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
    // The reduced reflection's Reflection (the target at its scale) is sampled; the stencil keeps
    // the draw inside the water.
    std::vector<Access> declaredAccesses(const FrameSetup& frame) const override {
        std::vector<Access> used{{Target::Reflection, Use::Write}, {Target::DepthStencil, Use::StencilTest}};
        if (frame.reflectionDivisor > 1)
            used.insert(used.begin(), {ScaledTarget{Target::Reflection, frame.reflectionDivisor}, Use::Sample});
        return used;
    }
    bool active(const FrameSetup& frame) const override {
        return frame.reflectionsActive && frame.reflectionDivisor > 1;
    }

protected:
    void execute(PassContext& context) override;
};

}  // namespace oasis
