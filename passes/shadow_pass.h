// ShadowPass: draws the terrain and the plants (alpha-tested billboards, as the frame draws them)
// from the sun into each cascade's depth map (render/shadow_maps.h), first in both pipelines.
// Active only while shadows are on and the sun is above the horizon: at night nothing runs.
#pragma once
#include "passes/pass.h"

namespace oasis {

class ShadowPass : public Pass {
public:
    std::string name() const override { return "ShadowPass"; }
    std::vector<Access> declaredAccesses(const FrameSetup& frame) const override {
        std::vector<Access> used = {{Buffer::TerrainHeights, Use::Sample}, {Buffer::ShadowMaps, Use::Replace}};  // no frame target
        if (frame.vegetationEnabled) used.push_back({Buffer::PlantInstances, Use::Sample});  // the plants cast too
        return used;
    }
    bool active(const FrameSetup& frame) const override { return frame.shadowsActive; }

protected:
    void execute(PassContext& context) override;
};

}  // namespace oasis
