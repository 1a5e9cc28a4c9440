// TerrainPass: draws the terrain grid, its surfaces to the G-buffer or shaded into Radiance,
// marking its pixels in the stencil buffer. Mirrored: its mirror image, inside the water only.
#pragma once
#include "passes/pass.h"

namespace oasis {

class TerrainPass : public SurfacePass {
public:
    TerrainPass(SurfaceOutput output, Mirroring mirroring = Mirroring::Direct)
        : SurfacePass("TerrainPass", output, mirroring) {}
    // The grid's vertices take their heights from TerrainHeightsPass's buffer.
    std::vector<Access> declaredAccesses(const FrameSetup& frame) const override {
        std::vector<Access> used = SurfacePass::declaredAccesses(frame);
        used.push_back({Buffer::TerrainHeights, Use::Sample});
        return used;
    }

protected:
    void execute(PassContext& context) override;
};

}  // namespace oasis
