// TerrainHeightsPass: places this frame's terrain grid around the camera and raises it to the
// noise height, once, for every terrain draw after it (the shadow cascades, the G-buffer or the
// forward draw, the reflection). The noise was most of those draws' vertex work: each evaluated
// it again for the same vertices. First in both pipelines and in the views' fills.
#pragma once
#include "passes/pass.h"

namespace oasis {

class TerrainHeightsPass : public Pass {
public:
    std::string name() const override { return "TerrainHeightsPass"; }
    std::vector<Access> declaredAccesses(const FrameSetup&) const override {
        return {{Buffer::TerrainHeights, Use::Replace}};  // the grid's heights buffer, no frame target
    }

protected:
    void execute(PassContext& context) override;
};

}  // namespace oasis
