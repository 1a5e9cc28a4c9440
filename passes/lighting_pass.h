// LightingPass: the deferred pipeline's shading. Reads the four G-buffer targets, writes Final.
#pragma once
#include "passes/pass.h"

namespace oasis {

class LightingPass : public Pass {
public:
    std::string name() const override { return "LightingPass"; }
    std::vector<Target> reads() const override {
        return {Target::Albedo, Target::Normal, Target::Position, Target::Info};
    }
    std::vector<Target> writes() const override { return {Target::Final}; }

protected:
    void execute(PassContext& context) override;
};

}  // namespace oasis
