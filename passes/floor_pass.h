// FloorPass: the timing floor. A full-screen write of every G-buffer target plus a full-screen
// read of them into Final: the least any deferred frame of this size and layout can cost.
// Not part of a pipeline; commands run it to report times as ratios against it.
#pragma once
#include "passes/pass.h"

namespace oasis {

class FloorPass : public Pass {
public:
    std::string name() const override { return "FloorPass"; }
    std::vector<Target> reads() const override {
        return {Target::Albedo, Target::Normal, Target::Position, Target::Info};
    }
    std::vector<Target> writes() const override {
        return {Target::Albedo, Target::Normal, Target::Position, Target::Info, Target::DepthStencil, Target::Final};
    }

protected:
    void execute(PassContext& context) override;
};

}  // namespace oasis
