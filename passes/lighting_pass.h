// LightingPass: the deferred pipeline's shading of the surfaces. Reads the four G-buffer targets and
// writes Radiance; mirrored, it lights the mirrored G-buffer into Reflection inside the water only.
// The sky is SkyPass's, after it, as in forward. With the tiled light method it adds the point
// lights too (the list from LightTilingPass).
#pragma once
#include "passes/pass.h"

namespace oasis {

class LightingPass : public Pass {
public:
    explicit LightingPass(Mirroring mirroring = Mirroring::Direct) : mirroring_(mirroring) {}
    std::string name() const override {
        return mirroring_ == Mirroring::Mirrored ? "LightingPass.mirrored" : "LightingPass";
    }
    std::vector<Access> declaredAccesses(const FrameSetup& frame) const override;
    bool reflectionWork() const override { return mirroring_ == Mirroring::Mirrored; }
    bool active(const FrameSetup& frame) const override { return mirroredPassActive(frame, mirroring_); }
    // Whether the depth test keeps the pass to the surfaces (else every pixel is shaded, the sky's
    // black): unless it samples the very target it would test and the context forbids that.
    bool testsSurfaces(const FrameSetup& frame) const;
    // Where it reads the surfaces' depth: the depth target itself for the direct half where the
    // frame reads it in place (render/frame_setup.h's lightingSamplesDepthTarget), else the copy.
    DepthRead depthRead(const FrameSetup& frame) const;

protected:
    void execute(PassContext& context) override;

private:
    Mirroring mirroring_;
};

}  // namespace oasis
