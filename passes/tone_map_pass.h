// ToneMapPass: Radiance (linear HDR) to Final (8-bit display colour); the last pass of both pipelines.
#pragma once
#include "passes/pass.h"

namespace oasis {

class ToneMapPass : public Pass {
public:
    std::string name() const override { return "ToneMapPass"; }
    std::vector<Target> reads() const override { return {Target::Radiance}; }
    std::vector<Target> writes() const override { return {Target::Final}; }

protected:
    void execute(PassContext& context) override;
};

}  // namespace oasis
