// SkyPass: fills every pixel nothing else covered with the procedural sky, flagged as sky,
// either into the G-buffer or shaded into Final.
#pragma once
#include "passes/pass.h"

namespace oasis {

class SkyPass : public Pass {
public:
    explicit SkyPass(SurfaceOutput output) : output_(output) {}
    std::string name() const override { return std::string("SkyPass.") + surfaceOutputName(output_); }
    std::vector<Target> reads() const override { return {Target::DepthStencil}; }
    std::vector<Target> writes() const override { return surfaceOutputTargets(output_); }

protected:
    void execute(PassContext& context) override;

private:
    SurfaceOutput output_;
};

}  // namespace oasis
