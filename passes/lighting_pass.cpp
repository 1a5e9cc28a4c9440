// One full-screen triangle; every pixel's surface comes from the G-buffer.
#include "passes/lighting_pass.h"

namespace oasis {

void LightingPass::execute(PassContext& context) {
    const FrameTargets& targets = context.targets;
    glBindFramebuffer(GL_FRAMEBUFFER, targets.finalFramebuffer());
    glViewport(0, 0, targets.width(), targets.height());
    glDisable(GL_DEPTH_TEST);
    bindGBufferInputs(targets);
    glUseProgram(context.shaders.program("lighting"));
    context.geometry.drawFullscreenTriangle();
}

}  // namespace oasis
