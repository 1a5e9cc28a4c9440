// The water quad again, stencil-masked to the water, blended (premultiplied) onto Radiance; with the
// tone map fused, blended in the shader and tone mapped into Final (Radiance keeps what is under).
#include "passes/water_composite_pass.h"

#include "passes/water_mask_pass.h"  // drawWaterSurface

namespace oasis {

void WaterCompositePass::execute(PassContext& context) {
    // Fused: the same blend done in the shader over Radiance (read, not attached) into Final.
    bool fused = this->fused(context.frame);
    bindDeclaredOutputs(context);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_EQUAL, kStencilWater, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glStencilMask(0x00);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);  // the mirrored scene's depths are behind us now; the water's replace them
    glDepthMask(GL_TRUE);
    if (!fused) glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    // As markWaterStencil: the grid depth-clamped, else the plane found per fragment.
    drawWaterSurface(context, fused ? "water.composite.tonemapped" : "water.composite");
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    glStencilMask(0xFF);
}

}  // namespace oasis
