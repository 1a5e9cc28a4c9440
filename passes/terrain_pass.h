// TerrainPass: draws the terrain grid, its surfaces to the G-buffer or shaded into Radiance,
// marking its pixels in the stencil buffer. Mirrored: its mirror image, inside the water only.
#pragma once
#include "passes/pass.h"

namespace oasis {

class TerrainPass : public Pass {
public:
    TerrainPass(SurfaceOutput output, Mirroring mirroring = Mirroring::Direct)
        : output_(output), mirroring_(mirroring) {}
    std::string name() const override { return variantName("TerrainPass", output_, mirroring_); }
    std::vector<Target> reads() const override { return {}; }
    std::vector<Target> writes() const override { return surfaceOutputTargets(output_, mirroring_); }
    bool active(const FrameSetup& frame) const override { return mirroredPassActive(frame, mirroring_); }

protected:
    void execute(PassContext& context) override;

private:
    SurfaceOutput output_;
    Mirroring mirroring_;
};

}  // namespace oasis
