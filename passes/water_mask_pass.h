// WaterMaskPass: marks kStencilWater wherever the water plane is the nearest surface (depth
// tested against what is already drawn) and leaves the water's depth there; writes no colour.
// Depth is then the visible surface's at every later stage, with reflections on or off.
// The views' fill of the direct scene (frame/view_fill.h) marks the water without its depth, so
// depth keeps the lakebed the G-buffer holds there.
#pragma once
#include "passes/pass.h"

namespace oasis {

enum class WaterDepth { Written, Kept };

// The water surface drawn with `program` in the state the caller set, never clipped by the near
// plane: the grid (water.vert) with depth clamp, or where the context has none the program's
// ".fullscreen" variant over a full-screen triangle, finding the plane per fragment
// (common/water_fragment.glsl). The water's mask and composite draw it.
void drawWaterSurface(PassContext& context, const std::string& program);

// The water surface drawn with `program` into the bound framebuffer's stencil, marking kStencilWater
// wherever a fragment survives the depth state the caller set; no colour. Shared by this pass and
// the reduced reflection's own mask.
void markWaterStencil(PassContext& context, const char* program);

class WaterMaskPass : public Pass {
public:
    explicit WaterMaskPass(WaterDepth depth = WaterDepth::Written) : depth_(depth) {}
    std::string name() const override { return "WaterMaskPass"; }
    // Depth-tested against the surfaces; marks the water in the stencil (and writes its depth
    // unless kept).
    std::vector<Access> declaredAccesses(const FrameSetup&) const override {
        std::vector<Access> used;
        appendDepthStencil(used, {Use::DepthTest, Use::StencilWrite});
        if (depth_ == WaterDepth::Written) appendDepthStencil(used, {Use::DepthWrite});
        return used;
    }
    std::string sceneStep() const override { return "WaterMaskPass"; }  // the same pass in both pipelines

protected:
    void execute(PassContext& context) override;

private:
    WaterDepth depth_;
};

}  // namespace oasis
