// WaterCompositePass: lays the water surface over Radiance inside the water mask: the
// reflection (or the sky alone, with reflections off) weighted by Fresnel, plus the sun's glint;
// then leaves the water surface's depth in the depth buffer. Skipped with the camera under water.
#pragma once
#include "passes/pass.h"

namespace oasis {

class WaterCompositePass : public Pass {
public:
    // `ontoRadiance`: the composite a view of Radiance needs after a frame whose tone map was fused
    // (which left Radiance without the water): the separate pass's blend onto Radiance, named
    // WaterCompositePass.radiance, with work only in such a frame (frame/frame_views.h).
    explicit WaterCompositePass(bool ontoRadiance = false) : ontoRadiance_(ontoRadiance) {}
    std::string name() const override { return ontoRadiance_ ? "WaterCompositePass.radiance" : "WaterCompositePass"; }
    // Fused, it blends Radiance (sampled) and tone-maps the water's pixels into Final; else it
    // blends onto Radiance. Either way it leaves the water surface's depth.
    std::vector<Access> declaredAccesses(const FrameSetup& frame) const override {
        // The reflection only where it was drawn (water_composite.frag's reflectionsActive()).
        std::vector<Access> used;
        if (frame.reflectionsActive) used.push_back({Target::Reflection, Use::Sample});
        if (fused(frame)) used.push_back({Target::Radiance, Use::Sample});
        used.push_back({fused(frame) ? Target::Final : Target::Radiance, Use::Write});
        appendDepthStencil(used, {Use::StencilTest, Use::DepthWrite});
        return used;
    }
    bool active(const FrameSetup& frame) const override {
        return frame.cameraAboveWater && (!ontoRadiance_ || frame.toneMapFused);
    }

protected:
    void execute(PassContext& context) override;

private:
    bool fused(const FrameSetup& frame) const { return frame.toneMapFused && !ontoRadiance_; }
    bool ontoRadiance_;
};

}  // namespace oasis
