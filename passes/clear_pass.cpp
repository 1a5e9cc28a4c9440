// Clears with every write mask open so an earlier pass's state cannot leave stale data.
#include "passes/clear_pass.h"

#include "common/shared_constants.glsl"

namespace oasis {

void ClearPass::execute(PassContext& context) {
    bindSurfaceOutput(context.targets, output_);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glStencilMask(0xFF);
    glDisable(GL_SCISSOR_TEST);
    const GLfloat nothing[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    if (output_ == SurfaceOutput::GBuffer) {
        // clearedInfo() in gbuffer.glsl: the sky flag in the layout's flags channel.
        glm::vec4 skyInfo = context.targets.layout().clearedInfo();
        const FrameTargets& targets = context.targets;
        for (int slot = 0; slot < targets.gbufferSlotCount(); ++slot) glClearBufferfv(GL_COLOR, slot, nothing);
        glClearBufferfv(GL_COLOR, targets.gbufferSlot(Target::Info), &skyInfo[0]);
    } else {
        glClearBufferfv(GL_COLOR, 0, nothing);
    }
    glClearBufferfi(GL_DEPTH_STENCIL, 0, context.targets.depth().farPlaneWindowDepth, kStencilNothing);
}

}  // namespace oasis
