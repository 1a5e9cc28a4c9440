// SkyPass (forward only): fills every pixel nothing else covered with the procedural sky.
// Mirrored: the mirrored sky inside the water. The deferred pipeline evaluates the same sky in
// its lighting pass, where the G-buffer clear left the sky flag.
#pragma once
#include "passes/pass.h"

namespace oasis {

class SkyPass : public Pass {
public:
    explicit SkyPass(Mirroring mirroring = Mirroring::Direct) : mirroring_(mirroring) {}
    std::string name() const override { return variantName("SkyPass", SurfaceOutput::Forward, mirroring_); }
    std::vector<Target> reads() const override { return {Target::DepthStencil}; }
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
