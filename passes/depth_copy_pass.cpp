// A full-screen draw that writes each pixel's depth from the G-buffer's depth texture.
#include "passes/depth_copy_pass.h"

namespace oasis {

void DepthCopyPass::execute(PassContext& context) {
    bindDeclaredOutputs(context);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glDepthMask(GL_TRUE);
    glDisable(GL_STENCIL_TEST);
    // The mirrored copy is read only inside the water (stencil-tested passes).
    bool mirrored = mirroring_ == Mirroring::Mirrored;
    if (mirrored) beginWaterBoundedDraw(context);
    glUseProgram(context.shaders.program(mirrored ? "depth.copy.mirrored" : "depth.copy"));
    context.geometry.drawFullscreenTriangle();
    if (mirrored) endWaterBoundedDraw(context);
    glDisable(GL_DEPTH_TEST);
}

}  // namespace oasis
