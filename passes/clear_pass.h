// ClearPass: resets the targets a pipeline draws into (depth 1, stencil 0, colour to "nothing
// drawn": for the G-buffer that is the sky flag in info, so lighting knows to evaluate the sky).
#pragma once
#include "passes/pass.h"

namespace oasis {

class ClearPass : public Pass {
public:
    explicit ClearPass(SurfaceOutput output) : output_(output) {}
    std::string name() const override { return std::string("ClearPass.") + surfaceOutputName(output_); }
    std::vector<Access> accesses(const FrameSetup& frame) const override;
    std::string sceneStep() const override { return "clear"; }

protected:
    void execute(PassContext& context) override;

private:
    SurfaceOutput output_;
};

}  // namespace oasis
