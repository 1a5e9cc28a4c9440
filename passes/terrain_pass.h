// TerrainPass: draws the terrain grid, its surfaces to the G-buffer or shaded into Radiance,
// marking its pixels in the stencil buffer. Mirrored: its mirror image, inside the water only.
#pragma once
#include "passes/pass.h"

namespace oasis {

class TerrainPass : public SurfacePass {
public:
    TerrainPass(SurfaceOutput output, Mirroring mirroring = Mirroring::Direct)
        : SurfacePass("TerrainPass", output, mirroring) {}

protected:
    void execute(PassContext& context) override;
};

}  // namespace oasis
