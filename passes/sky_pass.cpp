// The sky is a full-screen triangle at the far plane: depth test LEQUAL against the cleared
// depth of 1 keeps it only where nothing was drawn; it writes no depth and no stencil.
#include "passes/sky_pass.h"

namespace oasis {

void SkyPass::execute(PassContext& context) {
    bindSurfaceOutput(context.targets, output_);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_FALSE);
    glUseProgram(context.shaders.program(output_ == SurfaceOutput::GBuffer ? "sky.gbuffer" : "sky.forward"));
    context.geometry.drawFullscreenTriangle();
    glDepthMask(GL_TRUE);
    glDisable(GL_DEPTH_TEST);
}

}  // namespace oasis
