// WaterCompositePass: lays the water surface over Radiance inside the water mask: the
// reflection (or the sky alone, with reflections off) weighted by Fresnel, plus the sun's glint;
// then leaves the water surface's depth in the depth buffer. Skipped with the camera under water.
#pragma once
#include "passes/pass.h"

namespace oasis {

class WaterCompositePass : public Pass {
public:
    std::string name() const override { return "WaterCompositePass"; }
    // Fused, it blends Radiance (sampled) and tone-maps the water's pixels into Final; else it
    // blends onto Radiance. Either way it leaves the water surface's depth.
    std::vector<Access> declaredAccesses(const FrameSetup& frame) const override {
        // The reflection only where it was drawn (water_composite.frag's reflectionsActive()).
        std::vector<Access> used;
        if (frame.reflectionsActive) used.push_back({Target::Reflection, Use::Sample});
        if (frame.toneMapFused) used.push_back({Target::Radiance, Use::Sample});
        used.push_back({frame.toneMapFused ? Target::Final : Target::Radiance, Use::Write});
        appendDepthStencil(used, {Use::StencilTest, Use::DepthWrite});
        return used;
    }
    bool active(const FrameSetup& frame) const override { return frame.cameraAboveWater; }

protected:
    void execute(PassContext& context) override;
};

}  // namespace oasis
