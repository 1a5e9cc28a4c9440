// LightingPass: the deferred pipeline's shading. Reads the four G-buffer targets and writes
// Radiance; mirrored, it lights the mirrored G-buffer into Reflection inside the water only. With
// the tiled light method it adds the point lights too (the list from LightTilingPass).
#pragma once
#include "passes/pass.h"

namespace oasis {

class LightingPass : public Pass {
public:
    explicit LightingPass(Mirroring mirroring = Mirroring::Direct) : mirroring_(mirroring) {}
    std::string name() const override {
        return mirroring_ == Mirroring::Mirrored ? "LightingPass.mirrored" : "LightingPass";
    }
    std::vector<Target> reads() const override {
        return {Target::Albedo, Target::Normal, Target::Position, Target::Info};
    }
    std::vector<Target> writes() const override {
        return {mirroring_ == Mirroring::Mirrored ? Target::Reflection : Target::Radiance};
    }
    bool reflectionWork() const override { return mirroring_ == Mirroring::Mirrored; }
    bool active(const FrameSetup& frame) const override { return mirroredPassActive(frame, mirroring_); }

protected:
    void execute(PassContext& context) override;

private:
    Mirroring mirroring_;
};

}  // namespace oasis
