// Write pass with depth (as the geometry pass does), then a read pass like the lighting pass.
#include "passes/floor_pass.h"

namespace oasis {

void FloorPass::execute(PassContext& context) {
    const FrameTargets& targets = context.targets;
    bindSurfaceOutput(targets, SurfaceOutput::GBuffer);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glDepthMask(GL_TRUE);
    glUseProgram(context.shaders.program(targets.layout().program("floor.write")));
    context.geometry.drawFullscreenTriangle();
    glDisable(GL_DEPTH_TEST);

    glBindFramebuffer(GL_FRAMEBUFFER, targets.finalFramebuffer());
    bindGBufferInputs(targets);
    glUseProgram(context.shaders.program(targets.layout().program("floor.read")));
    context.geometry.drawFullscreenTriangle();
}

}  // namespace oasis
