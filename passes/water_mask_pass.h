// WaterMaskPass: marks kStencilWater wherever the water plane is the nearest surface (depth
// tested against what is already drawn, writing no colour and no depth).
#pragma once
#include "passes/pass.h"

namespace oasis {

class WaterMaskPass : public Pass {
public:
    std::string name() const override { return "WaterMaskPass"; }
    std::vector<Target> reads() const override { return {Target::DepthStencil}; }
    std::vector<Target> writes() const override { return {Target::DepthStencil}; }

protected:
    void execute(PassContext& context) override;
};

}  // namespace oasis
