// SkyPass: fills every pixel nothing else covered with the procedural sky, in both pipelines
// (deferred: after LightingPass, which shades only the surfaces). Mirrored: the mirrored sky
// inside the water.
#pragma once
#include "passes/pass.h"

namespace oasis {

class SkyPass : public Pass {
public:
    // `pipelineSurfaces`: how the pipeline's surfaces are drawn (forward shaded, or the G-buffer);
    // it only names the pass, SkyPass.forward or SkyPass.deferred: the sky is drawn alike in both.
    explicit SkyPass(SurfaceOutput pipelineSurfaces, Mirroring mirroring = Mirroring::Direct)
        : pipelineSurfaces_(pipelineSurfaces), mirroring_(mirroring) {}
    std::string name() const override {
        return std::string("SkyPass.") + (pipelineSurfaces_ == SurfaceOutput::Forward ? "forward" : "deferred") +
               (mirroring_ == Mirroring::Mirrored ? ".mirrored" : "");
    }
    // Where no surface was drawn (the depth test against the far plane); Final too where the tone
    // map is fused into the direct sky; mirrored, inside the water only.
    std::vector<Access> declaredAccesses(const FrameSetup& frame) const override {
        std::vector<Access> used;
        for (Target target : surfaceOutputTargets(frame, SurfaceOutput::Forward, mirroring_))
            used.push_back({target, Use::Write});
        appendDepthStencil(used, {Use::DepthTest});
        if (mirroring_ == Mirroring::Mirrored) appendDepthStencil(used, {Use::StencilTest});
        return used;
    }
    bool reflectionWork() const override { return mirroring_ == Mirroring::Mirrored; }
    bool active(const FrameSetup& frame) const override { return mirroredPassActive(frame, mirroring_); }

protected:
    void execute(PassContext& context) override;

private:
    SurfaceOutput pipelineSurfaces_;
    Mirroring mirroring_;
};

}  // namespace oasis
