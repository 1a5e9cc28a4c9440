// The water quad, stencil only.
#include "passes/water_mask_pass.h"

namespace oasis {

void WaterMaskPass::execute(PassContext& context) {
    // Any framebuffer with the shared depth-stencil will do; Radiance's needs no draw buffers set.
    glBindFramebuffer(GL_FRAMEBUFFER, context.targets.radianceFramebuffer());
    glViewport(0, 0, context.targets.width(), context.targets.height());
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_DEPTH_CLAMP);  // the plane must not be clipped by the near plane when the eye is at it
    glDepthFunc(context.targets.depth().nearerFunc);
    glDepthMask(depth_ == WaterDepth::Written ? GL_TRUE : GL_FALSE);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, kStencilWater, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glStencilMask(0xFF);
    glUseProgram(context.shaders.program("water.mask"));
    context.geometry.drawWaterQuad();
    glDisable(GL_STENCIL_TEST);
    glDepthMask(GL_TRUE);
    glDisable(GL_DEPTH_CLAMP);
    glDisable(GL_DEPTH_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

}  // namespace oasis
