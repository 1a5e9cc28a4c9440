// VegetationPass: the plant billboards, alpha-tested against the plant atlas, their surfaces to
// the G-buffer or shaded into Radiance, marking their pixels kStencilVegetation. Mirrored: their
// mirror images, inside the water only. Draws nothing when vegetation is off or has no atlas.
#pragma once
#include "passes/pass.h"

namespace oasis {

class VegetationPass : public SurfacePass {
public:
    VegetationPass(SurfaceOutput output, Mirroring mirroring = Mirroring::Direct)
        : SurfacePass("VegetationPass", output, mirroring) {}
    // The billboards are drawn from the instances the renderer uploaded for this frame.
    std::vector<Access> declaredAccesses(const FrameSetup& frame) const override {
        std::vector<Access> used = SurfacePass::declaredAccesses(frame);
        used.push_back({Buffer::PlantInstances, Use::Sample});
        return used;
    }
    bool active(const FrameSetup& frame) const override {
        return frame.vegetationEnabled && SurfacePass::active(frame);
    }

protected:
    void execute(PassContext& context) override;
};

}  // namespace oasis
