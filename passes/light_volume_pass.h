// LightVolumePass: the deferred pipeline's point lights. Per light, its volume is marked in the
// stencil buffer (both faces, depth-fail, toggling one upper bit) and then shaded only where
// marked, added to Radiance; the shading draw resets the bit, so nothing clears the whole stencil
// and the cost of a light follows the pixels its volume covers. Mirrored: the lights' mirror
// images over the mirrored G-buffer, inside the water only, added to Reflection.
#pragma once
#include "passes/pass.h"

namespace oasis {

// The stencil bit the light volumes use; the low bits keep the surface marks (passes/pass.h).
inline constexpr int kStencilLightVolumeBit = 0x80;

class LightVolumePass : public Pass {
public:
    explicit LightVolumePass(Mirroring mirroring = Mirroring::Direct) : mirroring_(mirroring) {}
    std::string name() const override {
        return mirroring_ == Mirroring::Mirrored ? "LightVolumePass.mirrored" : "LightVolumePass";
    }
    std::vector<Access> declaredAccesses(const FrameSetup& frame) const override {
        // It writes stencil while it tests depth, so a compact layout's depth comes from the copy.
        std::vector<Access> used = gbufferSamples(frame, DepthRead::FromCopy);
        used.push_back({mirroring_ == Mirroring::Mirrored ? Target::Reflection : Target::Radiance, Use::Write});
        appendDepthStencil(used, {Use::DepthTest, Use::StencilTest, Use::StencilWrite});
        used.push_back({Buffer::LightList, Use::Sample});  // a volume per light, shaded by it
        if (frame.shadowsActive) used.push_back({Buffer::ShadowMaps, Use::Sample});
        return used;
    }
    bool reflectionWork() const override { return mirroring_ == Mirroring::Mirrored; }
    bool active(const FrameSetup& frame) const override {
        return frame.lightMethod == LightMethod::Volumes && !frame.lights.empty() && mirroredPassActive(frame, mirroring_);
    }

protected:
    void execute(PassContext& context) override;

private:
    Mirroring mirroring_;
};

}  // namespace oasis
