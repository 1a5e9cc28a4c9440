// WaterCompositePass: lays the water surface over Radiance inside the water mask: the
// reflection (or the sky alone, with reflections off) weighted by Fresnel, plus the sun's glint;
// then leaves the water surface's depth in the depth buffer. Skipped with the camera under water.
#pragma once
#include "passes/pass.h"

namespace oasis {

class WaterCompositePass : public Pass {
public:
    std::string name() const override { return "WaterCompositePass"; }
    std::vector<Target> reads() const override { return {Target::Reflection, Target::DepthStencil}; }
    // Final where the tone map is fused (it blends and tone-maps the water's pixels into Final).
    std::vector<Target> writes() const override { return {Target::Radiance, Target::Final, Target::DepthStencil}; }
    bool active(const FrameSetup& frame) const override { return frame.cameraAboveWater; }

protected:
    void execute(PassContext& context) override;
};

}  // namespace oasis
