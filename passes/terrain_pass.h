// TerrainPass: draws the terrain grid, its surfaces to the G-buffer or shaded into Final,
// marking its pixels in the stencil buffer.
#pragma once
#include "passes/pass.h"

namespace oasis {

class TerrainPass : public Pass {
public:
    explicit TerrainPass(SurfaceOutput output) : output_(output) {}
    std::string name() const override { return std::string("TerrainPass.") + surfaceOutputName(output_); }
    std::vector<Target> reads() const override { return {}; }
    std::vector<Target> writes() const override { return surfaceOutputTargets(output_); }

protected:
    void execute(PassContext& context) override;

private:
    SurfaceOutput output_;
};

}  // namespace oasis
