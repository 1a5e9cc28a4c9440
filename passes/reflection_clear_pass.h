// ReflectionClearPass: with reflections active, resets depth inside the water to the far plane
// (and, for the G-buffers that store position, the "nothing drawn" values) so the mirrored scene is
// depth-tested against itself only. It clears nothing outside the water: Reflection is read only at
// water pixels, where the mirrored passes write every pixel.
#pragma once
#include "passes/pass.h"

namespace oasis {

class ReflectionClearPass : public Pass {
public:
    explicit ReflectionClearPass(SurfaceOutput output) : output_(output) {}
    std::string name() const override { return std::string("ReflectionClearPass.") + surfaceOutputName(output_); }
    std::vector<Access> accesses(const FrameSetup& frame) const override;
    bool active(const FrameSetup& frame) const override;
protected:
    void execute(PassContext& context) override;

private:
    SurfaceOutput output_;
};

}  // namespace oasis
